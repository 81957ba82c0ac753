#!/usr/bin/env bash
# The program restarts itself with glibc's malloc asking for transparent huge pages, on every
# rank of an MPI run, and leaves a GLIBC_TUNABLES of the user's alone.
#   huge_pages.sh MPIEXEC RANKS SIGNORINI INPUT.xml
set -u
mpiexec=$1 ranks=$2 signorini=$3 input=$4
output=$(mktemp -d)
trap 'rm -rf "$output"' EXIT
run() {  # run NAME [VAR=VALUE]: the summary's "huge_pages" field, or a failure
  rm -rf "$output/$1"
  if ! env -u GLIBC_TUNABLES ${2:+"$2"} "$mpiexec" -np "$ranks" "$signorini" "$input" --output "$output/$1" \
       --set "Output/write solution=false" >"$output/$1.log" 2>&1; then
    echo "the $1 run failed:"; cat "$output/$1.log"; exit 1
  fi
  grep -o '"huge_pages": [a-z]*' "$output/$1/summary.json"
}
restarted=$(run restarted)
if [ "$restarted" != '"huge_pages": true' ]; then
  echo "without GLIBC_TUNABLES the run should ask for huge pages, got: $restarted"; exit 1
fi
chosen=$(run chosen GLIBC_TUNABLES=glibc.malloc.hugetlb=0)
if [ "$chosen" != '"huge_pages": false' ]; then
  echo "the user's GLIBC_TUNABLES should be left alone, got: $chosen"; exit 1
fi
echo "2 passed, 0 failed"

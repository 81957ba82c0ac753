#!/usr/bin/env bash
# One rank fails alone (it cannot write its piece of the solution) while the others go on:
# the job ends on every rank, without hanging, with exit status 4 (an output error) and the
# failing rank's message.
#   one_rank_fails.sh MPIEXEC RANKS SIGNORINI INPUT.xml
set -u
mpiexec=$1 ranks=$2 signorini=$3 input=$4
output=$(mktemp -d)
trap 'rm -rf "$output"' EXIT
mkdir -p "$output/solution_1.vtu/occupied"  # rank 1's piece cannot replace a directory
"$mpiexec" -np "$ranks" "$signorini" "$input" --output "$output" >"$output/log" 2>&1
status=$?
if [ "$status" -ne 4 ]; then
  echo "expected exit status 4, got $status"; cat "$output/log"; exit 1
fi
if ! grep -q "signorini: output error.*cannot rename '$output/solution_1.vtu.tmp'" "$output/log"; then
  echo "the failing rank's message is missing:"; cat "$output/log"; exit 1
fi
if [ -e "$output/summary.json" ] || [ -e "$output/solution.pvtu" ]; then
  echo "a summary or a solution index was written for the failed run"; exit 1
fi
echo "1 passed, 0 failed"

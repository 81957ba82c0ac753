#!/usr/bin/env bash
# The results cannot be written (here a file size limit of 4 KiB, which fails the writes as
# a full disk does): the run ends with exit status 4 (an output error) and one line that
# names the file and says what the system said; no half-written file is left.
#   output_write_fails.sh MPIEXEC RANKS SIGNORINI INPUT.xml
set -u
mpiexec=$1 ranks=$2 signorini=$3 input=$4
output=$(mktemp -d)
trap 'rm -rf "$output"' EXIT
# The limit for the solver's processes alone, and no shared-memory transport: Open MPI's own
# files need more.
OMPI_MCA_btl=self,tcp "$mpiexec" -np "$ranks" bash -c 'trap "" XFSZ; ulimit -f 4; exec "$0" "$@"' \
  "$signorini" "$input" --output "$output/results" >"$output/log" 2>&1
status=$?
if [ "$status" -ne 4 ]; then
  echo "expected exit status 4, got $status"; cat "$output/log"; exit 1
fi
if ! grep -q "^signorini: output error: .*cannot write '$output/results/.*': File too large$" "$output/log"; then
  echo "the message with the system's reason is missing:"; cat "$output/log"; exit 1
fi
if [ -n "$(find "$output/results" -name '*.tmp')" ]; then
  echo "a temporary file was left behind"; ls -la "$output/results"; exit 1
fi
echo "1 passed, 0 failed"

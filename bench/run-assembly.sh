#!/usr/bin/env bash
# Assembly time and memory of ~1 million unknown members of the family, on 1 and 2 ranks.
# Writes bench/results/assembly.json (a list of records from signorini_bench_assembly).
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_btl_vader_single_copy_mechanism=none
records=()
for case in "3 1 70" "2 1 700" "3 2 35"; do
  for np in 1 2; do
    records+=("$(mpirun -np $np build/bin/signorini_bench_assembly $case | tail -n 1)")
  done
done
mkdir -p bench/results
{ echo "["; (IFS=$'\n'; echo "${records[*]}" | sed '$!s/$/,/'); echo "]"; } > bench/results/assembly.json
cat bench/results/assembly.json

#!/usr/bin/env bash
# The narration lint fails on what it is meant to catch and passes a measured comparison:
# it is run on a scratch tree holding one line at a time.
#   narration_lint_catches.sh SOURCE_DIR
set -u
lint=$1/tests/lint/no_development_narration.sh
tree=$(mktemp -d)
trap 'rm -rf "$tree"' EXIT
passed=0 failed=0
check() {  # check EXPECTED_STATUS LINE
  printf '%s\n' "$2" > "$tree/notes.md"
  bash "$lint" "$tree" > /dev/null
  local status=$?
  if [ "$status" -eq "$1" ]; then passed=$((passed + 1)); else failed=$((failed + 1)); echo "status $status for: $2"; fi
}
check 1 "3D P1 nx = 64 on 2 ranks: assembly 3.7 -> 2.6 s, solve about 12% shorter"
check 1 "smoother setups over 12 builds 0.79 → 0.35 s"
check 1 "nx = 100 on 2 ranks 12.0–12.9 → 10.5–10.8 s"
check 1 "where the 30 power iterations used before reached 98.4%"
check 1 "this is twice as fast, and faster than the old assembly"
work="sess""ion"  # assembled here, so that this file holds no such phrase itself
check 1 "measured in $work 12"
check 0 "assembly 2.6 s against 3.7 s without huge pages"
check 0 "the CG count grows from 15 to 30 (nx = 10 → 800)"
check 0 "a body that nothing holds is refused before the solve"
echo "$passed passed, $failed failed"
[ "$failed" -eq 0 ]

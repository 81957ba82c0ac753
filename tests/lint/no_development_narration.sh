#!/usr/bin/env bash
# The repository speaks of the product alone: no numbered work sessions or stages, no
# "one-off runs" or "the default until ...", no before -> after timings ("3.7 -> 2.6 s", "what
# was used before", "faster than the old one"). History lives in git and in CHANGELOG.md; a
# measured comparison says "x s against y s".
# Checks the tracked files (every file but build trees when git is not available).
set -euo pipefail
cd "$1"
pattern="\\b(sessions?|stages?) [0-9]+|one-off (run|trace)|measured once|default until"
pattern+="|[0-9][0-9.]* ?s? ?(->|→) ?[0-9][0-9.]*( ?[–-] ?[0-9][0-9.]*)? ?s\\b|\\bused before\\b|faster than (the )?(old|previous)"
if git rev-parse --is-inside-work-tree > /dev/null 2>&1; then
  files=$(git ls-files)
else
  files=$(find . -type f -not -path './build*' -not -path './.git/*')
fi
# This script and its test name the phrases it rejects.
hits=$(echo "$files" | grep -v -E '(^|/)(CHANGELOG\.md|no_development_narration\.sh|narration_lint_catches\.sh)$|\.(png|msh)$' | tr '\n' '\0' |
       xargs -0 grep -n -i -E "$pattern" -- 2> /dev/null || true)
if [ -n "$hits" ]; then
  echo "Development narration found (history belongs in git and CHANGELOG.md):"
  echo "$hits"
  exit 1
fi
echo "no development narration"

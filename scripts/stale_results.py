#!/usr/bin/env python3
"""Lists the result sets of bench/results that README.md and doc/ cite and that the current
code may no longer reproduce: those whose recorded commit predates the last commit that
changed src/ or include/, those made from a tree with uncommitted changes ("-dirty"), and
those that record no commit. A report, not a check: benchmarks take hours, and which ones to
rerun is a choice.

    scripts/stale_results.py

Prints one line per cited result set (its JSON file) and what is wrong with it (for a set made
before the last code change: how many commits changed the code since, and in which modules),
then a count.
"""
import glob
import json
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
CITING = ["README.md"] + sorted(glob.glob(os.path.join(ROOT, "doc", "*.md")))
# "bench/results/table2.md", "bench/results/table2.{json,md}", "bench/results/scaling.png"
CITATION = re.compile(r"bench/results/([A-Za-z0-9_-]+)")


def git(*args):
    return subprocess.run(["git", *args], cwd=ROOT, capture_output=True, text=True).stdout.strip()


def cited_sets():
    """The names (without extension) of the cited result sets that have a JSON file."""
    names = set()
    for path in CITING:
        with open(os.path.join(ROOT, path)) as f:
            names.update(CITATION.findall(f.read()))
    return sorted(name for name in names if os.path.isfile(os.path.join(ROOT, "bench", "results", name + ".json")))


def recorded_commits(name):
    """The commits the set records: one, or one per part for a set rerun in parts (such as
    hertz.json's studies)."""
    with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
        data = json.load(f)
    made = data.get("provenance", {}) if isinstance(data, dict) else {}
    if "commit" in made or not made:
        return [made.get("commit")]
    return [part.get("commit") for part in made.values() if isinstance(part, dict)] or [None]


def verdict(commit, last_code_change):
    """Why the set may be stale, or None."""
    if not commit or commit == "unknown":
        return "records no commit"
    if commit.endswith("-dirty"):
        return f"made from a tree with uncommitted changes ({commit})"
    full = git("rev-parse", "--verify", "--quiet", commit + "^{commit}")
    if not full:
        return f"records {commit}, which this repository does not hold"
    if full != last_code_change and subprocess.run(["git", "merge-base", "--is-ancestor", full, last_code_change],
                                                   cwd=ROOT).returncode == 0:
        return (f"made at {commit}, before the last change of src/ or include/ ({last_code_change[:7]}); "
                f"{changes_since(full, last_code_change)}")
    return None


def module_of(path):
    """src/solver/linear/X.cpp -> solver/linear; include/signorini/fe/X.hpp -> fe; src/X -> src."""
    for prefix in ("src/", "include/signorini/", "include/"):
        if path.startswith(prefix):
            return os.path.dirname(path[len(prefix):]) or prefix.rstrip("/")
    return os.path.dirname(path)


def changes_since(commit, last_code_change):
    """How many commits changed src/ or include/ after `commit`, and in which modules (the
    directories under src/ and include/signorini/): what to read before choosing to rerun."""
    count = git("rev-list", "--count", f"{commit}..{last_code_change}", "--", "src", "include")
    files = git("diff", "--name-only", commit, last_code_change, "--", "src", "include").split()
    modules = sorted({module_of(path) for path in files})
    return f"{count} commit(s) since, in {', '.join(modules) or 'no file that still differs'}"


def main():
    last_code_change = git("log", "-1", "--format=%H", "--", "src", "include")
    if not last_code_change:
        sys.exit("stale_results: no git history of src/ or include/ here")
    stale = 0
    names = cited_sets()
    for name in names:
        why = next(filter(None, (verdict(commit, last_code_change) for commit in recorded_commits(name))), None)
        print(f"bench/results/{name}.json: {why or 'current'}")
        stale += why is not None
    print(f"{stale} of {len(names)} cited result sets may not come from the current code")


if __name__ == "__main__":
    main()

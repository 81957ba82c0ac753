"""Where and with what a benchmark's results were made, for the "provenance" entry of its
JSON: the command, the git commit of the tree (git describe --always, with "-dirty" if a
tracked file outside bench/results differs from it: results that earlier benchmarks of the same
sitting rewrote do not change what is measured), the date, the host, its cores, the MPI ranks,
and the build's compiler, Signorini and Trilinos versions (as build/bin/signorini --version
reports them)."""
import datetime
import glob
import json
import os
import platform
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def compiler(build):
    """"GNU 12.2.0" from the build's CMake compiler record, or "unknown"."""
    for path in glob.glob(os.path.join(build, "CMakeFiles", "*", "CMakeCXXCompiler.cmake")):
        with open(path) as f:
            text = f.read()
        found = [re.search(r'set\(CMAKE_CXX_COMPILER_%s "([^"]*)"\)' % key, text) for key in ("ID", "VERSION")]
        if all(found):
            return " ".join(m.group(1) for m in found)
    return "unknown"


def provenance(ranks, build=os.path.join(ROOT, "build")):
    commit = subprocess.run(["git", "describe", "--always"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    changed = subprocess.run(["git", "status", "--porcelain", "--untracked-files=no", "--", ".",
                              ":(exclude)bench/results"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    if commit and changed:
        commit += "-dirty"
    version = subprocess.run([os.path.join(build, "bin", "signorini"), "--version"], capture_output=True,
                             text=True).stdout.strip()
    return {"command": " ".join([os.path.relpath(sys.argv[0], ROOT)] + sys.argv[1:]),
            "commit": commit or "unknown",
            "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
            "host": platform.node(), "cores": os.cpu_count(), "ranks": ranks,
            "compiler": compiler(build), "build": version}


def write_results(name, made, runs, table):
    """Writes bench/results/<name>.json (provenance and runs) and <name>.md (the table), and
    prints the table."""
    base = os.path.join(ROOT, "bench", "results", name)
    with open(base + ".json", "w") as f:
        json.dump({"provenance": made, "runs": runs}, f, indent=1)
    with open(base + ".md", "w") as f:
        f.write(table)
    print(table)

#!/usr/bin/python3
"""Reruns the result sets of bench/results that README.md and doc/ cite, each with the command
that makes it, one after the other, and regenerates the tables copied from them. Every set
records the commit it was made at, so it runs only from a committed tree whose build is that
commit's (build/bin/signorini --version).

    /usr/bin/python3 scripts/rerun_results.py [--stale] [--only NAME ...] [--dry-run] [--list]
    /usr/bin/python3 scripts/rerun_results.py --check

--stale reruns the sets that scripts/stale_results.py reports, --only the named ones (the
file names without .json); --list prints each set and its command. Without either, every
cited set runs: that takes hours on 2 cores (hertz, gmsh-meshes, the two --largest
matrix-free sets and the preconditioner sets are the long ones), more than one sitting may
hold: the sets made in several sittings stay current as long as src/ and include/ do not
change between them. --check exits with an error if a cited set has no command here or a
command names a script that does not exist (a test runs it).
"""
import argparse
import os
import subprocess
import sys
import time

from stale_results import ROOT, cited_sets, git, recorded_commits, verdict

PYTHON = "/usr/bin/python3"  # Debian's, with numpy, matplotlib and meshio
PRECONDITIONER_COMPONENTS = ("default,without contact-corrected start,from zero,without active-set finish,"
                             "algebraic,algebraic amg of Q")
# The command of each result set, relative to the repository's root.
COMMANDS = {
    "algebraic-drop-tol": ["bench/algebraic_drop_tolerance.py"],
    "amg-variants": ["bench/amg_variants.py"],
    "assembly": ["bench/assembly.py"],
    "communication": ["bench/communication.py"],
    "direct-solvers": ["bench/direct_solvers.py"],
    "expression": ["bench/expression.py"],
    "force-control": ["bench/force_control.py"],
    "forcing": ["bench/forcing.py"],
    "forcing-reduction": ["bench/forcing.py", "--forcing", "reduction", "--repeat", "2"],
    "gmsh-meshes": ["bench/gmsh_meshes.py"],
    "gmsh-meshes-coarse-grids": ["bench/gmsh_meshes.py", "--cases", "3d-p1,3d-p2,2d-p1", "--ranks", "2",
                                 "--repeat", "2", "--meshes", "box,msh all ranks,msh delaunay", "--name",
                                 "gmsh-meshes-coarse-grids"],
    "gmsh-meshes-refined-coarse-grids": ["bench/gmsh_meshes.py", "--cases", "3d-p1", "--ranks", "2", "--repeat", "2",
                                         "--meshes", "box,refined r1,refined r1 none", "--name",
                                         "gmsh-meshes-refined-coarse-grids"],
    "gmsh-meshes-msh-read": ["bench/gmsh_meshes.py", "--cases", "3d-p1", "--ranks", "2,4", "--meshes",
                             "box,msh,msh all ranks", "--name", "gmsh-meshes-msh-read"],
    "gmsh-pk": ["bench/gmsh_pk.py"],
    "hertz": ["scripts/hertz.py"],
    "incompressibility": ["bench/incompressibility.py"],
    "ipopt": ["bench/ipopt.py"],
    "matrix-free": ["bench/matrix_free.py"],
    "matrix-free-solve": ["bench/matrix_free_solve.py"],
    "matrix-free-solve-largest-p2": ["bench/matrix_free_solve.py", "--largest", "2"],
    "matrix-free-solve-largest-p3": ["bench/matrix_free_solve.py", "--largest", "3"],
    "preconditioners-algebraic-rebuild": ["bench/preconditioners.py", "--configs", "algebraic,algebraic default",
                                          "--forcing", "reduction", "--max-nx", "400", "--max-nx-3d", "40",
                                          "--name", "preconditioners-algebraic-rebuild"],
    "preconditioners-components": ["bench/preconditioners.py", "--forcing", "reduction,relative", "--configs",
                                   PRECONDITIONER_COMPONENTS, "--name", "preconditioners-components"],
    "preconditioners-forcing": ["bench/preconditioners.py", "--configs", "default,unfiltered,lagged rebuild",
                                "--name", "preconditioners-forcing"],
    "preconditioners-forcing-p2p3": ["bench/preconditioners.py", "--sequence", "2d-p2,2d-p3,3d-p2", "--configs",
                                     "default,unfiltered", "--name", "preconditioners-forcing-p2p3"],
    "qp-handover": ["bench/qp_handover.py"],
    "reference-solve": ["bench/reference_solve.py"],
    "refined-levels": ["bench/refined_levels.py"],
    "scaling": ["scripts/scaling.py", "--ranks", "1,2"],
    "table2": ["scripts/table2.py"],
    "table2-fixed-centering": ["scripts/table2.py", "--methods", "primal-dual", "--set",
                               "Solver/primal-dual: centering=fixed", "--name", "table2-fixed-centering"],
    "two-bodies": ["bench/two_bodies.py"],
}


def check():
    """Problems with the table: cited sets without a command, commands without a script."""
    problems = [f"bench/results/{name}.json is cited but has no command in scripts/rerun_results.py"
                for name in cited_sets() if name not in COMMANDS]
    problems += [f"{name}: {command[0]} does not exist" for name, command in COMMANDS.items()
                 if not os.path.isfile(os.path.join(ROOT, command[0]))]
    return problems


def stale_sets():
    last_code_change = git("log", "-1", "--format=%H", "--", "src", "include")
    return [name for name in cited_sets()
            if any(verdict(commit, last_code_change) for commit in recorded_commits(name))]


def refuse_unless_reproducible():
    """Exits unless the tree is committed and the build is of its commit."""
    if git("status", "--porcelain", "--untracked-files=no", "--", ".", ":(exclude)bench/results"):
        sys.exit("rerun_results: commit the tree first: every result set records the commit it was made at")
    head = git("describe", "--always")
    version = subprocess.run([os.path.join(ROOT, "build", "bin", "signorini"), "--version"], capture_output=True,
                             text=True).stdout
    if f"({head})" not in version:
        sys.exit(f"rerun_results: build/ is not of {head} (it reports {version.strip()!r}): rebuild it first")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--stale", action="store_true")
    parser.add_argument("--only", nargs="+", default=[])
    parser.add_argument("--dry-run", action="store_true")
    parser.add_argument("--list", action="store_true")
    parser.add_argument("--check", action="store_true")
    args = parser.parse_args()
    problems = check()
    if args.check or problems:
        print("\n".join(problems) or f"every one of the {len(cited_sets())} cited result sets has its command")
        sys.exit(1 if problems else 0)
    unknown = [name for name in args.only if name not in COMMANDS]
    if unknown:
        sys.exit("rerun_results: no result set " + ", ".join(unknown) + "; --list names them")
    names = args.only or (stale_sets() if args.stale else cited_sets())
    if args.list or args.dry_run:
        for name in names:
            print(f"{name}: {' '.join(COMMANDS[name])}")
        return
    refuse_unless_reproducible()
    for name in names:
        start = time.monotonic()
        print(f"{name}: {' '.join(COMMANDS[name])}", flush=True)
        subprocess.run([PYTHON] + COMMANDS[name], cwd=ROOT, check=True)
        print(f"{name}: done in {time.monotonic() - start:.0f} s", flush=True)
    subprocess.run([PYTHON, "scripts/benchmarks_md.py"], cwd=ROOT, check=True)


if __name__ == "__main__":
    main()

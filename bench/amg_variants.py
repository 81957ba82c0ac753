#!/usr/bin/python3
"""MueLu variants for the elasticity part of the Newton systems: Krylov iterations of the
first main iteration (predictor and corrector) solved to a fixed relative residual of 1e-8,
across the 2D and 3D P1 sequences, with the AMG's operator complexity and times.

    /usr/bin/python3 bench/amg_variants.py [--ranks N] [--variants NAME,...] [--problems XML,...]

Writes bench/results/amg-variants.{json,md}. The first Newton systems have D close to zero,
so their counts measure the multigrid of the elasticity operator itself. Every variant runs
MueLu's hierarchy alone ("hierarchy" = "algebraic", what Gmsh meshes get), except "geometric
levels", the default on box meshes (geometric levels above MueLu's default settings).
"""
import argparse
import json
import os
import re
import subprocess

from provenance import provenance

from preconditioners import ENV, ROOT

PRECONDITIONER = "Solver/Preconditioner/"
MUELU = PRECONDITIONER + "MueLu/"
ALGEBRAIC = {PRECONDITIONER + "hierarchy": "algebraic"}
VARIANTS = {
    "geometric levels": {},
    "smoothed aggregation": ALGEBRAIC,
    "W-cycle": {**ALGEBRAIC, MUELU + "cycle type": "W"},
    "Chebyshev degree 3": {**ALGEBRAIC, MUELU + "smoother: params/chebyshev: degree": "3"},
    "drop tol 0.02": {**ALGEBRAIC, MUELU + "aggregation: drop tol": "0.02"},
    "drop tol 0.1": {**ALGEBRAIC, MUELU + "aggregation: drop tol": "0.1"},
    "W + Chebyshev 3 + drop tol 0.02": {**ALGEBRAIC, MUELU + "cycle type": "W",
                                        MUELU + "smoother: params/chebyshev: degree": "3",
                                        MUELU + "aggregation: drop tol": "0.02"},
    "unsmoothed aggregation + W": {**ALGEBRAIC, MUELU + "multigrid algorithm": "unsmoothed", MUELU + "cycle type": "W"},
}
PROBLEMS = ["paper/M", "paper/J", "family/2d-p1-nx400", "family/2d-p1-nx800", "paper/E", "paper/L",
            "family/3d-p1-nx40"]
TIMERS = {"amg_setup": "Signorini: solve: AMG setup", "krylov": "Signorini: solve: Krylov"}


def run(problem, settings, ranks, out):
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"),
           os.path.join(ROOT, "xml", problem + ".xml"), "--output", out, "--set", "Output/write solution=false",
           "--set", "Solver/forcing: type=relative", "--set", "Solver/forcing: eta=1e-8",
           "--set", "Solver/maximum iterations=1", "--set", MUELU + "verbosity=medium"]
    for key, value in settings.items():
        cmd += ["--set", f"{key}={value}"]
    log = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False).stdout
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    complexity = re.search(r"Operator complexity\s*=\s*([0-9.]+)", log)
    levels = re.search(r"Number of levels\s*=\s*([0-9]+)", log)
    timers = {}
    for key, name in TIMERS.items():
        m = re.search(re.escape(name) + r"\s+([0-9.eE+-]+)", log)  # first column: rank 0's time
        timers[key] = float(m.group(1)) if m else None
    return {"problem": problem, "n": summary["n"], "krylov_first_iteration": summary["krylov_iterations"],
            "max_per_system": summary["max_krylov_per_newton"], "status": summary["status"],
            "operator_complexity": float(complexity.group(1)) if complexity else None,
            "levels": int(levels.group(1)) if levels else None, "solve_seconds": summary["time"]["solve"],
            **{k + "_seconds": v for k, v in timers.items()}}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--variants", default=",".join(VARIANTS))
    parser.add_argument("--problems", default=",".join(PROBLEMS))
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "amg-variants"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    records = []
    for variant in args.variants.split(","):
        for problem in args.problems.split(","):
            out = os.path.join(args.workdir, variant.replace(" ", "-").replace("+", "") + "-" + problem.replace("/", "-"))
            r = {"variant": variant, "settings": VARIANTS[variant], "ranks": args.ranks,
                 **run(problem, VARIANTS[variant], args.ranks, out)}
            records.append(r)
            print(f"{variant:32s} {problem:22s} max/system {r['max_per_system']:3d} complexity "
                  f"{r['operator_complexity']} setup {r['amg_setup_seconds']} s, Krylov {r['krylov_seconds']} s",
                  flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "amg-variants.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    rows = table(records)
    with open(os.path.join(ROOT, "bench", "results", "amg-variants.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


def table(records):
    """The Markdown rows; '-' where MueLu reported nothing (geometric levels ending in a direct solve)."""
    def cell(value):
        return "-" if value is None else value
    rows = ["| variant | problem | n | levels | operator complexity | CG iterations to the end of the first main iteration | "
            "max per system | AMG setup [s] | Krylov [s] |", "|---|---|---|---|---|---|---|---|---|"]
    for r in records:
        rows.append(f"| {r['variant']} | {r['problem']} | {r['n']} | {cell(r['levels'])} | {cell(r['operator_complexity'])} | "
                    f"{r['krylov_first_iteration']} | {r['max_per_system']} | {r['amg_setup_seconds']} | "
                    f"{r['krylov_seconds']} |")
    return rows


if __name__ == "__main__":
    main()

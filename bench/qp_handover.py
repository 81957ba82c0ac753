#!/usr/bin/python3
"""A QP handed over in files (signorini --export-qp, then signorini --qp) against the direct
run of the same problem: the benchmark family's problem on the unit square / cube meshed by
Gmsh and read as is (the quartic load, the top clamped, the bottom on the rigid plane;
bench/gmsh_meshes.py makes the meshes). Three runs per case:

  direct         the .msh solved directly (its P1 grid, Delaunay coarse grids below it);
  files          the exported Q, b, A, d, coords and cells.mtx solved with signorini --qp: a
                 SimplexGrid of the cells, with its Delaunay coarse grids;
  files no cells the same files without cells.mtx: MueLu's algebraic multigrid alone, as a
                 code that hands over no mesh gets.

Setup (for the files: reading them), solve and wall times, CG iterations, the grids' vertex
counts and the optimal value (the same in all three). Each run --repeat times in rounds, the
fastest (by solve time) kept; the record lists the solve times of all.

    /usr/bin/python3 bench/qp_handover.py [--cases 3d-p1,2d-p1,3d-p2] [--ranks 2] [--repeat 2]

Writes bench/results/qp-handover.{json,md}.
"""
import argparse
import json
import os
import shutil
import subprocess
import time

from gmsh_meshes import fine_msh
from preconditioners import ENV, ROOT
from provenance import provenance, write_results

FAMILY = os.path.join(ROOT, "xml", "family")
# name: (dimension, degree, family input whose load and supports are used, Gmsh mesh size)
CASES = {
    "3d-p1": (3, 1, "3d-p1-nx64.xml", 0.022),
    "2d-p1": (2, 1, "2d-p1-nx1000.xml", 0.0025),
    "3d-p2": (3, 2, "3d-p2-nx32.xml", 0.08),
}
RUNS = ("direct", "files", "files no cells")


def signorini(args, out):
    cmd = ["mpirun", "-np", str(args[0]), os.path.join(ROOT, "build", "bin", "signorini")] + args[1:] + ["--output", out]
    start = time.monotonic()
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    wall = time.monotonic() - start
    if done.returncode != 0:
        raise SystemExit(f"qp_handover: {' '.join(cmd)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f), wall


def export(case, ranks, workdir):
    """The case's QP files (with cells.mtx) and a copy without it; returns both directories."""
    family = CASES[case][2]
    files = os.path.join(workdir, f"{case}-qp")
    bare = files + "-no-cells"
    if not os.path.exists(os.path.join(bare, "Q.mtx")):
        signorini([ranks, os.path.join(FAMILY, family), "--export-qp", files] + direct_settings(case, workdir),
                  os.path.join(workdir, f"{case}-export"))
        os.makedirs(bare, exist_ok=True)
        for name in ("Q", "b", "A", "d", "coords"):
            shutil.copyfile(os.path.join(files, name + ".mtx"), os.path.join(bare, name + ".mtx"))
    return files, bare


def direct_settings(case, workdir):
    dim, degree, _, size = CASES[case]
    settings = ["Problem/mesh: type=gmsh", f"Problem/mesh: file={fine_msh(workdir, dim, size)}",
                f"Problem/element: degree={degree}", "Output/write solution=false",
                "Output/write contact samples=false"]
    return [word for s in settings for word in ("--set", s)]


def run(case, kind, ranks, workdir, dirs):
    out = os.path.join(workdir, f"{case}-{kind.replace(' ', '-')}-np{ranks}")
    if kind == "direct":
        args = [ranks, os.path.join(FAMILY, CASES[case][2])] + direct_settings(case, workdir)
    else:
        args = [ranks, "--qp", dirs[0] if kind == "files" else dirs[1]]
    s, wall = signorini(args, out)
    return {"case": case, "run": kind, "ranks": ranks, "n": s["n"], "m": s["m"], "status": s["status"],
            "objective": s["objective"], "cg_iterations": s["krylov_iterations"],
            "multigrid_setups": s["preconditioner_setups"], "grid_vertices": s["grid_vertices"],
            "setup_seconds": s["time"]["setup"] + s["time"]["assembly"], "solve_seconds": s["time"]["solve"],
            "wall_seconds": wall}


def table(runs):
    direct = {(r["case"], r["ranks"]): r for r in runs if r["run"] == "direct"}
    lines = ["| case | run | ranks | n | setup [s] | solve [s] | wall [s] | solve / direct | CG | grid vertices "
             "| objective |", "|" + "---|" * 11]
    for r in runs:
        d = direct[(r["case"], r["ranks"])]
        grids = ", ".join(str(v) for v in r["grid_vertices"]) or "-"
        lines.append(f"| {r['case']} | {r['run']} | {r['ranks']} | {r['n']} | {r['setup_seconds']:.2f} "
                     f"| {r['solve_seconds']:.2f} | {r['wall_seconds']:.1f} "
                     f"| {r['solve_seconds'] / d['solve_seconds']:.2f} | {r['cg_iterations']} | {grids} "
                     f"| {r['objective']:.10e} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--repeat", type=int, default=2, help="runs of each; the fastest solve is kept")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "qp-handover"))
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    os.makedirs(args.workdir, exist_ok=True)
    made = provenance(args.ranks)
    runs = []
    for case in args.cases.split(","):
        dirs = export(case, args.ranks, args.workdir)
        repeats = {kind: [] for kind in RUNS}
        for _ in range(args.repeat):
            for kind, done in repeats.items():
                done.append(run(case, kind, args.ranks, args.workdir, dirs))
                print(json.dumps(done[-1]), flush=True)
        for done in repeats.values():
            best = dict(min(done, key=lambda r: r["solve_seconds"]))
            best["solve_seconds_repeats"] = [r["solve_seconds"] for r in done]
            runs.append(best)
    write_results("qp-handover", made, runs, table(runs))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""MueLu's "aggregation: drop tol" where MueLu is the whole hierarchy (a Gmsh mesh read as
is): whole contact solves on the unit square and cube meshed by Gmsh (the family's load,
bench/gmsh_meshes.py's geometries, .msh files read by all ranks) and on the two blocks of
bench/two_bodies.py (the same three pairs of moduli, their mesh written to a .msh at size
factor 0.11), each with the drop tolerances given (0: MueLu's default, no entry dropped).
For each: the Newton systems, the CG iterations, the AMG setup, Krylov and solve times, on 2
ranks (--ranks), the other parameters at their defaults.

    /usr/bin/python3 bench/algebraic_drop_tolerance.py [--ranks 2] [--tolerances 0,0.01,0.02]

Writes bench/results/algebraic-drop-tol.{json,md}.
"""
import argparse
import json
import os
import re
import subprocess

from gmsh_meshes import fine_msh
from preconditioners import ENV, ROOT
from provenance import provenance, write_results

TIMERS = {"amg_setup": "Signorini: solve: AMG setup", "krylov": "Signorini: solve: Krylov"}
FAMILY = os.path.join(ROOT, "xml", "family")
TWO_BLOCKS = os.path.join(ROOT, "examples", "bodies", "two-blocks-3d")
# name, (dimension, Gmsh mesh size) of a unit square or cube on the family's problem, or the
# two blocks' (base modulus, block modulus)
MESHES = [("unit square h 0.004", (2, 0.004)), ("unit square h 0.002", (2, 0.002)),
          ("unit square h 0.0014", (2, 0.0014)), ("unit cube h 0.02", (3, 0.02)),
          ("unit cube h 0.0142", (3, 0.0142))]
BLOCKS = [("two blocks, equal moduli", (1, 1)), ("two blocks, soft base, block 1000x stiffer", (1, 1000)),
          ("two blocks, stiff base 1000x, soft block", (1000, 1))]


def two_blocks_msh(workdir):
    path = os.path.join(workdir, "two-blocks-3d-sf0.11.msh")
    if not os.path.exists(path):
        subprocess.run(["gmsh", "-3", TWO_BLOCKS + ".geo", "-clscale", "0.11", "-format", "msh41", "-o", path],
                       check=True, capture_output=True)
    return path


def problem_of(case, workdir):
    """The input and the settings of a case."""
    meshes, blocks = dict(MESHES), dict(BLOCKS)
    if case in meshes:
        dim, size = meshes[case]
        xml = os.path.join(FAMILY, "2d-p1-nx800.xml" if dim == 2 else "3d-p1-nx64.xml")
        return xml, ["Problem/mesh: type=gmsh", f"Problem/mesh: file={fine_msh(workdir, dim, size)}"]
    base, block = blocks[case]
    # The block's bottom the slave side whatever the moduli: one pair for every case.
    return TWO_BLOCKS + ".xml", [f"Problem/mesh: file={two_blocks_msh(workdir)}",
                                 f"Problem/material: young's modulus={base}",
                                 f"Problem/Bodies/block/material: young's modulus={block}",
                                 "Problem/Contact/boundary=block bottom", "Problem/Contact/master boundary=base top"]


def run(case, tolerance, ranks, workdir):
    xml, settings = problem_of(case, workdir)
    out = os.path.join(workdir, f"{case.replace(' ', '-').replace(',', '')}-drop{tolerance}-np{ranks}")
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"), xml, "--output", out,
           "--set", "Output/write solution=false",
           "--set", f"Solver/Preconditioner/MueLu/aggregation: drop tol={float(tolerance)!r}"]
    for assignment in settings:
        cmd += ["--set", assignment]
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f"algebraic_drop_tolerance: {' '.join(cmd)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    result = {"case": case, "drop_tol": float(tolerance), "ranks": ranks, "status": s["status"], "n": s["n"],
              "newton_systems": s["newton_steps"], "cg_iterations": s["krylov_iterations"],
              "multigrid_setups": s["preconditioner_setups"], "solve_seconds": s["time"]["solve"]}
    for key, name in TIMERS.items():
        m = re.search(re.escape(name) + r"\s+([0-9.eE+-]+)", done.stdout)  # first column: the fastest rank's
        result[key + "_seconds"] = float(m.group(1)) if m else None
    return result


def table(runs):
    lines = ["| case | n | drop tol | status | Newton systems | CG | CG per system | CG / drop tol 0 | AMG setup [s] "
             "| Krylov [s] | solve [s] | solve / drop tol 0 |", "|" + "---|" * 12]
    first = {}
    for r in runs:
        ref = first.setdefault((r["case"], r["ranks"]), r)
        lines.append(f"| {r['case']} | {r['n']} | {r['drop_tol']:g} | {r['status']} | {r['newton_systems']} "
                     f"| {r['cg_iterations']} | {r['cg_iterations'] / r['newton_systems']:.1f} "
                     f"| {r['cg_iterations'] / ref['cg_iterations']:.2f} | {r['amg_setup_seconds']:.2f} "
                     f"| {r['krylov_seconds']:.2f} | {r['solve_seconds']:.2f} "
                     f"| {r['solve_seconds'] / ref['solve_seconds']:.2f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--tolerances", default="0,0.01,0.02", help="the first is the reference of the ratios")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "algebraic-drop-tol"))
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    made = provenance(args.ranks)  # before any result file is rewritten
    runs = []
    for case, _ in MESHES + BLOCKS:
        for tolerance in args.tolerances.split(","):
            runs.append(run(case, tolerance, args.ranks, args.workdir))
            print(json.dumps(runs[-1]), flush=True)
    write_results("algebraic-drop-tol", made, runs, table(runs))


if __name__ == "__main__":
    main()

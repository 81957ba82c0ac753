#!/usr/bin/python3
"""Two bodies in mortar contact against one body on a rigid plane: the two unit cubes of
examples/bodies/two-blocks-3d (meshed apart, the upper one pressed by a uniform pressure of
0.01 and held vertically by the contact alone, rollers on the sides) with equal moduli, with
a soft base under a block 1000 times stiffer (the example) and with a stiff base under a soft
block; and, of about as many unknowns, one box [0,1]^2 x [0,2] meshed by Gmsh, on rollers,
pressed alike onto the rigid plane z = 0. The slave side is the softer body's surface, for
equal moduli the finer one's (the block's), as the docs advise. For each: the CG iterations
per Newton system and the contact solve's time over that of a linear solve of the same
problem (the block's bottom clamped normally instead: each body then on its own), on 2 ranks
(--ranks), the default parameters; and the contact force, to compare with the load (0.01 on
the unit area), the largest pressure (0.01 everywhere) and the master body's force. Every run
is made --repeat times, in rounds over all cases, and the one with the fastest solve is kept
(the wall time is mostly Gmsh meshing and setup).

    /usr/bin/python3 bench/two_bodies.py [--ranks 2] [--size-factor 0.11] [--repeat 2]

Writes bench/results/two-bodies.{json,md}.
"""
import argparse
import json
import os
import subprocess
import time

from gmsh_meshes import fastest
from preconditioners import ENV, ROOT
from provenance import provenance, write_results

BODIES = os.path.join(ROOT, "examples", "bodies")
# name, (base modulus, block modulus); None: the one-body counterpart
CASES = [("two blocks, equal moduli", (1, 1)), ("two blocks, soft base, block 1000x stiffer", (1, 1000)),
         ("two blocks, stiff base 1000x, soft block", (1000, 1)), ("one block on a rigid plane", None)]


def slave_and_master(moduli):
    """The contact pair as the docs advise: the softer body's surface the slave side, for equal
    moduli the finer one's (the block's, meshed at 0.22 against the base's 0.3)."""
    base, block = moduli
    return ("base top", "block bottom") if base < block else ("block bottom", "base top")


ONE_BLOCK_GEO = """// The two blocks of two-blocks-3d.geo as one body: [0,1]^2 x [0,2], meshed at the size
// that gives about as many nodes as their two sizes.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 2};
MeshSize{PointsOf{Volume{1};}} = 0.245;
Physical Surface("ground") = {5};
Physical Surface("top") = {6};
Physical Surface("x sides") = {1, 2};
Physical Surface("y sides") = {3, 4};
Physical Volume("block") = {1};
"""


def settings_of(moduli, size_factor, linear, workdir):
    common = [f"Problem/mesh: size factor={size_factor}", "Output/write solution=false"]
    if moduli is None:
        geo = os.path.join(workdir, "one-block-3d.geo")
        with open(geo, "w") as f:
            f.write(ONE_BLOCK_GEO)
        common += [f"Problem/mesh: file={geo}", "Problem/Bodies/block/material: young's modulus=1",
                   "Problem/Dirichlet/ground/displacement: z=", "Problem/Contact/boundary=ground",
                   "Problem/Contact/master boundary="]
        clamp = "ground"
    else:
        slave, master = slave_and_master(moduli)
        common += [f"Problem/material: young's modulus={moduli[0]}",
                   f"Problem/Bodies/block/material: young's modulus={moduli[1]}",
                   f"Problem/Contact/boundary={slave}", f"Problem/Contact/master boundary={master}"]
        clamp = "block bottom"  # the body that only the contact holds
    if linear:
        common += ["Problem/Contact/boundary=", f"Problem/Dirichlet/{clamp}/displacement: z=0"]
    return common


def run(name, moduli, size_factor, ranks, linear, workdir):
    out = os.path.join(workdir, f"{name.replace(' ', '-').replace(',', '')}-np{ranks}-{'linear' if linear else 'contact'}")
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"),
           os.path.join(BODIES, "two-blocks-3d.xml"), "--output", out]
    for assignment in settings_of(moduli, size_factor, linear, workdir):
        cmd += ["--set", assignment]
    start = time.monotonic()
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    wall = time.monotonic() - start
    if done.returncode != 0:
        raise SystemExit(f"two_bodies: {' '.join(cmd)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    result = {"case": name, "ranks": ranks, "solve": "linear" if linear else "contact", "status": s["status"],
              "n": s["n"], "m": s["m"], "cg_iterations": s["krylov_iterations"], "newton_systems": s["newton_steps"],
              "multigrid_setups": s["preconditioner_setups"], "solve_seconds": s["time"]["solve"],
              "wall_seconds": wall}
    if not linear:
        contact = s["contact"]
        result.update({"force": contact["force"], "normal_force": contact["normal_force"],
                       "peak_pressure": contact["peak_pressure"], "master_force": contact.get("master_force")})
    return result


def table(runs):
    linear = {(r["case"], r["ranks"]): r for r in runs if r["solve"] == "linear"}
    one = {r["ranks"]: r for r in runs if r["solve"] == "contact" and r["case"] == CASES[-1][0]}
    lines = ["| case | ranks | n | m | status | Newton systems | CG | CG per system | CG per system / one body "
             "| normal force | largest pressure | master force, z | solve [s] | linear solve [s] (CG) "
             "| contact / linear solve |", "|" + "---|" * 15]
    for r in runs:
        if r["solve"] != "contact":
            continue
        lin, ref = linear[(r["case"], r["ranks"])], one[r["ranks"]]
        per, per_one = r["cg_iterations"] / r["newton_systems"], ref["cg_iterations"] / ref["newton_systems"]
        master = f"{r['master_force'][-1]:.10g}" if r["master_force"] else "-"
        lines.append(f"| {r['case']} | {r['ranks']} | {r['n']} | {r['m']} | {r['status']} | {r['newton_systems']} "
                     f"| {r['cg_iterations']} | {per:.1f} | {per / per_one:.2f} | {r['normal_force']:.10g} "
                     f"| {r['peak_pressure']:.10g} | {master} | {r['solve_seconds']:.2f} "
                     f"| {lin['solve_seconds']:.2f} ({lin['cg_iterations']}) "
                     f"| {r['solve_seconds'] / lin['solve_seconds']:.1f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", default="2")
    parser.add_argument("--size-factor", type=float, default=0.11)
    parser.add_argument("--repeat", type=int, default=2, help="runs of each case and solve; the fastest is kept")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "two-bodies"))
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    ranks = [int(r) for r in args.ranks.split(",")]
    os.makedirs(args.workdir, exist_ok=True)
    made = provenance(max(ranks))  # before any result file is rewritten
    moduli = dict(CASES)
    repeats = {(np, name, linear): [] for np in ranks for name, _ in CASES for linear in (False, True)}
    for _ in range(args.repeat):
        for (np, name, linear), done in repeats.items():
            done.append(run(name, moduli[name], args.size_factor, np, linear, args.workdir))
            print(json.dumps(done[-1]), flush=True)
    runs = [fastest(done, by="solve_seconds") for done in repeats.values()]
    write_results("two-bodies", made, runs, table(runs))


if __name__ == "__main__":
    main()

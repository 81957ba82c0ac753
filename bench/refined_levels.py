#!/usr/bin/python3
"""The geometric multigrid on refined Gmsh meshes: how its rate depends on the coarse mesh's
cells and on the fine smoother. The family's problem on the unit cube (the quartic load, the
top clamped; doc/benchmark-family.md), 3D P1, refined 1 to 3 times, three kinds of mesh:

  box           the family's box mesh with 16, 32 and 64 boxes per direction (its own grids);
  structured    a Gmsh mesh of 8 x 8 x 8 hexahedra cut into tetrahedra (Transfinite Volume),
                refined 1 to 3 times (Problem/mesh: refinements): the box's sizes;
  unstructured  Gmsh's default (Delaunay) mesh of the cube at size 1/8, refined 1 to 3 times.

Each with the linear solve of the same problem with the bottom clamped instead (no contact)
and with the contact solve, with three smoothers (Solver/Preconditioner/Ifpack2): the default
Chebyshev polynomials of degree 2 on [lambda_max / 7, lambda_max] ("default"), of degree 4
("degree 4"), and of degree 2 on [lambda_max / 20, lambda_max] ("ratio 20"), on --ranks ranks
(2), each run once: CG iterations and solve times, in one sitting.

    /usr/bin/python3 bench/refined_levels.py [--ranks 2]   # bench/results/refined-levels.{json,md}
"""
import argparse
import json
import os
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance, write_results

INPUT = os.path.join(ROOT, "xml", "family", "3d-p1-nx64.xml")
SMOOTHERS = {"default": [], "degree 4": ["chebyshev: degree=4"], "ratio 20": ["chebyshev: ratio eigenvalue=20"]}
REFINEMENTS = (1, 2, 3)
NAMES = ('Physical Surface("zmin") = {5};\nPhysical Surface("zmax") = {6};\nPhysical Volume("body") = {1};\n')
GEOMETRY = {
    "structured": 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\nTransfinite Curve{:} = 9;\n'
                  'Transfinite Surface{:};\nTransfinite Volume{1};\n' + NAMES,
    "unstructured": 'SetFactory("OpenCASCADE");\nBox(1) = {0, 0, 0, 1, 1, 1};\n'
                    'MeshSize{ PointsOf{ Volume{1}; } } = 0.125;\n' + NAMES,
}


def mesh_settings(mesh, refinements, workdir):
    if mesh == "box":
        return [f"Problem/mesh: cells={{{8 << refinements}}}"]
    path = os.path.join(workdir, f"unit-cube-{mesh}.geo")
    with open(path, "w") as f:
        f.write(GEOMETRY[mesh])
    return ["Problem/mesh: type=gmsh", f"Problem/mesh: file={path}", f"Problem/mesh: refinements={refinements}"]


def run(mesh, refinements, smoother, linear, ranks, workdir):
    out = os.path.join(workdir, f"{mesh}-r{refinements}-{smoother.replace(' ', '')}-{'linear' if linear else 'contact'}")
    settings = mesh_settings(mesh, refinements, workdir) + ["Output/write solution=false"] + [
        "Solver/Preconditioner/Ifpack2/" + s for s in SMOOTHERS[smoother]]
    if linear:  # the bottom clamped like the top, no contact
        settings += ["Problem/Contact/boundary="] + [f"Problem/Dirichlet/zmin/displacement: {a}=0" for a in "xyz"]
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"), INPUT, "--output", out]
    for assignment in settings:
        cmd += ["--set", assignment]
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    if done.returncode != 0:
        raise SystemExit(f"refined_levels: {' '.join(cmd)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"mesh": mesh, "refinements": refinements, "smoother": smoother, "solve": "linear" if linear else "contact",
            "ranks": ranks, "status": s["status"], "n": s["n"], "cg_iterations": s["krylov_iterations"],
            "newton_systems": s["newton_steps"], "solve_seconds": s["time"]["solve"],
            "final_step_cg": s["active_set_finish"]["krylov_iterations"]}


def table(runs):
    at = {(r["mesh"], r["refinements"], r["smoother"], r["solve"]): r for r in runs}
    variants = " / ".join(SMOOTHERS)
    lines = [f"| mesh | refinements | n | linear CG: {variants} | linear solve [s] | contact CG | contact solve [s] "
             "| contact's last step CG |", "|" + "---|" * 8]

    def cells(mesh, r, solve, key, form):
        return " / ".join(form.format(at[(mesh, r, s, solve)][key]) for s in SMOOTHERS)

    for mesh in ("box", *GEOMETRY):
        for r in REFINEMENTS:
            lines.append(f"| {mesh} | {r} | {at[(mesh, r, 'default', 'linear')]['n']} "
                         f"| {cells(mesh, r, 'linear', 'cg_iterations', '{}')} "
                         f"| {cells(mesh, r, 'linear', 'solve_seconds', '{:.2f}')} "
                         f"| {cells(mesh, r, 'contact', 'cg_iterations', '{}')} "
                         f"| {cells(mesh, r, 'contact', 'solve_seconds', '{:.2f}')} "
                         f"| {cells(mesh, r, 'contact', 'final_step_cg', '{}')} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "refined-levels"))
    args = parser.parse_args()
    os.makedirs(args.workdir, exist_ok=True)
    made = provenance(args.ranks)  # before any result file is rewritten
    runs = []
    for mesh in ("box", *GEOMETRY):
        for refinements in REFINEMENTS:
            for smoother in SMOOTHERS:
                for linear in (True, False):
                    runs.append(run(mesh, refinements, smoother, linear, args.ranks, args.workdir))
                    print(json.dumps(runs[-1]), flush=True)
    write_results("refined-levels", made, runs, table(runs))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""P2 and P3 contact solves on Gmsh meshes (the Hertz examples, refined), on 2 ranks, with
four preconditioner paths: MueLu alone on the assembled Q + A^T D A ("algebraic"), the
geometric P_k -> P1 step on the mesh's own vertices with MueLu below, on an assembled Q
("assembled") and with Q applied cell by cell and never assembled ("matrix-free", the
default for degrees 2 and 3), and the same matrix-free Q with the P1 step to the mesh refined
at the nodes instead ("refined": as many P1 unknowns as P_k ones, MueLu below). Reports the optimal value, main iterations, Newton systems, CG
iterations, assembly and solve times and peak memory.

    /usr/bin/python3 bench/gmsh_pk.py [--ranks 2]

Writes bench/results/gmsh-pk.{json,md}.
"""
import argparse
import json
import os
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance, write_results

HERTZ = os.path.join(ROOT, "examples", "hertz")
# (input, degree, Gmsh size factor)
CASES = [("half-disk-2d", 2, 0.3), ("half-disk-2d", 3, 0.5), ("half-ball-3d", 2, 1.0), ("half-ball-3d", 2, 0.7),
         ("half-ball-3d", 3, 1.0)]
PATHS = {"algebraic": ["Problem/stiffness: operator=assembled", "Solver/Preconditioner/hierarchy=algebraic"],
         "assembled": ["Problem/stiffness: operator=assembled"],
         "matrix-free": ["Problem/stiffness: operator=matrix-free"],
         "refined": ["Problem/stiffness: operator=matrix-free", "Problem/stiffness: P1 grid=refined at nodes"]}


def run(case, path, ranks, workdir):
    problem, degree, size = case
    out = os.path.join(workdir, f"{problem}-p{degree}-h{size}-{path}")
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"),
           os.path.join(HERTZ, problem + ".xml"), "--output", out, "--set", "Output/write solution=false",
           "--set", "Output/write contact samples=false", "--set", f"Problem/element: degree={degree}",
           "--set", f"Problem/mesh: size factor={size}"]
    for assignment in PATHS[path]:
        cmd += ["--set", assignment]
    subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"problem": problem, "degree": degree, "size_factor": size, "path": path, "ranks": ranks,
            "status": s["status"], "n": s["n"], "objective": s["objective"], "main_iterations": s["outer_iterations"],
            "newton_systems": s["newton_steps"], "cg_iterations": s["krylov_iterations"],
            "assembly_seconds": s["time"]["assembly"], "solve_seconds": s["time"]["solve"],
            "peak_mib_max_rank": s["memory_mib"]["max_rank"],
            "peak_bytes_per_unknown": s["memory_mib"]["all_ranks"] * 2**20 / s["n"]}


def table(runs):
    lines = ["| mesh | P | size factor | n | path | status | it | Newton | CG | assembly [s] | solve [s] | "
             "peak MiB (max rank) | peak bytes per unknown | optimal value |", "|" + "---|" * 14]
    for r in runs:
        lines.append(f"| {r['problem']} | {r['degree']} | {r['size_factor']} | {r['n']} | {r['path']} | {r['status']} "
                     f"| {r['main_iterations']} | {r['newton_systems']} | {r['cg_iterations']} "
                     f"| {r['assembly_seconds']:.2f} | {r['solve_seconds']:.2f} | {r['peak_mib_max_rank']:.0f} "
                     f"| {r['peak_bytes_per_unknown']:.0f} | {r['objective']:.10e} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "gmsh-pk"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten
    runs = []
    for case in CASES:
        for path in PATHS:
            runs.append(run(case, path, args.ranks, args.workdir))
            print(json.dumps(runs[-1]), flush=True)
    write_results("gmsh-pk", made, runs, table(runs))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Whole contact solves of P2 and P3 members of the benchmark family, 2D and 3D, with the
stiffness assembled and matrix-free (`Problem/stiffness: operator`), on 2 ranks: peak memory
per unknown, assembly time, solve time per Newton system, main iterations, Newton systems and
CG iterations, and the optimal value.

The matrix-free path assembles no P_k stiffness on a box mesh (the geometric multigrid starts
from the mesh's P1 stiffness), so in the memory the assembled path needs for a problem it
solves a larger one: `--budget-case` names the assembled run whose peak memory per rank is
the budget, and the table marks the matrix-free runs that stay within it.

    /usr/bin/python3 bench/matrix_free_solve.py [--ranks 2] [--cases 3d-p3-nx12,2d-p2-nx200,...] [--largest 2|3]

Writes bench/results/matrix-free-solve.{json,md}; with --largest 2 or 3, 3D P2 or P3 near a
24 GB machine's memory on each path, bench/results/matrix-free-solve-largest-p<2|3>.{json,md}.
"""
import argparse
import json
import os
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance

# (dimension, degree, nx, paths), each run on the family member of its dimension (load and
# supports). P3 nx = 22 has 2.55 times the unknowns of nx = 16, the budget case; P3 nx = 32
# (2.7 M unknowns) and, matrix-free only, nx = 44 (7.1 M) are the large runs.
MEMBERS = {2: os.path.join(ROOT, "xml", "family", "2d-p2-nx200.xml"),
           3: os.path.join(ROOT, "xml", "family", "3d-p2-nx32.xml")}
BOTH = ("assembled", "matrix-free")
CASES = [(2, 2, 200, BOTH), (2, 3, 100, BOTH), (3, 2, 16, BOTH), (3, 2, 24, BOTH), (3, 2, 32, BOTH),
         (3, 3, 12, BOTH), (3, 3, 16, BOTH), (3, 3, 22, BOTH), (3, 3, 32, BOTH), (3, 3, 44, ("matrix-free",))]
# --largest DEGREE: 3D P2 or P3 near the memory of a 24 GB machine on each path (P3: 6.0 M
# unknowns assembled, 15.2 M matrix-free), written to matrix-free-solve-largest-p<DEGREE>.{json,md}.
LARGEST = {2: [(3, 2, 60, ("assembled",)), (3, 2, 80, ("matrix-free",))],
           3: [(3, 3, 44, ("assembled",)), (3, 3, 60, ("matrix-free",))]}


def name(dim, degree, nx):
    return f"{dim}d-p{degree}-nx{nx}"


def run(dim, degree, nx, path, ranks, workdir):
    out = os.path.join(workdir, f"{name(dim, degree, nx)}-{path}")
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"), MEMBERS[dim], "--output", out,
           "--set", "Output/write solution=false", "--set", f"Problem/element: degree={degree}",
           "--set", f"Problem/mesh: cells={{{nx}}}", "--set", f"Problem/stiffness: operator={path}"]
    subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"dim": dim, "degree": degree, "nx": nx, "path": path, "ranks": ranks, "status": s["status"], "n": s["n"],
            "objective": s["objective"], "main_iterations": s["outer_iterations"],
            "newton_systems": s["newton_steps"], "cg_iterations": s["krylov_iterations"],
            "assembly_seconds": s["time"]["assembly"], "solve_seconds": s["time"]["solve"],
            "seconds_per_newton_system": s["time"]["solve"] / max(s["newton_steps"], 1),
            "peak_mib_max_rank": s["memory_mib"]["max_rank"],
            "peak_bytes_per_unknown": s["memory_mib"]["all_ranks"] * 2**20 / s["n"]}


def table(runs, budget):
    lines = ["| d | P | nx | n | stiffness | status | it | Newton | CG | assembly [s] | solve [s] | s per Newton system "
             "| peak MiB (max rank) | peak bytes per unknown | within the budget |", "|" + "---|" * 15]
    for r in runs:
        within = "—" if budget is None else ("yes" if r["peak_mib_max_rank"] <= budget else "no")
        lines.append(f"| {r['dim']} | {r['degree']} | {r['nx']} | {r['n']} | {r['path']} | {r['status']} | {r['main_iterations']} "
                     f"| {r['newton_systems']} | {r['cg_iterations']} | {r['assembly_seconds']:.2f} "
                     f"| {r['solve_seconds']:.2f} | {r['seconds_per_newton_system']:.3f} "
                     f"| {r['peak_mib_max_rank']:.0f} | {r['peak_bytes_per_unknown']:.0f} | {within} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--cases", default="", help="comma-separated 3d-p<degree>-nx<nx> to keep")
    parser.add_argument("--budget-case", default="3d-p3-nx16", help="the assembled run whose peak memory is the budget")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "matrix-free-solve"))
    parser.add_argument("--largest", type=int, choices=sorted(LARGEST), help="run LARGEST[degree] instead of CASES")
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten
    keep = {c for c in args.cases.split(",") if c}
    runs = []
    for dim, degree, nx, paths in LARGEST[args.largest] if args.largest else CASES:
        if keep and name(dim, degree, nx) not in keep:
            continue
        for path in paths:
            runs.append(run(dim, degree, nx, path, args.ranks, args.workdir))
            print(table(runs[-1:], None).splitlines()[-1], flush=True)
    budget = next((r["peak_mib_max_rank"] for r in runs
                   if r["path"] == "assembled" and name(r["dim"], r["degree"], r["nx"]) == args.budget_case), None)
    base = os.path.join(ROOT, "bench", "results",
                        "matrix-free-solve" + (f"-largest-p{args.largest}" if args.largest else ""))
    with open(base + ".json", "w") as f:
        json.dump({"provenance": made, "budget_case": args.budget_case, "budget_mib_per_rank": budget,
                   "runs": runs}, f, indent=1)
    with open(base + ".md", "w") as f:
        budget_note = ("" if budget is None else
                       f"The budget: the peak memory per rank of the assembled {args.budget_case} run ({budget} MiB). ")
        f.write(table(runs, budget) + "\n" + budget_note + "The family's load and supports "
                f"(xml/family/2d-p2-nx200.xml, 3d-p2-nx32.xml), {args.ranks} ranks, default solver parameters. "
                "Written by bench/matrix_free_solve.py.\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""A contact solve against the floor it cannot beat: one linear solve of the same problem.

For each case the contact problem runs with the default parameters, then the same input
without its contact boundary (`Problem/Contact/boundary` empty: the same Q, b, preconditioner
and Krylov solver, one solve of Q v = b to the same KKT tolerance). The two runs of a case
follow each other, so their ratio is measured under the same load of the machine; the pair
runs `--repeats` times (3) and each of the two keeps its fastest solve, since single timings
on a shared machine vary by 10-25%.

    /usr/bin/python3 bench/reference_solve.py [--cases paper,2d,3d,high-order] [--only J,2d-p1-nx400]
                                              [--repeats 3]

Writes bench/results/reference-solve.{json,md}: per case and run the phase times (mesh and
space, assembly, solve and within it AMG setup with its parts, Krylov, initial guesses,
preconditioner construction, assembly of H; output; of the fastest run, with the solve
times of every run in `solve_seconds_per_run`), main
iterations, Newton systems, CG iterations, AMG setups, the active-set finish (attempts,
accepted, CG iterations), peak memory per unknown, and the
ratios contact / reference of solve time and CG iterations.
"""
import argparse
import json
import os
import re
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance

CASES = {
    "paper": [(f"paper/{p}", 1) for p in "ABCDEFGHIJKLM"],
    "2d": [("family/2d-p1-nx400", 2), ("family/2d-p1-nx1000", 2)],
    "3d": [("family/3d-p1-nx40", 2), ("family/3d-p1-nx64", 2), ("family/3d-p1-nx100", 2)],
    "high-order": [("family/2d-p2-nx200", 2), ("family/2d-p3-nx100", 2), ("family/3d-p2-nx32", 2)],
}
TIMERS = {"mesh": "Signorini: mesh and space", "assembly": "Signorini: assembly", "solve": "Signorini: solve",
          "amg_setup": "Signorini: solve: AMG setup", "krylov": "Signorini: solve: Krylov",
          "initial_guesses": "Signorini: solve: initial guesses", "output": "Signorini: output",
          "galerkin_products": "Signorini: solve: AMG setup: Galerkin products",
          "smoother_setup": "Signorini: solve: AMG setup: smoothers",
          "coarsest_level": "Signorini: solve: AMG setup: coarsest level",
          "preconditioner_construction": "Signorini: solve: preconditioner construction",
          "assemble_h": "Signorini: solve: assemble H"}


def run(xml, ranks, out, reference):
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"),
           os.path.join(ROOT, "xml", xml + ".xml"), "--output", out, "--set", "Output/write solution=false"]
    if reference:
        cmd += ["--set", "Problem/Contact/boundary="]
    log = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False).stdout
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    seconds = {}
    for key, name in TIMERS.items():
        # The timer table: one time on one rank; min, mean and max over the ranks on more.
        m = re.search(r"^" + re.escape(name) + r"\s+(.*)$", log, re.M)
        times = [float(t) for t in re.findall(r"([0-9.eE+-]+) \(", m.group(1))[:3]] if m else []
        seconds[key] = max(times) if times else None
    seconds["solve"] = s["time"]["solve"]  # the maximum over ranks
    return {"status": s["status"], "n": s["n"], "m": s["m"], "main_iterations": s["outer_iterations"],
            "newton_systems": s["newton_steps"], "cg_iterations": s["krylov_iterations"],
            "amg_setups": s["preconditioner_setups"], "active_set_finish": s.get("active_set_finish"),
            "objective": s["objective"], "seconds": seconds,
            "peak_bytes_per_unknown": s["memory_mib"]["all_ranks"] * 2**20 / s["n"]}


def fastest_pair(xml, ranks, out, repeats):
    """Contact and reference runs, alternating `repeats` times; of each, the run with the
    shortest solve, with every run's solve time."""
    pairs = [(run(xml, ranks, out, False), run(xml, ranks, out + "-reference", True)) for _ in range(repeats)]
    chosen = []
    for runs in zip(*pairs):
        best = min(runs, key=lambda r: r["seconds"]["solve"])
        best["solve_seconds_per_run"] = [r["seconds"]["solve"] for r in runs]
        chosen.append(best)
    return chosen


def row(case):
    c, r = case["contact"], case["reference"]
    t = c["seconds"]
    fmt = lambda x: "—" if x is None else f"{x:.2f}"  # noqa: E731
    return (f"| {case['problem']} | {case['ranks']} | {c['n']} | {c['m']} | {c['status']} | {c['main_iterations']} | "
            f"{c['newton_systems']} | {c['cg_iterations']} | {c['amg_setups']} | {fmt(t['mesh'])} | "
            f"{fmt(t['assembly'])} | {fmt(t['amg_setup'])} | {fmt(t['krylov'])} | {fmt(t['solve'])} | "
            f"{r['cg_iterations']} | {fmt(r['seconds']['solve'])} | {case['cg_ratio']:.1f} | "
            f"{case['solve_time_ratio']:.1f} | {c['peak_bytes_per_unknown']:.0f} |")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--cases", default="paper,2d,3d,high-order", help="comma-separated groups of CASES")
    parser.add_argument("--only", default="", help="comma-separated problem names (e.g. J,2d-p1-nx400) to keep")
    parser.add_argument("--name", default="reference-solve", help="basename of the result files")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "reference-solve"))
    parser.add_argument("--repeats", type=int, default=3, help="runs of each case; the fastest solve is kept")
    args = parser.parse_args()
    made = provenance("1 (paper), 2 (the others)")  # before any result file is rewritten
    only = {p for p in args.only.split(",") if p}
    cases = []
    for group in args.cases.split(","):
        if group not in CASES:
            parser.error(f"unknown group {group!r}; known: {', '.join(CASES)}")
        for xml, ranks in CASES[group]:
            if only and xml.split("/")[-1] not in only:
                continue
            out = os.path.join(args.workdir, xml.replace("/", "-"))
            contact, reference = fastest_pair(xml, ranks, out, args.repeats)
            case = {"problem": xml, "ranks": ranks, "repeats": args.repeats, "contact": contact, "reference": reference}
            case["cg_ratio"] = case["contact"]["cg_iterations"] / max(case["reference"]["cg_iterations"], 1)
            case["solve_time_ratio"] = case["contact"]["seconds"]["solve"] / case["reference"]["seconds"]["solve"]
            cases.append(case)
            print(row(case), flush=True)
    rows = ["| problem | ranks | n | m | status | it | Newton | CG | AMG setups | mesh [s] | assembly [s] | "
            "AMG setup [s] | Krylov [s] | solve [s] | reference: CG | solve [s] | CG ratio | solve time ratio | "
            "peak bytes per unknown |", "|" + "---|" * 19] + [row(c) for c in cases]
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    base = os.path.join(ROOT, "bench", "results", args.name)
    with open(base + ".json", "w") as f:
        json.dump({"provenance": made, "cases": cases}, f, indent=1)
    with open(base + ".md", "w") as f:
        f.write("\n".join(rows) + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The adaptive forcing's safety factor against Krylov iterations, main iterations and time:
the residual allowed in a Newton system is safety * max(||r_d||, ||b|| mu / mu0), so a larger
safety asks each system for fewer digits and the interior point method for more steps.

    /usr/bin/python3 bench/forcing.py [--ranks N] [--safety 0.1,0.2,...] [--problems XML,...]

Writes bench/results/forcing.{json,md}; every run selects the adaptive forcing and uses the
default configuration otherwise. The stored results include safety 1.0, beyond the range the
parameter accepts (at most 0.9): at 1 a step need not reduce the dual residual, and it
stagnated on 3D P1.
"""
import argparse
import json
import os

from provenance import provenance

from preconditioners import ROOT, run

PROBLEMS = ["paper/M", "paper/G", "paper/K", "paper/J", "family/2d-p1-nx200", "family/2d-p1-nx400",
            "paper/E", "paper/L", "family/3d-p1-nx40"]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--safety", default="0.1,0.2,0.3,0.5,0.9")
    parser.add_argument("--problems", default=",".join(PROBLEMS))
    parser.add_argument("--reuse", action="store_true", help="reuse the outputs of earlier runs in the workdir")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "forcing"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    if args.reuse:
        made["reused outputs of earlier runs"] = os.path.relpath(args.workdir, ROOT)
    safeties = args.safety.split(",")
    problems = args.problems.split(",")
    records = []
    for problem in problems:
        for safety in safeties:
            out = os.path.join(args.workdir, f"{problem.replace('/', '-')}-safety-{safety}")
            settings = {"Solver/forcing: type": "adaptive", "Solver/forcing: safety": safety}
            summary, history = run(problem, settings, args.ranks, out, args.reuse)
            records.append({"problem": problem, "safety": float(safety), "ranks": args.ranks, "summary": summary,
                            "history": history})
            print(f"{problem:22s} safety {safety:4s}: it {summary['outer_iterations']:3d}, "
                  f"Krylov {summary['krylov_iterations']:4d}, max/system {summary['max_krylov_per_newton']:3d}, "
                  f"solve {summary['time']['solve']:.2f} s, {summary['status']}", flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "forcing.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    header = "| problem | n | " + " | ".join(f"safety {s}: it / Krylov / solve [s]" for s in safeties) + " |"
    rows = [header, "|---|---|" + "---|" * len(safeties)]
    for problem in problems:
        runs = [r for r in records if r["problem"] == problem]
        cells = [f"{r['summary']['outer_iterations']} / {r['summary']['krylov_iterations']} / "
                 f"{r['summary']['time']['solve']:.2f}" for r in runs]
        rows.append(f"| {problem} | {runs[0]['summary']['n']} | " + " | ".join(cells) + " |")
    with open(os.path.join(ROOT, "bench", "results", "forcing.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    main()

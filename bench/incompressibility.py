#!/usr/bin/python3
"""Krylov work against the Poisson ratio: 2D P1 members of the family (plane strain) with
nu from 0.3 to 0.4999, with the default preconditioner and with variants of its smoothing
and hierarchy. P1 elements lock as nu -> 1/2 (the discrete problem stiffens and its
condition number grows like 1/(1 - 2 nu)): the comparison shows how much of the growth a
preconditioner setting removes.

    /usr/bin/python3 bench/incompressibility.py [--ranks 1] [--problems paper/G,paper/J]

Writes bench/results/incompressibility.{json,md}.
"""
import argparse
import json
import os

from preconditioners import ROOT, run
from provenance import provenance

P = "Solver/Preconditioner/"
CONFIGS = {
    "default": {},
    "chebyshev degree 4": {P + "Ifpack2/chebyshev: degree": "4"},
    "chebyshev degree 6": {P + "Ifpack2/chebyshev: degree": "6"},
    "algebraic": {P + "hierarchy": "algebraic"},
}
POISSON = ["0.3", "0.49", "0.499", "0.4999"]


def table(records):
    lines = ["| problem | configuration | " + " | ".join("nu = " + nu for nu in POISSON) + " |",
             "|---|---|" + "---|" * len(POISSON)]
    for problem in dict.fromkeys(r["problem"] for r in records):
        for config in CONFIGS:
            cells = []
            for nu in POISSON:
                s = next(r["summary"] for r in records
                         if (r["problem"], r["config"], r["nu"]) == (problem, config, float(nu)))
                cells.append("%d CG, %.2f s%s" % (s["krylov_iterations"], s["time"]["solve"],
                                                  "" if s["converged"] else " (not converged)"))
            lines.append("| %s | %s | %s |" % (problem, config, " | ".join(cells)))
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--problems", default="paper/G,paper/J")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "incompressibility"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    records = []
    for problem in args.problems.split(","):
        for config, settings in CONFIGS.items():
            for nu in POISSON:
                out = os.path.join(args.workdir, "%s-%s-nu%s" % (problem.replace("/", "-"), config.replace(" ", "-"), nu))
                summary, _ = run(problem, {**settings, "Problem/material: poisson ratio": nu}, args.ranks, out, False)
                records.append({"problem": problem, "config": config, "nu": float(nu), "summary": summary})
                print("%s %-20s nu %-6s CG %5d  solve %.2f s" % (problem, config, nu, summary["krylov_iterations"],
                                                                  summary["time"]["solve"]), flush=True)
    base = os.path.join(ROOT, "bench", "results", "incompressibility")
    with open(base + ".json", "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    with open(base + ".md", "w") as f:
        f.write(table(records))


if __name__ == "__main__":
    main()

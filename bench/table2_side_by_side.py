#!/usr/bin/python3
"""The README's results table, from the JSON that scripts/table2.py wrote:

    /usr/bin/python3 bench/table2_side_by_side.py

One row per problem A-M: the paper's Table 2 (main iterations, gradient evaluations, CPU
time) next to the primal-dual and the primal method's main iterations, CG iterations and
solve time (bench/results/table2.json).
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def main():
    with open(os.path.join(ROOT, "bench", "results", "table2.json")) as f:
        runs = json.load(f)["runs"]
    by_problem = {}
    for r in runs:
        by_problem.setdefault(r["summary"]["problem"], {})[r["summary"]["method"]] = r
    print("| problem | n | m | paper: it | ngr | time [s] | primal-dual: it | Krylov | time [s] "
          "| primal: it | Krylov | time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for problem, methods in sorted(by_problem.items()):
        any_run = next(iter(methods.values()))
        paper = any_run["paper"]
        cells = [problem, any_run["summary"]["n"], any_run["summary"]["m"]]
        cells += [paper["it"], paper["ngr"], paper["cpu_seconds"]] if paper.get("it") else ["—"] * 3
        for method in ("primal-dual", "primal"):
            s = methods[method]["summary"] if method in methods else None
            cells += [s["outer_iterations"], s["krylov_iterations"], f"{s['time']['solve']:.2f}"] if s else ["—"] * 3
        print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The README's preconditioning table, from bench/results/preconditioners-geometric.json and
preconditioners-geometric-p2p3.json (both written by bench/preconditioners.py):

    /usr/bin/python3 bench/readme_table.py

One row per member: the default configuration (geometric levels above MueLu on the box
meshes) with the adaptive forcing, the same with every Newton system solved to 1e-8, and
the previous default (MueLu's hierarchy alone) both ways.
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = "default"
ALGEBRAIC = "algebraic (previous default)"


def main():
    records = []
    for name in ("preconditioners-geometric", "preconditioners-geometric-p2p3"):
        with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
            records += json.load(f)
    runs = {(r["sequence"], r["nx"], r["config"], r["forcing"]): r for r in records}
    print("| sequence | nx | n | it | Krylov total | max per system | first / last step | AMG setups | solve [s] "
          "| fixed 1e-8: total | max per system | algebraic: it | Krylov total | max per system | solve [s] "
          "| algebraic, fixed 1e-8: max per system |")
    print("|" + "---|" * 16)
    members = sorted({(r["sequence"], r["nx"]) for r in records if r["config"] == DEFAULT},
                     key=lambda m: (["2d", "3d", "2d-p2", "2d-p3", "3d-p2"].index(m[0]), m[1]))
    for sequence, nx in members:
        d = runs[(sequence, nx, DEFAULT, "adaptive")]
        s = d["summary"]
        cells = [sequence, nx, s["n"], s["outer_iterations"], s["krylov_iterations"], s["max_krylov_per_newton"],
                 f"{d['history'][0]['krylov']} / {d['history'][-1]['krylov']}", s["preconditioner_setups"],
                 f"{s['time']['solve']:.2f}"]
        fixed = runs.get((sequence, nx, DEFAULT, "relative"))
        cells += [fixed["summary"]["krylov_iterations"], fixed["summary"]["max_krylov_per_newton"]] if fixed else ["—"] * 2
        algebraic = runs.get((sequence, nx, ALGEBRAIC, "adaptive"))
        cells += ([algebraic["summary"][k] for k in ("outer_iterations", "krylov_iterations", "max_krylov_per_newton")]
                  + [f"{algebraic['summary']['time']['solve']:.2f}"]) if algebraic else ["—"] * 4
        algebraicFixed = runs.get((sequence, nx, ALGEBRAIC, "relative"))
        cells += [algebraicFixed["summary"]["max_krylov_per_newton"] if algebraicFixed else "—"]
        print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()

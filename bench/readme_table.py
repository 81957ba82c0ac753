#!/usr/bin/python3
"""The README's preconditioning table, from the JSON that bench/preconditioners.py wrote:

    /usr/bin/python3 bench/readme_table.py

One row per member: the default configuration with the adaptive forcing and with every
Newton system solved to 1e-8 (preconditioners-projection{,-p2p3}.json); session 5's default,
whose Newton systems start from zero (same files); and MueLu's hierarchy alone, session 5's
"algebraic (previous default)" (preconditioners-geometric{,-p2p3}.json, an earlier run).
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = "default"
WITHOUT_PROJECTION = "without projection (session 5 default)"
ALGEBRAIC = "algebraic (previous default)"


def load(*names):
    records = []
    for name in names:
        with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
            records += json.load(f)
    return {(r["sequence"], r["nx"], r["config"], r["forcing"]): r for r in records}


def main():
    runs = load("preconditioners-projection", "preconditioners-projection-p2p3")
    earlier = load("preconditioners-geometric", "preconditioners-geometric-p2p3")
    print("| sequence | nx | n | it | Krylov total | max per system | first / last step | AMG setups | solve [s] "
          "| fixed 1e-8: total | max per system | from zero: it | Krylov total | max per system | solve [s] "
          "| algebraic: Krylov total | fixed 1e-8: max per system |")
    print("|" + "---|" * 17)
    members = sorted({(s, nx) for (s, nx, config, _) in runs if config == DEFAULT},
                     key=lambda m: (["2d", "3d", "2d-p2", "2d-p3", "3d-p2"].index(m[0]), m[1]))
    for sequence, nx in members:
        d = runs[(sequence, nx, DEFAULT, "adaptive")]
        s = d["summary"]
        cells = [sequence, nx, s["n"], s["outer_iterations"], s["krylov_iterations"], s["max_krylov_per_newton"],
                 f"{d['history'][0]['krylov']} / {d['history'][-1]['krylov']}", s["preconditioner_setups"],
                 f"{s['time']['solve']:.2f}"]
        fixed = runs.get((sequence, nx, DEFAULT, "relative"))
        cells += [fixed["summary"]["krylov_iterations"], fixed["summary"]["max_krylov_per_newton"]] if fixed else ["—"] * 2
        zero = runs.get((sequence, nx, WITHOUT_PROJECTION, "adaptive"))
        cells += ([zero["summary"][k] for k in ("outer_iterations", "krylov_iterations", "max_krylov_per_newton")]
                  + [f"{zero['summary']['time']['solve']:.2f}"]) if zero else ["—"] * 4
        algebraic = earlier.get((sequence, nx, ALGEBRAIC, "adaptive"))
        algebraicFixed = earlier.get((sequence, nx, ALGEBRAIC, "relative"))
        cells += [algebraic["summary"]["krylov_iterations"] if algebraic else "—",
                  algebraicFixed["summary"]["max_krylov_per_newton"] if algebraicFixed else "—"]
        print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The preconditioning table of doc/benchmarks.md, from the JSON that bench/preconditioners.py wrote:

    /usr/bin/python3 bench/preconditioners_table.py

One row per member (preconditioners-forcing{,-p2p3}.json, one run each): the default
configuration with the default forcing ("reduction"), with the adaptive forcing and with
every Newton system solved to 1e-8 ("relative"); then the AMG built for H itself without the
weight cap ("unfiltered"), and in addition rebuilt only when constraints switch ("lagged
rebuild"), where the JSON has them.
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT = "default"
UNFILTERED = "unfiltered"
LAGGED = "lagged rebuild"


def load(*names):
    records = []
    for name in names:
        with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
            data = json.load(f)
        records += data["runs"] if isinstance(data, dict) else data  # files without provenance are lists
    return {(r["sequence"], r["nx"], r["config"], r["forcing"]): r for r in records}


def ratios(records):
    """Three measures over one sequence: spread of the largest count per Newton system,
    spread of the totals, and last over first Newton step (largest over the sequence)."""
    maxima = [r["summary"]["max_krylov_per_newton"] for r in records]
    totals = [r["summary"]["krylov_iterations"] for r in records]
    last_first = [r["history"][-1]["krylov"] / max(r["history"][0]["krylov"], 1) for r in records]
    return max(maxima) / max(min(maxima), 1), max(totals) / max(min(totals), 1), max(last_first)


def first_last(run):
    return f"{run['history'][0]['krylov']} / {run['history'][-1]['krylov']}"


def main():
    runs = load("preconditioners-forcing", "preconditioners-forcing-p2p3")
    print("| sequence | nx | n | it | Krylov total | max per system | first / last step | AMG setups | solve [s] "
          "| adaptive: it | Krylov total | max per system | first / last step | solve [s] "
          "| fixed 1e-8: total | max per system | unfiltered: Krylov total | max per system | first / last step "
          "| solve [s] | lagged rebuild: Krylov total | solve [s] |")
    print("|" + "---|" * 22)
    members = sorted({(s, nx) for (s, nx, config, _) in runs if config == DEFAULT},
                     key=lambda m: (["2d", "3d", "2d-p2", "2d-p3", "3d-p2"].index(m[0]), m[1]))
    for sequence, nx in members:
        d = runs[(sequence, nx, DEFAULT, "reduction")]
        s = d["summary"]
        cells = [sequence, nx, s["n"], s["outer_iterations"], s["krylov_iterations"], s["max_krylov_per_newton"],
                 first_last(d), s["preconditioner_setups"], f"{s['time']['solve']:.2f}"]
        a = runs.get((sequence, nx, DEFAULT, "adaptive"))
        cells += ([a["summary"][k] for k in ("outer_iterations", "krylov_iterations", "max_krylov_per_newton")]
                  + [first_last(a), f"{a['summary']['time']['solve']:.2f}"]) if a else ["—"] * 5
        fixed = runs.get((sequence, nx, DEFAULT, "relative"))
        cells += [fixed["summary"]["krylov_iterations"], fixed["summary"]["max_krylov_per_newton"]] if fixed else ["—"] * 2
        u = runs.get((sequence, nx, UNFILTERED, "reduction"))
        cells += [u["summary"]["krylov_iterations"], u["summary"]["max_krylov_per_newton"], first_last(u),
                  f"{u['summary']['time']['solve']:.2f}"] if u else ["—"] * 4
        r = runs.get((sequence, nx, LAGGED, "reduction"))
        cells += [r["summary"]["krylov_iterations"], f"{r['summary']['time']['solve']:.2f}"] if r else ["—"] * 2
        print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()

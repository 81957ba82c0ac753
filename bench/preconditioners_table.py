#!/usr/bin/python3
"""The preconditioning table of doc/benchmarks.md, from the JSON that bench/preconditioners.py wrote:

    /usr/bin/python3 bench/preconditioners_table.py

One row per member (preconditioners-forcing{,-p2p3}.json, one run each): the default
configuration with the default forcing ("reduction"), with the adaptive forcing and with
every Newton system solved to 1e-8 ("relative"); then the AMG built for H itself without the
weight cap ("unfiltered"), and in addition rebuilt only when constraints switch ("lagged
rebuild"), where the JSON has them. "Max per system" and "first / last step" are over the
barrier steps; "finish" is the CG iterations of the active-set finish, whose system is solved
to the KKT tolerance (in the totals too).
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


def barrier_steps(run):
    """The history's records of the barrier steps: not the active-set finish's (mu 0)."""
    return [h for h in run["history"] if h["mu"] > 0]


def finish_krylov(run):
    """CG iterations of the active-set finish attempts, solved to the KKT tolerance."""
    return run["summary"].get("active_set_finish", {}).get("krylov_iterations", 0)


def approximate(records):
    """The members whose preconditioner is not an exact solve: where the coarsest grid is the
    whole mesh, every system takes one CG iteration, which says nothing about the mesh."""
    kept = [r for r in records if r["summary"]["max_krylov_per_newton"] > 1]
    return kept if len(kept) >= 2 else records


def ratios(records):
    """Three measures over one sequence: spread of the largest count per Newton system of
    the barrier steps, spread of the totals (the active-set finish included), and last over
    first barrier step (largest over the sequence)."""
    maxima = [r["summary"]["max_krylov_per_newton"] for r in records]
    totals = [r["summary"]["krylov_iterations"] for r in records]
    last_first = [barrier_steps(r)[-1]["krylov"] / max(barrier_steps(r)[0]["krylov"], 1) for r in records]
    return max(maxima) / max(min(maxima), 1), max(totals) / max(min(totals), 1), max(last_first)


def first_last(run):
    steps = barrier_steps(run)
    return f"{steps[0]['krylov']} / {steps[-1]['krylov']}"


def main():
    runs = load("preconditioners-forcing", "preconditioners-forcing-p2p3")
    print("| sequence | nx | n | it | Krylov total | max per system | first / last step | finish | AMG setups | solve [s] "
          "| adaptive: it | Krylov total | max per system | first / last step | solve [s] "
          "| fixed 1e-8: total | max per system | unfiltered: Krylov total | max per system | first / last step "
          "| solve [s] | lagged rebuild: Krylov total | solve [s] |")
    print("|" + "---|" * 23)
    members = sorted({(s, nx) for (s, nx, config, _) in runs if config == DEFAULT},
                     key=lambda m: (["2d", "3d", "2d-p2", "2d-p3", "3d-p2"].index(m[0]), m[1]))
    for sequence, nx in members:
        d = runs[(sequence, nx, DEFAULT, "reduction")]
        s = d["summary"]
        cells = [sequence, nx, s["n"], s["outer_iterations"], s["krylov_iterations"], s["max_krylov_per_newton"],
                 first_last(d), finish_krylov(d), s["preconditioner_setups"], f"{s['time']['solve']:.2f}"]
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

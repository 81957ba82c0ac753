#!/usr/bin/python3
"""The table of doc/benchmarks.md that takes one component out of the default preconditioner,
start and method at a time, from bench/results/preconditioners-components.json:

    /usr/bin/python3 bench/preconditioners.py --forcing reduction,relative --configs \\
        "default,without contact-corrected start,from zero,without active-set finish,algebraic,algebraic amg of Q" \\
        --name preconditioners-components
    /usr/bin/python3 bench/components_table.py

One row per member: for each configuration, main iterations, CG iterations and solve time
with the default forcing; for those that change the preconditioner, the largest count per
Newton system at the fixed accuracy 1e-8 ("relative"), which measures the preconditioner
alone.
"""
from preconditioners_table import load

CONFIGS = ["default", "without contact-corrected start", "from zero", "without active-set finish", "algebraic",
           "algebraic amg of Q"]
SEQUENCES = ["2d", "3d", "2d-p2", "2d-p3", "3d-p2"]


def measured_at_fixed_accuracy(runs, config):
    return any(key[2] == config and key[3] == "relative" for key in runs)


def main():
    runs = load("preconditioners-components")
    header = ["sequence", "nx", "n"]
    for config in CONFIGS:
        header += [f"{config}: it", "CG", "solve [s]"]
        if measured_at_fixed_accuracy(runs, config):
            header += ["max per system at 1e-8"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    members = sorted({(s, nx) for (s, nx, _, _) in runs}, key=lambda m: (SEQUENCES.index(m[0]), m[1]))
    for sequence, nx in members:
        first = runs[(sequence, nx, "default", "reduction")]["summary"]
        cells = [sequence, nx, first["n"]]
        for config in CONFIGS:
            r = runs.get((sequence, nx, config, "reduction"))
            s = r["summary"] if r else None
            cells += [s["outer_iterations"], s["krylov_iterations"], f"{s['time']['solve']:.2f}"] if s else ["—"] * 3
            if measured_at_fixed_accuracy(runs, config):
                fixed = runs.get((sequence, nx, config, "relative"))
                cells.append(fixed["summary"]["max_krylov_per_newton"] if fixed else "—")
        print("| " + " | ".join(str(c) for c in cells) + " |")


if __name__ == "__main__":
    main()

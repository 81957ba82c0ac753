#!/usr/bin/python3
"""The ratio table of doc/benchmarks.md, from the JSON of bench/preconditioners.py (standard
library only, like every table script that scripts/benchmarks_md.py runs):

    /usr/bin/python3 bench/ratios_table.py

Three measures of how far the CG counts depend on the mesh and on mu, per sequence,
configuration and forcing of preconditioners-forcing{,-p2p3}.json: the largest count per
Newton system of the barrier steps, max/min over the sequence (target 1.5); the total count
of a solve, max/min (target 2); the last over the first barrier step, worst member (target
1.5). Members whose preconditioner is an exact solve (one CG iteration per system) are left
out. Bold: within the target. The other forcings are shown for the default configuration only.
"""
from preconditioners_table import approximate, load, ratios

SEQUENCES = {"2d": "2D P1", "3d": "3D P1", "2d-p2": "2D P2", "2d-p3": "2D P3", "3d-p2": "3D P2"}
FORCINGS = {"reduction": "", "adaptive": ", adaptive", "relative": ", fixed 1e-8"}
TARGETS = (1.5, 2.0, 1.5)


def main():
    runs = load("preconditioners-forcing", "preconditioners-forcing-p2p3")
    print("| sequence | configuration, forcing | max per system | totals | last / first |")
    print("|---|---|---|---|---|")
    for sequence, label in SEQUENCES.items():
        configs = list(dict.fromkeys(key[2] for key in runs if key[0] == sequence))
        for config in configs:
            for forcing, suffix in FORCINGS.items():
                group = approximate(sorted((r for key, r in runs.items() if key[0] == sequence and key[2] == config
                                            and key[3] == forcing), key=lambda r: r["nx"]))
                if len(group) < 2 or (forcing != "reduction" and config != "default"):
                    continue
                cells = [f"**{v:.2f}**" if v <= t else f"{v:.2f}" for v, t in zip(ratios(group), TARGETS)]
                members = f"{label} nx = {group[0]['nx']}–{group[-1]['nx']}"
                print(f"| {members} | {config}{suffix} | " + " | ".join(cells) + " |")


if __name__ == "__main__":
    main()

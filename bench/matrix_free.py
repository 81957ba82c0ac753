#!/usr/bin/python3
"""The stiffness Q applied as the assembled matrix and matrix-free, on 3D P1, P2 and P3
members with about a million unknowns, on 1 and 2 ranks: bytes per unknown each keeps and
seconds per application.

    /usr/bin/python3 bench/matrix_free.py [--ranks 1,2]

Runs build/bin/signorini_bench_operator DIM DEGREE NX under mpirun and writes
bench/results/matrix-free.json ({"provenance", "runs"}) and bench/results/matrix-free.md.
"""
import argparse
import json
import os

from bench_binary import run_cases
from provenance import provenance

from preconditioners import ROOT

CASES = [(3, 1, 70), (3, 2, 35), (3, 3, 24)]
RESULTS = os.path.join(ROOT, "bench", "results")


def table(runs):
    lines = ["| d | P | nx | n | ranks | assembled: bytes per unknown | ms per apply "
             "| matrix-free: bytes per unknown | ms per apply | time ratio |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        lines.append(f"| {r['dim']} | {r['degree']} | {r['nx']} | {int(r['n'])} | {r['ranks']} "
                     f"| {r['assembled_bytes_per_unknown']:.0f} | {1e3 * r['assembled_seconds_per_apply']:.1f} "
                     f"| {r['matrix_free_bytes_per_unknown']:.0f} | {1e3 * r['matrix_free_seconds_per_apply']:.1f} "
                     f"| {r['matrix_free_seconds_per_apply'] / r['assembled_seconds_per_apply']:.2f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    ranks = [int(r) for r in args.ranks.split(",")]
    made = provenance(max(ranks))  # before the result files are rewritten (git describe --dirty)
    runs = run_cases("signorini_bench_operator", CASES, ranks)
    with open(os.path.join(RESULTS, "matrix-free.json"), "w") as f:
        json.dump({"provenance": made, "runs": runs}, f, indent=1)
    with open(os.path.join(RESULTS, "matrix-free.md"), "w") as f:
        f.write(table(runs) + "\nBytes: the assembled matrix's CSR arrays (values, column indices, row offsets); "
                "the matrix-free operator's per-cell data, tables and work vectors. Median of 11 applications, "
                "the slowest rank's time. Written by bench/matrix_free.py.\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Assembly time and memory of members of the family with about a million unknowns (3D P1
nx = 70, 2D P1 nx = 700, 3D P2 nx = 35), on 1 and 2 ranks.

    /usr/bin/python3 bench/assembly.py [--ranks 1,2]

Runs build/bin/signorini_bench_assembly DIM DEGREE NX under mpirun and writes
bench/results/assembly.json ({"provenance", "runs"}: one record per case and rank count).
"""
import argparse
import json
import os

from bench_binary import run_cases
from provenance import provenance

from preconditioners import ROOT

CASES = [(3, 1, 70), (2, 1, 700), (3, 2, 35)]


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", default="1,2")
    args = parser.parse_args()
    ranks = [int(r) for r in args.ranks.split(",")]
    made = provenance(max(ranks))  # before the result file is rewritten (git describe --dirty)
    records = run_cases("signorini_bench_assembly", CASES, ranks)
    with open(os.path.join(ROOT, "bench", "results", "assembly.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)


if __name__ == "__main__":
    main()

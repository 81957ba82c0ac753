#!/usr/bin/python3
"""Factorization of coarsest-level matrices on one rank, KLU2 (LU) against CHOLMOD (Cholesky):
first factorization, refactorization on the same pattern and solve, for P1 boxes from the
sizes of the coarsest geometric grids up to the largest one might factor.

    /usr/bin/python3 bench/direct_solvers.py

Runs build/bin/signorini_bench_direct_solver DIM NX and writes
bench/results/direct-solvers.json ({"provenance", "runs"}: one record per case).
"""
import json
import os

from bench_binary import run_cases
from provenance import provenance

from preconditioners import ROOT

CASES = [(3, 4), (3, 8), (3, 10), (3, 12), (3, 16), (2, 25), (2, 50), (2, 100), (2, 125)]


def main():
    made = provenance(1)  # before the result file is rewritten (git describe --dirty)
    records = run_cases("signorini_bench_direct_solver", CASES, [1])
    with open(os.path.join(ROOT, "bench", "results", "direct-solvers.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)


if __name__ == "__main__":
    main()

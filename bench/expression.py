#!/usr/bin/python3
"""Cost of evaluating the family's load per point: muparser point by point against a cell's
quadrature points at once (7 in 2D, 14 in 3D, the default rules for P1), on one process.

    /usr/bin/python3 bench/expression.py

Runs build/bin/signorini_bench_expression DIM and writes bench/results/expression.json
({"provenance", "runs"}: one record per dimension).
"""
import json
import os

from bench_binary import run_cases
from provenance import provenance

from preconditioners import ROOT


def main():
    made = provenance(1)  # before the result file is rewritten (git describe --dirty)
    records = run_cases("signorini_bench_expression", [(2,), (3,)], [1])
    with open(os.path.join(ROOT, "bench", "results", "expression.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)


if __name__ == "__main__":
    main()

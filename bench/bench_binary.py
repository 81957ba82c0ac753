"""Runs one of the C++ benchmark programs (build/bin/signorini_bench_*) over cases and rank
counts; each run prints its record as JSON on its last line."""
import json
import os
import subprocess

from preconditioners import ENV, ROOT


def run_cases(binary, cases, ranks):
    """One record per (case, rank count), cases outermost; a case is the program's arguments."""
    records = []
    for case in cases:
        for np in ranks:
            cmd = ["mpirun", "-np", str(np), os.path.join(ROOT, "build", "bin", binary)] + [str(a) for a in case]
            out = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=True).stdout
            records.append(json.loads(out.strip().splitlines()[-1]))
            print(json.dumps(records[-1]), flush=True)
    return records

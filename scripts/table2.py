#!/usr/bin/python3
"""Runs problems A-M of the benchmark family with both interior point methods and puts the
results next to the paper's Table 2 (Tanoh, Renard, Noll).

    /usr/bin/python3 scripts/table2.py [--ranks N] [--methods primal-dual,primal] [--problems A,B,...]
                            [--set "Solver/name=value" ...] [--name table2]

Writes bench/results/<name>.json (every summary.json, plus the paper's row) and
bench/results/<name>.md (the Markdown table), and prints the table. The paper's problems
used loads it does not print, so its optimal values are not comparable to ours; its
counters and times (Fortran 90, 2003 hardware) are.
"""
import argparse
import json
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the repository
sys.path.insert(0, os.path.join(ROOT, "bench"))
from provenance import provenance  # noqa: E402

# Table 2 of the paper: n, m, ngr, nfc, it, optimal value, cpu seconds (F: not solved).
PAPER = {
    "A": (50, 5, 45, 84, 19, -0.1407047, 0.09),
    "B": (375, 25, 59, 62, 19, -0.0597285072, 0.39),
    "C": (1995, 81, 42, 42, 14, -0.372374397, 11.14),
    "D": (13203, 289, 47, 47, 15, -0.753245045, 177.11),
    "E": (3993, 121, 49, 49, 16, -0.350213401, 15.17),
    "F": (24783, 441, None, None, None, None, None),
    "G": (882, 21, 82, 82, 18, -0.755060513, 1.58),
    "H": (3362, 41, 171, 171, 16, -1.89351901, 38.0199),
    "I": (7442, 61, 330, 330, 15, -3.05307295, 448.19),
    "J": (20402, 101, 224, 224, 14, -4.15773494, 490.660),
    "K": (5202, 51, 134, 134, 15, -2.03452994, 56.889),
    "L": (27783, 441, 49, 49, 16, -0.819527298, 167.669),
    "M": (242, 11, 67, 67, 18, -0.339076629, 0.30),
}


def run(problem, method, ranks, workdir, extra):
    out = os.path.join(workdir, f"{problem}-{method}-np{ranks}")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"),
           os.path.join(ROOT, "xml/paper", problem + ".xml"), "--output", out,
           "--set", "Solver/method=" + method, "--set", "Output/write solution=false"]
    for assignment in extra:
        cmd += ["--set", assignment]
    subprocess.run(cmd, env=env, stdout=subprocess.DEVNULL, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def cell(value, fmt="{}"):
    return "—" if value is None else fmt.format(value)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--methods", default="primal-dual,primal")
    parser.add_argument("--problems", default=",".join(PAPER))
    parser.add_argument("--set", action="append", default=[], dest="extra",
                        help="extra parameter override for every run, as signorini --set takes it")
    parser.add_argument("--name", default="table2", help="basename of the files in bench/results")
    parser.add_argument("--workdir", default=None)
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    workdir = args.workdir or os.path.join(ROOT, "results", args.name)

    rows, records = [], []
    header = ("| problem | n | m | method | ngr | nfc | it | Newton | Krylov | optimal value | time [s] "
              "| paper ngr | paper nfc | paper it | paper time [s] |")
    rows.append(header)
    rows.append("|" + "---|" * (header.count("|") - 1))
    for problem in args.problems.split(","):
        paper = PAPER[problem]
        for method in args.methods.split(","):
            s = run(problem, method, args.ranks, workdir, args.extra)
            records.append({"summary": s, "paper": dict(zip(
                ["n", "m", "ngr", "nfc", "it", "optimal_value", "cpu_seconds"], paper))})
            status = "" if s["converged"] else f" ({s['status']})"
            rows.append(
                f"| {problem} | {s['n']} | {s['m']} | {method}{status} | {s['gradient_evaluations']} | "
                f"{s['function_evaluations']} | {s['outer_iterations']} | {s['newton_steps']} | "
                f"{s['krylov_iterations']} | {s['objective']:.9e} | {s['time']['solve']:.2f} | "
                f"{cell(paper[2])} | {cell(paper[3])} | {cell(paper[4])} | {cell(paper[6])} |")
            print(rows[-1], flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", args.name + ".json"), "w") as f:
        json.dump({"provenance": made, "ranks": args.ranks, "overrides": args.extra,
                   "runs": records}, f, indent=1)
    with open(os.path.join(ROOT, "bench", "results", args.name + ".md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


if __name__ == "__main__":
    sys.exit(main())

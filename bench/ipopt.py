#!/usr/bin/python3
"""Signorini against IPOPT with MUMPS on problems A-M of the benchmark family: the same
discrete QP (exported with signorini --export-qp), solve times measured in one sitting.

    /usr/bin/python3 bench/ipopt.py [--problems A,B,...] [--repeats 3]

Needs build/bin/signorini_bench_ipopt, which is built where Debian's coinor-libipopt-dev is
installed (scripts/install-deps.sh --bench). For every problem it runs signorini on 1 rank
(the default method) with the export, then, --repeats times each, signorini and IPOPT in
two configurations: its defaults with the QP's constant derivatives declared, and the same
with mehrotra_algorithm=yes (IPOPT's advice for convex QPs). It keeps the fastest run of
each and writes bench/results/ipopt.json ({"provenance", "runs"}) and bench/results/ipopt.md.
Times are Signorini's solve phase (summary.json time.solve) and IPOPT's OptimizeTNLP;
reading, meshing and assembly are outside both.
"""
import argparse
import json
import os
import subprocess
import sys
import tempfile

from preconditioners import ENV, ROOT
from provenance import provenance

PROBLEMS = "ABCDEFGHIJKLM"
IPOPT_CONFIGS = {"defaults": [], "mehrotra": ["mehrotra_algorithm=yes"]}


def signorini(problem, out, export=None):
    cmd = [os.path.join(ROOT, "build", "bin", "signorini"), os.path.join(ROOT, "xml", "paper", problem + ".xml"),
           "--output", out, "--set", "Output/write solution=false"]
    if export:
        cmd += ["--export-qp", export]
    subprocess.run(["mpirun", "-np", "1"] + cmd, env=ENV, stdout=subprocess.DEVNULL, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def ipopt(qp, options):
    cmd = [os.path.join(ROOT, "build", "bin", "signorini_bench_ipopt"), qp, "sb=yes"] + options
    done = subprocess.run(cmd, capture_output=True, text=True)
    if done.returncode not in (0, 1):
        raise RuntimeError(f"{' '.join(cmd)} failed: {done.stderr}")
    return json.loads(done.stdout.strip().splitlines()[-1])


def fastest(runs, seconds):
    return min(runs, key=seconds)


def compare(problem, repeats, workdir):
    qp = os.path.join(workdir, problem, "qp")
    first = signorini(problem, os.path.join(workdir, problem, "run0"), export=qp)
    ours = fastest([first] + [signorini(problem, os.path.join(workdir, problem, f"run{r}"))
                              for r in range(1, repeats)], lambda s: s["time"]["solve"])
    record = {"problem": problem, "n": ours["n"], "m": ours["m"], "signorini": {
        "method": ours["method"], "converged": ours["converged"], "objective": ours["objective"],
        "outer_iterations": ours["outer_iterations"], "newton_steps": ours["newton_steps"],
        "krylov_iterations": ours["krylov_iterations"], "solve_seconds": ours["time"]["solve"]}, "ipopt": {}}
    for name, options in IPOPT_CONFIGS.items():
        record["ipopt"][name] = fastest([ipopt(qp, options) for _ in range(repeats)], lambda r: r["seconds"])
    print(json.dumps(record), flush=True)
    return record


def table(records):
    rows = ["| problem | n | m | Signorini: it | solve [s] | IPOPT: it | solve [s] | IPOPT, Mehrotra: it | "
            "solve [s] | IPOPT's best / Signorini | objective: relative difference |", "|" + "---|" * 11]
    for r in records:
        s, d, m = r["signorini"], r["ipopt"]["defaults"], r["ipopt"]["mehrotra"]
        best = min((c for c in (d, m) if c["converged"]), key=lambda c: c["seconds"], default=None)
        ratio = f"{best['seconds'] / s['solve_seconds']:.1f}" if best else "—"
        difference = (f"{abs(best['objective'] - s['objective']) / abs(s['objective']):.1e}" if best else "—")
        cell = lambda c: (f"{c['iterations']} | {c['seconds']:.3f}" if c["converged"]  # noqa: E731
                          else f"{c['iterations']} (status {c['status']}) | {c['seconds']:.3f}")
        rows.append(f"| {r['problem']} | {r['n']} | {r['m']} | {s['outer_iterations']} | {s['solve_seconds']:.3f} | "
                    f"{cell(d)} | {cell(m)} | {ratio} | {difference} |")
    return "\n".join(rows) + "\n"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--problems", default=",".join(PROBLEMS))
    parser.add_argument("--repeats", type=int, default=3)
    args = parser.parse_args()
    if not os.path.exists(os.path.join(ROOT, "build", "bin", "signorini_bench_ipopt")):
        sys.exit("bench/ipopt.py: build/bin/signorini_bench_ipopt is not built: install coinor-libipopt-dev "
                 "(scripts/install-deps.sh --bench) and rebuild")
    made = provenance(1)  # before the result file is rewritten (git describe --dirty)
    with tempfile.TemporaryDirectory() as workdir:
        records = [compare(p, args.repeats, workdir) for p in args.problems.split(",")]
    results = os.path.join(ROOT, "bench", "results")
    with open(os.path.join(results, "ipopt.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    with open(os.path.join(results, "ipopt.md"), "w") as f:
        f.write(table(records))
    print(table(records))


if __name__ == "__main__":
    main()

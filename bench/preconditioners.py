#!/usr/bin/python3
"""Krylov iterations per Newton step against mu, for each preconditioner option, on
sequences of the benchmark family (issue: Krylov iterations independent of mesh size and mu).

    /usr/bin/python3 bench/preconditioners.py [--ranks N] [--sequence 2d|3d|all] [--max-nx N]
                                              [--max-nx-3d N] [--reuse]

For every (problem, preconditioner) pair it runs build/bin/signorini, reads summary.json and
history.csv, and writes bench/results/preconditioners.json; then bench/results/
preconditioners.png (Krylov iterations per Newton step against mu, one panel per option)
and a Markdown table of the largest and total Krylov counts per solve.
"""
import argparse
import csv
import json
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")
OPTIONS = ["amg of Q", "amg of H"]
SEQUENCES = {
    "2d": [("paper/M", 10), ("paper/G", 20), ("paper/K", 50), ("paper/J", 100), ("family/2d-p1-nx200", 200),
           ("family/2d-p1-nx400", 400), ("family/2d-p1-nx800", 800)],
    "3d": [("paper/E", 10), ("paper/L", 20), ("family/3d-p1-nx40", 40), ("family/3d-p1-nx64", 64)],
}


def run(xml, option, ranks, out, reuse):
    if not (reuse and os.path.exists(os.path.join(out, "summary.json"))):
        run_signorini(xml, option, ranks, out)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "history.csv")) as f:
        history = [{"mu": float(r["mu"]), "krylov": int(r["krylov_iterations"])} for r in csv.DictReader(f)]
    return summary, history


def run_signorini(xml, option, ranks, out):
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"), os.path.join(ROOT, "xml", xml + ".xml"),
           "--output", out, "--set", "Solver/Preconditioner/type=" + option, "--set", "Output/write solution=false"]
    subprocess.run(cmd, env=ENV, stdout=subprocess.DEVNULL, check=False)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--sequence", default="all")
    parser.add_argument("--max-nx", type=int, default=10**9)
    parser.add_argument("--max-nx-3d", type=int, default=10**9)
    parser.add_argument("--reuse", action="store_true", help="reuse the outputs of earlier runs in the workdir")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "preconditioners"))
    args = parser.parse_args()
    names = ["2d", "3d"] if args.sequence == "all" else [args.sequence]
    records = []
    for name in names:
        for xml, nx in SEQUENCES[name]:
            if nx > (args.max_nx_3d if name == "3d" else args.max_nx):
                continue
            for option in OPTIONS:
                out = os.path.join(args.workdir, xml.replace("/", "-") + "-" + option.replace(" ", "-"))
                summary, history = run(xml, option, args.ranks, out, args.reuse)
                records.append({"sequence": name, "problem": xml, "nx": nx, "preconditioner": option,
                                "ranks": args.ranks, "summary": summary, "history": history})
                print(f"{name} nx={nx:4d} {option:9s}: it {summary['outer_iterations']:3d}, "
                      f"Krylov total {summary['krylov_iterations']:5d}, max/step {summary['max_krylov_per_newton']:4d}, "
                      f"solve {summary['time']['solve']:.2f} s, {summary['status']}", flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "preconditioners.json"), "w") as f:
        json.dump(records, f, indent=1)

    rows = ["| sequence | nx | n | preconditioner | it | Krylov total | max Krylov per Newton step | first / last step | solve [s] |",
            "|---|---|---|---|---|---|---|---|---|"]
    for r in records:
        s, h = r["summary"], r["history"]
        rows.append(f"| {r['sequence']} | {r['nx']} | {s['n']} | {r['preconditioner']} | {s['outer_iterations']} | "
                    f"{s['krylov_iterations']} | {s['max_krylov_per_newton']} | {h[0]['krylov']} / {h[-1]['krylov']} | "
                    f"{s['time']['solve']:.2f} |")
    with open(os.path.join(ROOT, "bench", "results", "preconditioners.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    fig, axes = plt.subplots(len(names), len(OPTIONS), figsize=(6 * len(OPTIONS), 4 * len(names)), squeeze=False)
    for i, name in enumerate(names):
        for j, option in enumerate(OPTIONS):
            ax = axes[i][j]
            for r in records:
                if r["sequence"] == name and r["preconditioner"] == option:
                    ax.loglog([h["mu"] for h in r["history"]], [max(h["krylov"], 1) for h in r["history"]], "o-",
                              ms=3, label=f"nx = {r['nx']}")
            ax.invert_xaxis()
            ax.set_xlabel("mu (target of the Newton step)")
            ax.set_ylabel("Krylov iterations per Newton step")
            ax.set_title(f"{name.upper()} P1, {option}")
            ax.legend(fontsize=8)
            ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "bench", "results", "preconditioners.png"), dpi=110)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Strong and weak scaling studies on the inputs of xml/scaling/.

    /usr/bin/python3 scripts/scaling.py [--ranks 1,2] [--studies strong-2d,strong-3d,weak-2d,weak-3d]

Runs build/bin/signorini under mpirun for every rank count (more ranks than cores are run
with --oversubscribe: they check correctness, their times mean nothing), reads each
summary.json and writes bench/results/scaling.json, bench/results/scaling.md (time per
phase, Newton and Krylov counts, parallel efficiency of the solve phase, memory per rank)
and bench/results/scaling.png.
"""
import argparse
import json
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))  # the repository
sys.path.insert(0, os.path.join(ROOT, "bench"))
from provenance import provenance  # noqa: E402
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")


def run(xml, ranks, out, reuse=False):
    if reuse and os.path.exists(os.path.join(out, "summary.json")):
        with open(os.path.join(out, "summary.json")) as f:
            return json.load(f)
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"), os.path.join(ROOT, "xml/scaling", xml),
           "--output", out]
    subprocess.run(cmd, env=ENV, stdout=subprocess.DEVNULL, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--studies", default="strong-2d,strong-3d,weak-2d,weak-3d")
    parser.add_argument("--reuse", action="store_true", help="tabulate the summaries of earlier runs in the workdir")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "scaling"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    if args.reuse:
        made["reused outputs of earlier runs"] = os.path.relpath(args.workdir, ROOT)
    ranks = [int(r) for r in args.ranks.split(",")]
    cores = os.cpu_count() or 1
    records = []
    for study in args.studies.split(","):
        for np in ranks:
            xml = f"{study}.xml" if study.startswith("strong") else f"{study}-np{np}.xml"
            if not os.path.exists(os.path.join(ROOT, "xml/scaling", xml)):
                continue
            s = run(xml, np, os.path.join(args.workdir, f"{study}-np{np}"), args.reuse)
            records.append({"study": study, "ranks": np, "oversubscribed": np > cores, "summary": s})
            print(f"{study} np={np}: n={s['n']} {s['status']} it={s['outer_iterations']} "
                  f"Krylov={s['krylov_iterations']} solve={s['time']['solve']:.2f}s total={s['time']['total']:.2f}s "
                  f"memory/rank={s['memory_mib']['max_rank']:.0f} MiB", flush=True)

    rows = ["| study | ranks | n | status | it | Newton | Krylov | setup [s] | assembly [s] | solve [s] | total [s] "
            "| solve efficiency | per Krylov iteration | memory per rank [MiB] |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in records:
        s = r["summary"]
        base = next(x for x in records if x["study"] == r["study"] and x["ranks"] == ranks[0])["summary"]
        if r["study"].startswith("strong"):
            efficiency = base["time"]["solve"] * ranks[0] / (s["time"]["solve"] * r["ranks"])
        else:
            efficiency = base["time"]["solve"] / s["time"]["solve"]
        r["solve_efficiency"] = efficiency
        # The same with the solve time divided by the Krylov count: the rank count changes the
        # aggregates and smoothers, hence the Krylov count, and this factors it out.
        per = base["time"]["solve"] / base["krylov_iterations"]
        per_r = s["time"]["solve"] / s["krylov_iterations"]
        work = (ranks[0] / r["ranks"]) if r["study"].startswith("strong") else 1.0
        r["per_krylov_efficiency"] = per * work / per_r
        note = " (oversubscribed)" if r["oversubscribed"] else ""
        rows.append(f"| {r['study']} | {r['ranks']}{note} | {s['n']} | {s['status']} | {s['outer_iterations']} | "
                    f"{s['newton_steps']} | {s['krylov_iterations']} | {s['time']['setup']:.2f} | "
                    f"{s['time']['assembly']:.2f} | {s['time']['solve']:.2f} | {s['time']['total']:.2f} | "
                    f"{efficiency:.0%} | {r['per_krylov_efficiency']:.0%} | {s['memory_mib']['max_rank']:.0f} |")
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", "scaling.json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    with open(os.path.join(ROOT, "bench", "results", "scaling.md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    studies = sorted({r["study"] for r in records})
    fig, axes = plt.subplots(1, 2, figsize=(11, 4))
    for study in studies:
        rs = [r for r in records if r["study"] == study]
        x = [r["ranks"] for r in rs]
        axes[0].plot(x, [r["summary"]["time"]["solve"] for r in rs], "o-", label=study)
        axes[1].plot(x, [r["solve_efficiency"] for r in rs], "o-", label=study)
    axes[0].set_ylabel("solve time [s]")
    axes[1].set_ylabel("parallel efficiency of the solve")
    for ax in axes:
        ax.set_xlabel("MPI ranks")
        ax.grid(alpha=0.3)
        ax.legend()
    fig.tight_layout()
    fig.savefig(os.path.join(ROOT, "bench", "results", "scaling.png"), dpi=110)


if __name__ == "__main__":
    main()

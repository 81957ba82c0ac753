#!/usr/bin/python3
"""Krylov iterations per Newton step against mu, for each preconditioner configuration, on
sequences of the benchmark family (doc/benchmark-family.md; goal: Krylov iterations
independent of mesh size and mu).

    /usr/bin/python3 bench/preconditioners.py [--ranks N] [--sequence all|2d,3d,2d-p2,2d-p3,3d-p2]
        [--max-nx N] [--name BASENAME]
        [--max-nx-3d N] [--configs NAME,...] [--full-sequence-configs NAME,...]
        [--forcing all|reduction,adaptive,relative] [--reuse]

For every (problem, configuration, forcing) it runs build/bin/signorini, reads summary.json
and history.csv, and writes into bench/results: NAME.json (every run, with its per-step
history), NAME.md (one row per run, then three ratios per configuration and sequence) and
NAME.png (Krylov iterations per Newton step against mu, one panel per sequence and
configuration); NAME is --name, "preconditioners" by default.

Forcing "reduction" is the solver's default: every Krylov solve reduces the residual of its
starting vector (the projection on earlier solutions) by forcing: eta. Forcing "adaptive" lets the
Krylov tolerance follow mu, so its counts also measure how much
accuracy each step asks for. Forcing "relative" solves every Newton system to the same
relative residual (1e-8): the same linear problem at every mu, which isolates the
preconditioner's dependence on mu and on the mesh.
"""
import argparse
import csv
import json
import os
import subprocess

from preconditioners_table import approximate, first_last, ratios
from provenance import provenance

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")
P = "Solver/Preconditioner/"
A = {P + "hierarchy": "algebraic"}  # MueLu's smoothed aggregation alone
UNFILTERED = {P + "amg of H: weight cap": "0"}  # no filtering: the AMG sees H itself
LAGGED = {**UNFILTERED, P + "amg of H: rebuild tolerance": "0.9"}  # rebuilt only when constraints switch
CONFIGS = {
    # The default configuration: geometric levels on the box meshes above MueLu, AMG of
    # Q + A^T D' A with D' capped at 10 times the constraint stiffness (filtering), rebuilt at
    # every Newton step (Galerkin update, warm-started eigenvalue estimates), multiplicative
    # contact correction; each Newton system starts from the projection on the two previous
    # solutions, corrected on the contact DOFs.
    "default": {},
    # The AMG built for H itself, without the weight cap.
    "unfiltered": UNFILTERED,
    # The AMG of H itself, rebuilt only when constraints switch between free and firmly active.
    "lagged rebuild": LAGGED,
    # The default with the projected start not corrected on the contact DOFs.
    "without contact-corrected start": {"Solver/Krylov/initial guess: contact correction": "false"},
    # The default with every Newton system started from zero (the corrector from the
    # predictor's step).
    "from zero": {"Solver/Krylov/initial guess: previous solutions": "0",
                  "Solver/Krylov/initial guess: contact correction": "false"},
    # The default with MueLu's smoothed aggregation alone instead of the geometric levels,
    # rebuilt at every Newton step like them.
    "algebraic": {**A, P + "amg of H: rebuild tolerance": "0"},
    # MueLu's smoothed aggregation alone as Gmsh meshes get it: rebuilt only when
    # constraints switch (the default rebuild tolerance without geometric levels).
    "algebraic default": A,
    # MueLu's smoothed aggregation with the AMG built for Q alone (no contact weights), set up once.
    "algebraic amg of Q": {**A, P + "type": "amg of Q"},
    # The default without the primal-dual method's active-set finish: the barrier steps go on
    # until the KKT tolerance is met.
    "without active-set finish": {"Solver/primal-dual: active-set finish": "false"},
}
# Configurations that change the starting vectors or the method's last step, not the
# preconditioner: not run with the fixed forcing "relative", which measures the preconditioner
# alone (and a relative residual to reach from another start is not the same linear problem).
# Every configuration runs with the solver's defaults for what it does not set.
NOT_THE_PRECONDITIONER = {"without contact-corrected start", "from zero", "without active-set finish"}
FORCING = {
    "reduction": {},  # the default: each solve reduces its start's residual by forcing: eta
    "adaptive": {"Solver/forcing: type": "adaptive"},
    "relative": {"Solver/forcing: type": "relative", "Solver/forcing: eta": "1e-8"},
}
SEQUENCES = {
    "2d": [("paper/M", 10), ("paper/G", 20), ("paper/K", 50), ("paper/J", 100), ("family/2d-p1-nx200", 200),
           ("family/2d-p1-nx400", 400), ("family/2d-p1-nx800", 800)],
    "3d": [("paper/E", 10), ("paper/L", 20), ("family/3d-p1-nx40", 40), ("family/3d-p1-nx64", 64)],
    "2d-p2": [("paper/H", 20), ("family/2d-p2-nx200", 200)],
    "2d-p3": [("paper/I", 20), ("family/2d-p3-nx100", 100)],
    "3d-p2": [("paper/C", 4), ("paper/D", 8), ("paper/F", 10), ("family/3d-p2-nx32", 32)],
}


def run(xml, settings, ranks, out, reuse):
    if not (reuse and os.path.exists(os.path.join(out, "summary.json"))):
        # a family or paper member by name (paper/M), or any input by its path from the root
        path = os.path.join(ROOT, xml) if xml.endswith(".xml") else os.path.join(ROOT, "xml", xml + ".xml")
        cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"), path, "--output", out,
               "--set", "Output/write solution=false"]
        for key, value in settings.items():
            cmd += ["--set", f"{key}={value}"]
        subprocess.run(cmd, env=ENV, stdout=subprocess.DEVNULL, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(os.path.join(out, "history.csv")) as f:
        history = [{"mu": float(r["mu"]), "krylov": int(r["krylov_iterations"])} for r in csv.DictReader(f)]
    return summary, history


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--sequence", default="all")
    parser.add_argument("--max-nx", type=int, default=10**9)
    parser.add_argument("--max-nx-3d", type=int, default=10**9)
    parser.add_argument("--configs", default=",".join(CONFIGS), help="comma-separated names of CONFIGS")
    parser.add_argument("--full-sequence-configs", default="",
                        help="configurations run on every member; the others stop at --max-nx / --max-nx-3d")
    parser.add_argument("--forcing", default="all", help="comma-separated names of FORCING, or all")
    parser.add_argument("--reuse", action="store_true", help="reuse the outputs of earlier runs in the workdir")
    parser.add_argument("--name", default="preconditioners", help="basename of the result files")
    parser.add_argument("--output", default=os.path.join(ROOT, "bench", "results"), help="where results go")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "preconditioners"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    if args.reuse:
        made["reused outputs of earlier runs"] = os.path.relpath(args.workdir, ROOT)
    names = ["2d", "3d"] if args.sequence == "all" else args.sequence.split(",")
    for name in names:
        if name not in SEQUENCES:
            parser.error(f"unknown sequence {name!r}; known: {', '.join(SEQUENCES)}")
    full = [c for c in args.full_sequence_configs.split(",") if c]
    configs = [c for c in args.configs.split(",") if c]
    configs += [c for c in full if c not in configs]
    for c in configs:
        if c not in CONFIGS:
            parser.error(f"unknown configuration {c!r}; known: {', '.join(CONFIGS)}")
    forcings = list(FORCING) if args.forcing == "all" else args.forcing.split(",")
    for f in forcings:
        if f not in FORCING:
            parser.error(f"unknown forcing {f!r}; known: {', '.join(FORCING)}")
    records = []
    for name in names:
        for xml, nx in SEQUENCES[name]:
            limited = nx > (args.max_nx_3d if name.startswith("3d") else args.max_nx)
            for config in configs:
                if limited and config not in full:
                    continue
                for forcing in forcings:
                    if forcing not in ("reduction", "adaptive") and config in NOT_THE_PRECONDITIONER:
                        continue
                    out = os.path.join(args.workdir, "-".join([xml.replace("/", "-"), config.replace(" ", "-"), forcing]))
                    summary, history = run(xml, {**CONFIGS[config], **FORCING[forcing]}, args.ranks, out, args.reuse)
                    records.append({"sequence": name, "problem": xml, "nx": nx, "config": config, "forcing": forcing,
                                    "ranks": args.ranks, "summary": summary, "history": history})
                    print(f"{name} nx={nx:4d} {config:33s} {forcing:8s}: it {summary['outer_iterations']:3d}, "
                          f"Krylov total {summary['krylov_iterations']:5d}, "
                          f"max/system {summary['max_krylov_per_newton']:4d}, setups {summary['preconditioner_setups']}, "
                          f"solve {summary['time']['solve']:.2f} s, {summary['status']}", flush=True)
    os.makedirs(args.output, exist_ok=True)
    with open(os.path.join(args.output, args.name + ".json"), "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)

    rows = ["| sequence | nx | n | configuration | forcing | it | Krylov total | max per Newton system | "
            "first / last Newton step | AMG setups | solve [s] |", "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in records:
        s = r["summary"]
        rows.append(f"| {r['sequence']} | {r['nx']} | {s['n']} | {r['config']} | {r['forcing']} | {s['outer_iterations']} | "
                    f"{s['krylov_iterations']} | {s['max_krylov_per_newton']} | {first_last(r)} | "
                    f"{s['preconditioner_setups']} | {s['time']['solve']:.2f} |")
    rows += ["", "Ratios over each sequence (targets: 1.5, 2, 1.5), without the members whose preconditioner is "
             "an exact solve (one CG iteration per system); a Newton step of the primal-dual method solves two "
             "systems (predictor and corrector); the maximum and the steps are the barrier steps', the totals "
             "include the active-set finish.", "",
             "| sequence | nx range | configuration | forcing | max per system: max / min | total: max / min | "
             "last / first step (worst) |", "|---|---|---|---|---|---|---|"]
    for name in names:
        for config in configs:
            for forcing in forcings:
                if forcing not in ("reduction", "adaptive") and config in NOT_THE_PRECONDITIONER:
                    continue
                group = [r for r in records if r["sequence"] == name and r["config"] == config and r["forcing"] == forcing]
                # Over the members every configuration ran, then over all of this one's.
                common = [r for r in group if r["nx"] <= (args.max_nx_3d if name.startswith("3d") else args.max_nx)]
                for members in ([common, group] if len(common) < len(group) else [group]):
                    if len(members) < 2:
                        continue
                    members = approximate(members)
                    a, b, c = ratios(members)
                    rows.append(f"| {name} | {members[0]['nx']}–{members[-1]['nx']} | {config} | {forcing} | "
                                f"{a:.2f} | {b:.2f} | {c:.2f} |")
    with open(os.path.join(args.output, args.name + ".md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))

    cols = len(configs)
    fig, axes = plt.subplots(len(names), cols, figsize=(4.5 * cols, 3.8 * len(names)), squeeze=False)
    for i, name in enumerate(names):
        for j, config in enumerate(configs):
            ax = axes[i][j]
            for r in records:
                if r["sequence"] == name and r["config"] == config:
                    style = {"reduction": "o-", "adaptive": "^:"}.get(r["forcing"], "s--")
                    steps = [h for h in r["history"] if h["mu"] > 0]  # not the active-set finish (mu 0)
                    ax.loglog([h["mu"] for h in steps], [max(h["krylov"], 1) for h in steps], style,
                              ms=3, label=f"nx = {r['nx']}, {r['forcing']}")
            ax.invert_xaxis()
            ax.set_xlabel("mu (target of the Newton step)")
            ax.set_ylabel("Krylov iterations per Newton step")
            ax.set_title(f"{name.upper()}{'' if '-p' in name else ' P1'}, {config}", fontsize=9)
            ax.legend(fontsize=6)
            ax.grid(alpha=0.3)
    fig.tight_layout()
    fig.savefig(os.path.join(args.output, args.name + ".png"), dpi=100)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The paper's Figures 2 and 3 for our runs of the benchmark family.

    /usr/bin/python3 scripts/figures.py [--ranks N] [--outdir doc/figures]

Figure 2: inner (Newton) iterations per main iteration of the primal method (Algorithm
3.1) on problems J, K, G and M. Figure 3: the deformed configurations of M, G, K and J
(displacement magnified) with the active contact nodes marked. Uses Debian's
python3-matplotlib and python3-meshio (hence /usr/bin/python3).
"""
import argparse
import glob
import json
import os
import subprocess

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")


def run(problem, method, ranks, out):
    subprocess.run(["mpirun", "-np", str(ranks), os.path.join(ROOT, "build/bin/signorini"),
                    os.path.join(ROOT, "xml/paper", problem + ".xml"), "--output", out,
                    "--set", "Solver/method=" + method], env=ENV, stdout=subprocess.DEVNULL, check=True)
    with open(os.path.join(out, "summary.json")) as f:
        return json.load(f)


def figure2(ranks, work, outdir):
    fig, ax = plt.subplots(figsize=(6, 4))
    for problem, marker in zip("JKGM", "osd^"):
        s = run(problem, "primal", ranks, os.path.join(work, problem + "-primal"))
        inner = s["inner_iterations"]
        ax.plot(range(1, len(inner) + 1), inner, marker=marker, label=f"{problem} (n = {s['n']})")
    ax.set_xlabel("main iteration")
    ax.set_ylabel("inner Newton iterations\n(after the predictor step)")
    ax.set_title("Primal method: Newton steps per barrier subproblem")
    ax.legend()
    ax.grid(alpha=0.3)
    fig.tight_layout()
    path = os.path.join(outdir, "figure2.png")
    fig.savefig(path, dpi=120)
    return path


def figure3(ranks, work, outdir):
    fig, axes = plt.subplots(1, 4, figsize=(16, 4.8))
    for ax, problem in zip(axes, "MGKJ"):
        out = os.path.join(work, problem + "-pd")
        s = run(problem, "primal-dual", ranks, out)
        pieces = sorted(glob.glob(os.path.join(out, "solution_*.vtu")))
        umax = max(np.abs(meshio.read(p).point_data["displacement"]).max() for p in pieces)
        scale = 0.15 / umax
        for piece in pieces:
            mesh = meshio.read(piece)
            x = mesh.points[:, :2] + scale * mesh.point_data["displacement"][:, :2]
            triangles = np.vstack([c.data[:, :3] for c in mesh.cells])
            ax.triplot(x[:, 0], x[:, 1], triangles, lw=0.3, color="0.4")
            active = mesh.point_data["active"].reshape(-1) > 0.5
            ax.plot(x[active, 0], x[active, 1], "o", color="crimson", ms=3)
        ax.axhline(0.0, color="k", lw=1.5)
        ax.set_aspect("equal")
        ax.set_title(f"{problem}: nx = {s['nx']}, {s['active_constraints']} active nodes, u x{scale:.0f}",
                     fontsize=10)
        ax.set_xlim(-0.05, 1.05)
        ax.axis("off")
    fig.tight_layout()
    path = os.path.join(outdir, "figure3.png")
    fig.savefig(path, dpi=120)
    return path


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--ranks", type=int, default=1)
    parser.add_argument("--outdir", default=os.path.join(ROOT, "doc", "figures"))
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "figures"))
    args = parser.parse_args()
    os.makedirs(args.outdir, exist_ok=True)
    print(figure2(args.ranks, args.workdir, args.outdir))
    print(figure3(args.ranks, args.workdir, args.outdir))


if __name__ == "__main__":
    main()

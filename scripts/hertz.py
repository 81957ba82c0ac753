#!/usr/bin/env python3
"""Hertz validation: refinement studies of a rigid cylinder (2D) and sphere (3D) pressed into
an elastic block, of a rigid sphere pressed into a deep block meshed by Gmsh, of an elastic
half-disk and half-ball meshed by Gmsh pressed onto a rigid plane, and of a rigid flat punch
(examples/hertz/); and of an elastic half-disk pressed onto an elastic block meshed apart
(examples/bodies/disk-on-block-2d, mortar contact), of equal moduli and with a disk 100 times
stiffer than the block, and of an elastic half-ball pressed onto an elastic block meshed apart
(examples/bodies/ball-on-block-3d), of equal moduli and with a block 100 times stiffer. For each run, the computed contact half-width or radius, peak pressure and
the L2 error of the pressure on the contact boundary are compared with Hertz' solution for the
computed total force, and the nodal pressure field a user sees (solution.pvtu) is checked for
tension (its most negative value), for pressure off the active nodes and for whether the
node of the peak is active; on the deep block, the force against the force-approach law
P = (4/3) E* sqrt(R) delta^(3/2) for several approaches delta. Writes
bench/results/hertz.{json,md,png} and hertz-profiles.png.

    scripts/hertz.py [--build build] [--np 2] [--quick] [--only EXAMPLE ...] [--formulation F]
                     [--recovery R]

--only reruns the named studies and keeps the other rows of the existing JSON; --formulation
("nodal", "weighted gap" or "dual mortar") and --recovery (an Output/contact pressure choice) rerun only the
rows of that contact formulation or pressure recovery.
"""
import argparse
import base64
import glob
import json
import re
import math
import os
import subprocess
import sys
import tempfile

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# mpirun as root (containers, CI), ranks beyond the cores, no single-copy shared memory.
ENV = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
           OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_btl_vader_single_copy_mechanism="none")

# (example, dimension, {degree: meshes}) per study: box cells (the same nodes per row across
# degrees), or a Gmsh geometry's mesh size factor.
STUDIES = {
    "cylinder-2d": (2, {1: [(80, 40), (160, 80), (320, 160), (640, 320)],
                        2: [(40, 20), (80, 40), (160, 80), (320, 160)],
                        3: [(40, 20), (80, 40), (160, 80)]}),
    "sphere-3d": (3, {1: [(16, 16, 8), (32, 32, 16), (48, 48, 24), (64, 64, 32)],
                      2: [(8, 8, 4), (16, 16, 8), (24, 24, 12), (32, 32, 16)],
                      3: [(8, 8, 4), (16, 16, 8), (24, 24, 12)]}),
}
STUDIES["half-disk-2d"] = (2, {1: [2.0, 1.0, 0.5, 0.25], 2: [2.0, 1.0, 0.5, 0.25], 3: [2.0, 1.0, 0.5]})
STUDIES["half-ball-3d"] = (3, {1: [2.0, 1.4, 1.0, 0.7], 2: [2.0, 1.4, 1.0]})
STUDIES["deep-block-3d"] = (3, {1: [1.4, 1.0, 0.7], 2: [2.0, 1.4]})
STUDIES["punch-2d"] = (2, {1: [(80, 40), (160, 80), (320, 160)], 2: [(40, 20), (80, 40), (160, 80)]})
STUDIES["disk-on-block-2d"] = (2, {1: [1.0, 0.5, 0.25, 0.125]})
STUDIES["stiff-disk-on-block-2d"] = (2, {1: [1.0, 0.5, 0.25, 0.125]})
STUDIES["ball-on-block-3d"] = (3, {1: [1.0, 0.7, 0.5, 0.35]})
STUDIES["ball-on-stiff-block-3d"] = (3, {1: [1.0, 0.7, 0.5, 0.35]})
# Studies whose input is not examples/hertz/<name>.xml: the input (under examples/) and settings.
INPUT = {"disk-on-block-2d": ("bodies/disk-on-block-2d", []),
         "stiff-disk-on-block-2d": ("bodies/disk-on-block-2d", ["Problem/Bodies/disk/material: young's modulus=100"]),
         "ball-on-block-3d": ("bodies/ball-on-block-3d", []),
         "ball-on-stiff-block-3d": ("bodies/ball-on-block-3d", ["Problem/material: young's modulus=100"])}
TWO_BODIES = set(INPUT)  # their contact is mortar, whose constraints are dual mortar ones
PUNCH_HALF_WIDTH = 0.25
GMSH_CONTACT_SIZE = {"half-disk-2d": 0.004, "half-ball-3d": 0.01, "deep-block-3d": 0.002, "disk-on-block-2d": 0.005,
                     "stiff-disk-on-block-2d": 0.005, "ball-on-block-3d": 0.02,
                     "ball-on-stiff-block-3d": 0.02}  # the .geo's mesh size at the contact, factor 1
QUICK = {"cylinder-2d": {1: 2, 2: 2, 3: 1}, "sphere-3d": {1: 2, 2: 2, 3: 1}, "half-disk-2d": {1: 2, 2: 2, 3: 1},
         "half-ball-3d": {1: 2, 2: 1}, "deep-block-3d": {1: 1, 2: 1}, "punch-2d": {1: 2, 2: 2},
         "disk-on-block-2d": {1: 2}, "stiff-disk-on-block-2d": {1: 2}, "ball-on-block-3d": {1: 2},
         "ball-on-stiff-block-3d": {1: 2}}
# The force-approach law on the deep block: (degree, mesh size factor) and the approaches.
FORCE_APPROACH = (2, 1.4, [0.0002, 0.0004, 0.0008])
# (Contact/formulation, Output/contact pressure): the nodal constraints with each pressure
# recovery, and weighted gaps and the dual mortar basis, whose multipliers are the pressure.
# The patch average of the lumped pressure rests on HRZ weights, which suit P1 only.
VARIANTS = [("nodal", "consistent"), ("nodal", "lumped"), ("nodal", "patch"), ("weighted gap", "auto"),
            ("dual mortar", "auto")]
P1_ONLY = {("nodal", "patch")}


def variants(example, degree):
    if example in TWO_BODIES:
        return [("dual mortar", "auto")]
    return [v for v in VARIANTS if degree == 1 or v not in P1_ONLY]


def label(formulation, recovery):
    return formulation if formulation != "nodal" else "nodal, " + recovery


def hertz(dim, force, radius, e_star):
    """Contact half-width/radius a and peak pressure p0 for the total force."""
    if dim == 2:
        a = math.sqrt(4.0 * force * radius / (math.pi * e_star))
        return a, 2.0 * force / (math.pi * a)
    a = (3.0 * force * radius / (4.0 * e_star)) ** (1.0 / 3.0)
    return a, 3.0 * force / (2.0 * math.pi * a * a)


def mesh_setting(mesh):
    if isinstance(mesh, float):
        return "Problem/mesh: size factor=%g" % mesh
    return "Problem/mesh: cells={%s}" % ", ".join(map(str, mesh))


def mesh_label(mesh):
    return "size x%g" % mesh if isinstance(mesh, float) else "x".join(map(str, mesh))


def spacing(example, dim, mesh):
    """Element size at the contact."""
    if isinstance(mesh, float):
        return GMSH_CONTACT_SIZE[example] * mesh
    return 1.0 / mesh[0] * (2.0 if dim == 2 else 1.0)


def run(args, example, degree, cells, formulation, recovery, directory, settings=()):
    relative, extra = INPUT.get(example, ("hertz/" + example, []))
    xml = os.path.join(ROOT, "examples", relative + ".xml")
    cmd = ["mpirun", "-np", str(args.np), os.path.join(args.build, "bin", "signorini"), xml,
           "--set", "Output/write contact samples=true",
           "--set", mesh_setting(cells),
           "--set", "Problem/element: degree=%d" % degree,
           "--set", "Output/write history=false",
           "--set", "Problem/Contact/formulation=" + formulation,
           "--set", "Output/contact pressure=" + recovery, "--output", directory]
    for setting in list(extra) + list(settings):
        cmd += ["--set", setting]
    subprocess.run(cmd, check=True, stdout=subprocess.DEVNULL, env=ENV)
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    samples = np.genfromtxt(os.path.join(directory, "contact.csv"), delimiter=",", names=True)
    summary["nodal_field"] = nodal_field(directory)
    return summary, samples


def vtu_arrays(path, names):
    """The named point arrays of a .vtu in VTK's inline binary format (base64 of a UInt64 byte
    count and little-endian Float64 values), as Signorini writes them."""
    with open(path) as f:
        text = f.read()
    arrays = {}
    for name in names:
        match = re.search(r'<DataArray type="Float64" Name="%s"[^>]*format="binary">\s*([A-Za-z0-9+/=]+)' % name, text)
        raw = base64.b64decode(match.group(1))
        count = int(np.frombuffer(raw[:8], "<u8")[0])
        arrays[name] = np.frombuffer(raw[8:8 + count], "<f8")
    return arrays


def nodal_field(directory):
    """What the nodal pressure shown in ParaView says: its most negative value and its largest
    value off the active nodes, both relative to its peak, and whether the peak's node is active."""
    pressure, active = [], []
    for path in sorted(glob.glob(os.path.join(directory, "solution_*.vtu"))):
        arrays = vtu_arrays(path, ["contact pressure", "active"])
        pressure.append(arrays["contact pressure"])
        active.append(arrays["active"])
    pressure, active = np.concatenate(pressure), np.concatenate(active)
    peak = pressure.max()
    off = pressure[active == 0]
    return {"tension": float(pressure.min() / peak), "off_active": float(off.max() / peak) if off.size else 0.0,
            "peak_node_active": bool(active[np.argmax(pressure)] != 0)}


def measure_punch(summary, samples, center):
    """The flat punch against the half-space solution p = P / (pi sqrt(b^2 - x^2)) for the
    computed force: contact half-width against b, the pressure at the centre against
    P / (pi b), and the L2 error over the inner 80% of the punch (the edges are singular)."""
    contact = summary["contact"]
    force, b = contact["normal_force"], PUNCH_HALF_WIDTH
    x = samples["x"] - center[0]
    w, p = samples["weight"], samples["pressure"]
    inner = np.abs(x) < 0.8 * b
    exact = force / (math.pi * np.sqrt(np.maximum(b * b - x * x, 1e-300)))
    p_center, p_exact = p[np.argmin(np.abs(x))], force / (math.pi * b)
    return {"force": force, "a": contact["length"] / 2.0, "a_hertz": b, "a_error": contact["length"] / 2.0 / b - 1.0,
            "p0": p_center, "p0_hertz": p_exact, "p0_error": p_center / p_exact - 1.0,
            "l2_error": math.sqrt(np.sum(w[inner] * (p[inner] - exact[inner]) ** 2) / np.sum(w[inner] * exact[inner] ** 2))}


def measure(dim, summary, samples, center, radius, e_star):
    contact = summary["contact"]
    force = contact["normal_force"]
    a, p0 = hertz(dim, force, radius, e_star)
    r = np.abs(samples["x"] - center[0]) if dim == 2 else np.hypot(samples["x"] - center[0], samples["y"] - center[1])
    exact = p0 * np.sqrt(np.maximum(0.0, 1.0 - (r / a) ** 2))
    w, p = samples["weight"], samples["pressure"]
    a_h = contact["length"] / 2.0 if dim == 2 else math.sqrt(contact["area"] / math.pi)
    return {"force": force, "a": a_h, "a_hertz": a, "a_error": a_h / a - 1.0,
            "p0": contact["peak_pressure"], "p0_hertz": p0, "p0_error": contact["peak_pressure"] / p0 - 1.0,
            "l2_error": math.sqrt(np.sum(w * (p - exact) ** 2) / np.sum(w * exact ** 2))}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", default=os.path.join(ROOT, "build"))
    parser.add_argument("--np", type=int, default=2)
    parser.add_argument("--quick", action="store_true", help="the two coarsest meshes of each study only")
    parser.add_argument("--only", nargs="+", choices=list(STUDIES), help="rerun these studies only")
    parser.add_argument("--formulation", choices=sorted({f for f, _ in VARIANTS}),
                        help="rerun the rows of this contact formulation only")
    parser.add_argument("--recovery", choices=sorted({r for _, r in VARIANTS}),
                        help="rerun the rows of this pressure recovery only")
    parser.add_argument("--out", default=os.path.join(ROOT, "bench", "results", "hertz"))
    args = parser.parse_args()
    results = {"provenance": {}, "rows": [], "profiles": [], "force_approach": None}
    if args.only or args.formulation or args.recovery:
        with open(args.out + ".json") as f:
            results = json.load(f)
        rerun = lambda r: (not args.only or r["example"] in args.only) and (
            not args.formulation or r["formulation"] == args.formulation) and (
            not args.recovery or r["recovery"] == args.recovery)
        results["rows"] = [r for r in results["rows"] if not rerun(r)]
        results["profiles"] = [p for p in results["profiles"] if not rerun(p)]
    with tempfile.TemporaryDirectory() as tmp:
        for example in args.only or STUDIES:
            rows, profiles, summary = run_study(args, example, tmp)
            results["rows"] += rows
            results["profiles"] += profiles
            key = example + "".join(": " + part for part in (args.formulation, args.recovery) if part)
            if key == example:  # every row of the study is new: so is its only provenance
                results["provenance"] = {k: v for k, v in results["provenance"].items()
                                         if k != example and not k.startswith(example + ": ")}
            results["provenance"][key] = provenance(args, summary)
            if example == "deep-block-3d" and args.formulation in (None, "nodal") and args.recovery in (None, "auto"):
                results["force_approach"] = force_approach(args, tmp)
    order = list(STUDIES)
    results["rows"].sort(key=lambda r: (order.index(r["example"]), r["degree"], -r["h"],
                                        VARIANTS.index((r["formulation"], r["recovery"]))))
    add_orders(results["rows"])
    results["profiles"] = [thin(p) for p in results["profiles"]]
    with open(args.out + ".json", "w") as f:
        json.dump(results, f, indent=1)
    write_table(results, args.out + ".md")
    plot(results["rows"], args.out + ".png")
    plot_profiles(results["profiles"], args.out + "-profiles.png")


E_STAR = 1.0 / (1.0 - 0.3 ** 2)
# Of two elastic bodies: 1 / E* = (1 - nu^2) (1 / E_1 + 1 / E_2), moduli 1 and 1 or 1 and 100.
E_STARS = {"disk-on-block-2d": 1.0 / ((1.0 - 0.3 ** 2) * 2.0), "stiff-disk-on-block-2d": 1.0 / ((1.0 - 0.3 ** 2) * 1.01),
           "ball-on-block-3d": 1.0 / ((1.0 - 0.3 ** 2) * 2.0), "ball-on-stiff-block-3d": 1.0 / ((1.0 - 0.3 ** 2) * 1.01)}
GEOMETRY = {"cylinder-2d": ((1.0, 0.0), 1.0), "sphere-3d": ((0.5, 0.5), 1.0), "deep-block-3d": ((0.0, 0.0), 1.0),
            "half-disk-2d": ((0.0, 0.0), 1.0), "half-ball-3d": ((0.0, 0.0), 1.0), "punch-2d": ((1.0, 0.0), None),
            "disk-on-block-2d": ((0.0, 0.0), 1.0), "stiff-disk-on-block-2d": ((0.0, 0.0), 1.0),
            "ball-on-block-3d": ((0.0, 0.0), 1.0), "ball-on-stiff-block-3d": ((0.0, 0.0), 1.0)}


def run_study(args, example, tmp):
    """Every mesh, degree and constraint variant of one example: table rows, and the pressure
    profiles of the finest mesh per degree."""
    dim, plan = STUDIES[example]
    center, radius = GEOMETRY[example]
    rows, profiles = [], {}
    for degree, meshes in plan.items():
        for cells in meshes[:QUICK[example][degree]] if args.quick else meshes:
            for formulation, recovery in variants(example, degree):
                if (args.formulation and formulation != args.formulation) or (
                        args.recovery and recovery != args.recovery):
                    continue
                summary, samples = run(args, example, degree, cells, formulation, recovery, tmp)
                row = {"example": example, "d": dim, "degree": degree, "mesh": mesh_label(cells),
                       "h": spacing(example, dim, cells), "n": summary["n"],
                       "m": summary["m"], "formulation": formulation, "recovery": recovery,
                       "converged": summary["converged"], "seconds": summary["time"]["total"],
                       "krylov": summary["krylov_iterations"], **summary["nodal_field"]}
                if example == "punch-2d":
                    row.update(measure_punch(summary, samples, center))
                else:
                    row.update(measure(dim, summary, samples, center, radius, E_STARS.get(example, E_STAR)))
                    r, p = profile(dim, samples, center, row["a_hertz"], row["p0_hertz"])
                    profiles[(degree, formulation, recovery)] = {
                        "example": example, "degree": degree, "formulation": formulation, "recovery": recovery,
                        "r": r, "p": p}
                rows.append(row)
                print("%-13s P%d %-14s %-24s a %+6.2f%%  p0 %+6.2f%%  L2 %.4f  min p %+5.1f%%  off %4.1f%%  CG %d" % (
                    example, degree, mesh_label(cells), label(formulation, recovery), 100 * row["a_error"],
                    100 * row["p0_error"], row["l2_error"], 100 * row["tension"], 100 * row["off_active"],
                    row["krylov"]), flush=True)
    return rows, list(profiles.values()), summary


def force_approach(args, tmp):
    """The deep block at several approaches delta (the top face's displacement; the sphere
    touches the block at delta = 0): the force against P = (4/3) E* sqrt(R) delta^(3/2) and
    the observed exponent of P(delta) between consecutive approaches."""
    degree, factor, approaches = FORCE_APPROACH
    rows = []
    for delta in approaches:
        summary, _ = run(args, "deep-block-3d", degree, factor, "nodal", "auto", tmp,
                         ["Problem/Dirichlet/top/displacement: z=%g" % -delta])
        force = summary["contact"]["normal_force"]
        law = 4.0 / 3.0 * E_STAR * math.sqrt(GEOMETRY["deep-block-3d"][1]) * delta ** 1.5
        rows.append({"delta": delta, "force": force, "force_law": law, "error": force / law - 1.0,
                     "exponent": None if not rows else math.log(force / rows[-1]["force"]) / math.log(
                         delta / rows[-1]["delta"])})
        print("deep-block-3d P%d size x%g delta %g: P / P_law - 1 = %+.2f%%" % (degree, factor, delta,
                                                                              100 * rows[-1]["error"]), flush=True)
    return {"degree": degree, "mesh": mesh_label(factor), "n": summary["n"], "rows": rows}


def provenance(args, summary):
    """Where and with what the results were made."""
    import datetime
    import platform
    commit = subprocess.run(["git", "describe", "--always", "--dirty"], cwd=ROOT, capture_output=True,
                            text=True).stdout.strip()
    command = "scripts/hertz.py" + (" --quick" if args.quick else "") + (
        " --only " + " ".join(args.only) if args.only else "") + (
        " --formulation '%s'" % args.formulation if args.formulation else "") + (
        " --recovery " + args.recovery if args.recovery else "")
    return {"command": command, "commit": commit or "unknown",
            "date": datetime.datetime.now(datetime.timezone.utc).isoformat(timespec="seconds"),
            "host": platform.node(), "cores": os.cpu_count(), "ranks": args.np,
            "build": summary.get("signorini", {})}


def profile(dim, samples, center, a, p0):
    """Samples of the finest run as (r / a, p / p0), r the distance to the axis."""
    r = np.abs(samples["x"] - center[0]) if dim == 2 else np.hypot(samples["x"] - center[0], samples["y"] - center[1])
    keep = r < 1.5 * a
    return (r[keep] / a).tolist(), (samples["pressure"][keep] / p0).tolist()


def thin(profile, points=1500):
    """A profile with at most `points` samples (every k-th, in the order sampled), each value
    to 5 significant digits: enough for the plot, small enough to keep in the repository."""
    stride = max(1, -(-len(profile["r"]) // points))
    return {**profile, "r": [float("%.5g" % x) for x in profile["r"][::stride]],
            "p": [float("%.5g" % x) for x in profile["p"][::stride]]}


def add_orders(rows):
    """Observed order of the L2 error between consecutive meshes of a series."""
    series = {}
    for r in rows:
        series.setdefault((r["example"], r["degree"], r["formulation"], r["recovery"]), []).append(r)
    for runs in series.values():
        runs[0]["l2_order"] = None
        for coarse, fine in zip(runs, runs[1:]):
            fine["l2_order"] = math.log(coarse["l2_error"] / fine["l2_error"]) / math.log(coarse["h"] / fine["h"])


def write_table(results, path):
    lines = ["| example | P | mesh | n | constraints | a / a_Hertz - 1 | p0 / p0_Hertz - 1 | L2 error of p | order "
             "| nodal p: min / peak | off the active nodes: max / peak | peak's node active | CG |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in results["rows"]:
        order = "" if r["l2_order"] is None else "%.2f" % r["l2_order"]
        nodal = ("%+.1f%% | %.1f%% | %s | %d" % (100 * r["tension"], 100 * r["off_active"],
                                                "yes" if r["peak_node_active"] else "no", r["krylov"])
                 if "tension" in r else " | | | ")  # rows of a run that did not check the nodal field
        lines.append("| %s | %d | %s | %d | %s | %+.2f%% | %+.2f%% | %.4f | %s | %s |" % (
            r["example"], r["degree"], r["mesh"], r["n"], label(r["formulation"], r["recovery"]),
            100 * r["a_error"], 100 * r["p0_error"], r["l2_error"], order, nodal))
    fa = results.get("force_approach")
    if fa:
        lines += ["", "Force-approach law on deep-block-3d, P%d, mesh %s (n = %d):" % (fa["degree"], fa["mesh"], fa["n"]),
                  "", "| approach delta | P | (4/3) E* sqrt(R) delta^(3/2) | P / law - 1 | exponent |",
                  "|---|---|---|---|---|"]
        for r in fa["rows"]:
            exponent = "" if r["exponent"] is None else "%.3f" % r["exponent"]
            lines.append("| %g | %.5g | %.5g | %+.2f%% | %s |" % (r["delta"], r["force"], r["force_law"],
                                                                   100 * r["error"], exponent))
    with open(path, "w") as f:
        f.write("\n".join(lines) + "\n")


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, len(STUDIES), figsize=(5 * len(STUDIES), 4))
    for ax, example in zip(axes, STUDIES):
        for degree in sorted({r["degree"] for r in rows if r["example"] == example}):
            for (formulation, recovery), style in zip(VARIANTS, ["-o", "--s", "-.d", ":^", "-v"]):
                sel = [r for r in rows if r["example"] == example and r["degree"] == degree
                       and r["formulation"] == formulation and r["recovery"] == recovery]
                if sel:
                    ax.loglog([r["h"] / r["degree"] for r in sel], [r["l2_error"] for r in sel], style,
                              label="P%d %s" % (degree, label(formulation, recovery)))
        ax.set_title(example)
        ax.set_xlabel("node spacing h / k")
        ax.set_ylabel("relative L2 error of the contact pressure")
        ax.legend(fontsize=7)
        ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def plot_profiles(profiles, path):
    """Computed pressure against Hertz' p0 sqrt(1 - r^2/a^2) on the finest meshes, P2 where
    the study has it."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    hertz = [example for example in STUDIES if any(p["example"] == example for p in profiles)]
    fig, axes = plt.subplots(1, len(hertz), figsize=(5 * len(hertz), 4))
    for ax, example in zip(axes, hertz):
        degree = max(p["degree"] for p in profiles if p["example"] == example)
        for (formulation, recovery), marker in zip(VARIANTS, ["o", "s", "d", "^", "v"]):
            for p in profiles:
                if (p["example"], p["degree"], p["formulation"], p["recovery"]) == (example, degree, formulation,
                                                                                   recovery):
                    ax.plot(p["r"], p["p"], marker, markersize=2, alpha=0.5, linestyle="none",
                            label=label(formulation, recovery))
        t = np.linspace(0.0, 1.5, 301)
        ax.plot(t, np.sqrt(np.maximum(0.0, 1.0 - t * t)), "k-", label="Hertz")
        ax.set_title("%s, P%d, finest mesh" % (example, degree))
        ax.set_xlabel("r / a (Hertz)")
        ax.set_ylabel("p / p0 (Hertz)")
        ax.legend(fontsize=7)
        ax.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


if __name__ == "__main__":
    sys.exit(main())

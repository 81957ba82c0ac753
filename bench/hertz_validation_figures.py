#!/usr/bin/python3
"""The figures that doc/hertz-validation.md and the README quote, from
bench/results/hertz.json (written by scripts/hertz.py):

    /usr/bin/python3 bench/hertz_validation_figures.py SECTION

SECTION is one of readme (the README's table of the finest meshes with the default
constraints, and a sentence on the dual mortar field and the force-approach law),
force-approach (the deep block's force against P = (4/3) E* sqrt(R) delta^(3/2)), cylinder,
field (the nodal pressure field of P2 and P3), dual-mortar, p1, half-disk, half-ball,
deep-block, two-bodies-2d, two-bodies-3d and punch (a bullet list each). Every figure, and
every comparison worded from them (which variant is closest, how far a set of runs strays),
is computed from the JSON.
"""
import textwrap

from quoted_figures import results, run

CONSISTENT, LUMPED, PATCH = ("nodal", "consistent"), ("nodal", "lumped"), ("nodal", "patch")
WEIGHTED, DUAL = ("weighted gap", "auto"), ("dual mortar", "auto")
VARIANTS = [CONSISTENT, LUMPED, PATCH, WEIGHTED, DUAL]
NAMES = {CONSISTENT: "consistent", LUMPED: "lumped", PATCH: "patch", WEIGHTED: "weighted gaps", DUAL: "dual mortar"}
LONG = {CONSISTENT: "the consistent recovery", LUMPED: "the lumped recovery", PATCH: "the patch average",
        WEIGHTED: "weighted gaps", DUAL: "dual mortar"}
# Studies against a rigid obstacle with Hertz' solution; the flat punch; two elastic bodies.
HERTZ = ["cylinder-2d", "sphere-3d", "half-disk-2d", "half-ball-3d", "deep-block-3d"]
PUNCH = "punch-2d"
BODIES = {"disk-on-block-2d": "equal moduli", "stiff-disk-on-block-2d": "the disk 100 times stiffer",
          "ball-on-block-3d": "equal moduli", "ball-on-stiff-block-3d": "the block 100 times stiffer"}
GMSH = {"half-disk-2d", "half-ball-3d", "deep-block-3d"}
# The README's rows: (example, degree), each on its finest mesh with the default constraints.
README_ROWS = [("cylinder-2d", 1), ("cylinder-2d", 3), ("sphere-3d", 1), ("sphere-3d", 2), ("sphere-3d", 3),
               ("half-ball-3d", 2), ("deep-block-3d", 1)]


def variant(run):
    return run["formulation"], run["recovery"]


def series(rows, example, degree, kind):
    """The runs of one example, degree and constraint variant, coarsest mesh first."""
    return sorted((r for r in rows if r["example"] == example and r["degree"] == degree and variant(r) == kind),
                  key=lambda r: -r["h"])


def finest(rows, example, degree, kind):
    return series(rows, example, degree, kind)[-1]


def degrees(rows, example):
    return sorted({r["degree"] for r in rows if r["example"] == example})


def kinds(rows, example, degree):
    return [k for k in VARIANTS if series(rows, example, degree, k)]


def runs_of(rows, examples, kind=None, min_degree=1, max_degree=3):
    return [r for r in rows if r["example"] in examples and min_degree <= r["degree"] <= max_degree
            and (kind is None or variant(r) == kind)]


def possessive(kind):
    return LONG[kind] + ("'" if LONG[kind].endswith("s") else "'s")


def pct(x, digits=None):
    """A signed percentage: two decimals below 1%, one below 10%, none above."""
    v = 100.0 * x
    if digits is None:
        digits = 2 if abs(v) < 1 else 1 if abs(v) < 10 else 0
    return ("%+.*f%%" % (digits, v)).replace("-", "−")


def bound(x):
    """An unsigned percentage, for "within" and for shares of the peak."""
    return pct(abs(x)).lstrip("+")


def share(x):
    v = 100.0 * x
    return "%.*f%%" % (0 if abs(v) >= 10 else 1, v)


def l2(x):
    return "%.3g" % x


def order(x):
    return ("%.2f" % x).replace("-", "−")


def spacings(x):
    return ("%+.2f" % x).replace("-", "−")


def mesh(label):
    if label.startswith("size x"):
        return "size ×" + label[len("size x"):]
    return label.replace("x", " × ")


def joined(runs, key, fmt):
    return ", ".join(fmt(r[key]) for r in runs)


def mesh_span(runs):
    """"coarsest to finest" by the runs' mesh labels."""
    return "%s to %s" % (mesh(runs[0]["mesh"]), mesh(runs[-1]["mesh"]))


def spacing(run):
    """The node spacing at the contact: the element size over the degree."""
    return run["h"] / run["degree"]


def wrap(text, indent=""):
    return textwrap.fill(text, 95, subsequent_indent=indent, break_long_words=False, break_on_hyphens=False)


def bullet(text):
    return wrap("- " + text, "  ")


def largest(runs, key, magnitude=abs):
    """The run of the largest value of key (by magnitude), named by example, degree and mesh."""
    run = max(runs, key=lambda r: magnitude(r[key]))
    return run, "%s P%d %s" % (run["example"], run["degree"], mesh(run["mesh"]))


def tension_words(runs):
    """What the most negative nodal pressure over runs says."""
    low = min(r["tension"] for r in runs)
    return "no negative nodal pressure" if low >= 0 else "nodal pressure down to %s of the peak" % pct(low)


# The README ---------------------------------------------------------------------------------

def default(dim, degree):
    """The default constraints: nodal for P1 (lumped in 2D, patch average in 3D), dual mortar above."""
    return DUAL if degree > 1 else LUMPED if dim == 2 else PATCH


def readme_table(rows):
    lines = ["| problem | P | n | constraints | a / a_Hertz − 1 | p₀ / p₀,Hertz − 1 | L² error of p |",
             "|---|---|---|---|---|---|---|"]
    for example, degree in README_ROWS:
        dim = series(rows, example, degree, DUAL)[0]["d"]
        r = finest(rows, example, degree, default(dim, degree))
        name = example + (" (Gmsh)" if example in GMSH else "")
        constraints = "nodal (%s)" % r["recovery"] if r["formulation"] == "nodal" else r["formulation"]
        lines.append("| %s | %d | %d | %s | %s | %s | %.3f |" % (
            name, degree, r["n"], constraints, pct(r["a_error"], 2), pct(r["p0_error"], 2), r["l2_error"]))
    return lines


def readme(data):
    dual = runs_of(data["rows"], HERTZ + [PUNCH], DUAL, 2)
    off, where = largest(dual, "off_active")
    law = data["force_approach"]
    worst = max(abs(r["error"]) for r in law["rows"])
    return readme_table(data["rows"]) + ["", wrap(
        "With dual mortar constraints (P2 and P3, every mesh of every study against a rigid obstacle) the pressure "
        "field has %s and at most %s of its peak on nodes that are not active (%s). On the deep block the "
        "force–approach law P = (4/3)E*√R δ^(3/2) holds within %s (P%d, δ = %g to %g)." % (
            tension_words(dual), share(off["off_active"]), where, bound(worst), law["degree"],
            law["rows"][0]["delta"], law["rows"][-1]["delta"]))]


def force_approach(data):
    law = data["force_approach"]
    lines = ["Force–approach law on deep-block-3d, P%d, mesh %s (n = %d):" % (law["degree"], mesh(law["mesh"]), law["n"]),
             "", "| approach δ | P | (4/3) E* √R δ^(3/2) | P / law − 1 | exponent of P(δ) |", "|---|---|---|---|---|"]
    for r in law["rows"]:
        exponent = "" if r["exponent"] is None else "%.3f" % r["exponent"]
        lines.append("| %g | %.5g | %.5g | %s | %s |" % (r["delta"], r["force"], r["force_law"], pct(r["error"], 2),
                                                        exponent))
    return lines


# doc/hertz-validation.md ---------------------------------------------------------------------

def finest_by_variant(rows, example, degree, key, fmt, kinds_=None):
    """"consistent +0.89%, lumped +0.88%, ..." on the finest mesh of one example and degree."""
    return ", ".join("%s %s" % (NAMES[k], fmt(finest(rows, example, degree, k)[key]))
                     for k in kinds_ or kinds(rows, example, degree))


def smallest_l2(rows, example, degree):
    runs = [finest(rows, example, degree, k) for k in kinds(rows, example, degree)]
    best = min(runs, key=lambda r: r["l2_error"])
    others = [r["l2_error"] for r in runs if r is not best]
    return "P%d (%s) %s, %s (the other variants %s to %s)" % (
        degree, mesh(best["mesh"]), possessive(variant(best)), l2(best["l2_error"]), l2(min(others)), l2(max(others)))


def rim_against_nodal(rows, example, degree):
    """Weighted gaps' half-width against the nodal constraints' on the finest mesh, in node spacings."""
    gap, nodal = finest(rows, example, degree, WEIGHTED), finest(rows, example, degree, CONSISTENT)
    shorter = (nodal["a"] - gap["a"]) / spacing(nodal)
    return "P%d %s against %s, %.1f node spacings %s (a node spacing is %s of a)" % (
        degree, pct(gap["a_error"]), pct(nodal["a_error"]), abs(shorter), "shorter" if shorter >= 0 else "longer",
        bound(spacing(nodal) / nodal["a_hertz"]))


def cylinder(data):
    rows, example = data["rows"], "cylinder-2d"
    ds = degrees(rows, example)
    nodal = {d: series(rows, example, d, CONSISTENT) for d in ds}
    depth = sorted({"%.2f" % nodal[d][-1]["a_hertz"] for d in ds})
    return [
        bullet("Half-width, nodal constraints, coarsest to finest mesh: " + "; ".join(
            "P%d %s (%s)" % (d, joined(nodal[d], "a_error", pct), mesh_span(nodal[d])) for d in ds) + "."),
        bullet("Peak pressure on the finest meshes, nodal constraints: " + "; ".join(
            "P%d %s" % (d, finest_by_variant(rows, example, d, "p0_error", pct, [k for k in (CONSISTENT, LUMPED, PATCH)
                                                                                 if series(rows, example, d, k)]))
            for d in ds) + "."),
        bullet("Hertz' half-width against the block's depth H = 1 on the finest meshes: a/H = %s." % " to ".join(depth)),
        bullet("Observed order of the L² error between consecutive meshes, nodal constraints, consistent "
               "recovery: " + "; ".join("P%d %s" % (d, joined(nodal[d][1:], "l2_order", order))
                                        for d in ds) + "."),
        bullet("Peak pressure of the lumped recovery for P3, %s: %s." % (
            mesh_span(series(rows, example, 3, LUMPED)), joined(series(rows, example, 3, LUMPED), "p0_error", pct))),
        bullet("Smallest L² error on the finest mesh: " + "; ".join(smallest_l2(rows, example, d) for d in ds) + "."),
        bullet("Weighted gaps' half-width on the finest meshes against the nodal constraints': " + "; ".join(
            rim_against_nodal(rows, example, d) for d in ds) + "."),
    ]


def finest_field(rows, example, degree, kind):
    r = finest(rows, example, degree, kind)
    return "%s P%d (%s): peak %s, most negative nodal pressure %s of the peak, %s of the peak off the active nodes" % (
        example, degree, mesh(r["mesh"]), pct(r["p0_error"]), pct(r["tension"]), share(r["off_active"]))


def high_degrees(rows, examples):
    return [(e, d) for e in examples for d in degrees(rows, e) if d >= 2]


def field(data):
    rows = data["rows"]
    studies = HERTZ + [PUNCH]
    lines = [bullet("Consistent recovery, finest meshes: " + "; ".join(
        finest_field(rows, e, d, CONSISTENT) for e, d in [("sphere-3d", 2), ("sphere-3d", 3), ("half-ball-3d", 2)]) + ".")]
    for kind in (LUMPED, WEIGHTED):
        lines.append(bullet("%s, every mesh of every study against a rigid obstacle: %s." % (
            LONG[kind][0].upper() + LONG[kind][1:], tension_words(runs_of(rows, studies, kind)))))
    lines.append(bullet("Peak pressure of the lumped recovery on the finest meshes: " + "; ".join(
        "%s P%d %s" % (e, d, pct(finest(rows, e, d, LUMPED)["p0_error"])) for e, d in high_degrees(rows, HERTZ)) + "."))
    lines.append(bullet("Weighted gaps on the finest 3D meshes: " + "; ".join(
        "%s P%d peak %s, %s of the peak off the active nodes" % (
            e, d, pct(finest(rows, e, d, WEIGHTED)["p0_error"]), share(finest(rows, e, d, WEIGHTED)["off_active"]))
        for e, d in high_degrees(rows, [e for e in HERTZ if e.endswith("3d")])) + "."))
    return lines


def dual_field(rows):
    dual = runs_of(rows, HERTZ + [PUNCH], DUAL, 2)
    off, where = largest(dual, "off_active")
    inactive = [r for r in dual if not r["peak_node_active"]]
    return bullet("P2 and P3, every mesh of every study against a rigid obstacle (%d runs): %s, at most %s of the "
                  "peak off the active nodes (%s), the peak's node active in %d of them." % (
                      len(dual), tension_words(dual), share(off["off_active"]), where, len(dual) - len(inactive)))


def dual_finest(rows):
    pairs = high_degrees(rows, HERTZ)
    finest_runs = [finest(rows, e, d, DUAL) for e, d in pairs]
    worst, where = largest(finest_runs, "a_error")
    return bullet("Finest meshes, P2 and P3: peak pressure " + "; ".join(
        "%s P%d %s" % (r["example"], r["degree"], pct(r["p0_error"])) for r in finest_runs) +
        "; contact half-width or radius within %s (%s)." % (bound(worst["a_error"]), where))


def dual_l2(rows):
    parts = []
    for e, d in high_degrees(rows, [e for e in HERTZ if e.endswith("3d")]):
        dual = finest(rows, e, d, DUAL)
        other = min((finest(rows, e, d, k) for k in kinds(rows, e, d) if k != DUAL), key=lambda r: r["l2_error"])
        parts.append("%s P%d %s, %s %s %s" % (e, d, l2(dual["l2_error"]),
                                              "below" if dual["l2_error"] < other["l2_error"] else "above",
                                              possessive(variant(other)), l2(other["l2_error"])))
    return bullet("L² error on the finest 3D meshes against the smallest of the other variants: " +
                  "; ".join(parts) + ".")


def dual_lumped_2d(rows):
    """Per 2D P2 study, the largest differences between dual mortar and the lumped recovery over its meshes."""
    parts = []
    for e, d in high_degrees(rows, HERTZ + [PUNCH]):
        if e.endswith("2d") and d == 2:
            pairs = list(zip(series(rows, e, d, DUAL), series(rows, e, d, LUMPED)))
            largest_difference = lambda key: max(abs(dual[key] - lumped[key]) for dual, lumped in pairs)
            parts.append("%s %.2f, %.2f and %.4f" % (e, 100 * largest_difference("a_error"),
                                                    100 * largest_difference("p0_error"), largest_difference("l2_error")))
    return bullet("2D P2, dual mortar against the lumped recovery, largest difference over the meshes in the "
                  "half-width and the peak (percentage points) and in the L² error: " + "; ".join(parts) + ".")


def dual_cg(rows):
    pairs = high_degrees(rows, HERTZ + [PUNCH])
    diffs = [dual["krylov"] - nodal["krylov"] for e, d in pairs
             for dual, nodal in zip(series(rows, e, d, DUAL), series(rows, e, d, CONSISTENT))]
    fewer, same, more = sum(x < 0 for x in diffs), sum(x == 0 for x in diffs), sum(x > 0 for x in diffs)
    finest_pairs = "; ".join("%s P%d %d against %d" % (e, d, finest(rows, e, d, DUAL)["krylov"],
                                                      finest(rows, e, d, CONSISTENT)["krylov"]) for e, d in pairs)
    return bullet("CG iterations against the nodal constraints' on the same mesh, P2 and P3 (%d meshes): fewer on %d, "
                  "as many on %d, more on %d%s. Finest meshes: %s." % (
                      len(diffs), fewer, same, more, " (by at most %d)" % max(diffs) if more else "", finest_pairs))


def dual_mortar(data):
    rows = data["rows"]
    return [dual_field(rows), dual_finest(rows), dual_l2(rows), dual_lumped_2d(rows), dual_cg(rows)]


def cells_per_radius(runs):
    """Hertz' contact radius in cells of the structured mesh (h is its cell size)."""
    return ", ".join("%.1f" % (r["a_hertz"] / r["h"]) for r in runs)


def lumped_against_patch_2d(rows):
    pairs = [(lumped, patch) for e in HERTZ if e.endswith("2d")
             for lumped, patch in zip(series(rows, e, 1, LUMPED), series(rows, e, 1, PATCH))]
    smaller = sum(lumped["l2_error"] < patch["l2_error"] for lumped, patch in pairs)
    apart = max(abs(lumped["p0_error"] - patch["p0_error"]) for lumped, patch in pairs)
    return bullet("2D P1 (%s, every mesh): the lumped recovery has the smaller L² error on %d of %d meshes; the "
                  "two peaks are at most %.1f percentage points apart." % (
                      ", ".join(e for e in HERTZ if e.endswith("2d")), smaller, len(pairs), 100 * apart))


def gmsh_p1(rows):
    examples = [e for e in sorted(GMSH) if e.endswith("3d")]
    lumped, patch = runs_of(rows, examples, LUMPED, 1, 1), runs_of(rows, examples, PATCH, 1, 1)
    ratios = [p["l2_error"] / q["l2_error"] for p, q in zip(patch, lumped)]
    worst, where = largest(patch, "p0_error")
    return bullet("Gmsh meshes, P1 (%s, every mesh): peak %s to %s with the lumped recovery, within %s with the "
                  "patch average (%s); L² error of the patch average %.2f to %.2f times the lumped one's." % (
                      ", ".join(examples), pct(min(r["p0_error"] for r in lumped)),
                      pct(max(r["p0_error"] for r in lumped)), bound(worst["p0_error"]), where, min(ratios), max(ratios)))


def p1(data):
    rows = data["rows"]
    sphere = {k: series(rows, "sphere-3d", 1, k) for k in kinds(rows, "sphere-3d", 1)}
    dual_3d = "; ".join("%s %s" % (e, joined(series(rows, e, 1, DUAL), "p0_error", pct))
                        for e in HERTZ if e.endswith("3d"))
    return [
        bullet("Sphere, contact radius, %s: %s." % (mesh_span(sphere[CONSISTENT]),
                                                   joined(sphere[CONSISTENT], "a_error", pct))),
        bullet("Sphere, peak of the lumped recovery, %s: %s (Hertz' contact radius spans %s cells)." % (
            mesh_span(sphere[LUMPED]), joined(sphere[LUMPED], "p0_error", pct), cells_per_radius(sphere[LUMPED]))),
        bullet("Sphere, peak on the finest mesh (%s): %s." % (
            mesh(sphere[LUMPED][-1]["mesh"]), finest_by_variant(rows, "sphere-3d", 1, "p0_error", pct))),
        bullet("Sphere, patch average, %s: peak %s; L² error on the finest mesh %s against the lumped "
               "recovery's %s." % (mesh_span(sphere[PATCH]), joined(sphere[PATCH], "p0_error", pct),
                                   l2(sphere[PATCH][-1]["l2_error"]), l2(sphere[LUMPED][-1]["l2_error"]))),
        gmsh_p1(rows),
        lumped_against_patch_2d(rows),
        bullet("3D P1 dual mortar, peak from the coarsest to the finest mesh: %s." % dual_3d),
    ]


def half_disk(data):
    rows, example = data["rows"], "half-disk-2d"
    nodal = [finest(rows, example, 1, k) for k in (CONSISTENT, LUMPED, PATCH)]
    p2 = [finest(rows, example, 2, k) for k in kinds(rows, example, 2)]
    closest = min(round(abs(r["p0_error"]), 6) for r in p2)
    best = [NAMES[variant(r)] for r in p2 if round(abs(r["p0_error"]), 6) == closest]
    return [
        bullet("P1, finest mesh (%s), nodal constraints: half-width %s, peak %s." % (
            mesh(nodal[0]["mesh"]), pct(nodal[0]["a_error"]), finest_by_variant(rows, example, 1, "p0_error", pct,
                                                                                 [CONSISTENT, LUMPED, PATCH]))),
        bullet("P2, finest mesh (%s): peak %s; closest to Hertz: %s." % (
            mesh(p2[0]["mesh"]), finest_by_variant(rows, example, 2, "p0_error", pct), " and ".join(best))),
    ]


def half_ball(data):
    rows, example = data["rows"], "half-ball-3d"
    nodal, lumped, patch = (series(rows, example, 1, k) for k in (CONSISTENT, LUMPED, PATCH))
    worst, where = largest(nodal, "a_error")
    return [
        bullet("P1, contact radius with nodal constraints within %s on every mesh (%s)." % (bound(worst["a_error"]), where)),
        bullet("P1 peak, %s: %s with the lumped recovery, %s with the patch average." % (
            mesh_span(lumped), joined(lumped, "p0_error", pct), joined(patch, "p0_error", pct))),
        bullet("P1 L² error of the patch average, %s: %s." % (mesh_span(patch), joined(patch, "l2_error", l2))),
    ]


def deep_p2(rows, example):
    parts = []
    for k in kinds(rows, example, 2):
        r = finest(rows, example, 2, k)
        parts.append("%s: peak %s, L² error %s, contact radius %s (%s node spacings), %s, %s of the peak off the "
                     "active nodes" % (NAMES[k], pct(r["p0_error"]), l2(r["l2_error"]), pct(r["a_error"]),
                                       spacings((r["a"] - r["a_hertz"]) / spacing(r)), tension_words([r]),
                                       share(r["off_active"])))
    return bullet("P2, finest mesh (%s): %s." % (mesh(finest(rows, example, 2, DUAL)["mesh"]), "; ".join(parts)))


def deep_block(data):
    rows, example, law = data["rows"], "deep-block-3d", data["force_approach"]
    lumped, patch = series(rows, example, 1, LUMPED), series(rows, example, 1, PATCH)
    exponents = [r["exponent"] for r in law["rows"] if r["exponent"] is not None]
    return [
        bullet("Force–approach law, P%d, %s: P / law − 1 = %s for δ = %s; exponent of P(δ) %s against 3/2." % (
            law["degree"], mesh(law["mesh"]), ", ".join(pct(r["error"]) for r in law["rows"]),
            ", ".join("%g" % r["delta"] for r in law["rows"]), " and ".join("%.3f" % x for x in exponents))),
        bullet("Contact radius on the finest meshes, nodal constraints: " + "; ".join(
            "P%d (%s) %s" % (d, mesh(finest(rows, example, d, CONSISTENT)["mesh"]),
                             pct(finest(rows, example, d, CONSISTENT)["a_error"])) for d in degrees(rows, example)) + "."),
        bullet("P1 peak, %s (n = %d at the finest): %s with the lumped recovery, %s with the patch average." % (
            mesh_span(lumped), lumped[-1]["n"], joined(lumped, "p0_error", pct), joined(patch, "p0_error", pct))),
        deep_p2(rows, example),
    ]


def two_bodies(rows, examples):
    runs = runs_of(rows, examples)
    peak, peak_where = largest(runs, "p0_error")
    coarse = [series(rows, e, 1, DUAL)[0] for e in examples]
    finer = [r for e in examples for r in series(rows, e, 1, DUAL)[1:]]
    width, width_where = largest(finer, "a_error")
    return [
        bullet("Peak pressure within %s of Hertz on every mesh (%s)." % (bound(peak["p0_error"]), peak_where)),
        bullet("Contact %s on the coarsest mesh (%s): %s, where a node spacing is %s of a; within %s from %s on "
               "(%s)." % ("half-width" if examples[0].endswith("2d") else "radius", mesh(coarse[0]["mesh"]),
                          ", ".join("%s %s" % (BODIES[r["example"]], pct(r["a_error"])) for r in coarse),
                          bound(spacing(coarse[0]) / coarse[0]["a_hertz"]), bound(width["a_error"]),
                          mesh(series(rows, examples[0], 1, DUAL)[1]["mesh"]), width_where)),
        bullet("L² error, %s: " % mesh_span(series(rows, examples[0], 1, DUAL)) + "; ".join(
            "%s %s (observed orders %s)" % (BODIES[e], joined(series(rows, e, 1, DUAL), "l2_error", l2),
                                            joined(series(rows, e, 1, DUAL)[1:], "l2_order", order))
            for e in examples) + "."),
        bullet("Every mesh: %s; off the active nodes at most " % tension_words(runs) + ", ".join(
            "%s of the peak with %s" % (share(max(r["off_active"] for r in runs_of(rows, [e]))), BODIES[e])
            for e in examples) + "."),
    ]


def width_in_spacings(runs):
    return ", ".join("%s (%s)" % (pct(r["a_error"]), spacings(r["a_error"] * r["a_hertz"] / spacing(r))) for r in runs)


def punch(data):
    rows = data["rows"]
    ds = degrees(rows, PUNCH)
    finest_nodal = [finest(rows, PUNCH, d, k) for d in ds for k in kinds(rows, PUNCH, d) if k[0] == "nodal"]
    return [
        bullet("Half-width against b, nodal constraints, coarsest to finest mesh (in node spacings): " + "; ".join(
            "P%d %s" % (d, width_in_spacings(series(rows, PUNCH, d, CONSISTENT))) for d in ds) + "."),
        bullet("Finest meshes, nodal constraints: pressure at the centre %s to %s against P/(πb), L² error over the "
               "inner 80%% %s to %s." % (pct(min(r["p0_error"] for r in finest_nodal)),
                                        pct(max(r["p0_error"] for r in finest_nodal)),
                                        l2(min(r["l2_error"] for r in finest_nodal)),
                                        l2(max(r["l2_error"] for r in finest_nodal)))),
        bullet("Weighted gaps' half-width on the finest meshes (in node spacings): " + "; ".join(
            "P%d %s" % (d, width_in_spacings([finest(rows, PUNCH, d, WEIGHTED)])) for d in ds) + "."),
    ]


SECTIONS = {"readme": readme, "force-approach": force_approach, "cylinder": cylinder, "field": field,
            "dual-mortar": dual_mortar, "p1": p1, "half-disk": half_disk, "half-ball": half_ball,
            "deep-block": deep_block, "punch": punch,
            "two-bodies-2d": lambda data: two_bodies(data["rows"], ["disk-on-block-2d", "stiff-disk-on-block-2d"]),
            "two-bodies-3d": lambda data: two_bodies(data["rows"], ["ball-on-block-3d", "ball-on-stiff-block-3d"])}


def printed(section):
    """The section as run calls it: printing its lines, computed from hertz.json."""
    return lambda: print("\n".join(section(results("hertz"))))


if __name__ == "__main__":
    run({name: printed(section) for name, section in SECTIONS.items()})

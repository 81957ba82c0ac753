#!/usr/bin/python3
"""The measured figures that doc/algorithms.md quotes beside its reasoning, from the JSON in
bench/results (standard library only, like every script that scripts/benchmarks_md.py runs):

    /usr/bin/python3 bench/algorithms_figures.py SECTION

SECTION is one of
  primal          the primal method's Newton steps on problems A-M (table2.json);
  v-cycles        CG iterations per Newton system on the family (reference-solve.json), and
                  the share of the V-cycles a last preconditioner application would add;
  starts          the starting vectors: their time (reference-solve.json) and the default
                  against the components taken out (preconditioners-components.json);
  weight-cap      the capped weights against the uncapped ones ("unfiltered") on the
                  preconditioners-forcing{,-p2p3}.json members;
  direct-solvers  refactorization times of CHOLMOD and KLU2 (direct-solvers.json);
  gmsh-pk         the P_k -> P1 step on Gmsh meshes against MueLu alone and against the mesh
                  refined at the nodes (gmsh-pk.json);
  rebuilds        a multigrid setup after the first: the contact solve's setup times less
                  the linear solve's (reference-solve.json); the lagged rebuild
                  (preconditioners-forcing.json) and MueLu's hierarchy rebuilt when
                  constraints switch (preconditioners-algebraic-rebuild.json).
Each prints Markdown: a sentence or a bullet list.
"""
from preconditioners_table import approximate, first_last, load
from quoted_figures import SEQUENCES, count, records, results, run, span

DIMENSION = {s: SEQUENCES[s] for s in ("2d", "3d")}


def seconds(t):
    """Two significant digits (all the digits from 10 on), in ms below one second."""
    value, unit = (t, "s") if t >= 1 else (1e3 * t, "ms")
    return f"{value:.0f} {unit}" if value >= 10 else f"{value:.2g} {unit}"


def fewer(percentages):
    """"0–12% fewer", "3–5% more" or "from 3% more to 12% fewer" over the percentages fewer."""
    values = [round(p) + 0 for p in percentages]
    if min(values) >= 0:
        return f"{span(values)}% fewer"
    if max(values) <= 0:
        return f"{span([-v for v in values])}% more"
    return f"from {-min(values)}% more to {max(values)}% fewer"


def primal():
    runs = [r["summary"] for r in records("table2") if r["summary"]["method"] == "primal"]
    print(f"On problems A–M (`bench/results/table2.json`, {span([s['ranks'] for s in runs])} rank) the primal "
          f"method takes {span([s['newton_steps'] for s in runs])} Newton steps in "
          f"{span([s['outer_iterations'] for s in runs])} main iterations.")


def family_cases():
    """The family's members of bench/reference_solve.py (not problems A-M)."""
    return [c for c in results("reference-solve")["cases"] if c["problem"].startswith("family/")]


def case_name(problem):
    """"3D P1 nx = 64" for "family/3d-p1-nx64"."""
    dim, degree, nx = problem.split("/")[1].split("-")
    return f"{dim.upper()} {degree.upper()} nx = {nx[2:]}"


def largest_3d_p1():
    return max((c for c in family_cases() if c["problem"].startswith("family/3d-p1")), key=lambda c: c["contact"]["n"])


def v_cycles():
    cases = family_cases()
    per_system = [c["contact"]["cg_iterations"] / c["contact"]["newton_systems"] for c in cases]
    share = [100 * c["contact"]["newton_systems"] / (c["contact"]["cg_iterations"] + c["contact"]["newton_systems"])
             for c in cases]
    print(f"On the family's members in `bench/results/reference-solve.json` a Newton system takes "
          f"{span(per_system, 1)} CG iterations on average, so that a last application per system "
          f"would be {span(share, 0)}% of all V-cycles.")


def component_members(runs):
    return sorted({(s, nx) for (s, nx, config, forcing) in runs if config == "default" and forcing == "reduction"})


def starts():
    case = largest_3d_p1()
    contact = case["contact"]
    print(f"- The starting vectors (projection and contact correction) of {case_name(case['problem'])} on "
          f"{case['ranks']} ranks (`bench/results/reference-solve.json`): "
          f"{seconds(contact['seconds']['initial_guesses'])} over "
          f"{contact['newton_systems']} Newton systems, against {seconds(contact['seconds']['krylov'])} of CG "
          "iterations.")
    runs = load("preconditioners-components")
    members = component_members(runs)
    configs = ["default", "without contact-corrected start", "from zero"]
    largest = {s: max(n for q, n in members if q == s) for s in DIMENSION}
    largest = [f"{DIMENSION[s]} nx = {nx}: "
               + ", ".join(str(runs[(s, nx, c, "reduction")]["summary"]["krylov_iterations"]) for c in configs)
               for s, nx in largest.items()]
    print("- CG iterations in all with both, with the projection alone and from zero "
          f"(`bench/results/preconditioners-components.json`, {span([r['ranks'] for r in runs.values()])} ranks): "
          + "; ".join(largest) + ".")
    more = {c: [runs[(s, nx, c, "reduction")]["summary"]["outer_iterations"]
                - runs[(s, nx, "default", "reduction")]["summary"]["outer_iterations"] for s, nx in members]
            for c in configs[1:]}
    print(f"- Main iterations beyond those with both, over the {len(members)} members: "
          f"{span(more[configs[1]])} with the projection alone, {span(more[configs[2]])} from zero.")


def approximate_defaults(runs, sequence):
    """The sequence's default runs, by mesh size, without those whose preconditioner is H's
    inverse (one CG iteration per system: the weight cap does not apply)."""
    return approximate(sorted((r for (s, nx, c, f), r in runs.items() if s == sequence and c == "default"
                               and f == "reduction"), key=lambda r: r["nx"]))


def weight_cap():
    runs = load("preconditioners-forcing", "preconditioners-forcing-p2p3")
    print("CG iterations for both systems of the first → last barrier step, capped against uncapped "
          "(`bench/results/preconditioners-forcing.json`, `preconditioners-forcing-p2p3.json`):")
    print()
    for sequence in ("2d", "2d-p2", "2d-p3"):
        default = approximate_defaults(runs, sequence)[0]
        uncapped = runs[(sequence, default["nx"], "unfiltered", "reduction")]
        print(f"- {default['problem']} ({SEQUENCES[sequence]}): {first_last(default).replace(' / ', ' → ')} against "
              f"{first_last(uncapped).replace(' / ', ' → ')};")
    saved = [100 * (1 - d["summary"]["krylov_iterations"]
                    / runs[(s, d["nx"], "unfiltered", "reduction")]["summary"]["krylov_iterations"])
             for s in DIMENSION for d in approximate_defaults(runs, s)]
    print(f"- CG iterations in all on the {len(saved)} P1 members not solved exactly: {fewer(saved)} capped.")


def direct_solvers():
    runs = records("direct-solvers")
    print("Refactorization on one rank, CHOLMOD against KLU2 (`bench/results/direct-solvers.json`):")
    print()
    for dim in sorted({r["dim"] for r in runs}, reverse=True):
        cells = [f"{count(r['n'])} unknowns ({r['nx']}{'³' if dim == 3 else '²'} boxes) "
                 f"{seconds(r['cholmod_refactor_seconds'])} against {seconds(r['klu2_refactor_seconds'])}"
                 for r in sorted((r for r in runs if r["dim"] == dim), key=lambda r: r["n"])]
        print(f"- {dim}D P1: " + "; ".join(cells) + ".")


def gmsh_pk_ratios(runs, path, key):
    """"a–b" over the meshes of the path's figure over that of the matrix-free P1 level."""
    base = {(r["problem"], r["degree"], r["size_factor"]): r for r in runs if r["path"] == "matrix-free"}
    ratios = [r[key] / base[(r["problem"], r["degree"], r["size_factor"])][key] for r in runs
              if r["path"] == path and (r["problem"], r["degree"], r["size_factor"]) in base]
    return span(ratios, 1)


def gmsh_pk():
    runs = [r for r in records("gmsh-pk") if r["status"] == "converged"]
    meshes = len({(r["problem"], r["degree"], r["size_factor"]) for r in runs})
    print("Against the P1 level on the mesh's vertices (the `matrix-free` rows of `bench/results/gmsh-pk.json`, "
          f"{meshes} meshes):")
    print()
    print(f"- MueLu alone on the P_k matrix (`algebraic`): {gmsh_pk_ratios(runs, 'algebraic', 'cg_iterations')} "
          f"times the CG iterations, {gmsh_pk_ratios(runs, 'algebraic', 'peak_mib_max_rank')} times the peak "
          "memory;")
    print(f"- the mesh refined at the nodes (`refined`): {gmsh_pk_ratios(runs, 'refined', 'cg_iterations')} times "
          f"the CG iterations, {gmsh_pk_ratios(runs, 'refined', 'solve_seconds')} times the solve time, "
          f"{gmsh_pk_ratios(runs, 'refined', 'peak_mib_max_rank')} times the peak memory.")


def setup_parts():
    """A setup of the contact solve after the first, estimated as the contact solve's setup
    times less those of the linear solve of the same problem (one setup, the first's work)
    over the other setups."""
    case = largest_3d_p1()
    c, linear = case["contact"], case["reference"]
    later = c["amg_setups"] - linear["amg_setups"]
    each = {key: seconds((c["seconds"][key] - linear["seconds"][key]) / later)
            for key in ("amg_setup", "galerkin_products", "smoother_setup", "coarsest_level", "assemble_h")}
    print(f"- {case_name(case['problem'])} on {case['ranks']} ranks (`bench/results/reference-solve.json`): the "
          f"first setup {seconds(linear['seconds']['amg_setup'])} (timed by the linear solve of the same problem, "
          f"which makes only that one); each of the {later} later ones {each['amg_setup']} on average "
          f"({each['galerkin_products']} Galerkin products, {each['smoother_setup']} smoother setup, "
          f"{each['coarsest_level']} coarsest grid) and {each['assemble_h']} to form AᵀD′A; one CG iteration "
          f"{seconds(c['seconds']['krylov'] / c['cg_iterations'])}.")


def summaries(runs, config):
    """{(sequence, nx): summary} of the configuration's runs with the default forcing."""
    return {(s, nx): r["summary"] for (s, nx, c, f), r in runs.items() if c == config and f == "reduction"}


def lagged():
    runs = load("preconditioners-forcing")
    default, stale = summaries(runs, "default"), summaries(runs, "lagged rebuild")
    setups = {name: span([s["preconditioner_setups"] for s in group.values()])
              for name, group in (("default", default), ("lagged", stale))}
    print(f"- Setups per solve (`bench/results/preconditioners-forcing.json`): {setups['lagged']} with the lagged "
          f"rebuild, {setups['default']} with the default.")
    members = approximate_defaults(runs, "2d")
    ends = [("2d", members[0]["nx"]), ("2d", members[-1]["nx"])]
    grows = {name: " → ".join(str(group[m]["max_krylov_per_newton"]) for m in ends)
             for name, group in (("default", default), ("lagged", stale))}
    print(f"- Largest CG count per Newton system, 2D P1 nx = {ends[0][1]} → {ends[1][1]}: {grows['lagged']} with "
          f"the lagged rebuild, {grows['default']} with the default.")


def algebraic_rebuild():
    runs = load("preconditioners-algebraic-rebuild")
    switching, every = summaries(runs, "algebraic default"), summaries(runs, "algebraic")
    pairs = [(switching[m], every[m]) for m in sorted(switching)]

    def ratio(get):
        return span([get(a) / get(b) for a, b in pairs], 2)
    print(f"- MueLu alone (`bench/results/preconditioners-algebraic-rebuild.json`, {len(pairs)} P1 members), rebuilt "
          f"when constraints switch against at every step: {span([a['preconditioner_setups'] for a, _ in pairs])} "
          f"setups per solve against {span([b['preconditioner_setups'] for _, b in pairs])}, "
          f"{ratio(lambda s: s['krylov_iterations'])} times the CG iterations, "
          f"{ratio(lambda s: s['time']['solve'])} times the solve time.")


def rebuilds():
    setup_parts()
    lagged()
    algebraic_rebuild()


SECTIONS = {"primal": primal, "v-cycles": v_cycles, "starts": starts, "weight-cap": weight_cap,
            "direct-solvers": direct_solvers, "gmsh-pk": gmsh_pk, "rebuilds": rebuilds}

if __name__ == "__main__":
    run(SECTIONS)

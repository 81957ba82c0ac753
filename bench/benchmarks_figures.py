#!/usr/bin/python3
"""The figures that the prose of doc/benchmarks.md quotes, computed from bench/results/*.json
(standard library only, like every script that scripts/benchmarks_md.py runs):

    /usr/bin/python3 bench/benchmarks_figures.py SECTION

SECTION names one generated block of the page: a table of a result set that has no Markdown
table of its own (assembly, expression, direct-solvers) or the bullets and sentences of a
paragraph (the others; SECTIONS below lists them with their result files). Every sentence
that compares is worded from the data: it says what holds in the current files, so a rerun
of a set rewrites it.
"""
import datetime
import statistics

from preconditioners_table import approximate, barrier_steps, finish_krylov, load as load_runs, ratios
from quoted_figures import SEQUENCES, records, results, run, span
from ratios_table import TARGETS

LARGE = 1e5  # "the members with more than 10⁵ unknowns"
MACHINE_BYTES = 24e9  # the memory of the machine the largest matrix-free sets were sized for
TARGET_NAMES = ("the largest count per system", "the totals", "last over first step")  # of ratios_table's TARGETS


# ---------------------------------------------------------------- helpers

def percent_span(fractions):
    return span([100 * f for f in fractions], 0, "%")


def seconds(value):
    return f"{value:.{2 if value < 10 else 1}f}"


def words(items, empty="none"):
    items = list(items)
    if not items:
        return empty
    return items[0] if len(items) == 1 else ", ".join(items[:-1]) + " and " + items[-1]


def millions(n):
    return f"{n / 1e6:.1f} M"


def relative(a, b):
    return abs(a - b) / max(abs(b), 1e-300)


def apart(first, second):
    """How far apart two provenance dates are, in words."""
    times = [datetime.datetime.fromisoformat(d) for d in (first, second)]
    minutes = abs((times[1] - times[0]).total_seconds()) / 60
    if minutes < 1:
        return "within a minute of each other"
    if minutes < 120:
        return f"{minutes:.0f} minutes apart"
    return f"{minutes / 60:.0f} hours apart"


def ratio_clause(ratios_by_name, better_below_one, noun):
    """'faster on every one' / 'faster on A and B only' from ratios new/old (below 1: better)."""
    better = [name for name, r in ratios_by_name.items() if (r < 1) == better_below_one]
    if len(better) == len(ratios_by_name):
        return f"{noun} on every one"
    if not better:
        return f"{noun} on none"
    return f"{noun} on {words(better)} only"


# ---------------------------------------------------------------- introduction

def noise():
    """Spread of the repeated solves of reference-solve.json, the set that repeats them."""
    cases = [c for c in results("reference-solve")["cases"] if c["contact"]["n"] > LARGE]
    spreads = [max(runs) / min(runs) - 1 for c in cases for runs in
               (c["contact"]["solve_seconds_per_run"], c["reference"]["solve_seconds_per_run"])]
    repeats = sorted({c["repeats"] for c in cases})
    print(f"The one set that repeats its solves, `reference-solve.json` ({words(map(str, repeats))} runs of each "
          f"contact and reference solve), shows how far: on its members with more than 10⁵ unknowns the slowest "
          f"run of a solve took {percent_span(spreads)} longer than the fastest (median "
          f"{100 * statistics.median(spreads):.0f}%).")


# ---------------------------------------------------------------- Table 2

def table2_runs(name="table2"):
    return {(r["summary"]["problem"], r["summary"]["method"]): r for r in records(name)}


def table2():
    runs = table2_runs()
    problems = sorted({p for p, _ in runs})
    pd = {p: runs[(p, "primal-dual")]["summary"] for p in problems}
    primal = {p: runs[(p, "primal")]["summary"] for p in problems}
    agree = max(relative(primal[p]["objective"], pd[p]["objective"]) for p in problems)
    converged = all(s["converged"] for s in list(pd.values()) + list(primal.values()))
    f_status = "converges with both methods" if pd["F"]["converged"] and primal["F"]["converged"] else \
        f"ends with status {pd['F']['status']} (primal-dual) and {primal['F']['status']} (primal)"
    print(f"- {'Every run converges' if converged else 'Not every run converges (status in the JSON)'}; the "
          f"primal-dual and primal optimal values agree with each other to {agree:.0e} relative or better. F, which "
          f"the paper's solver failed on, {f_status}.")
    paper = {p: runs[(p, "primal-dual")]["paper"] for p in problems}
    krylov = lambda s: [s[p]["krylov_iterations"] for p in problems]  # noqa: E731
    print(f"- The paper's ngr: {paper['M']['ngr']} on M (2D P1, nx = {pd['M']['nx']}), {paper['J']['ngr']} on J "
          f"(nx = {pd['J']['nx']}); {paper['G']['ngr']}, {paper['H']['ngr']} and {paper['I']['ngr']} on G, H and I "
          f"(nx = {pd['G']['nx']}, P1, P2 and P3). The primal-dual Krylov totals here: "
          f"{pd['M']['krylov_iterations']} on M, {pd['J']['krylov_iterations']} on J, {pd['G']['krylov_iterations']}, "
          f"{pd['H']['krylov_iterations']} and {pd['I']['krylov_iterations']} on G, H and I; {span(krylov(pd), 0)} "
          f"across the family (primal: {span(krylov(primal), 0)}).")
    finished = [p for p in problems if pd[p].get("active_set_finish", {}).get("accepted")]
    finish_cg = [finish_krylov({"summary": pd[p]}) for p in finished]
    ending = (f", the last of them an active-set finish on {words(finished)} ({span(finish_cg, 0)} CG iterations)"
              if finished else "; the active-set finish ends none of them")
    print(f"- The primal-dual method takes {span([pd[p]['outer_iterations'] for p in problems], 0)} main "
          f"iterations{ending}; the primal one {span([primal[p]['outer_iterations'] for p in problems], 0)}, with "
          f"{span([primal[p]['newton_steps'] for p in problems], 0)} Newton systems and "
          f"{span([primal[p]['preconditioner_setups'] for p in problems], 0)} AMG setups.")


def fixed_centering():
    fixed, mehrotra = table2_runs("table2-fixed-centering"), table2_runs()
    problems = sorted(p for p, _ in fixed)
    f = {p: fixed[(p, "primal-dual")]["summary"] for p in problems}
    m = {p: mehrotra[(p, "primal-dual")]["summary"] for p in problems}
    per_main = sorted({s["newton_steps"] / s["outer_iterations"] for s in f.values()})
    systems = "one Newton system each" if per_main == [1.0] else "Newton systems: " + span(
        [s["newton_steps"] for s in f.values()], 0)
    finished = [p for p in problems if f[p].get("active_set_finish", {}).get("accepted")]
    where = "every problem" if len(finished) == len(problems) else (words(finished) if finished else "no problem")
    ratio = {p: f[p]["time"]["solve"] / m[p]["time"]["solve"] for p in problems}
    largest = max(problems, key=lambda p: f[p]["n"])
    dates = (results("table2")["provenance"]["date"], results("table2-fixed-centering")["provenance"]["date"])
    print(f"The fixed rule takes {span([s['outer_iterations'] for s in f.values()], 0)} main iterations with "
          f"{systems}, the last of them an active-set finish on {where} (Mehrotra: "
          f"{span([s['outer_iterations'] for s in m.values()], 0)} main iterations, "
          f"{span([s['newton_steps'] for s in m.values()], 0)} Newton systems), "
          f"{span([s['krylov_iterations'] for s in f.values()], 0)} CG iterations in all (Mehrotra: "
          f"{span([s['krylov_iterations'] for s in m.values()], 0)}). Its solve takes {span(ratio.values(), 2)} times "
          f"Mehrotra's, {ratio_clause(ratio, True, 'faster')} (the largest, {largest}: "
          f"{seconds(f[largest]['time']['solve'])} s against {seconds(m[largest]['time']['solve'])} s); one run "
          f"each, the two sets started {apart(*dates)}.")


# ---------------------------------------------------------------- reference solve

def reference_solve():
    cases = results("reference-solve")["cases"]
    large = [c for c in cases if c["contact"]["n"] > LARGE]
    paper = [c for c in cases if c["problem"].startswith("paper/")]
    one = [c["problem"].split("/")[1] for c in paper if c["reference"]["cg_iterations"] == 1]
    of = lambda chosen, key: [c[key] for c in chosen]  # noqa: E731
    print(f"- Members with more than 10⁵ unknowns: the contact solve takes {span(of(large, 'solve_time_ratio'), 1)} "
          f"times the reference's time and {span(of(large, 'cg_ratio'), 1)} times its CG iterations; problems A–M: "
          f"{span(of(paper, 'solve_time_ratio'), 1)} and {span(of(paper, 'cg_ratio'), 1)}"
          + (f" (the reference takes one CG iteration on {words(one)})." if one else "."))
    share = [c["contact"]["seconds"]["amg_setup"] / c["contact"]["seconds"]["solve"] for c in large]
    setups = lambda run: span([c[run]["amg_setups"] for c in large], 0)  # noqa: E731
    print(f"- On those members the contact solve sets up the AMG {setups('contact')} times, the reference "
          f"{setups('reference')}; the setups take {percent_span(share)} of the contact solve.")
    biggest = max((c for c in cases if c["problem"].startswith("family/3d-p1")), key=lambda c: c["contact"]["n"])
    s = biggest["contact"]["seconds"]
    print(f"- 3D P1 with {millions(biggest['contact']['n'])} unknowns on {biggest['ranks']} ranks (the fastest run): "
          f"mesh and space {seconds(s['mesh'])} s, assembly {seconds(s['assembly'])} s, solve {seconds(s['solve'])} s, "
          f"of which AMG setups {seconds(s['amg_setup'])} s, Krylov {seconds(s['krylov'])} s and starting vectors "
          f"{seconds(s['initial_guesses'])} s; the reference's solve "
          f"{seconds(biggest['reference']['seconds']['solve'])} s.")
    peak = sorted(cases, key=lambda c: c["contact"]["peak_bytes_per_unknown"])
    print(f"- Peak memory per unknown of the contact solve: from {peak[-1]['contact']['peak_bytes_per_unknown']:.0f} "
          f"bytes on {peak[-1]['problem']} ({peak[-1]['contact']['n']} unknowns) to "
          f"{peak[0]['contact']['peak_bytes_per_unknown']:.0f} on {peak[0]['problem']} "
          f"({millions(peak[0]['contact']['n'])}); {span([c['contact']['peak_bytes_per_unknown'] for c in large], 0)} "
          f"on the members with more than 10⁵ unknowns.")


# ---------------------------------------------------------------- IPOPT

IPOPT_CONFIGS = {"defaults": "with its defaults", "mehrotra": "with Mehrotra's algorithm"}  # bench/ipopt.py's


def ipopt_best(run):
    converged = [c for c in run["ipopt"].values() if c["converged"]]
    return min(converged, key=lambda c: c["seconds"]) if converged else None


def ipopt():
    runs = records("ipopt")
    best = {r["problem"]: ipopt_best(r) for r in runs}
    ratio = {r["problem"]: best[r["problem"]]["seconds"] / r["signorini"]["solve_seconds"]
             for r in runs if best[r["problem"]]}
    failed = [p for p, b in best.items() if b is None]
    small = {p: v for p, v in ratio.items() if next(r["n"] for r in runs if r["problem"] == p) < 1e4}
    large = {p: v for p, v in ratio.items() if p not in small}
    faster = [p for p, v in ratio.items() if v > 1]
    head = ("Signorini is faster on every problem" if len(faster) == len(runs) else
            f"Signorini is faster on {words(faster)}" if faster else "Signorini is faster on none")
    smallest = min(runs, key=lambda r: r["n"])["problem"]
    print(f"- {head}: IPOPT's best takes {span(small.values(), 1)} times as long on the problems below 10⁴ unknowns "
          f"({ratio[smallest]:.1f} on {smallest}, the smallest), {span(large.values(), 1)} times on "
          f"{words(sorted(large))}" + (f"; IPOPT did not converge on {words(failed)}." if failed else "."))
    counts = " and ".join(f"{span([r['ipopt'][name]['iterations'] for r in runs], 0)} {label}"
                          for name, label in IPOPT_CONFIGS.items())
    print(f"- Signorini takes {span([r['signorini']['outer_iterations'] for r in runs], 0)} main iterations, IPOPT "
          f"{counts}.")
    differences = [relative(best[r["problem"]]["objective"], r["signorini"]["objective"]) for r in runs
                   if best[r["problem"]]]
    print(f"- IPOPT's optimal values differ from Signorini's by {min(differences):.0e}–{max(differences):.0e} "
          f"relative.")


# ---------------------------------------------------------------- assembly, expressions, direct solvers

def assembly():
    print("| d | P | nx | n | nonzeros | ranks | mesh and space [s] | assembly [s] | peak MiB (max rank) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for r in records("assembly"):
        print(f"| {r['dim']} | {r['degree']} | {r['nx']} | {r['n']} | {r['nonzeros']} | {r['ranks']} "
              f"| {r['setup_seconds']:.2f} | {r['assembly_seconds']:.2f} | {r['peak_rss_mib_max_rank']:.0f} |")


def expression():
    print("| d | points per call | points | point by point [ns per point] | batched [ns per point] | ratio "
          "| largest difference |")
    print("|---|---|---|---|---|---|---|")
    for r in records("expression"):
        print(f"| {r['dim']} | {r['points_per_call']} | {r['points']} | {r['pointwise_ns_per_point']:.0f} "
              f"| {r['batched_ns_per_point']:.0f} | {r['speedup']:.1f} | {r['largest_difference']:.0e} |")


def direct_solvers():
    print("| d | box | n | nonzeros | KLU2: first [s] | refactorization [s] | solve [s] | CHOLMOD: first [s] "
          "| refactorization [s] | solve [s] | refactorization: KLU2 / CHOLMOD | solve: KLU2 / CHOLMOD |")
    print("|" + "---|" * 12)
    for r in records("direct-solvers"):
        box = " × ".join([str(r["nx"])] * r["dim"])
        cells = [r[f"{solver}_{phase}_seconds"] for solver in ("klu2", "cholmod")
                 for phase in ("first", "refactor", "solve")]
        print(f"| {r['dim']} | {box} | {r['n']} | {r['nonzeros']} | " + " | ".join(f"{c:.2g}" for c in cells)
              + f" | {cells[1] / cells[4]:.1f} | {cells[2] / cells[5]:.1f} |")


# ---------------------------------------------------------------- matrix-free stiffness

def matrix_free():
    runs = records("matrix-free")
    kept = lambda rs: percent_span([r["matrix_free_bytes_per_unknown"] / r["assembled_bytes_per_unknown"]  # noqa: E731
                                    for r in rs])
    slower = lambda rs: span([r["matrix_free_seconds_per_apply"] / r["assembled_seconds_per_apply"]  # noqa: E731
                              for r in rs], 2)
    high = [r for r in runs if r["degree"] > 1]
    p1 = [r for r in runs if r["degree"] == 1]
    print(f"Matrix-free, P2 and P3 keep {kept(high)} of the assembled matrix's bytes per unknown and take "
          f"{slower(high)} times the CSR product's time per application; P1 keeps {kept(p1)} and takes {slower(p1)} "
          f"times (median of the benchmark's repeated applications).")


def solve_pairs(name):
    runs = records(name)
    by = {(r["dim"], r["degree"], r["nx"], r["path"]): r for r in runs}
    return [(by[k], by[(k[0], k[1], k[2], "matrix-free")]) for k in sorted(by)
            if k[3] == "assembled" and (k[0], k[1], k[2], "matrix-free") in by], runs


def matrix_free_solve():
    pairs, runs = solve_pairs("matrix-free-solve")
    counters = ("main_iterations", "newton_systems", "cg_iterations")
    differing = [f"{a['dim']}D P{a['degree']} nx = {a['nx']}" for a, m in pairs if any(a[c] != m[c] for c in counters)]
    agree = max(relative(m["objective"], a["objective"]) for a, m in pairs)
    members = f"every member but {words(differing)}" if differing else "every member"
    print(f"- Both paths take the same main iterations, Newton systems and CG iterations on {members}, and reach "
          f"the same optimal value to {agree:.0e} relative.")
    saved = lambda d: [1 - m["peak_bytes_per_unknown"] / a["peak_bytes_per_unknown"]  # noqa: E731
                       for a, m in pairs if a["dim"] == d]
    p3 = [r for r in runs if r["dim"] == 3 and r["degree"] == 3]
    big = [r for r in p3 if r["path"] == "matrix-free" and r["n"] > 2e6]
    assembled = max((r for r in p3 if r["path"] == "assembled"), key=lambda r: r["n"])
    print(f"- Matrix-free, the peak memory per unknown is {percent_span(saved(2))} lower in 2D and "
          f"{percent_span(saved(3))} lower in 3D: {span([r['peak_bytes_per_unknown'] for r in big], 0)} bytes per "
          f"unknown at 3D P3 with {span([r['n'] / 1e6 for r in big], 1)} M unknowns, against "
          f"{assembled['peak_bytes_per_unknown']:.0f} assembled with {millions(assembled['n'])}.")
    for line in same_memory(runs):
        print(line)
    print(matrix_free_times(pairs))


def same_memory(runs):
    """For each assembled run, the largest matrix-free run of its kind within its peak memory per rank."""
    lines = []
    for a in (r for r in runs if r["path"] == "assembled"):
        within = [r for r in runs if r["path"] == "matrix-free" and (r["dim"], r["degree"]) == (a["dim"], a["degree"])
                  and r["peak_mib_max_rank"] <= a["peak_mib_max_rank"] and r["n"] > a["n"]]
        if within:
            m = max(within, key=lambda r: r["n"])
            lines.append(f"- {a['dim']}D P{a['degree']}: matrix-free, nx = {m['nx']} ({m['n']} unknowns) peaks at "
                         f"{m['peak_mib_max_rank']:.0f} MiB per rank, assembled nx = {a['nx']} ({a['n']} unknowns) "
                         f"at {a['peak_mib_max_rank']:.0f} MiB: in that memory the matrix-free path solves "
                         f"{m['n'] / a['n']:.2f} times as many unknowns.")
    return lines


def matrix_free_times(pairs):
    solve = [m["solve_seconds"] / a["solve_seconds"] for a, m in pairs]
    assembly_ = [m["assembly_seconds"] / a["assembly_seconds"] for a, m in pairs]
    total = lambda r: r["assembly_seconds"] + r["solve_seconds"]  # noqa: E731
    end = [total(m) / total(a) for a, m in pairs]
    a, m = max(pairs, key=lambda p: p[0]["n"])
    return (f"- Matrix-free, the solve takes {span(solve, 2)} times as long as assembled, the assembly "
            f"{span(assembly_, 2)} times, assembly and solve together {span(end, 2)} times ({a['dim']}D P{a['degree']} "
            f"nx = {a['nx']}: {total(m):.1f} s against {total(a):.1f} s).")


def largest(degree):
    runs = {r["path"]: r for r in records(f"matrix-free-solve-largest-p{degree}")}
    a, m = runs["assembled"], runs["matrix-free"]
    ranks = a["ranks"]
    gib = lambda r: r["peak_mib_max_rank"] * r["ranks"] / 1024  # noqa: E731
    print(f"The assembled path solves {a['n']} unknowns in {a['peak_mib_max_rank']:.0f} MiB per rank "
          f"({a['peak_bytes_per_unknown']:.0f} bytes per unknown, about {gib(a):.1f} GiB on the {ranks} ranks); the "
          f"matrix-free path {m['n']}, {m['n'] / a['n']:.2f} times as many, in {m['peak_mib_max_rank']:.0f} MiB per "
          f"rank ({m['peak_bytes_per_unknown']:.0f} bytes per unknown, about {gib(m):.1f} GiB), with "
          f"{m['cg_iterations']} CG iterations against {a['cg_iterations']} and "
          + (f"the same {a['main_iterations']} main iterations" if a["main_iterations"] == m["main_iterations"] else
             f"{m['main_iterations']} main iterations against {a['main_iterations']}")
          + ". By these figures 24 GB holds about "
          f"{MACHINE_BYTES / a['peak_bytes_per_unknown'] / 1e6:.0f} M P{degree} unknowns assembled and about "
          f"{MACHINE_BYTES / m['peak_bytes_per_unknown'] / 1e6:.0f} M matrix-free.")


# ---------------------------------------------------------------- Gmsh meshes of degree 2 and 3

def gmsh_pk_groups():
    groups = {}
    for r in records("gmsh-pk"):
        groups.setdefault((r["problem"], r["degree"], r["size_factor"]), {})[r["path"]] = r
    return list(groups.values())


def compare(groups, path, against, key):
    return [g[path][key] / g[against][key] for g in groups if path in g and against in g]


def gmsh_pk():
    groups = gmsh_pk_groups()
    step = [(g["algebraic"], g[p]) for g in groups for p in ("assembled", "matrix-free") if p in g and "algebraic" in g]
    fewer = [1 - r["cg_iterations"] / a["cg_iterations"] for a, r in step]
    same = all(r["main_iterations"] == a["main_iterations"] and r["newton_systems"] == a["newton_systems"]
               for a, r in step)
    agree = max(relative(r["objective"], first["objective"]) for g in groups
                for first in [next(iter(g.values()))] for r in g.values())
    print(f"- The P_k → P1 step (`assembled`, `matrix-free`) against MueLu alone (`algebraic`): "
          f"{percent_span(fewer)} fewer CG iterations, "
          f"{'the same' if same else 'not always the same (the table)'} main iterations and Newton systems, solves "
          f"{span([r['solve_seconds'] / a['solve_seconds'] for a, r in step], 2)} times as long; every path reaches "
          f"the same optimal value to {agree:.0e} relative.")
    peak = compare(groups, "assembled", "algebraic", "peak_mib_max_rank")
    free = compare(groups, "matrix-free", "assembled", "peak_mib_max_rank")
    print(f"- Peak memory per rank: with the step and Q assembled {span(peak, 2)} times MueLu alone's; matrix-free "
          f"{span(free, 2)} times the assembled step's.")
    print(f"- Matrix-free against Q assembled, both with the step: solve "
          f"{span(compare(groups, 'matrix-free', 'assembled', 'solve_seconds'), 2)} times as long, assembly "
          f"{span(compare(groups, 'matrix-free', 'assembled', 'assembly_seconds'), 2)} times.")
    cg = {f"{g['refined']['problem']} P{g['refined']['degree']} at size factor {g['refined']['size_factor']}":
          g["refined"]["cg_iterations"] / g["matrix-free"]["cg_iterations"] for g in groups
          if "refined" in g and "matrix-free" in g}
    print(f"- Refined at the nodes against the mesh's own P1 grid (both matrix-free): {span(cg.values(), 2)} times the "
          f"CG iterations (fewer on {words(k for k, v in cg.items() if v < 1)}), solves "
          f"{span(compare(groups, 'refined', 'matrix-free', 'solve_seconds'), 1)} times as long, peak memory "
          f"{span(compare(groups, 'refined', 'matrix-free', 'peak_mib_max_rank'), 1)} times.")


# ---------------------------------------------------------------- preconditioning

def sequence_runs(runs, sequence, config, forcing="reduction"):
    return sorted((r for key, r in runs.items() if key[0] == sequence and key[2] == config and key[3] == forcing),
                  key=lambda r: r["nx"])


def member(r):
    return f"{SEQUENCES[r['sequence']]} nx = {r['nx']}"


def targets(runs):
    met, missed = [], []
    for sequence, label in SEQUENCES.items():
        group = approximate(sequence_runs(runs, sequence, "default"))
        if len(group) < 2:
            continue
        misses = [f"{name} ({value:.2f} against {target})"
                  for name, value, target in zip(TARGET_NAMES, ratios(group), TARGETS) if value > target]
        if misses:
            missed.append(f"on {label} {words(misses)}")
        else:
            met.append(label)
    head = f"meets the three targets on {words(met)}" if met else "meets the three targets on no sequence"
    return f"- **Targets**: the default {head}" + (f"; it misses {'; '.join(missed)}." if missed else ".")


def default_counts(runs):
    parts = []
    for sequence, label in SEQUENCES.items():
        group = sequence_runs(runs, sequence, "default")
        if group:
            parts.append(f"{label} {span([r['summary']['max_krylov_per_newton'] for r in group], 0)} per system and "
                         f"{span([r['summary']['krylov_iterations'] for r in group], 0)} in all (nx = "
                         f"{group[0]['nx']}–{group[-1]['nx']}, up to {millions(group[-1]['summary']['n'])} unknowns)")
    return "- **Counts** of the default: " + "; ".join(parts) + "."


def default_steps(runs):
    defaults = [r for key, r in runs.items() if key[2] == "default" and key[3] == "reduction"]
    kept = [r for sequence in SEQUENCES for r in approximate(sequence_runs(runs, sequence, "default"))]
    first = [barrier_steps(r)[0]["krylov"] for r in defaults]
    last = [barrier_steps(r)[-1]["krylov"] for r in defaults]
    worst = max(kept, key=lambda r: barrier_steps(r)[-1]["krylov"] / max(barrier_steps(r)[0]["krylov"], 1))
    steps = barrier_steps(worst)
    ended = [r for r in defaults if r["summary"].get("active_set_finish", {}).get("accepted")]
    untried = [r for r in defaults if not r["summary"].get("active_set_finish", {}).get("attempts")]
    order = lambda rs: sorted(rs, key=lambda r: (list(SEQUENCES).index(r["sequence"]), r["nx"]))  # noqa: E731
    return (f"- **First and last steps**: the first main iteration takes {span(first, 0)} CG iterations for both "
            f"systems, the last barrier "
            f"step {span(last, 0)}; the largest last over first is {member(worst)}'s ({steps[0]['krylov']} / "
            f"{steps[-1]['krylov']}). The active-set finish ends {len(ended)} of the {len(defaults)} solves, with "
            f"{span([finish_krylov(r) for r in ended], 0) if ended else 'no'} CG iterations for its one accurate "
            f"solve" + (f"; it is not tried on {words(member(r) for r in order(untried))}." if untried else "."))


def preconditioners():
    runs = load_runs("preconditioners-forcing", "preconditioners-forcing-p2p3")
    for line in (targets(runs), default_counts(runs), default_steps(runs), filtering(runs), rebuild_time(runs),
                 adaptive(runs)):
        print(line)


def pairs_of(runs, config, forcing="reduction", against="default"):
    return [(runs[(s, nx, against, forcing)], r) for (s, nx, c, f), r in runs.items()
            if c == config and f == forcing and (s, nx, against, forcing) in runs]


def filtering(runs):
    pairs = pairs_of(runs, "unfiltered")
    cg = lambda ps: [d["summary"]["krylov_iterations"] / u["summary"]["krylov_iterations"] for d, u in ps]  # noqa: E731
    p1 = [p for p in pairs if p[0]["sequence"] in ("2d", "3d")]
    high = [p for p in pairs if p not in p1]
    largest = [max((p for p in p1 if p[0]["sequence"] == s), key=lambda p: p[0]["nx"]) for s in ("2d", "3d")]
    last = lambda ps, i: [barrier_steps(p[i])[-1]["krylov"] for p in ps]  # noqa: E731
    return (f"- **Filtering**, the default against unfiltered: {span(cg(p1), 2)} times the CG iterations on the P1 "
            f"members (" + "; ".join(f"{member(d)}: {d['summary']['krylov_iterations']} against "
                                     f"{u['summary']['krylov_iterations']}" for d, u in largest)
            + f"), {span(cg(high), 2)} times on P2/P3; the last barrier step of the P2/P3 members takes "
            f"{span(last(high, 0), 0)} CG iterations filtered, {span(last(high, 1), 0)} unfiltered.")


def time_ratios(pairs):
    return {member(new): new["summary"]["time"]["solve"] / old["summary"]["time"]["solve"] for old, new in pairs}


def rebuild_time(runs):
    pairs = pairs_of(runs, "lagged rebuild")
    setups = lambda i: span([p[i]["summary"]["preconditioner_setups"] for p in pairs], 0)  # noqa: E731
    cg = [new["summary"]["krylov_iterations"] / old["summary"]["krylov_iterations"] for old, new in pairs]
    most = max(new["summary"]["max_krylov_per_newton"] for _, new in pairs)
    small = time_ratios([p for p in pairs if p[0]["summary"]["n"] < LARGE])
    large = time_ratios([p for p in pairs if p[0]["summary"]["n"] >= LARGE])
    unfiltered = time_ratios(pairs_of(runs, "unfiltered"))
    case = next(c for c in results("reference-solve")["cases"] if c["problem"] == "family/3d-p1-nx64")["contact"]
    return (f"- **Lagged rebuild** against the default: {setups(1)} AMG setups instead of {setups(0)}, "
            f"{span(cg, 2)} times the CG iterations (up to {most} per system); its solve takes "
            f"{span(small.values(), 2)} times the default's below 10⁵ unknowns, {ratio_clause(small, True, 'faster')}, "
            f"and {span(large.values(), 2)} times above, {ratio_clause(large, True, 'faster')}. The unfiltered AMG's "
            f"solve takes {span(unfiltered.values(), 2)} times the default's. In `reference-solve.json` the "
            f"{case['amg_setups']} AMG setups of 3D P1 nx = 64 take {seconds(case['seconds']['amg_setup'])} s of its "
            f"{seconds(case['seconds']['solve'])} s solve.")


def adaptive(runs):
    pairs = [(runs[(s, nx, c, "reduction")], r) for (s, nx, c, f), r in runs.items()
             if c == "default" and f == "adaptive" and r["summary"]["n"] >= LARGE and (s, nx, c, "reduction") in runs]
    times = time_ratios(pairs)
    cg = [a["summary"]["krylov_iterations"] / d["summary"]["krylov_iterations"] for d, a in pairs]
    every = [r for key, r in runs.items() if key[2] == "default" and key[3] == "adaptive"]
    return (f"- **Adaptive against reduction forcing**, default preconditioner, members with more than 10⁵ unknowns: "
            f"the adaptive forcing's solve takes {span(times.values(), 2)} times the reduction's, "
            f"{ratio_clause(times, True, 'faster')}, with {span(cg, 2)} times its CG iterations. Its first main "
            f"iteration takes {span([barrier_steps(r)[0]['krylov'] for r in every], 0)} CG iterations for both "
            f"systems, its last barrier step {span([barrier_steps(r)[-1]['krylov'] for r in every], 0)}.")


# ---------------------------------------------------------------- one component out at a time

def largest_members(pairs):
    return [max((p for p in pairs if p[0]["sequence"] == s), key=lambda p: p[0]["nx"])
            for s in ("2d", "3d") if any(p[0]["sequence"] == s for p in pairs)]


def against(pairs, key="krylov_iterations"):
    return "; ".join(f"{member(old)}: {new['summary'][key]} against {old['summary'][key]}"
                     for old, new in largest_members(pairs))


def starting_vectors(runs):
    lines = []
    for config, name in (("without contact-corrected start", "without the correction of the projected start"),
                         ("from zero", "from zero")):
        pairs = pairs_of(runs, config)
        more_it = [n["summary"]["outer_iterations"] - o["summary"]["outer_iterations"] for o, n in pairs]
        cg = [n["summary"]["krylov_iterations"] / o["summary"]["krylov_iterations"] for o, n in pairs]
        lines.append(f"{name}, {span(more_it, 0)} more main iterations and {span(cg, 2)} times the CG "
                     f"iterations ({against(pairs)})")
    pair = largest_members(pairs_of(runs, "from zero"))[-1][0]
    table_run = load_runs("preconditioners-forcing")[(pair["sequence"], pair["nx"], "default", "reduction")]
    case = next((c for c in results("reference-solve")["cases"]
                 if c["contact"]["n"] == pair["summary"]["n"] and c["ranks"] == pair["ranks"]), None)
    reference = (f" and {seconds(case['contact']['seconds']['solve'])} s in `reference-solve.json` (the fastest of "
                 f"{case['repeats']})" if case else "")
    return (f"- **Starting vectors**: {lines[0]}; {lines[1]}. The default run of {member(pair)} took "
            f"{seconds(pair['summary']['time']['solve'])} s in this set, "
            f"{seconds(table_run['summary']['time']['solve'])} s in the preconditioning table's{reference}.")


def finish(runs):
    pairs = pairs_of(runs, "without active-set finish")
    listed = lambda keep: words(member(o) for o, n in pairs if keep(o, n))  # noqa: E731
    it = lambda o, n: n["summary"]["outer_iterations"] - o["summary"]["outer_iterations"]  # noqa: E731
    cg = lambda o, n: n["summary"]["krylov_iterations"] - o["summary"]["krylov_iterations"]  # noqa: E731
    three = sorted((p for p in pairs if p[0]["sequence"] == "3d"), key=lambda p: p[0]["nx"])
    totals = lambda i: " to ".join(str(three[j][i]["summary"]["krylov_iterations"]) for j in (0, -1))  # noqa: E731
    times = time_ratios([(n, o) for o, n in pairs])
    return (f"- **Active-set finish**, with it against without: fewer main iterations on "
            f"{listed(lambda o, n: it(o, n) > 0)}, more on {listed(lambda o, n: it(o, n) < 0)}; fewer CG iterations "
            f"on {listed(lambda o, n: cg(o, n) > 0)}, more on {listed(lambda o, n: cg(o, n) < 0)}; the solve takes "
            f"{span(times.values(), 2)} times as long. The 3D P1 totals from nx = {three[0][0]['nx']} to "
            f"{three[-1][0]['nx']}: {totals(0)} with it, {totals(1)} without.")


def geometric_against_algebraic(runs):
    fixed = lambda config, s: [r["summary"]["max_krylov_per_newton"]  # noqa: E731
                               for r in sequence_runs(runs, s, config, "relative")]
    pairs = pairs_of(runs, "algebraic")
    memory = "; ".join(f"{member(o)}: {n['summary']['memory_mib']['max_rank'] / 1024:.2f} GiB against "
                       f"{o['summary']['memory_mib']['max_rank'] / 1024:.2f}" for o, n in largest_members(pairs))
    times = "; ".join(f"{member(o)}: {seconds(n['summary']['time']['solve'])} s against "
                      f"{seconds(o['summary']['time']['solve'])} s" for o, n in largest_members(pairs))
    return (f"- **Geometric levels against MueLu alone**: at the fixed accuracy the largest count per system is "
            f"{span(fixed('algebraic', '2d'), 0)} "
            f"in 2D and {span(fixed('algebraic', '3d'), 0)} in 3D with MueLu alone, {span(fixed('default', '2d'), 0)} "
            f"and {span(fixed('default', '3d'), 0)} with the geometric levels. Solve with MueLu alone against the "
            f"geometric levels: "
            f"{span(time_ratios(pairs).values(), 1)} times as long ({times}). Peak memory per rank: {memory}.")


def amg_of_q(runs):
    pairs = [(runs[(s, nx, "algebraic", f)], r) for (s, nx, c, f), r in runs.items()
             if c == "algebraic amg of Q" and f == "reduction" and (s, nx, "algebraic", f) in runs]
    fixed = [(runs.get((o["sequence"], o["nx"], "algebraic", "relative")),
              runs.get((o["sequence"], o["nx"], "algebraic amg of Q", "relative"))) for o, _ in largest_members(pairs)]
    counts = "; ".join(f"{member(o)}: {n['summary']['max_krylov_per_newton']} against "
                       f"{o['summary']['max_krylov_per_newton']}" for o, n in fixed if o and n)
    times = time_ratios(pairs)
    once = span([n["summary"]["preconditioner_setups"] for _, n in pairs], 0)
    return (f"- **AMG of Q**, set up {'once' if once == '1' else once + ' times'} against "
            f"{span([o['summary']['preconditioner_setups'] for o, _ in pairs], 0)} for MueLu's AMG of H: its solve "
            f"takes {span(times.values(), 2)} times as long, {ratio_clause(times, True, 'faster')} ({against(pairs)} "
            f"CG iterations); the largest count per system at 1e-8, AMG of Q against AMG of H: {counts}.")


def components():
    runs = load_runs("preconditioners-components")
    for line in (starting_vectors(runs), finish(runs), geometric_against_algebraic(runs), amg_of_q(runs)):
        print(line)


def algebraic_rebuild():
    runs = load_runs("preconditioners-algebraic-rebuild")
    pairs = pairs_of(runs, "algebraic default", against="algebraic")
    same = all(o["summary"]["outer_iterations"] == n["summary"]["outer_iterations"] for o, n in pairs)
    more = [n["summary"]["krylov_iterations"] / o["summary"]["krylov_iterations"] - 1 for o, n in pairs]
    per_dim = []
    for sequence in ("2d", "3d"):
        chosen = [p for p in pairs if p[0]["sequence"] == sequence]
        old, new = max(chosen, key=lambda p: p[0]["nx"])
        per_dim.append(f"{span(time_ratios(chosen).values(), 2)} times in {SEQUENCES[sequence][:2]} (nx = "
                       f"{min(p[0]['nx'] for p in chosen)}–{old['nx']}; nx = {old['nx']}: "
                       f"{seconds(new['summary']['time']['solve'])} s against "
                       f"{seconds(old['summary']['time']['solve'])} s,"
                       f" at most {new['summary']['max_krylov_per_newton']} CG iterations per system against "
                       f"{old['summary']['max_krylov_per_newton']})")
    setups = lambda i: span([p[i]["summary"]["preconditioner_setups"] for p in pairs], 0)  # noqa: E731
    print(f"Rebuilt when constraints switch, MueLu alone takes {setups(1)} setups instead of {setups(0)}, "
          f"{'the same' if same else 'not always the same'} main iterations and {percent_span(more)} more CG "
          f"iterations; its solve takes the rebuild at every step's {' and '.join(per_dim)}.")


# ---------------------------------------------------------------- forcing safety, MueLu variants

DEFAULT_SAFETY = 0.3  # the default of Solver/forcing: safety
LARGEST_SAFETY = 0.9  # the largest the parameter accepts


def forcing_safety():
    by = {}
    for r in records("forcing"):
        if r["safety"] <= LARGEST_SAFETY:
            by.setdefault(r["problem"], {})[r["safety"]] = r["summary"]
    low, high = min(next(iter(by.values()))), max(next(iter(by.values())))
    cg = [s[high]["krylov_iterations"] / s[low]["krylov_iterations"] for s in by.values()]
    it = [s[high]["outer_iterations"] - s[low]["outer_iterations"] for s in by.values()]
    spread = [max(t) / min(t) - 1 for t in
              ([v["time"]["solve"] for k, v in s.items() if k >= DEFAULT_SAFETY] for s in by.values())]
    largest = [max((s for s in by.values() if s[low]["d"] == d), key=lambda s: s[low]["n"]) for d in (2, 3)]
    examples = "; ".join(f"{name}: {s[low]['krylov_iterations']} and {s[high]['krylov_iterations']}"
                         for name, s in by.items() if any(s is chosen for chosen in largest))
    print(f"From safety {low} to {high} the CG iterations of a solve fall to {percent_span(cg)} of theirs "
          f"({examples}), for {span(it, 0)} more main iterations; from {DEFAULT_SAFETY} (the default) upward the "
          f"slowest solve of a problem took {percent_span(spread)} longer than its fastest.")


DEFAULT_ETA = 0.3  # the default of Solver/forcing: eta


def forcing_reduction():
    by = {}
    for r in records("forcing-reduction"):
        by.setdefault(r["problem"], {})[r["eta"]] = r["summary"]
    etas = sorted(next(iter(by.values())))
    low = etas[0]
    for eta in etas[1:]:
        runs = [(s[low], s[eta]) for s in by.values()]
        cg = [b["krylov_iterations"] / a["krylov_iterations"] for a, b in runs]
        it = [b["outer_iterations"] - a["outer_iterations"] for a, b in runs]
        large = [(a, b) for a, b in runs if a["n"] > LARGE]
        time = [b["time"]["solve"] / a["time"]["solve"] for a, b in large]
        failed = [p for p, s in by.items() if not s[eta]["converged"]]
        print(f"- **eta {eta}**{' (the default)' if eta == DEFAULT_ETA else ''}: {percent_span(cg)} of the CG "
              f"iterations at eta {low}, {span(it, 0)} more main iterations; on the {len(large)} problems with more "
              f"than 10⁵ unknowns the solve takes {span(time, 2)} times its time at eta {low}; "
              f"{'every run converged' if not failed else 'failed: ' + words(failed)}.")


def amg_variants():
    runs = records("amg-variants")
    dims = {f"paper/{r['summary']['problem']}": r["summary"]["d"] for r in records("table2")}
    dim = lambda p: dims.get(p, 3 if "/3d" in p else 2)  # noqa: E731
    by = {(r["variant"], r["problem"]): r for r in runs}
    problems = sorted({r["problem"] for r in runs}, key=lambda p: (dim(p), by[("geometric levels", p)]["n"]))
    largest = [max((p for p in problems if dim(p) == d), key=lambda p: by[("geometric levels", p)]["n"])
               for d in (2, 3)]
    variants = list(dict.fromkeys(r["variant"] for r in runs))
    geometric, sa = variants[0], variants[1]
    exact = [p for p in problems if by[(variants[0], p)]["max_per_system"] == 1]  # the coarsest grid the whole mesh
    first = lambda v, d: [by[(v, p)]["krylov_first_iteration"] for p in problems  # noqa: E731
                          if dim(p) == d and (v != variants[0] or p not in exact)]
    cheapest = [p for p in problems if by[(geometric, p)]["amg_setup_seconds"] ==
                min(by[(v, p)]["amg_setup_seconds"] for v in variants)]
    setup = [by[(sa, p)]["amg_setup_seconds"] / by[(geometric, p)]["amg_setup_seconds"] for p in problems]
    complexity = lambda d: [by[(sa, p)]["operator_complexity"] for p in problems if dim(p) == d]  # noqa: E731
    solved = "".join(f" ({p} is solved exactly: {by[(geometric, p)]['krylov_first_iteration']})" for p in exact)
    print(f"- {geometric.capitalize()}: {span(first(geometric, 2), 0)} CG iterations in the first main iteration in "
          f"2D, {span(first(geometric, 3), 0)} in 3D{solved}; its setup is the cheapest of the table's on "
          f"{'every problem' if len(cheapest) == len(problems) else words(cheapest) or 'no problem'}.")
    print(f"- {sa.capitalize()}: {span(first(sa, 2), 0)} in 2D and {span(first(sa, 3), 0)} in 3D, from the "
          f"smallest problem to the largest; operator complexity {span(complexity(2), 2)} in 2D, "
          f"{span(complexity(3), 2)} in 3D; setup {span(setup, 1)} times the geometric levels'.")
    base = [by[(sa, p)] for p in largest]
    both = lambda cells, key: " and ".join(str(c[key]) for c in cells)  # noqa: E731
    print(f"- On the largest problems, {' and '.join(largest)}, against smoothed aggregation's "
          f"{both(base, 'krylov_first_iteration')} CG iterations (operator complexity "
          f"{both(base, 'operator_complexity')}):")
    for v in variants[2:]:
        cells = [by[(v, p)] for p in largest]
        ratio = lambda key: span([c[key] / b[key] for c, b in zip(cells, base)], 2)  # noqa: E731
        print(f"  - {v}: {both(cells, 'krylov_first_iteration')} CG iterations, operator complexity "
              f"{both(cells, 'operator_complexity')}, setup {ratio('amg_setup_seconds')} times and Krylov time "
              f"{ratio('krylov_seconds')} times smoothed aggregation's.")


# ---------------------------------------------------------------- force control

def force_control():
    runs = records("force-control")
    converged = all(r["force"]["status"] == "converged" for r in runs)
    it = [r["force"]["main_iterations"] / r["displacement"]["main_iterations"] for r in runs]
    cg = lambda rs, key="displacement": [r["force"]["cg_iterations"] / r[key]["cg_iterations"]  # noqa: E731
                                         for r in rs]
    default = lambda r: r["formulation"] == ("dual mortar" if "P2" in r["case"] else "nodal")  # noqa: E731
    defaults = [r for r in runs if default(r)]
    gaps = [r for r in runs if r["formulation"] == "weighted gap"]
    worst = max(defaults, key=lambda r: r["force"]["cg_iterations"] / r["displacement"]["cg_iterations"])
    label = lambda r: f"{r['case']} ({r['method']}, {r['formulation']})"  # noqa: E731
    reached = lambda r: all(r[c]["status_at_fixed_accuracy"] == "converged"  # noqa: E731
                            for c in ("force", "displacement"))
    fixed = {label(r): r["force"]["cg_per_system_at_fixed_accuracy"] / r["displacement"]["cg_per_system_at_fixed_accuracy"]
             for r in runs if reached(r)}
    short = [label(r) for r in runs if not reached(r)]
    more = [k for k, v in fixed.items() if v > 1]
    print(f"- {'Every' if converged else 'Not every'} force-controlled run converges, in {span(it, 2)} times the "
          f"main iterations of its displacement-controlled counterpart.")
    print(f"- CG iterations per Newton system at the fixed accuracy, force over displacement control: "
          f"{span(fixed.values(), 2)}; more under force control on {words(more) if more else 'none'}"
          + (f"; {words(short)} did not reach that accuracy (left out)." if short else "."))
    methods = [span(cg([r for r in defaults if r["method"] == method]), 2) for method in ("primal-dual", "primal")]
    print(f"- At the defaults (nodal constraints for P1, dual mortar for P2) the force-controlled runs take "
          f"{methods[0]} times the CG iterations of their counterparts with the primal-dual method, {methods[1]} with "
          f"the primal one (the most: {worst['case']}, {worst['method']}); with weighted gaps {span(cg(gaps), 2)}.")
    same = [r for r in runs if r["formulation"] != "weighted gap"]
    print(f"- Against counterparts solved to the same absolute stationarity: "
          f"{span(cg(same, 'displacement_same_forces'), 2)} times the CG iterations with nodal constraints and dual "
          f"mortar, {span(cg(gaps, 'displacement_same_forces'), 2)} with weighted gaps.")


# ---------------------------------------------------------------- Gmsh meshes, two bodies, incompressibility

def gmsh_runs():
    return {(r["case"], r["mesh"], r["ranks"], r["solve"]): r for r in records("gmsh-meshes")}


def mesh_ratio(runs, mesh, base, key, cases, solve="contact"):
    return [r[key] / runs[(c, base, ranks, solve)][key] for (c, m, ranks, s), r in runs.items()
            if m == mesh and s == solve and c in cases and (c, base, ranks, solve) in runs]


def gmsh_meshes():
    runs = gmsh_runs()
    cases = sorted({key[0] for key in runs})
    flat, deep = [c for c in cases if c.startswith("2d")], [c for c in cases if c.startswith("3d")]
    refined = sorted({key[1] for key in runs if key[1].startswith("refined")})

    def against(meshes, base, key, chosen, digits=2, solve="contact"):
        return span([x for mesh in meshes for x in mesh_ratio(runs, mesh, base, key, chosen, solve)], digits)

    print(f"- 2D, the refined Gmsh mesh against the box: wall {against(refined, 'box', 'wall_seconds', flat)} "
          f"times, solve {against(refined, 'box', 'solve_seconds', flat)} times, CG iterations "
          f"{against(refined, 'box', 'cg_iterations', flat)} times.")
    for mesh in refined:
        chosen = [c for c in deep if any(key[:2] == (c, mesh) for key in runs)]
        if chosen:
            print(f"- 3D, {mesh} against the box ({', '.join(chosen)}): wall "
                  f"{against([mesh], 'box', 'wall_seconds', chosen)} times, "
                  f"{against([mesh], 'box', 'cg_iterations', chosen)} times the CG iterations of the contact solve, "
                  f"{against([mesh], 'box', 'cg_iterations', chosen, solve='linear')} times those of the linear solve.")
    setups = lambda meshes: [r["multigrid_setups"] for (c, m, _, s), r in runs.items()  # noqa: E731
                             if m in meshes and s == "contact" and "-p1" in c]
    print(f"- P1 on the `.msh` meshes: {span(setups(('msh', 'parts')), 0)} multigrid setups per contact solve "
          f"(box: {span(setups(('box',)), 0)}). Read in parts against read whole: setup "
          f"{against(['parts'], 'msh', 'setup_seconds', cases)} times, rank 0's growth "
          f"{against(['parts'], 'msh', 'rank0_setup_mib', cases)} times.")
    print(f"- Refined against the box: setup {against(refined, 'box', 'setup_seconds', cases, 1)} times, rank 0's "
          f"growth {against(refined, 'box', 'rank0_setup_mib', cases, 1)} times.")
    for (case, mesh, ranks, solve), r in sorted(runs.items()):
        one = runs.get((case, mesh, 1, solve))
        if ranks > 2 and solve == "contact" and mesh != "box" and one:
            print(f"- {case}, {mesh} on {ranks} ranks: rank 0's setup growth {r['rank0_setup_mib']:.0f} MiB, "
                  f"{r['rank0_setup_mib'] / one['rank0_setup_mib']:.2f} times its growth on 1 rank.")


PRESSURE = 0.01  # the pressure bench/two_bodies.py applies on a unit area: the load and the pressure


def two_bodies():
    contact = [r for r in records("two-bodies") if r["solve"] == "contact"]
    force = max(relative(r["normal_force"], PRESSURE) for r in contact)
    pressure = max(relative(r["peak_pressure"], PRESSURE) for r in contact)
    masters = [r for r in contact if r["master_force"]]
    # The slave side's force and the master body's, as vectors: their vertical components.
    opposite = max(relative(-r["master_force"][-1], r["force"][-1]) for r in masters)
    print(f"The contact force differs from the load ({PRESSURE}) by at most {force:.0e} relative, the largest "
          f"pressure from the applied one by at most {pressure:.0e}, and the master body's force from the contact "
          f"force's opposite by at most {opposite:.0e}.")


def incompressibility():
    runs = records("incompressibility")
    cg = {(r["problem"], r["config"], r["nu"]): r["summary"]["krylov_iterations"] for r in runs}
    time = {(r["problem"], r["config"], r["nu"]): r["summary"]["time"]["solve"] for r in runs}
    problems = list(dict.fromkeys(r["problem"] for r in runs))
    configs = list(dict.fromkeys(r["config"] for r in runs))
    nus = sorted({r["nu"] for r in runs})
    low, high = [nu for nu in nus if nu >= 0.49][0], nus[-1]
    growth = ((1 - 2 * low) / (1 - 2 * high)) ** 0.5
    grows = words(f"{span([cg[(p, config, high)] / cg[(p, config, low)] for p in problems], 1)} "
                  + ("times with the default" if config == "default" else f"with {config}") for config in configs)
    converged = all(r["summary"]["converged"] for r in runs)
    parts = []
    for config in configs[1:]:
        its = [cg[(p, config, high)] / cg[(p, "default", high)] for p in problems]
        secs = [time[(p, config, high)] / time[(p, "default", high)] for p in problems]
        parts.append(f"{config} {span(its, 2)} times the default's CG iterations in {span(secs, 2)} times its time")
    print(f"{'Every run converges' if converged else 'Not every run converges'} to the default KKT tolerance. From "
          f"ν = {low} to {high}, where 1/(1 − 2ν)^(1/2) grows {growth:.0f} times, the CG iterations on "
          f"{words(p.split('/')[-1] for p in problems)} grow {grows}. At ν = {high}: " + "; ".join(parts) + ".")


SECTIONS = {
    "noise": noise,  # reference-solve.json
    "table2": table2,  # table2.json
    "fixed-centering": fixed_centering,  # table2-fixed-centering.json, table2.json
    "reference-solve": reference_solve,  # reference-solve.json
    "ipopt": ipopt,  # ipopt.json
    "assembly": assembly,  # assembly.json
    "expression": expression,  # expression.json
    "direct-solvers": direct_solvers,  # direct-solvers.json
    "matrix-free": matrix_free,  # matrix-free.json
    "matrix-free-solve": matrix_free_solve,  # matrix-free-solve.json
    "largest-p3": lambda: largest(3),  # matrix-free-solve-largest-p3.json
    "largest-p2": lambda: largest(2),  # matrix-free-solve-largest-p2.json
    "gmsh-pk": gmsh_pk,  # gmsh-pk.json
    "preconditioners": preconditioners,  # preconditioners-forcing{,-p2p3}.json, reference-solve.json
    "components": components,  # preconditioners-components.json, preconditioners-forcing.json, reference-solve.json
    "algebraic-rebuild": algebraic_rebuild,  # preconditioners-algebraic-rebuild.json
    "forcing": forcing_safety,  # forcing.json
    "forcing-reduction": forcing_reduction,  # forcing-reduction.json
    "amg-variants": amg_variants,  # amg-variants.json, table2.json (the paper's problems' dimension)
    "force-control": force_control,  # force-control.json
    "gmsh-meshes": gmsh_meshes,  # gmsh-meshes.json
    "two-bodies": two_bodies,  # two-bodies.json
    "incompressibility": incompressibility,  # incompressibility.json
}


if __name__ == "__main__":
    run(SECTIONS)

#!/usr/bin/python3
"""The measured figures that doc/performance-model.md quotes in its prose, from the JSON in
bench/results (standard library only, like every script that scripts/benchmarks_md.py runs):

    /usr/bin/python3 bench/performance_model_figures.py SECTION

SECTION is one of
  family         iterations per solve of problems A-M (table2.json, primal-dual, 1 rank);
  memory         nonzeros per row of Q (assembly.json), operator complexity of MueLu's
                 hierarchy (amg-variants.json), peak memory per unknown of whole 3D P1 solves
                 (reference-solve.json) and of the assembly benchmark (assembly.json);
  matrix-free    the matrix-free stiffness's stored bytes per unknown (matrix-free.json) and
                 whole 3D P2/P3 solves per unknown beyond a rank's fixed memory
                 (matrix-free-solve*.json, the fixed memory being problem A's peak in table2.json);
  iterations     whether the iterations of the communication runs depend on the rank count;
  reductions     all-reduces per CG iteration and Newton system, MPI_Reduce calls per
                 preconditioner setup (communication.json, 2 ranks);
  calibration    the messages per neighbour and CG iteration the model is calibrated with;
  agreement      the model against the counts at more ranks (bench/performance_model.py check);
  beyond         what the predictions of bench/performance_model.py predict say.
Each prints Markdown: a sentence or a bullet list.
"""
from performance_model import CASES, calibration, check_rows, prediction_rows
from quoted_figures import count, records, results, run, span

DIMENSION = {"2d-p1-nx200": "2D", "3d-p1-nx40": "3D"}


def signed_span(values):
    """"+3% to +23%" over the percentages, or "+3%" if they are all alike."""
    low, high = f"{min(values):+.0f}%", f"{max(values):+.0f}%"
    return low if low == high else f"{low} to {high}"


def family():
    runs = [r["summary"] for r in records("table2") if r["summary"]["method"] == "primal-dual"]
    ranks = span([s["ranks"] for s in runs])
    print(f"Per solve of problems A–M with the primal-dual method ({ranks} rank, `bench/results/table2.json`): "
          f"{span([s['outer_iterations'] for s in runs])} main iterations, "
          f"{span([s['newton_steps'] for s in runs])} Newton systems, "
          f"{span([s['krylov_iterations'] for s in runs])} CG iterations in all.")


def mueLu_complexity():
    """Operator complexity of MueLu's smoothed aggregation alone, per dimension."""
    dims = {s["summary"]["problem"]: s["summary"]["d"] for s in records("table2")}
    by_dim = {}
    for r in records("amg-variants"):
        if r["variant"] == "smoothed aggregation" and r["operator_complexity"] is not None:
            name = r["problem"].split("/")[1]
            dim = dims.get(name) or int(name[0])  # "paper/J", or "family/3d-p1-nx40"
            by_dim.setdefault(dim, []).append(r["operator_complexity"])
    return ", ".join(f"{span(v, 2)} in {d}D P1" for d, v in sorted(by_dim.items()))


def memory():
    assembly = records("assembly")
    rows = {(r["dim"], r["degree"]): r["nonzeros"] / r["n"] for r in assembly if r["ranks"] == 1}
    print("- Nonzeros per row of Q (`bench/results/assembly.json`): "
          + ", ".join(f"{v:.0f} in {d}D P{k}" for (d, k), v in sorted(rows.items())) + ".")
    print(f"- Operator complexity of MueLu's hierarchy alone (smoothed aggregation, "
          f"`bench/results/amg-variants.json`): {mueLu_complexity()}.")
    cases = [c for c in results("reference-solve")["cases"] if c["problem"].startswith("family/3d-p1")]
    largest = sorted(cases, key=lambda c: c["contact"]["n"])[-2:]
    print("- Peak memory of whole 3D P1 solves (`bench/results/reference-solve.json`): "
          + ", ".join(f"{c['contact']['peak_bytes_per_unknown']:.0f} bytes per unknown at "
                      f"{c['problem'].split('-')[-1].replace('nx', 'nx = ')} ({count(c['contact']['n'])} unknowns, "
                      f"{c['ranks']} ranks)" for c in largest) + ".")
    big = max((r for r in assembly if (r["dim"], r["degree"]) == (3, 1)), key=lambda r: r["n"])
    runs = sorted((r for r in assembly if (r["dim"], r["degree"], r["nx"]) == (3, 1, big["nx"])),
                  key=lambda r: r["ranks"])
    print(f"- Peak resident memory of the assembly benchmark, 3D P1 with {count(big['n'])} unknowns "
          "(`bench/results/assembly.json`), each rank making only its part of the mesh: "
          + ", ".join(f"{r['peak_rss_mib_max_rank']:.0f} MiB on " + ("1 rank" if r["ranks"] == 1 else
                      f"the largest of {r['ranks']} ranks") for r in runs) + ".")


def fixed_mib():
    """A rank's fixed memory: the peak of problem A (50 unknowns) on one rank."""
    run = next(r["summary"] for r in records("table2") if r["summary"]["problem"] == "A")
    return run["memory_mib"]["max_rank"]


def matrix_free():
    stored = [r for r in records("matrix-free") if r["degree"] > 1]
    parts = []
    for dim, degree in sorted({(r["dim"], r["degree"]) for r in stored}):
        same = [r for r in stored if (r["dim"], r["degree"]) == (dim, degree)]
        free = [r["matrix_free_bytes_per_unknown"] for r in same]
        assembled = [r["assembled_bytes_per_unknown"] for r in same]
        parts.append(f"{span(free, 0)} bytes at {dim}D P{degree} ({span(assembled, 0)} assembled)")
    print("- Stored per unknown by the matrix-free stiffness (`bench/results/matrix-free.json`): "
          + ", ".join(parts) + ".")
    runs = [r for name in ("matrix-free-solve", "matrix-free-solve-largest-p2", "matrix-free-solve-largest-p3")
            for r in records(name) if r["dim"] == 3 and r["status"] == "converged"]
    fixed = fixed_mib()
    parts = []
    for degree in sorted({r["degree"] for r in runs}):
        for path in ("matrix-free", "assembled"):
            r = max((r for r in runs if r["degree"] == degree and r["path"] == path), key=lambda r: r["n"])
            beyond = r["peak_bytes_per_unknown"] - r["ranks"] * fixed * 2 ** 20 / r["n"]
            parts.append(f"3D P{degree} {path} {beyond:.0f} bytes per unknown ({count(r['n'])} unknowns)")
    print(f"- Whole solves on the largest members of `bench/results/matrix-free-solve*.json`, beyond a rank's "
          f"fixed {fixed:.0f} MiB (the peak of problem A): " + ", ".join(parts) + ".")


def two_ranks():
    return {r["case"]: r for r in records("communication") if r["ranks"] == 2}


def iterations():
    runs = records("communication")
    for case in CASES:
        counts = sorted({(r["main_iterations"], r["newton_systems"], r["cg_iterations"])
                         for r in runs if r["case"] == case})
        ranks = ", ".join(str(r) for r in sorted(r["ranks"] for r in runs if r["case"] == case))
        if len(counts) == 1:
            main, newton, cg = counts[0]
            print(f"- {case}: {main} main iterations, {newton} Newton systems and {cg} CG iterations on each "
                  f"of {ranks} ranks.")
        else:
            print(f"- {case}: main iterations, Newton systems and CG iterations vary over {ranks} ranks "
                  f"({'; '.join(f'{m}, {n}, {c}' for m, n, c in counts)}).")


def reduces_per_setup(run):
    """MPI_Reduce calls per rank and preconditioner setup: one per new Import or Export plan."""
    calls = run["functions"]["preconditioner_setup"]["calls"].get("MPI_Reduce", 0)
    return calls / run["ranks"] / run["preconditioner_setups"]


def reductions():
    runs = two_ranks()
    per_cg = ", ".join(f"{r['per_cg_iteration']['allreduces']['max']:.1f} in {DIMENSION[c]}" for c, r in runs.items())
    per_newton = ", ".join(f"{r['per_newton_system']['allreduces']['max']:.0f} in {DIMENSION[c]}"
                           for c, r in runs.items())
    plans = ", ".join(f"{reduces_per_setup(r):.0f} in {DIMENSION[c]}" for c, r in runs.items())
    print("On 2 ranks (`bench/results/communication.json`, " + " and ".join(runs) + "):")
    print()
    print(f"- all-reduces per CG iteration: {per_cg}; per Newton system: {per_newton};")
    print(f"- MPI_Reduce calls per rank and preconditioner setup: {plans}.")


def calibration_figures():
    runs = records("communication")
    halos = ", ".join(f"{calibration(runs, c)[0]:.1f} in {DIMENSION[c]}" for c in CASES)
    print(f"E = {halos} (`bench/results/communication.json`).")


def percent(model, measured):
    return 100 * (model - measured) / measured


def agreement():
    rows = check_rows()
    volume = max(abs(percent(r["model_bytes"], r["bytes"])) for r in rows)
    print(f"- Bytes sent: the model is within {volume:.0f}% of the counts.")
    for case in CASES:
        errors = [percent(r["model_messages"], r["messages"]) for r in rows if r["case"] == case]
        print(f"- Messages, {case}: the model is off by {signed_span(errors)} "
              f"at {span([r['ranks'] for r in rows if r['case'] == case])} ranks.")


def beyond():
    rows = prediction_rows()
    weak = [r for r in rows if r["scaling"].startswith("weak")]
    strong = [r for r in rows if r["scaling"].startswith("strong")]
    share = ", ".join(f"{r['compute'] / r['total']:.0%} at {r['ranks']}" for r in weak)
    print(f"- Weak scaling: the compute's share of a CG iteration is {share} ranks.")
    over = [r["ranks"] for r in strong if r["gather"] > r["compute"]]
    last = strong[-1]
    counts = ", ".join(str(r["ranks"]) for r in strong)
    where = f"at {', '.join(map(str, over))} of {counts} ranks" if over else f"at none of {counts} ranks"
    print(f"- Strong scaling: the coarsest-grid gather exceeds the compute {where} "
          f"({1e3 * last['gather']:.2f} against {1e3 * last['compute']:.2f} ms at {last['ranks']} ranks).")
    print(f"- Halo latency per CG iteration: {span([1e3 * r['latency'] for r in rows], 2)} ms "
          f"({span([r['neighbours'] for r in rows])} neighbours); all-reduces at most "
          f"{1e3 * max(r['reduce'] for r in rows):.2f} ms.")


SECTIONS = {"family": family, "memory": memory, "matrix-free": matrix_free, "iterations": iterations,
            "reductions": reductions,
            "calibration": calibration_figures, "agreement": agreement, "beyond": beyond}

if __name__ == "__main__":
    run(SECTIONS)

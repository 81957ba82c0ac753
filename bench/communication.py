#!/usr/bin/python3
"""Messages and bytes per phase of a solve against the rank count, counted by the MPI
profiling library of bench/mpi_counters.cpp: what a scaling run on a cluster would send.

    /usr/bin/python3 bench/communication.py [--ranks 1,2,4,8,16] [--cases 3d-p1-nx40,2d-p1-nx200]
        [--xml FILE.xml ...] [--set "Sublist/name=value" ...] [--name BASENAME] [--table]

For every case and rank count it runs build/bin/signorini under mpirun (more ranks than cores
are oversubscribed: the counts are exact, the times mean nothing) with
build/bench/libsignorini_mpi_counters.so preloaded (the CMake target signorini_mpi_counters,
built here if missing) and SIGNORINI_MPI_COUNTERS naming a file, reads that file and the
run's summary.json, and writes into bench/results NAME.json and NAME.md ("communication" by
default). --xml adds inputs of your own (the case is the file's name), --set overrides a
parameter in every run; --table rewrites NAME.md from NAME.json without running anything.

The counters split a run by the MPI_Pcontrol levels Signorini sets: mesh_and_space, assembly,
solve (the interior point iterations but for the next two), krylov (the CG iterations with
their preconditioner applications), preconditioner_setup (multigrid, AMG and contact-subspace
setups), output and other. Per case and rank count NAME.json holds n, m, the main
iterations, Newton systems and CG iterations, then
  per_cg_iteration: phase krylov divided by the CG iterations of the run,
  per_newton_system: phases solve + preconditioner_setup divided by the Newton systems,
each with messages_sent, bytes_sent and allreduces as {"max": over ranks, "mean": over
ranks}; setup: the totals of phases mesh_and_space and assembly ({"max", "mean"} per rank
of messages_sent, bytes_sent, collectives, collective_bytes); and the counters' summary of
every phase (bench/mpi_counters.cpp documents them). Point-to-point messages are MPI_Send, Isend,
Ssend, Rsend and Sendrecv; collectives are counted apart. A one-rank run sends nothing.
"""
import argparse
import json
import os
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance

BUILD = os.path.join(ROOT, "build")
LIBRARY = os.path.join(BUILD, "bench", "libsignorini_mpi_counters.so")
# Members of the benchmark family (doc/benchmark-family.md) that 16 ranks on two cores solve in
# under a minute each.
CASES = {"3d-p1-nx40": "family/3d-p1-nx40", "2d-p1-nx200": "family/2d-p1-nx200"}
QUANTITIES = ["messages_sent", "bytes_sent", "allreduces"]
SETUP_QUANTITIES = ["messages_sent", "bytes_sent", "collectives", "collective_bytes"]


def counters_library():
    if not os.path.exists(LIBRARY):
        subprocess.run(["cmake", "--build", BUILD, "--target", "signorini_mpi_counters"], check=True)
    return LIBRARY


def run(xml, settings, ranks, out):
    """summary.json and the counters of one run of xml on ranks ranks."""
    os.makedirs(out, exist_ok=True)
    counters = os.path.join(out, "mpi-counters.json")
    if os.path.exists(counters):
        os.remove(counters)
    cmd = ["mpirun", "-np", str(ranks), "-x", "LD_PRELOAD=" + counters_library(), "-x",
           "SIGNORINI_MPI_COUNTERS=" + counters, os.path.join(BUILD, "bin", "signorini"), xml, "--output", out]
    for setting in settings:
        cmd += ["--set", setting]
    status = subprocess.run(cmd, env=ENV, stdout=subprocess.DEVNULL, check=False).returncode
    if status not in (0, 1) or not os.path.exists(counters):  # 1: stopped without converging
        raise SystemExit(f"communication: {' '.join(cmd)} exited with {status}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    with open(counters) as f:
        return summary, json.load(f)


def per_rank(counters, phases, quantity):
    """Per rank, the quantity summed over the phases."""
    return [sum(counters["phases"][p]["per_rank"][r][quantity] for p in phases) for r in range(counters["ranks"])]


def stats(counters, phases, quantities, divisor=1):
    """{quantity: {"max", "mean"}} over the ranks of the phases' sum, divided by divisor."""
    result = {}
    for q in quantities:
        values = per_rank(counters, phases, q)
        result[q] = {"max": max(values) / max(divisor, 1), "mean": sum(values) / len(values) / max(divisor, 1)}
    return result


def record(case, xml, ranks, summary, counters):
    cg, newton = summary["krylov_iterations"], summary["newton_steps"]
    return {"case": case, "xml": os.path.relpath(xml, ROOT), "ranks": ranks, "oversubscribed": ranks > os.cpu_count(),
            "status": summary["status"], "n": summary["n"], "m": summary["m"],
            "main_iterations": summary["outer_iterations"], "newton_systems": newton, "cg_iterations": cg,
            "preconditioner_setups": summary["preconditioner_setups"],
            "per_cg_iteration": stats(counters, ["krylov"], QUANTITIES, cg),
            "per_newton_system": stats(counters, ["solve", "preconditioner_setup"], QUANTITIES, newton),
            "setup": {p: stats(counters, [p], SETUP_QUANTITIES) for p in ("mesh_and_space", "assembly")},
            "phases": {name: phase["summary"] for name, phase in counters["phases"].items()},
            "functions": {name: phase["total"] for name, phase in counters["phases"].items()}}


def table(records):
    """The Markdown table of NAME.md: one row per case and rank count."""
    def pair(s, scale=1.0, digits=1):
        return f"{s['max'] / scale:.{digits}f} / {s['mean'] / scale:.{digits}f}"

    rows = ["| case | ranks | n | m | it | Newton | CG | per CG iteration: messages sent | KiB sent | all-reduces "
            "| per Newton system: messages sent | KiB sent | all-reduces | mesh and space: messages sent | KiB sent "
            "| collective KiB | assembly: messages sent | KiB sent | collective KiB |", "|" + "---|" * 19]
    for r in records:
        c, s = r["per_cg_iteration"], r["per_newton_system"]
        ms, asm = r["setup"]["mesh_and_space"], r["setup"]["assembly"]
        note = " (oversubscribed)" if r["oversubscribed"] else ""
        rows.append(f"| {r['case']} | {r['ranks']}{note} | {r['n']} | {r['m']} | {r['main_iterations']} | "
                    f"{r['newton_systems']} | {r['cg_iterations']} | {pair(c['messages_sent'])} | "
                    f"{pair(c['bytes_sent'], 1024)} | {c['allreduces']['max']:.1f} | {pair(s['messages_sent'])} | "
                    f"{pair(s['bytes_sent'], 1024)} | {s['allreduces']['max']:.1f} | "
                    f"{pair(ms['messages_sent'], 1, 0)} | {pair(ms['bytes_sent'], 1024)} | "
                    f"{pair(ms['collective_bytes'], 1024)} | "
                    f"{pair(asm['messages_sent'], 1, 0)} | {pair(asm['bytes_sent'], 1024)} | "
                    f"{pair(asm['collective_bytes'], 1024)} |")
    notes = ["", "Point-to-point messages and KiB sent as max / mean over the ranks; collective KiB: what each "
             "rank passes to collective calls (its send buffers; the mesh and space setup exchanges node ids "
             "by MPI_Alltoallv), max / mean; all-reduces per rank "
             "(the max over the ranks). Per CG iteration: the Krylov phase (CG with its preconditioner "
             "applications) over the run's CG iterations; per Newton system: the rest of the solve with the "
             "preconditioner setups over the Newton systems; mesh and space, assembly: totals of the phase. "
             "Counted by bench/mpi_counters.cpp, written by bench/communication.py."]
    return "\n".join(rows + notes) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", default="1,2,4,8,16")
    parser.add_argument("--cases", default=",".join(CASES), help="comma-separated names of CASES, or none")
    parser.add_argument("--xml", nargs="*", default=[], help="more inputs, each a case named by its file")
    parser.add_argument("--set", action="append", default=[], help='"Sublist/name=value" for every run')
    parser.add_argument("--name", default="communication", help="basename of the result files")
    parser.add_argument("--table", action="store_true", help="rewrite NAME.md from NAME.json, run nothing")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "communication"))
    args = parser.parse_args()
    base = os.path.join(ROOT, "bench", "results", args.name)
    if args.table:
        with open(base + ".json") as f:
            records = json.load(f)["runs"]
        with open(base + ".md", "w") as f:
            f.write(table(records))
        return
    cases = []
    for name in [c for c in args.cases.split(",") if c and c != "none"]:
        if name not in CASES:
            parser.error(f"unknown case {name!r}; known: {', '.join(CASES)}")
        cases.append((name, os.path.join(ROOT, "xml", CASES[name] + ".xml")))
    cases += [(os.path.splitext(os.path.basename(x))[0], os.path.abspath(x)) for x in args.xml]
    ranks = [int(r) for r in args.ranks.split(",")]
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    if args.set:
        made["settings"] = args.set
    records = []
    for case, xml in cases:
        for np in ranks:
            summary, counters = run(xml, args.set, np, os.path.join(args.workdir, f"{case}-np{np}"))
            records.append(record(case, xml, np, summary, counters))
            r, c = records[-1], records[-1]["per_cg_iteration"]
            print(f"{case} np={np}: n={r['n']} {r['status']} Newton={r['newton_systems']} CG={r['cg_iterations']}; "
                  f"per CG iteration (max over ranks) {c['messages_sent']['max']:.1f} messages, "
                  f"{c['bytes_sent']['max'] / 1024:.1f} KiB, {c['allreduces']['max']:.1f} all-reduces", flush=True)
            phased = [p for name, p in counters["phases"].items() if name != "other"]
            if np > 1 and not any(p["per_rank"][0]["calls"] for p in phased):
                print("  everything counted in phase other: this build of signorini calls no MPI_Pcontrol")
    os.makedirs(os.path.dirname(base), exist_ok=True)
    with open(base + ".json", "w") as f:
        json.dump({"provenance": made, "runs": records}, f, indent=1)
    with open(base + ".md", "w") as f:
        f.write(table(records))
    print(table(records))


if __name__ == "__main__":
    main()

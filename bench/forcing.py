#!/usr/bin/python3
"""A forcing rule's parameter against Krylov iterations, main iterations and time.

    /usr/bin/python3 bench/forcing.py [--forcing adaptive|reduction] [--ranks N] [--values V,...]
        [--problems XML,...] [--repeat N] [--name BASENAME]

--forcing adaptive (the default; bench/results/forcing.{json,md}) sweeps the adaptive
forcing's safety factor: the residual allowed in a Newton system is safety * max(||r_d||,
||b|| mu / mu0), so a larger safety asks each system for fewer digits and the interior point
method for more steps. The stored results include safety 1.0, beyond the range the parameter
accepts (at most 0.9): at 1 a step need not reduce the dual residual, and it stagnated on 3D P1.

--forcing reduction (bench/results/forcing-reduction.{json,md}) sweeps forcing: eta of the
default forcing, by which every Krylov solve reduces the residual of its starting vector, on
the family's members (P1 to P3, the largest 2D and 3D P1 ones included) and on the examples
of bodies of Gmsh geometries, Hertz contact and mortar contact between two bodies.

Every run selects the forcing and uses the default configuration otherwise. A problem is a
member's name (paper/M, family/2d-p1-nx200) or an input's path from the root (examples/...xml).
"""
import argparse
import json
import os

from provenance import provenance

from preconditioners import ROOT, run

SWEEPS = {
    "adaptive": {
        "parameter": "safety",
        "values": "0.1,0.2,0.3,0.5,0.9",
        "name": "forcing",
        "problems": ["paper/M", "paper/G", "paper/K", "paper/J", "family/2d-p1-nx200", "family/2d-p1-nx400",
                     "paper/E", "paper/L", "family/3d-p1-nx40"],
    },
    "reduction": {
        "parameter": "eta",
        "values": "0.1,0.2,0.3,0.5",
        "name": "forcing-reduction",
        "problems": ["paper/M", "paper/J", "family/2d-p1-nx400", "family/2d-p1-nx1000", "family/2d-p2-nx200",
                     "family/2d-p3-nx100", "paper/E", "paper/L", "family/3d-p1-nx40", "family/3d-p1-nx64",
                     "family/3d-p2-nx32", "examples/bodies/disk-on-block-2d.xml",
                     "examples/bodies/padded-block-2d.xml", "examples/bodies/ball-on-block-3d.xml",
                     "examples/bodies/two-blocks-3d.xml", "examples/hertz/half-disk-2d.xml",
                     "examples/hertz/deep-block-3d.xml", "examples/hertz/half-ball-pressed-3d.xml"],
    },
}


def label(problem):
    return problem[len("examples/"):-len(".xml")] if problem.endswith(".xml") else problem


def write_table(records, problems, values, parameter, name):
    header = "| problem | n | " + " | ".join(f"{parameter} {v}: it / Krylov / solve [s]" for v in values) + " |"
    rows = [header, "|---|---|" + "---|" * len(values)]
    for problem in problems:
        runs = [r for r in records if r["problem"] == problem]
        cells = [f"{r['summary']['outer_iterations']} / {r['summary']['krylov_iterations']} / "
                 f"{r['summary']['time']['solve']:.2f}" + ("" if r["summary"]["converged"] else " (failed)")
                 for r in runs]
        rows.append(f"| {label(problem)} | {runs[0]['summary']['n']} | " + " | ".join(cells) + " |")
    with open(os.path.join(ROOT, "bench", "results", name + ".md"), "w") as f:
        f.write("\n".join(rows) + "\n")
    print("\n".join(rows))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--forcing", choices=sorted(SWEEPS), default="adaptive")
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--values", default=None, help="the swept parameter's values")
    parser.add_argument("--problems", default=None)
    parser.add_argument("--name", default=None, help="basename of the result files")
    parser.add_argument("--repeat", type=int, default=1, help="runs of each problem and value; the fastest is kept")
    parser.add_argument("--reuse", action="store_true", help="reuse the outputs of earlier runs in the workdir")
    parser.add_argument("--workdir", default=None)
    args = parser.parse_args()
    sweep = SWEEPS[args.forcing]
    parameter = sweep["parameter"]
    values = (args.values or sweep["values"]).split(",")
    problems = args.problems.split(",") if args.problems else sweep["problems"]
    name = args.name or sweep["name"]
    workdir = args.workdir or os.path.join(ROOT, "results", name)
    made = provenance(args.ranks)  # before any result file is rewritten (git describe --dirty)
    if args.reuse:
        made["reused outputs of earlier runs"] = os.path.relpath(workdir, ROOT)
    records = []
    for problem in problems:
        for value in values:
            out = os.path.join(workdir, f"{label(problem).replace('/', '-')}-{parameter}-{value}")
            settings = {"Solver/forcing: type": args.forcing, f"Solver/forcing: {parameter}": value}
            summary, history = min((run(problem, settings, args.ranks, out + (f"-{k}" if k else ""), args.reuse)
                                    for k in range(args.repeat)), key=lambda s: s[0]["time"]["solve"])
            records.append({"problem": problem, parameter: float(value), "ranks": args.ranks, "summary": summary,
                            "history": history})
            print(f"{label(problem):22s} {parameter} {value:4s}: it {summary['outer_iterations']:3d}, "
                  f"Krylov {summary['krylov_iterations']:4d}, max/system {summary['max_krylov_per_newton']:3d}, "
                  f"solve {summary['time']['solve']:.2f} s, {summary['status']}", flush=True)
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "bench", "results", name + ".json"), "w") as f:
        json.dump({"provenance": made, "forcing": args.forcing, "repeat": args.repeat, "runs": records}, f, indent=1)
    write_table(records, problems, values, parameter, name)


if __name__ == "__main__":
    main()

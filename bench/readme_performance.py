#!/usr/bin/python3
"""The README's performance table, from the result sets it quotes:

    /usr/bin/python3 bench/readme_performance.py

Each row is one figure and the command that measures it: the contact solve against a linear
solve and the 3D P1 member with 3.1 M unknowns (bench/results/reference-solve.json, the
fastest of its repeats), the largest CG count per Newton system with the default
preconditioner and forcing (preconditioners-forcing.json, preconditioners-forcing-p2p3.json),
IPOPT against Signorini (ipopt.json) and the strong scaling of the solve phase from 1 to 2
ranks (scaling.json, one run each).
"""
import json
import os

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def load(name):
    with open(os.path.join(ROOT, "bench", "results", name + ".json")) as f:
        return json.load(f)


def span(values, digits=1):
    low, high = min(values), max(values)
    return f"{low:.{digits}f}" if f"{low:.{digits}f}" == f"{high:.{digits}f}" else f"{low:.{digits}f}–{high:.{digits}f}"


def reference_rows():
    cases = {c["problem"]: c for c in load("reference-solve")["cases"]}
    large = [c["solve_time_ratio"] for c in cases.values() if c["contact"]["n"] > 1e5]
    two_d, three_d = cases["family/2d-p1-nx1000"], cases["family/3d-p1-nx100"]
    seconds = three_d["contact"]["seconds"]
    end_to_end = sum(seconds[phase] for phase in ("mesh", "assembly", "solve", "output"))
    j, l = cases["paper/J"]["contact"], cases["paper/L"]["contact"]
    command = "`bench/reference_solve.py`"
    return [
        ("a contact solve against one linear solve of the same problem without contact (members with more than "
         "10⁵ unknowns)",
         f"{span(large)} times its time; {two_d['solve_time_ratio']:.1f} at 2D P1 with "
         f"{two_d['contact']['n'] / 1e6:.1f} M unknowns, {three_d['solve_time_ratio']:.1f} at 3D P1 with "
         f"{three_d['contact']['n'] / 1e6:.1f} M", command),
        (f"3D P1 with {three_d['contact']['n'] / 1e6:.1f} M unknowns, end to end",
         f"{end_to_end:.0f} s (assembly {seconds['assembly']:.0f} s, solve {seconds['solve']:.0f} s), "
         f"{three_d['contact']['peak_bytes_per_unknown'] / 1000:.1f} KB per unknown", command),
        ("problems J and L, solve phase on 1 rank", f"{j['seconds']['solve']:.2f} s and {l['seconds']['solve']:.2f} s",
         command),
    ]


def krylov_row():
    runs = [r for name in ("preconditioners-forcing", "preconditioners-forcing-p2p3") for r in load(name)["runs"]
            if r["config"] == "default" and r["forcing"] == "reduction"]

    def largest(sequences, smallest_nx=0):
        chosen = [r for r in runs if r["sequence"] in sequences and r["nx"] >= smallest_nx]
        return span([r["summary"]["max_krylov_per_newton"] for r in chosen], 0), chosen

    two_d, runs_2d = largest({"2d"}, 20)
    three_d, runs_3d = largest({"3d"})
    high, _ = largest({"2d-p2", "2d-p3", "3d-p2"})
    nx = lambda chosen: span([r["nx"] for r in chosen], 0)  # noqa: E731
    return ("largest CG count per Newton system",
            f"{two_d} on 2D P1 nx = {nx(runs_2d)}, {three_d} on 3D P1 nx = {nx(runs_3d)}, {high} on P2/P3",
            "`bench/preconditioners.py`")


def ipopt_row():
    ratios = []
    for r in load("ipopt")["runs"]:
        converged = [c for c in r["ipopt"].values() if c["converged"]]
        if converged:
            ratios.append(min(c["seconds"] for c in converged) / r["signorini"]["solve_seconds"])
    return ("IPOPT with MUMPS on the same exported QPs, A–M",
            f"{min(ratios):.1f}–{max(ratios):.0f} times as long as Signorini", "`bench/ipopt.py`")


def scaling_row():
    solve = {(r["study"], r["ranks"]): r["summary"]["time"]["solve"] for r in load("scaling")["runs"]}
    n = {r["study"]: r["summary"]["n"] for r in load("scaling")["runs"]}
    efficiency = lambda study: solve[(study, 1)] / (2 * solve[(study, 2)])  # noqa: E731
    return ("strong scaling of the solve phase from 1 to 2 ranks (one run)",
            f"{efficiency('strong-2d'):.0%} on 2D P1 with {n['strong-2d'] / 1e6:.1f} M unknowns, "
            f"{efficiency('strong-3d'):.0%} on 3D P1 with {n['strong-3d'] / 1e6:.2f} M", "`scripts/scaling.py --ranks 1,2`")


def main():
    print("| figure | measured | command |")
    print("|---|---|---|")
    for figure, measured, command in reference_rows() + [krylov_row(), ipopt_row(), scaling_row()]:
        print(f"| {figure} | {measured} | {command} |")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Force control against displacement control: the force-controlled examples of
examples/hertz (a steel half-cylinder under 350 MPa, the half-ball under a pressure and under
its own weight; only the contact holds them in the load's direction) and the same bodies with
the loaded face moved towards the obstacle instead, on 2 ranks with the default parameters.
Reports main iterations, Newton systems and CG iterations of both, the contact force against
the load, and, as a check on the preconditioner, the CG iterations per Newton system when every
system is solved from zero to the same relative residual (forcing "relative", eta = 1e-8,
without the active-set finish, whose penalised system is another one; such a run may stop
short of the KKT target: the table then gives its status). The stationarity test is relative to
max(||b||, ||A^T lambda||), and a displacement-controlled b holds the lifting forces of the
prescribed values, far above the contact forces: so each counterpart is also solved to the
absolute stationarity of its force-controlled run (its KKT tolerance scaled by the ratio of
the two runs' absolute stationarity residuals), the same accuracy of the forces.

    /usr/bin/python3 bench/force_control.py [--ranks 2]

Writes bench/results/force-control.{json,md}.
"""
import argparse
import json
import os
import subprocess

from preconditioners import ENV, ROOT
from provenance import provenance, write_results

HERTZ = os.path.join(ROOT, "examples", "hertz")
# name, input, settings, the loaded face's displacement component and approach of the
# displacement-controlled counterpart, the traction component the counterpart removes
CASES = [
    ("steel half-cylinder 2D", "steel-half-cylinder-2d", [], "y", "-0.35"),
    ("steel half-cylinder 2D P2", "steel-half-cylinder-2d", ["Problem/element: degree=2"], "y", "-0.35"),
    ("half-ball 3D, size factor 2", "half-ball-pressed-3d", ["Problem/mesh: size factor=2"], "z", "-0.015"),
    ("half-ball 3D", "half-ball-pressed-3d", [], "z", "-0.015"),
    ("half-ball 3D, weight", "half-ball-pressed-3d",
     ["Problem/Traction/top/traction: z=0", "Problem/body force: z=-0.0015"], "z", "-0.015"),
    ("half-ball 3D P2, size factor 2", "half-ball-pressed-3d",
     ["Problem/mesh: size factor=2", "Problem/element: degree=2"], "z", "-0.015"),
]
FORMULATIONS = {name: ["Problem/Contact/formulation=" + name] for name in ("nodal", "weighted gap", "dual mortar")}
METHODS = ["primal-dual", "primal"]
FIXED_ACCURACY = ["Solver/forcing: type=relative", "Solver/forcing: eta=1e-8",
                  "Solver/Krylov/initial guess: previous solutions=0", "Solver/primal-dual: active-set finish=false"]


def solve(xml, settings, ranks, out):
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"), os.path.join(HERTZ, xml + ".xml"),
           "--output", out, "--set", "Output/write solution=false", "--set", "Output/write contact samples=false"]
    for assignment in settings:
        cmd += ["--set", assignment]
    subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"status": s["status"], "main_iterations": s["outer_iterations"], "newton_systems": s["newton_steps"],
            "cg_iterations": s["krylov_iterations"], "normal_force": s["contact"]["normal_force"],
            "stationarity_absolute": s["kkt_absolute"]["stationarity"], "solve_seconds": s["time"]["solve"]}


def run(case, method, formulation, ranks, workdir):
    name, xml, settings, component, approach = case
    common = settings + FORMULATIONS[formulation] + [f"Solver/method={method}"]
    counterpart = common + [f"Problem/Traction/top/traction: {component}=0",
                            f"Problem/Dirichlet/top/displacement: {component}={approach}"]
    tag = f"{xml}-{len(settings)}-{method}-{formulation.replace(' ', '-')}"
    result = {"case": name, "method": method, "formulation": formulation, "ranks": ranks}
    for control, chosen in (("force", common), ("displacement", counterpart)):
        result[control] = solve(xml, chosen, ranks, os.path.join(workdir, f"{tag}-{control}"))
        fixed = solve(xml, chosen + FIXED_ACCURACY, ranks, os.path.join(workdir, f"{tag}-{control}-fixed"))
        result[control]["cg_per_system_at_fixed_accuracy"] = fixed["cg_iterations"] / max(fixed["newton_systems"], 1)
        result[control]["status_at_fixed_accuracy"] = fixed["status"]
    scale = min(1.0, result["force"]["stationarity_absolute"] / result["displacement"]["stationarity_absolute"])
    result["displacement_same_forces"] = solve(xml, counterpart + [f"Solver/kkt: tolerance={1e-8 * scale:.3e}"], ranks,
                                               os.path.join(workdir, f"{tag}-displacement-same-forces"))
    return result


def at_fixed_accuracy(control):
    """CG per system at the fixed accuracy, with the run's status where it did not converge."""
    status = control["status_at_fixed_accuracy"]
    return f"{control['cg_per_system_at_fixed_accuracy']:.1f}" + ("" if status == "converged" else f" ({status})")


def table(runs):
    lines = ["| problem | method | constraints | status | it | CG | it, displ. control | CG, displ. control | "
             "it ratio | CG ratio | it / CG, displ. control, same absolute stationarity | CG ratio there "
             "| CG per system at 1e-8, force / displ. |", "|" + "---|" * 13]
    for r in runs:
        f, d, e = r["force"], r["displacement"], r["displacement_same_forces"]
        lines.append(f"| {r['case']} | {r['method']} | {r['formulation']} | {f['status']} | {f['main_iterations']} "
                     f"| {f['cg_iterations']} | {d['main_iterations']} | {d['cg_iterations']} "
                     f"| {f['main_iterations'] / d['main_iterations']:.2f} | {f['cg_iterations'] / d['cg_iterations']:.2f} "
                     f"| {e['main_iterations']} / {e['cg_iterations']} ({e['status']}) "
                     f"| {f['cg_iterations'] / e['cg_iterations']:.2f} "
                     f"| {at_fixed_accuracy(f)} / {at_fixed_accuracy(d)} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", type=int, default=2)
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "force-control"))
    args = parser.parse_args()
    made = provenance(args.ranks)  # before any result file is rewritten
    runs = []
    for case in CASES:
        for method in METHODS:
            for formulation in FORMULATIONS:
                if method == "primal" and formulation != "nodal":
                    continue  # the primal method needs rows that share no unknowns (P2 triangles' do)
                runs.append(run(case, method, formulation, args.ranks, args.workdir))
                print(json.dumps(runs[-1]), flush=True)
    write_results("force-control", made, runs, table(runs))


if __name__ == "__main__":
    main()

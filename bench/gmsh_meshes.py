#!/usr/bin/python3
"""The benchmark family's problem on the unit square / cube meshed by Gmsh against the box
mesh of about the same size: the quartic load, the top clamped, the bottom on the rigid
plane (doc/benchmark-family.md). Three meshes per case:

  box      the family's box mesh (its nested geometric grids);
  refined  a coarse Gmsh mesh of the .geo refined uniformly on every rank
           (Problem/mesh: refinements), each refinement a geometric level, the default
           Delaunay coarse grids below the coarse mesh; "refined r2" is refined twice;
           "refined r1 none" is "refined r1" with MueLu below its coarse mesh where that is
           too large for the direct solver (Problem/mesh: coarse grids = none);
  msh      the fine mesh written by Gmsh as a .msh file and read as is by rank 0, which
           partitions it (Problem/mesh: read = rank 0; its own P1 grid, MueLu below:
           Problem/mesh: coarse grids = none);
  msh all ranks  the same .msh read by all ranks together (Problem/mesh: read = all ranks,
           the default: each reads a slice, PT-Scotch partitions; runs on 2 ranks or more);
  parts    the same fine mesh partitioned by Gmsh and written as one file per rank
           (gmsh -part N -part_split), each rank reading its own (runs on 2 ranks or more);
  msh delaunay  the .msh read by all ranks with the default coarse grids, Delaunay
           triangulations of its vertices' maximal independent sets below its P1 grid
           (Problem/mesh: coarse grids = delaunay); the other .msh rows have MueLu there.

Each on 1 and 2 ranks (--ranks; the large case on 4 ranks too), with the contact solve and a
linear solve of the same problem with the bottom clamped instead (no contact): setup,
assembly and solve times, end-to-end wall time, CG iterations, multigrid setups, peak memory
of the largest rank, the growth of the resident set during setup (rank 0's and the largest
rank's), and the contact solve over the linear one.

Timings on a shared machine swing between periods, so every run is made --repeat times, in
rounds over all meshes of a case and rank count (the box and the Gmsh meshes alternate), and
the fastest (by wall time) is kept whole; the record lists the wall and phase times of all of them.

    /usr/bin/python3 bench/gmsh_meshes.py [--ranks 1,2] [--cases 3d-p1,3d-p2,2d-p1,3d-p1-large]
                                          [--meshes box,msh,...] [--repeat 2] [--name gmsh-meshes]

Writes bench/results/<name>.{json,md}. The .msh files are made once by the gmsh program
in the work directory (their meshing time is not part of any run).
"""
import argparse
import json
import os
import subprocess
import time

from preconditioners import ENV, ROOT
from provenance import provenance, write_results

FAMILY = os.path.join(ROOT, "xml", "family")
# name: (dimension, degree, box input, box cells, the refined meshes' coarse sizes and refinements,
# fine .msh size or None, more rank counts than --ranks). Gmsh cuts the cube's edges into whole
# numbers of segments, so the sizes come near the box's unknowns, not to them: the table gives n.
# 3D P1 has three refined meshes: coarse size 1/17 refined twice comes nearest the box's size
# (17 x 4 segments per edge), 0.116 refined three times (9 x 8 segments) has one level more,
# 0.031 refined once (32 x 2 segments) has a coarse mesh of about 90 000 unknowns, as a
# geometry whose features need many coarse cells would.
CASES = {
    "3d-p1": (3, 1, "3d-p1-nx64.xml", 64, [(0.0588, 2), (0.116, 3), (0.031, 1)], 0.0142, []),
    "3d-p2": (3, 2, "3d-p2-nx32.xml", 32, [(0.127, 2)], 0.032, []),
    "2d-p1": (2, 1, "2d-p1-nx1000.xml", 1000, [(0.035, 5)], 0.0011, []),
    "3d-p1-large": (3, 1, "3d-p1-nx100.xml", 100, [(0.08, 3)], None, [4]),
}


# The meshes that need more than one rank: a mesh in parts, and a reading by all ranks.
PARALLEL_ONLY = ("parts", "msh all ranks")
# The .msh meshes as is, MueLu below their P1 grid but for "msh delaunay".
AS_IS = ("msh", *PARALLEL_ONLY, "msh delaunay")
# A refined mesh's name with this suffix: MueLu below its coarse mesh (no Delaunay coarse grids).
WITHOUT_COARSE_GRIDS = " none"


def refined_mesh(refinements):
    """The table's name of a refined mesh."""
    return f"refined r{refinements}"


def geometry(dim, size):
    """A unit square or cube with the box mesh's boundary names for bottom and top."""
    low, high = ("ymin", "ymax") if dim == 2 else ("zmin", "zmax")
    shape = "Rectangle(1) = {0, 0, 0, 1, 1};" if dim == 2 else "Box(1) = {0, 0, 0, 1, 1, 1};"
    entity, bottom, top = ("Surface", 1, 3) if dim == 2 else ("Volume", 5, 6)
    group = "Curve" if dim == 2 else "Surface"
    return (f'SetFactory("OpenCASCADE");\n{shape}\nMeshSize{{ PointsOf{{ {entity}{{1}}; }} }} = {size};\n'
            f'Physical {group}("{low}") = {{{bottom}}};\nPhysical {group}("{high}") = {{{top}}};\n'
            f'Physical {entity}("body") = {{1}};\n')


def write_geometry(workdir, dim, size):
    path = os.path.join(workdir, f"unit-{dim}d-h{size}.geo")
    with open(path, "w") as f:
        f.write(geometry(dim, size))
    return path


def fine_msh(workdir, dim, size):
    path = os.path.join(workdir, f"unit-{dim}d-h{size}.msh")
    if not os.path.exists(path):
        geo = write_geometry(workdir, dim, size)
        subprocess.run(["gmsh", f"-{dim}", geo, "-format", "msh41", "-o", path], check=True, capture_output=True)
    return path


def fine_parts(workdir, dim, size, ranks):
    """The fine .msh in `ranks` part files, name_1.msh .. name_<ranks>.msh; returns name.msh."""
    path = os.path.join(workdir, f"unit-{dim}d-h{size}-in{ranks}.msh")
    first = path[:-len(".msh")] + "_1.msh"
    if not os.path.exists(first):
        subprocess.run(["gmsh", fine_msh(workdir, dim, size), "-part", str(ranks), "-part_split", "-o", path, "-save"],
                       check=True, capture_output=True)
    return path


def mesh_settings(case, mesh, workdir, ranks):
    dim, degree, _, cells, refined, fine, _ = CASES[case]
    if mesh == "box":
        return [f"Problem/mesh: cells={{{cells}}}"]
    for coarse, refinements in refined:
        if mesh in (refined_mesh(refinements), refined_mesh(refinements) + WITHOUT_COARSE_GRIDS):
            grids = "none" if mesh.endswith(WITHOUT_COARSE_GRIDS) else "delaunay"
            return ["Problem/mesh: type=gmsh", f"Problem/mesh: file={write_geometry(workdir, dim, coarse)}",
                    f"Problem/mesh: refinements={refinements}", f"Problem/mesh: coarse grids={grids}"]
    file = fine_parts(workdir, dim, fine, ranks) if mesh == "parts" else fine_msh(workdir, dim, fine)
    read = [f"Problem/mesh: read={'rank 0' if mesh == 'msh' else 'all ranks'}",
            f"Problem/mesh: coarse grids={'delaunay' if mesh == 'msh delaunay' else 'none'}"]
    return ["Problem/mesh: type=gmsh", f"Problem/mesh: file={file}"] + read


def run(case, mesh, ranks, linear, workdir):
    dim, degree, box_input, *_ = CASES[case]
    out = os.path.join(workdir, f"{case}-{mesh}-np{ranks}-{'linear' if linear else 'contact'}")
    settings = mesh_settings(case, mesh, workdir, ranks) + [f"Problem/element: degree={degree}", "Output/write solution=false",
                                                     "Output/write contact samples=false"]
    bottom, top = ("ymin", "ymax") if dim == 2 else ("zmin", "zmax")
    if linear:  # the bottom clamped like the top, no contact
        settings += ["Problem/Contact/boundary="] + [f"Problem/Dirichlet/{bottom}/displacement: {a}=0"
                                                     for a in "xyz"[:dim]]
    cmd = ["mpirun", "-np", str(ranks), os.path.join(ROOT, "build", "bin", "signorini"),
           os.path.join(FAMILY, box_input), "--output", out]
    for assignment in settings:
        cmd += ["--set", assignment]
    start = time.monotonic()
    done = subprocess.run(cmd, env=ENV, capture_output=True, text=True, check=False)
    wall = time.monotonic() - start
    if done.returncode != 0:
        raise SystemExit(f"gmsh_meshes: {' '.join(cmd)} failed:\n{done.stdout[-2000:]}{done.stderr[-2000:]}")
    with open(os.path.join(out, "summary.json")) as f:
        s = json.load(f)
    return {"case": case, "mesh": mesh, "ranks": ranks, "solve": "linear" if linear else "contact",
            "status": s["status"], "n": s["n"], "m": s["m"], "objective": s["objective"],
            "cg_iterations": s["krylov_iterations"], "newton_systems": s["newton_steps"],
            "multigrid_setups": s["preconditioner_setups"], "setup_seconds": s["time"]["setup"],
            "assembly_seconds": s["time"]["assembly"], "solve_seconds": s["time"]["solve"], "wall_seconds": wall,
            "peak_mib_max_rank": s["memory_mib"]["max_rank"], "rank0_setup_mib": s["setup_peak_rss_mib"][0],
            "setup_mib_max_rank": max(s["setup_peak_rss_mib"])}


def asked_for(meshes, asked):
    """The meshes of `asked` among `meshes` and their refined ones without coarse grids."""
    variants = [v for m in meshes for v in ([m, m + WITHOUT_COARSE_GRIDS] if m.startswith("refined") else [m])]
    return [v for v in variants if v in asked]


PHASES = ("setup_seconds", "assembly_seconds", "solve_seconds")


def fastest(repeats, by="wall_seconds"):
    """The fastest of the repeats of one run (by `by`), with the times `by` and the phases'
    times (those the runs record) of all."""
    best = dict(min(repeats, key=lambda r: r[by]))
    for key in (by, *PHASES):
        if all(key in r for r in repeats):
            best[key + "_repeats"] = [r[key] for r in repeats]
    return best


def table(runs):
    linear = {(r["case"], r["mesh"], r["ranks"]): r for r in runs if r["solve"] == "linear"}
    box = {(r["case"], r["ranks"]): r for r in runs if r["solve"] == "contact" and r["mesh"] == "box"}
    lines = ["| case | mesh | ranks | n | setup [s] | assembly [s] | solve [s] | wall [s] | wall / box | CG | CG / box "
             "| multigrid setups | peak MiB (max rank) | rank 0 setup MiB | setup MiB (max rank) | linear CG "
             "| contact / linear solve |",
             "|" + "---|" * 17]
    for r in runs:
        if r["solve"] != "contact":
            continue
        b, lin = box[(r["case"], r["ranks"])], linear.get((r["case"], r["mesh"], r["ranks"]))
        lines.append(
            f"| {r['case']} | {r['mesh']} | {r['ranks']} | {r['n']} | {r['setup_seconds']:.2f} "
            f"| {r['assembly_seconds']:.2f} | {r['solve_seconds']:.2f} | {r['wall_seconds']:.1f} "
            f"| {r['wall_seconds'] / b['wall_seconds']:.2f} | {r['cg_iterations']} "
            f"| {r['cg_iterations'] / b['cg_iterations']:.2f} | {r['multigrid_setups']} | {r['peak_mib_max_rank']:.0f} "
            f"| {r['rank0_setup_mib']:.0f} | {r['setup_mib_max_rank']:.0f} | {lin['cg_iterations'] if lin else '-'} "
            f"| {r['solve_seconds'] / lin['solve_seconds'] if lin else float('nan'):.1f} |")
    return "\n".join(lines) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--ranks", default="1,2")
    parser.add_argument("--cases", default=",".join(CASES))
    parser.add_argument("--meshes", default=None, help="only these meshes (box, refined rK, msh, parts, "
                        "msh all ranks, msh delaunay, refined rK none); the box is the reference of the ratios")
    parser.add_argument("--repeat", type=int, default=2, help="runs of each case, mesh and solve; the fastest is kept")
    parser.add_argument("--name", default="gmsh-meshes", help="the result set's name")
    parser.add_argument("--workdir", default=os.path.join(ROOT, "results", "gmsh-meshes"))
    args = parser.parse_args()
    if args.repeat < 1:
        parser.error("--repeat must be at least 1")
    ranks = [int(r) for r in args.ranks.split(",")]
    cases = args.cases.split(",")
    rank_counts = {case: sorted(set(ranks + CASES[case][6])) for case in cases}
    os.makedirs(args.workdir, exist_ok=True)
    made = provenance(max(max(counts) for counts in rank_counts.values()))  # before any result file is rewritten
    runs = []
    for case in cases:
        _, _, _, _, refined, fine_size, _ = CASES[case]
        meshes = ["box"] + [refined_mesh(r) for _, r in refined] + (list(AS_IS) if fine_size else [])
        if args.meshes:
            meshes = asked_for(meshes, args.meshes.split(","))
        for np in rank_counts[case]:
            repeats = {(m, linear): [] for m in meshes if m not in PARALLEL_ONLY or np > 1 for linear in (False, True)}
            for _ in range(args.repeat):
                for (mesh, linear), done in repeats.items():
                    done.append(run(case, mesh, np, linear, args.workdir))
                    print(json.dumps(done[-1]), flush=True)
            runs += [fastest(done) for done in repeats.values()]
    write_results(args.name, made, runs, table(runs))


if __name__ == "__main__":
    main()

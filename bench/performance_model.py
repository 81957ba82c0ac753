#!/usr/bin/python3
"""The communication model of doc/performance-model.md, calibrated on the 2-rank run of
bench/results/communication.json and checked against its runs at more ranks.

A rank's block (the box decomposition of src/fe/BoxMesh.cpp) talks to every block it
touches (face, edge or corner). Per CG iteration it sends E messages to each neighbour
(E: the halo exchanges of one CG iteration, measured on 2 ranks, where every rank has one
neighbour and the coarsest-grid gather adds its 2 messages) and, to each face neighbour,
bytes in proportion to the nodes of the shared face. Rank 0 also receives and sends the
coarsest-grid gather: 2 (p - 1) messages. All-reduces: the measured count per CG iteration,
each costing 2 log2(p) latencies (a reduction tree and a broadcast).

    bench/performance_model.py check     # model against the measured counts
    bench/performance_model.py predict   # time per CG iteration at 64-1024 ranks

Times in milliseconds per CG iteration: compute from the measured Krylov time per unknown
of 3D P1 nx = 100 on this machine (bench/results/reference-solve.json), communication from
LATENCY and BANDWIDTH below.
"""
import itertools
import json
import math
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
RESULTS = os.path.join(ROOT, "bench", "results")

# A typical InfiniBand cluster: MPI latency per message and bandwidth per rank.
LATENCY = 2e-6  # s
BANDWIDTH = 10e9  # bytes/s
CASES = {"3d-p1-nx40": (3, 40), "2d-p1-nx200": (2, 200)}


def decompose(dim, n, parts):
    """Blocks per axis, as decomposeBox chooses them (cubic boxes, n per axis)."""
    best = None
    for p0 in range(parts, 0, -1):
        for p1 in range(parts // p0, 0, -1):
            if parts % p0 or (parts // p0) % p1:
                continue
            p = [p0, p1, parts // p0 // p1]
            if dim == 2 and p[2] != 1:
                continue
            boxes = [n] * dim + [1] * (3 - dim)
            if any(p[a] > boxes[a] for a in range(3)):
                continue
            largest = math.prod(-(-boxes[a] // p[a]) for a in range(3))
            area = sum((p[a] - 1) * math.prod(boxes) // boxes[a] for a in range(3))
            if best is None or (largest, area) < best[0]:
                best = ((largest, area), p)
    return best[1]


def neighbours(p, block):
    """(all neighbours, face neighbours' axes) of a block."""
    count, faces = 0, []
    for offset in itertools.product((-1, 0, 1), repeat=3):
        if offset == (0, 0, 0):
            continue
        if all(0 <= block[a] + offset[a] < p[a] for a in range(3)):
            count += 1
            if sum(map(abs, offset)) == 1:
                faces.append([a for a in range(3) if offset[a]][0])
    return count, faces


def blocks(p):
    return [(b0, b1, b2) for b2 in range(p[2]) for b1 in range(p[1]) for b0 in range(p[0])]


def face_nodes(dim, n, p, axis):
    """Nodes of a block face normal to axis (P1: boxes + 1 per side)."""
    return math.prod(n // p[a] + 1 for a in range(dim) if a != axis)


def load(name):
    with open(os.path.join(RESULTS, name)) as f:
        return json.load(f)


def calibration(runs, case):
    """E (messages per neighbour and CG iteration) and bytes per face node, from 2 ranks."""
    dim, n = CASES[case]
    two = next(r for r in runs if r["case"] == case and r["ranks"] == 2)
    per_cg = two["per_cg_iteration"]
    halo = per_cg["messages_sent"]["mean"] - 1  # less the rank's half of the coarse gather
    p = decompose(dim, n, 2)
    return halo, per_cg["bytes_sent"]["mean"] / face_nodes(dim, n, p, 0), per_cg["allreduces"]["max"]


def predicted(dim, n, parts, halo, per_node):
    """Mean messages and bytes sent per rank and CG iteration."""
    p = decompose(dim, n, parts)
    messages = volume = 0.0
    for block in blocks(p):
        count, faces = neighbours(p, block)
        messages += halo * count
        volume += per_node * sum(face_nodes(dim, n, p, axis) for axis in faces)
    messages += 2 * (parts - 1)  # the coarse gather and scatter, all on rank 0's side
    return messages / parts, volume / parts


def check_rows():
    """Per case and rank count above 2: the blocks, and mean messages and bytes sent per rank
    and CG iteration, measured and modelled."""
    runs = load("communication.json")["runs"]
    rows = []
    for case, (dim, n) in CASES.items():
        halo, per_node, _ = calibration(runs, case)
        for r in sorted((r for r in runs if r["case"] == case and r["ranks"] > 2), key=lambda r: r["ranks"]):
            messages, volume = predicted(dim, n, r["ranks"], halo, per_node)
            measured = r["per_cg_iteration"]
            rows.append({"case": case, "ranks": r["ranks"], "blocks": decompose(dim, n, r["ranks"])[:dim],
                         "messages": measured["messages_sent"]["mean"], "model_messages": messages,
                         "bytes": measured["bytes_sent"]["mean"], "model_bytes": volume})
    return rows


def check():
    print("| case | ranks | blocks | messages per CG iteration, measured | model | KiB sent, measured | model |")
    print("|---|---|---|---|---|---|---|")
    for r in check_rows():
        print(f"| {r['case']} | {r['ranks']} | {' x '.join(map(str, r['blocks']))} | {r['messages']:.0f} "
              f"| {r['model_messages']:.0f} | {r['bytes'] / 1024:.0f} | {r['model_bytes'] / 1024:.0f} |")


def prediction_rows():
    """3D P1: 128^3 boxes (6.4 M unknowns) over 64-1024 ranks (strong), and blocks of 40^3
    boxes (~200 000 unknowns) per rank (weak). Both hierarchies end in a coarsest geometric
    grid of at most 2500 unknowns, gathered to rank 0. Times in seconds per CG iteration."""
    runs = load("communication.json")["runs"]
    halo, per_node, allreduces = calibration(runs, "3d-p1-nx40")
    reference = next(c for c in load("reference-solve.json")["cases"] if c["problem"] == "family/3d-p1-nx100")
    contact = reference["contact"]
    # Compute time per unknown and CG iteration on one rank of the measured run.
    per_unknown = contact["seconds"]["krylov"] / contact["cg_iterations"] * reference["ranks"] / contact["n"]
    rows = []
    for label, boxes in (("strong, 128^3 boxes", lambda parts: 128), ("weak, 40^3 boxes per rank", None)):
        for parts in (64, 256, 1024):
            if boxes:  # the interior block of the decomposition
                n = boxes(parts)
                p = decompose(3, n, parts)
                count, faces = neighbours(p, tuple(min(1, p[a] - 1) for a in range(3)))
                faceNodes = sum(face_nodes(3, n, p, a) for a in faces)
                unknowns = 3 * (n + 1) ** 3 / parts
            else:
                count, faceNodes, unknowns = 26, 6 * 41 ** 2, 3 * 40 ** 3
            row = {"scaling": label, "ranks": parts, "unknowns": unknowns, "neighbours": count,
                   "compute": per_unknown * unknowns, "latency": halo * count * LATENCY,
                   "volume": per_node * faceNodes / BANDWIDTH, "gather": 2 * (parts - 1) * LATENCY,
                   "reduce": allreduces * 2 * math.log2(parts) * LATENCY}
            row["total"] = sum(row[k] for k in ("compute", "latency", "volume", "gather", "reduce"))
            rows.append(row)
    return rows


def predict():
    ms = lambda t: f"{1e3 * t:.2f}"
    print("| scaling | ranks | unknowns per rank | compute | halo latency | halo volume | coarse gather | all-reduces "
          "| per CG iteration | compute share |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in prediction_rows():
        print(f"| {r['scaling']} | {r['ranks']} | {r['unknowns']:.0f} | {ms(r['compute'])} | {ms(r['latency'])} "
              f"| {ms(r['volume'])} | {ms(r['gather'])} | {ms(r['reduce'])} | {ms(r['total'])} "
              f"| {r['compute'] / r['total']:.0%} |")


if __name__ == "__main__":
    {"check": check, "predict": predict}[sys.argv[1] if len(sys.argv) > 1 else "check"]()

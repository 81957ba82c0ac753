#!/usr/bin/python3
"""The Python module on 1 or more MPI ranks: paper problem J, exported by the program
(signorini --export-qp), read with scipy and solved through `signorini.solve` with each rank
passing its rows, reaches the program's optimum and active set; the multipliers are
compressive and complementary; inputs of the wrong size or nodes split across ranks are
refused with a ValueError naming what to fix, on every rank when one rank's input is wrong. Paper problem H (P2) given its P1 cells gets
the geometric P2 -> P1 step: the program's optimum in at most 1.3 times its CG iterations.

    mpiexec -np N python3 test_python_module.py J_QP_DIR J_SUMMARY_JSON H_QP_DIR H_SUMMARY_JSON
"""
import json
import sys

import numpy as np
import scipy.io

import signorini


def read(directory):
    def vector(name):
        return np.asarray(scipy.io.mmread(f"{directory}/{name}.mtx")).ravel()
    return (scipy.io.mmread(f"{directory}/Q.mtx").tocsr(), vector("b"), scipy.io.mmread(f"{directory}/A.mtx").tocsr(),
            vector("d"), np.asarray(scipy.io.mmread(f"{directory}/coords.mtx")))


def my_rows(Q, A, coordinates):
    """This rank's whole nodes and their interlaced rows, and its share of the constraints."""
    rank, size = signorini.rank(), signorini.size()
    dim = coordinates.shape[1]
    nodes = np.array_split(np.arange(coordinates.shape[0]), size)[rank]
    rows = (dim * nodes[:, None] + np.arange(dim)).ravel()
    constraints = np.array_split(np.arange(A.shape[0]), size)[rank]
    return nodes, rows, constraints


def refused(call, words):
    try:
        call()
    except ValueError as error:
        assert words in str(error), str(error)
        return
    raise AssertionError(f"not refused: expected an error saying '{words}'")


def p2_with_cells(qp_dir, summary_path):
    Q, b, A, d, coordinates = read(qp_dir)
    cells = np.asarray(scipy.io.mmread(f"{qp_dir}/cells.mtx")).astype(np.int64)
    with open(summary_path) as f:
        program = json.load(f)
    nodes, rows, constraints = my_rows(Q, A, coordinates)
    # Every rank passes all cells: they hold its nodes, and the grid keeps what it needs.
    v, multipliers, summary = signorini.solve(Q[rows], b[rows], A[constraints], d[constraints],
                                              coordinates=coordinates[nodes], cells=cells)
    assert summary["converged"], summary["message"]
    assert abs(summary["objective"] - program["objective"]) <= 1e-10 * abs(program["objective"])
    assert summary["krylov_iterations"] <= 1.3 * program["krylov_iterations"], \
        (summary["krylov_iterations"], program["krylov_iterations"])
    levels = summary["multigrid_nonzeros"]
    assert len(levels) >= 2 and all(count > 0 for count in levels[1:]), levels
    if levels[0] > 0:
        assert abs(summary["operator_complexity"] - sum(levels) / levels[0]) <= 1e-12 * sum(levels), summary
    refused(lambda: signorini.solve(Q[rows], b[rows], A[constraints], d[constraints], cells=cells), "coordinates")
    return summary["krylov_iterations"], program["krylov_iterations"]


def main():
    qp_dir, summary_path = sys.argv[1], sys.argv[2]
    Q, b, A, d, coordinates = read(qp_dir)
    with open(summary_path) as f:
        program = json.load(f)
    nodes, rows, constraints = my_rows(Q, A, coordinates)
    v, multipliers, summary = signorini.solve(Q[rows], b[rows], A[constraints], d[constraints],
                                              coordinates=coordinates[nodes])
    assert summary["converged"], summary["message"]
    assert abs(summary["objective"] - program["objective"]) <= 1e-10 * abs(program["objective"]), \
        (summary["objective"], program["objective"])
    assert summary["active_constraints"] == program["active_constraints"], summary
    assert v.shape == (len(rows),) and multipliers.shape == (len(constraints),)
    # Compressive multipliers, none on a constraint with a gap: checked on this rank's
    # constraints whose unknowns are all this rank's (v holds this rank's rows only).
    assert multipliers.max() <= 1e-12 * max(1.0, -multipliers.min())
    mine = np.zeros(Q.shape[0], dtype=bool)
    mine[rows] = True
    rows_of_A = A[constraints]
    local = np.array([mine[rows_of_A.indices[rows_of_A.indptr[i]:rows_of_A.indptr[i + 1]]].all()
                      for i in range(len(constraints))], dtype=bool)
    v_full = np.zeros(Q.shape[0])
    v_full[rows] = v
    slack = (d[constraints] - rows_of_A @ v_full)[local]
    scale = max(np.abs(d).max(), np.abs(v).max())  # a displacement scale
    if local.any():
        assert slack.min() >= -1e-8 * scale, slack.min()
        assert np.abs(multipliers[local] * slack).max() <= 1e-6 * np.abs(multipliers).max() * scale

    refused(lambda: signorini.solve(Q[rows], b[rows][:-1], A[constraints], d[constraints]), "b must be a vector")
    refused(lambda: signorini.solve(Q[rows][:, :-1], b[rows], A[constraints], d[constraints]), "columns")
    refused(lambda: signorini.solve(Q[rows], b[rows], A[constraints], d[constraints],
                                    coordinates=coordinates[nodes][:-1]), "whole nodes")
    if signorini.size() > 1:  # one rank's bad input stops every rank, none hangs
        last = signorini.rank() == signorini.size() - 1
        b_mine = b[rows][:-1] if last else b[rows]
        refused(lambda: signorini.solve(Q[rows], b_mine, A[constraints], d[constraints]),
                "b must be a vector" if last else "another rank")
    p2, p2_program = p2_with_cells(sys.argv[3], sys.argv[4])
    if signorini.rank() == 0:
        print(f"python module on {signorini.size()} rank(s): J objective {summary['objective']:.15e}, "
              f"{summary['active_constraints']} active, {summary['krylov_iterations']} CG iterations; "
              f"H (P2) with its cells {p2} CG iterations (the program: {p2_program})")


if __name__ == "__main__":
    main()

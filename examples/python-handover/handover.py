#!/usr/bin/python3
"""A contact problem assembled in Python and handed to Signorini: an elastic block pressed
onto a rigid cylinder, the way a code with its own assembly (scikit-fem, GetFEM, an in-house
code) hands over its QP.

The block [-1, 1] x [0, 1] (plane strain, E = 1, nu = 0.3, P1 triangles) has its top moved
down by `approach`; its bottom rests on a rigid cylinder of radius R whose top touches y = 0,
so that the gap under x is x^2 / (2 R). This script

  1. meshes the block and assembles the stiffness Q with numpy and scipy,
  2. imposes the prescribed top by the convention Signorini expects of an assembled Q (the
     prescribed DOFs' rows and columns zeroed, a unit diagonal, their values in b, and the
     columns' contribution moved to b),
  3. writes the contact rows -u_y(node) <= gap(node) for the bottom nodes as A v <= d,
  4. solves with signorini.solve (node coordinates for the multigrid's rigid body modes),
  5. plots the contact pressure (the multipliers over each node's share of the bottom).

    python3 handover.py [OUTPUT.png]          (on several ranks: see doc/python.md)
"""
import sys

import matplotlib
matplotlib.use("Agg")  # files only, no display
import matplotlib.pyplot as plt
import numpy as np
import scipy.sparse as sp

import signorini

# 1. A structured mesh of right triangles, nodes numbered row by row.
nx, ny, R, approach, E, nu = 80, 40, 2.0, 0.01, 1.0, 0.3
x, y = np.meshgrid(np.linspace(-1, 1, nx + 1), np.linspace(0, 1, ny + 1))
points = np.column_stack([x.ravel(), y.ravel()])
node = lambda i, j: j * (nx + 1) + i
cells = []
for j in range(ny):
    for i in range(nx):
        a, b, c, d = node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)
        cells += [(a, b, c), (a, c, d)]
cells = np.array(cells)

# P1 plane strain stiffness, DOF 2 * node + component.
lam, mu = E * nu / ((1 + nu) * (1 - 2 * nu)), E / (2 * (1 + nu))
D = np.array([[lam + 2 * mu, lam, 0], [lam, lam + 2 * mu, 0], [0, 0, mu]])
rows, cols, vals = [], [], []
for cell in cells:
    p = points[cell]
    area = 0.5 * abs(np.cross(p[1] - p[0], p[2] - p[0]))
    gradients = np.linalg.solve(np.column_stack([np.ones(3), p]), np.eye(3))[1:].T  # d phi_k / dx, dy
    B = np.zeros((3, 6))
    B[0, 0::2], B[1, 1::2] = gradients[:, 0], gradients[:, 1]
    B[2, 0::2], B[2, 1::2] = gradients[:, 1], gradients[:, 0]
    dofs = np.column_stack([2 * cell, 2 * cell + 1]).ravel()
    rows += np.repeat(dofs, 6).tolist()
    cols += np.tile(dofs, 6).tolist()
    vals += (area * B.T @ D @ B).ravel().tolist()
n = 2 * len(points)
Q = sp.csr_matrix((vals, (rows, cols)), shape=(n, n))

# 2. The top moved down by `approach`, held sideways: prescribed DOFs eliminated.
top = np.flatnonzero(np.isclose(points[:, 1], 1.0))
prescribed = np.concatenate([2 * top, 2 * top + 1])
values = np.zeros(n)
values[2 * top + 1] = -approach
b = -(Q @ values)
keep = np.ones(n)
keep[prescribed] = 0
Q = sp.diags(keep) @ Q @ sp.diags(keep) + sp.diags(1 - keep)
b[prescribed] = values[prescribed]

# 3. Contact rows: -u_y <= x^2 / (2 R) at every bottom node.
bottom = np.flatnonzero(np.isclose(points[:, 1], 0.0))
A = sp.csr_matrix((-np.ones(len(bottom)), (np.arange(len(bottom)), 2 * bottom + 1)), shape=(len(bottom), n))
d = points[bottom, 0] ** 2 / (2 * R)

# 4. Solve (one rank: the whole problem; doc/python.md shows how ranks split the rows).
v, multipliers, summary = signorini.solve(Q, b, A, d, coordinates=points)
print(f"{summary['status']}: {summary['outer_iterations']} main iterations, {summary['krylov_iterations']} CG "
      f"iterations, {summary['active_constraints']} nodes in contact")

# 5. Pressure: each bottom node's force over its share of the bottom (h, h/2 at the ends).
h = 2.0 / nx
share = np.where(np.isclose(np.abs(points[bottom, 0]), 1.0), h / 2, h)
pressure = -multipliers / share
force = -multipliers.sum()
Estar = E / (1 - nu**2)
a = np.sqrt(4 * force * R / (np.pi * Estar))  # Hertz, a cylinder on a half-plane
print(f"contact force {force:.6f} per unit thickness, peak pressure {pressure.max():.5f} "
      f"(Hertz for that force: {2 * force / (np.pi * a):.5f}, half-width {a:.4f})")
order = np.argsort(points[bottom, 0])
plt.plot(points[bottom, 0][order], pressure[order], ".-")
plt.xlabel("x")
plt.ylabel("contact pressure")
plt.title(f"block on a rigid cylinder (R = {R}), contact force {force:.4f}")
output = sys.argv[1] if len(sys.argv) > 1 else "handover-pressure.png"
plt.savefig(output, dpi=120)
print(f"pressure plot: {output}")
sys.exit(0 if summary["converged"] else 1)

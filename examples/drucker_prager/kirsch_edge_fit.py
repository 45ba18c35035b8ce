#!/usr/bin/env python3
"""How much of the hole-edge stress error (plate_hole.md, P1) is the correspondence model's fit of F alone: the exact
plane-strain Kirsch displacement field (infinite plate, hole radius R, uniaxial stress S along x) sampled on the
lattice (Grid = Nodes: a point on the hole's edge at (0, R)), the deformation gradient fitted over that point's
one-sided family as the model does (F = sum omega (u_j - u_i) x xi V K^-1, K = sum omega xi x xi V; omega = 1, whole
volumes V = dx^2, delta = 3.015 dx, neighbours inside the hole left out), and sigma_xx from sym(F - I) against the
local 3 S. Prints the shortfall at R = 4 ... 64 dx and exits 1 when the values quoted in plate_hole.md (to 0.05
percentage points) are not reproduced. Check of the field: the local stress at the edge (central differences) is
(3 S, 0) and far away (S, 0) to 1e-3.

usage: kirsch_edge_fit.py
"""
import sys

import numpy as np

NU, MU, S = 0.25, 1.0, 1.0
KAPPA = 3.0 - 4.0 * NU
LAM = 2.0 * MU * NU / (1.0 - 2.0 * NU)
QUOTED = {4: -31.0, 8: -17.0, 16: -8.1, 32: -3.9, 64: -1.9}  # % of 3 S, plate_hole.md


def displacement(x, y, a):
    """Kirsch's plane-strain displacements in Cartesian components (main() checks the edge and far-field stresses)."""
    r, th = np.hypot(x, y), np.arctan2(y, x)
    c = S / (4.0 * MU)
    ur = c * (r * ((KAPPA - 1.0) / 2.0 + np.cos(2 * th)) + (a * a / r) * (1.0 + (1.0 + KAPPA) * np.cos(2 * th))
              - (a ** 4 / r ** 3) * np.cos(2 * th))
    ut = c * ((1.0 - KAPPA) * (a * a / r) - r - a ** 4 / r ** 3) * np.sin(2 * th)
    return np.array([ur * np.cos(th) - ut * np.sin(th), ur * np.sin(th) + ut * np.cos(th)])


def stress(G):
    e = 0.5 * (G + G.T)
    return LAM * np.trace(e) * np.eye(2) + 2.0 * MU * e


def local_gradient(x, y, a, h=1e-6):
    G = np.zeros((2, 2))
    for j, step in enumerate(([h, 0.0], [0.0, h])):
        G[:, j] = (displacement(x + step[0], y + step[1], a) - displacement(x - step[0], y - step[1], a)) / (2 * h)
    return G


def fitted_gradient(n, a=1.0):
    dx = a / n
    delta, V = 3.015 * dx, dx * dx
    xi = np.array([0.0, a])
    ui = displacement(xi[0], xi[1], a)
    K, N = np.zeros((2, 2)), np.zeros((2, 2))
    m = int(np.ceil(delta / dx)) + 1
    for i in range(-m, m + 1):
        for j in range(-m, m + 1):
            p = xi + dx * np.array([i, j])
            bond = p - xi
            if not 0.0 < np.hypot(*bond) <= delta or np.hypot(*p) < a * (1.0 - 1e-12):
                continue
            K += np.outer(bond, bond) * V
            N += np.outer(displacement(p[0], p[1], a) - ui, bond) * V
    return N @ np.linalg.inv(K)


def main():
    edge, far = stress(local_gradient(0.0, 1.0 + 1e-9, 1.0)), stress(local_gradient(0.0, 50.0, 1.0))
    if not (abs(edge[0, 0] - 3 * S) < 1e-3 and abs(edge[1, 1]) < 1e-3 and abs(far[0, 0] - S) < 1e-3):
        sys.exit("the Kirsch field is wrong: edge %s, far %s" % (edge.diagonal(), far.diagonal()))
    missed = []
    for n, quoted in QUOTED.items():
        got = 100.0 * (stress(fitted_gradient(n))[0, 0] / (3 * S) - 1.0)
        print("R = %2d dx: sigma_xx of the fitted F at the edge point %+.1f %% of the local 3 S" % (n, got))
        if abs(got - quoted) > 0.05:
            missed.append("R = %d dx: %+.2f %% (quoted %+.1f %%)" % (n, got, quoted))
    if missed:
        sys.exit("not reproduced: " + "; ".join(missed))


if __name__ == "__main__":
    main()

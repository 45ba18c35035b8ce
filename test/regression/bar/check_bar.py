#!/usr/bin/env python3
"""Checks a uniaxial-tension bar run (test/regression/bar/*.xml) against elasticity.

Region used: the interior strain is (u_x(Q3) - u_x(Q1)) / (x_Q3 - x_Q1) from the two probes on the bar
axis at L/4 and 3L/4 (one horizon and more from the driven layers); the reaction is the x reaction on
the right layer. Both are compared with the applied strain eps and with E' A eps, E' = E (3D, plane
stress) or E/(1 - nu^2) (plane strain). --lattice also computes the uniaxial-stress modulus that the
OSB model has on a square lattice with this horizon (its fourth moment is not isotropic; the error
this causes is a property of the discretization, reported next to the classical one).
"""
import argparse
import csv
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np


def lattice_modulus(dim, ratio, E, nu, plane):
    """Uniaxial-stress modulus along a lattice axis of an interior OSB point (omega = 1)."""
    n = int(np.ceil(ratio))
    r = np.arange(-n, n + 1)
    if dim == 3:
        g = np.array(np.meshgrid(r, r, r, indexing="ij")).reshape(3, -1).T.astype(float)
    else:
        g = np.array(np.meshgrid(r, r, indexing="ij")).reshape(2, -1).T.astype(float)
    d = np.linalg.norm(g, axis=1)
    keep = (d > 0) & (d <= ratio * (1 + 1e-10))
    g, d = g[keep], d[keep]
    nv = g / d[:, None]
    m = np.sum(d ** 2)
    M4 = np.einsum("b,bi,bj,bk,bl->ijkl", d ** 2, nv, nv, nv, nv)
    kappa, mu = E / (3 * (1 - 2 * nu)), E / (2 * (1 + nu))
    if dim == 3:
        D, k, c, A, B = 3, 1, 1 / 3, 3 * kappa, 15 * mu
    elif plane == "stress":
        D, k, c, A, B = 2, (1 - 2 * nu) / (1 - nu), 1 / 3 + kappa / (8 * mu), 2 * kappa, 8 * mu
    else:
        D, k, c, A, B = 2, 1, 5 / 12, 2 * kappa, 8 * mu
    # sigma = (A - B c) k tr(eps)/D I + (B/m) M4 : eps   (interior point, M2 = m/D I)
    C = np.zeros((dim, dim, dim, dim))
    I = np.eye(dim)
    C += (A - B * c) * k / D * np.einsum("ij,kl->ijkl", I, I)
    C += B / m * M4
    # uniaxial stress along x: eps_xx = 1, other normal strains free, shear zero
    free = list(range(1, dim))
    K = np.array([[C[a, a, b, b] for b in free] for a in free])
    rhs = -np.array([C[a, a, 0, 0] for a in free])
    e = np.linalg.solve(K, rhs)
    return C[0, 0, 0, 0] + sum(C[0, 0, b, b] * e[i] for i, b in enumerate(free))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv")
    p.add_argument("--dim", type=int, choices=[2, 3], required=True)
    p.add_argument("--plane", choices=["stress", "strain", "none"], default="none")
    p.add_argument("--E", type=float, required=True)
    p.add_argument("--nu", type=float, required=True)
    p.add_argument("--area", type=float, required=True)
    p.add_argument("--strain", type=float, required=True)
    p.add_argument("--ratio", type=float, required=True, help="horizon / spacing")
    p.add_argument("--tol", type=float, default=0.01)
    p.add_argument("--reaction-against", choices=["classical", "lattice"], default="classical")
    a = p.parse_args()

    rows = list(csv.DictReader(open(a.csv)))
    last = rows[-1]
    # probe x positions are not in the CSV: the decks put Q1 at L/4 and Q3 at 3L/4 of a 0.1 m bar
    # on cell centres, which with the decks' spacings are 0.05 m apart exactly.
    eps_int = (float(last["Probe_Q3_DisplacementX"]) - float(last["Probe_Q1_DisplacementX"])) / 0.05
    F = float(last["Reaction_Right_Layer_X"])
    Ep = a.E / (1 - a.nu ** 2) if a.plane == "strain" else a.E
    El = lattice_modulus(a.dim, a.ratio, a.E, a.nu, a.plane)
    F_classical = Ep * a.area * a.strain
    F_lattice = El * a.area * a.strain
    err_strain = eps_int / a.strain - 1
    err_F = F / F_classical - 1
    err_Fl = F / F_lattice - 1
    print(f"interior strain {eps_int:.6e} vs applied {a.strain:.6e}: {100*err_strain:+.3f} %")
    print(f"reaction {F:.6e} N vs E'A eps = {F_classical:.6e} N: {100*err_F:+.3f} %")
    print(f"lattice modulus / E' = {El/Ep:.5f}; reaction vs lattice E A eps = {F_lattice:.6e} N: {100*err_Fl:+.3f} %")
    ok = abs(err_strain) <= a.tol
    ok &= abs(err_F if a.reaction_against == "classical" else err_Fl) <= a.tol
    print("check_bar: PASS" if ok else "check_bar: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

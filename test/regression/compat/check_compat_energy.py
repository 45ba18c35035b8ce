#!/usr/bin/env python3
"""Checks compat_energy.e (Stored_Elastic_Energy and QuasiStatic "Time Steps").

Times must be the deck's list 0, 0.5, 0.75, 1. At t = 1 (isotropic stretch eps = 1e-3) every node must hold
the closed form 9/2 kappa eps^2 V. At every step the energy must equal an independent evaluation of Peridigm's
definition V_i (kappa theta_i^2/2 + (15 mu / (2 m_i)) sum_j omega (e - theta |xi|/3)^2 V_j), with omega =
1/|xi| and the bond sums done here from the node coordinates and displacements (theta and m from the
same sums, checked against the Dilatation and Weighted_Volume outputs).
usage: check_compat_energy.py RUN.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element, nodal  # noqa: E402

KAPPA, MU, EPS, HORIZON = 2.0e9, 1.0e9, 1.0e-3, 1.75


d = netCDF4.Dataset(sys.argv[1])
nv = lambda n: nodal(d, n)
ev = lambda n: element(d, n)
ok = True
t = np.asarray(d["time_whole"][:])
if not np.allclose(t, [0.0, 0.5, 0.75, 1.0], rtol=0, atol=1e-15):
    print("times", t, "expected the Time Steps 0 0.5 0.75 1"); ok = False
X = np.stack([np.asarray(d[c][:]) for c in ("coordx", "coordy", "coordz")], axis=1)
V = ev("Volume")[0]
E = ev("Stored_Elastic_Energy")
n = len(X)
xi = X[None, :, :] - X[:, None, :]
r = np.linalg.norm(xi, axis=2)
bond = (r > 0) & (r <= HORIZON * (1 + 1e-12))
omega = np.where(bond, 1.0 / np.where(r > 0, r, 1.0), 0.0)
m = (omega * r * r * V[None, :]).sum(axis=1)
if not np.allclose(ev("Weighted_Volume")[0], m, rtol=1e-12):
    print("Weighted_Volume differs from the bond sum"); ok = False
for s in range(len(t)):
    U = np.stack([nv("Displacement" + c)[s] for c in "XYZ"], axis=1)
    Y = X + U
    e = np.where(bond, np.linalg.norm(Y[None, :, :] - Y[:, None, :], axis=2) - r, 0.0)
    theta = 3.0 / m * (omega * r * e * V[None, :]).sum(axis=1)
    ed = e - theta[:, None] * r / 3.0
    W = 0.5 * KAPPA * theta ** 2 + 0.5 * 15.0 * MU / m * (omega * ed * ed * V[None, :]).sum(axis=1)
    if not np.allclose(ev("Dilatation")[s], theta, rtol=1e-9, atol=1e-15):
        print("step", s, "Dilatation differs from the bond sum"); ok = False
    if not np.allclose(E[s], W * V, rtol=1e-9, atol=1e-12 * max(1.0, np.abs(W * V).max())):
        print("step", s, "Stored_Elastic_Energy", E[s][:4], "expected", (W * V)[:4]); ok = False
closed = 4.5 * KAPPA * EPS ** 2 * V
if not np.allclose(E[-1], closed, rtol=1e-8):
    print("t = 1: energy", E[-1][:4], "expected 9/2 kappa eps^2 V =", closed[:4]); ok = False
if not (E[1] > 0).all() or not (E[1] < E[2]).all():
    print("energy should be positive and grow with the load"); ok = False
print("compat_energy: max |E - 9/2 kappa eps^2 V| / E = %.2e" % (np.abs(E[-1] - closed) / closed).max())
print("compat_energy: PASS" if ok else "compat_energy: FAIL")
sys.exit(0 if ok else 1)

#!/usr/bin/env python3
"""Thermal expansion against the closed forms of linear thermoelasticity (alpha = 1e-5 /K, dT = 100 K,
E = 200 GPa, nu = 0.3; the decks of this folder, last step).

free:    the body expands force-free, u = a dT (X - X_min) with a = alpha in 3D and plane stress and (1 + nu) alpha
         in plane strain (the out-of-plane constraint adds nu alpha dT); its stress is 0: |sigma_mean| from the
         Dilatation below 1e-6 E alpha dT.
clamped: u = 0 everywhere; the mean (in-plane) stress is -3 K alpha dT in 3D and plane strain and -E alpha dT / (1 - nu)
         in plane stress. The OSB solid's mean stress is kappa theta (3D), E/(2(1-nu)) tr (plane stress) and
         (kappa + mu/3) theta (plane strain), for the mechanical dilatation theta, whose plane-stress value is
         k tr with k = (1-2nu)/(1-nu) (tr: the in-plane strain trace; materials/OsbConstants.hpp).

corr (Elastic Correspondence, 3D and plane strain): the unrotated Cauchy stress itself: free, every in-plane
         component below 1e-6 E alpha dT (and, in plane strain, sigma_zz = -E alpha dT, the held out-of-plane strain);
         clamped, sigma_xx = sigma_yy (= sigma_zz) = -3 K alpha dT. The thermal increment leaves d in the form of the
         model's 'Rate Of Deformation', so a uniform heating of a free body is stress-free to round-off. Its default
         for Elastic Correspondence, Peridigm's end-of-step rate with the increment alpha (dT - dT_n): the free body
         stretches by 1/(1 - a dT) in one step, a dT = 1e-3 relative beyond the closed form (measured 1.0e-3, 1.3e-3
         in plane strain; within the 0.5 %), the clamped stress is the closed form to round-off (4e-13); with
         'Midpoint' the free stretch is 1 + a dT exactly and a held strain comes out as a dT / (1 + a dT / 2), 5e-4
         below the closed form (within the 1 %).

Tolerances: 0.5 % of alpha dT for the strain and 1 % of the closed-form stress (the issue's); the solver's relative
tolerance 1e-10 leaves the free solution exact to ~1e-9 and the clamped dilatation is exact up to round-off at every
point (each point's sum of omega |xi|^2 V over its family is its own m), so a wrong thermal term shows at the
percent level or more.
"""
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset

E, NU, ALPHA, DT = 200e9, 0.3, 1e-5, 100.0
K, MU = E / (3 * (1 - 2 * NU)), E / (2 * (1 + NU))


def read(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    ele = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_elem_var"][:]]
    X = np.stack([np.asarray(d.variables[f"coord{c}"][:]) for c in "xyz" if f"coord{c}" in d.variables], axis=1)
    u = np.stack([d.variables[f"vals_nod_var{nod.index('Displacement' + c) + 1}"][-1, :] for c in "XYZ"[:X.shape[1]]], axis=1)
    def elem(name):
        return np.asarray(d.variables[f"vals_elem_var{ele.index(name) + 1}eb1"][-1, :])
    if "Dilatation" in ele:
        theta = elem("Dilatation")
    else:  # correspondence: the stress components
        theta = {c: elem("Unrotated_Cauchy_Stress" + c) for c in ("XX", "YY", "ZZ", "XY")}
    change = d.variables[f"vals_nod_var{nod.index('Temperature_Change') + 1}"][-1, :]
    return X, u, theta, change


def main_corr(kind, dim, X, u, s):
    a = (1 + NU) * ALPHA if dim == "plane_strain" else ALPHA
    if kind == "free":
        exact = a * DT * (X - X.min(axis=0))
        err = np.max(np.abs(u - exact)) / (a * DT * np.max(X - X.min(axis=0)))
        inplane = max(np.max(np.abs(s[c])) for c in ("XX", "YY", "XY"))
        zz = -E * ALPHA * DT if dim == "plane_strain" else 0.0
        ezz = np.max(np.abs(s["ZZ"] - zz))
        print(f"free corr {dim}: max |u - a dT (X - X0)| / (a dT L) = {err:.3e}; max in-plane |sigma| / (E alpha dT) = "
              f"{inplane / (E * ALPHA * DT):.3e}; max |sigma_zz - ({zz:.4g})| / (E alpha dT) = {ezz / (E * ALPHA * DT):.3e}")
        # sigma_zz against the small-strain closed form to 1 %, as the clamped stress: the rate form integrates the
        # held strain as d = a dT / (1 + a dT / 2), a second-order difference of a dT / 2 = 5e-4.
        return err < 5e-3 and inplane < 1e-6 * E * ALPHA * DT and ezz < 1e-2 * E * ALPHA * DT
    closed = -3 * K * ALPHA * DT
    err = max(np.max(np.abs(s[c] - closed)) for c in ("XX", "YY", "ZZ")) / abs(closed)
    print(f"clamped corr {dim}: sigma_xx {s['XX'].min():.6e} .. {s['XX'].max():.6e} Pa, closed form {closed:.6e} Pa, "
          f"max rel. error over xx, yy, zz {err:.3e}; max |u| = {np.max(np.abs(u)):.1e}")
    return err < 1e-2 and np.max(np.abs(u)) == 0.0


def main(kind, dim, path):
    X, u, theta, change = read(path)
    if isinstance(theta, dict):
        ok = np.allclose(change, DT, rtol=0, atol=1e-9) and main_corr(kind, dim.replace("corr_", ""), X, u, theta)
        print("check_thermal: PASS" if ok else "check_thermal: FAIL")
        return 0 if ok else 1
    ok = np.allclose(change, DT, rtol=0, atol=1e-9)
    print(f"Temperature_Change: {change.min():.9g} .. {change.max():.9g} (expected {DT})")
    a = (1 + NU) * ALPHA if dim == "plane_strain" else ALPHA
    scale = {"3d": K, "plane_stress": E / (2 * (1 - NU)) * (1 - NU) / (1 - 2 * NU), "plane_strain": K + MU / 3}[dim]
    sigma = scale * theta
    if kind == "free":
        exact = a * DT * (X - X.min(axis=0))
        err = np.max(np.abs(u - exact)) / (a * DT * np.max(X - X.min(axis=0)))
        smax = np.max(np.abs(sigma)) / (E * ALPHA * DT)
        print(f"free {dim}: max |u - a dT (X - X0)| / (a dT L) = {err:.3e}; max |sigma_mean| / (E alpha dT) = {smax:.3e}")
        ok = ok and err < 5e-3 and smax < 1e-6
    else:
        closed = -E * ALPHA * DT / (1 - NU) if dim == "plane_stress" else -3 * K * ALPHA * DT
        err = np.max(np.abs(sigma - closed)) / abs(closed)
        umax = np.max(np.abs(u))
        print(f"clamped {dim}: sigma_mean {sigma.min():.6e} .. {sigma.max():.6e} Pa, closed form {closed:.6e} Pa, "
              f"max rel. error {err:.3e}; max |u| = {umax:.1e}")
        ok = ok and err < 1e-2 and umax == 0.0
    if dim == "3d":
        ok = check_energy(kind, path) and ok
    print("check_thermal: PASS" if ok else "check_thermal: FAIL")
    return 0 if ok else 1


def check_energy(kind, path):
    """3D Elastic: Stored_Elastic_Energy is that of the mechanical extension. Free: 0 (below 1e-9 of the clamped
    density times V: the expansion stores nothing); clamped: K theta^2 / 2 V with theta = -3 alpha dT at every point
    (the deviatoric part vanishes; 1e-9 relative, the dilatation is exact to round-off). Counting the thermal extension
    as strain would give the clamped value to the free block and 0 to the clamped one."""
    d = Dataset(path)
    d.set_auto_mask(False)
    ele = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_elem_var"][:]]
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]

    def last(name):
        if name in nod:
            return np.asarray(d.variables[f"vals_nod_var{nod.index(name) + 1}"][-1, :])
        return np.asarray(d.variables[f"vals_elem_var{ele.index(name) + 1}eb1"][-1, :])
    density = last("Stored_Elastic_Energy") / last("Volume")
    clamped = 0.5 * K * (3 * ALPHA * DT) ** 2
    if kind == "free":
        err = np.max(np.abs(density)) / clamped
        print(f"free 3d: max Stored_Elastic_Energy / V = {np.max(np.abs(density)):.3e} J/m^3, {err:.2e} of the clamped "
              f"block's {clamped:.6e}")
    else:
        err = np.max(np.abs(density - clamped)) / clamped
        print(f"clamped 3d: Stored_Elastic_Energy / V {density.min():.9e} .. {density.max():.9e} J/m^3, closed form "
              f"K (3 alpha dT)^2 / 2 = {clamped:.9e}, max rel. error {err:.2e}")
    return err < 1e-9


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:4]))

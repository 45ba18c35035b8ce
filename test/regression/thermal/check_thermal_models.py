#!/usr/bin/env python3
"""Thermal expansion of Elastic Plastic (ep), Elastic Plastic Hardening (eph) and Microelastic (micro) against the
closed forms of thermoelasticity and J2 plasticity (alpha = 1e-5 /K, dT = 100 K; the decks thermal_{free,clamped}_
{ep,eph,micro}_* and thermal_yield_*, last step; docs/thermal.md).

usage: check_thermal_models.py CASE MODEL KIND DIM FILE.e
  CASE: elastic (sigma_y = 500 MPa: the heating stays elastic) or yield (sigma_y = 100 MPa: past yield);
  MODEL: ep, eph, micro; KIND: free, clamped; DIM: 3d, plane_stress, plane_strain.

free:    u = eps (X - X_min) with eps = a dT, a = alpha (3D, plane stress) or (1 + nu) alpha (plane strain: the held
         out-of-plane direction adds nu alpha dT), to 0.5 % of eps; stress-free (below 1e-6 E alpha dT).
clamped: u = 0; the mean (in-plane) stress -3 K alpha dT (3D, plane strain) or -E alpha dT / (1 - nu) (plane stress),
         to 1 % (of the interior points for micro).
J2 models (E 200 GPa, nu 0.3): the mean stress from the mechanical Dilatation theta as check_thermal.py (3D: K theta,
plane stress: E / (2 (1 - nu) k) theta); in plane strain theta is the 3D volume strain (the thermal strain alpha dT I
is hydrostatic there, its held out-of-plane part included: it lowers theta by 3 alpha dT and leaves the deviatoric
state alone), so the in-plane mean stress is K theta + 2 mu tr Q with tr Q = tr eps / 6 = (theta + 3 alpha dT) / 6.
Von_Mises_Stress (Discrete normalisation: exact at every point of a uniform state) is the 3D one: 0 for a free 3D or
plane-stress block and for a clamped 3D or plane-strain one (hydrostatic), E alpha dT / (1 - nu) for a clamped
plane-stress block, E alpha dT (sigma_zz) for a free plane-strain one. Equivalent_Plastic_Strain: 0, or past yield
(perfect plasticity): clamped plane stress sigma_xx = sigma_yy = -sigma_y, eps_p = 2 (alpha dT - (1 - nu) sigma_y/E);
free plane strain sigma_zz = -sigma_y, eps_p = alpha dT - sigma_y / E, in-plane strain nu sigma_y / E + eps_p / 2 +
alpha dT, theta = -sigma_y / (3 K); eph past yield (K_h = 20 GPa): sigma = sigma_y + K_h eps_p with
eps_p = (alpha dT - (1 - nu) sigma_y / E) / (1/2 + K_h (1 - nu) / E). Tolerances 1 % (plastic values) and
1e-6 E alpha dT (zero stresses); eps_p = 0 exactly where the closed form has no plastic flow.
Microelastic (K 100 GPa, nu 1/4 in 3D and plane strain, 1/3 in plane stress; E = 3K (1 - 2 nu)): no stress output,
so the interior points' mean stress comes from Stored_Elastic_Energy: every bond of a clamped point has the stretch
s = -a dT, w = (c/4) s^2 S and the virial mean stress is c s S / (2 D), i.e. 2 w / (D s) (S = sum |xi| V_j over
the family, D the dimension). The micromodulus c is calibrated on the continuum moment Q = pi delta^4 (3D),
2 pi h delta^3 / 3 (2D), so on a lattice the model's bulk modulus is K S / Q: S / Q is counted here from the
lattice (whole neighbours within delta, as the decks' discretization), 1.0987 in 3D and 1.0254 in 2D at
delta = 3.015 dx, and the closed form is taken with that modulus (the continuum ratio is printed too). Free:
the energy-equivalent stress sqrt(2 E w) below 1e-6 E alpha dT.
"""
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset

ALPHA, DT, DX, DELTA = 1e-5, 100.0, 1e-3, 3.015e-3


def read(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    ele = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_elem_var"][:]]
    X = np.stack([np.asarray(d.variables[f"coord{c}"][:]) for c in "xyz" if f"coord{c}" in d.variables], axis=1)
    u = np.stack([d.variables[f"vals_nod_var{nod.index('Displacement' + c) + 1}"][-1, :] for c in "XYZ"[:X.shape[1]]],
                 axis=1)
    out = {n: np.asarray(d.variables[f"vals_elem_var{ele.index(n) + 1}eb1"][-1, :]) for n in ele}
    out["Temperature_Change"] = np.asarray(d.variables[f"vals_nod_var{nod.index('Temperature_Change') + 1}"][-1, :])
    return X, u, out


def lattice_ratio(dim):
    """S / Q of a whole family: sum |xi| V_j over the lattice neighbours within delta over its continuum moment."""
    n, r = int(DELTA / DX) + 1, DELTA / DX
    g = np.arange(-n, n + 1)
    axes = np.meshgrid(*([g] * (3 if dim == "3d" else 2)), indexing="ij")
    L = np.sqrt(sum(a.astype(float) ** 2 for a in axes))
    S = L[(L > 0) & (L <= r * (1 + 1e-12))].sum()
    return S / (np.pi * r ** 4 if dim == "3d" else 2 * np.pi * r ** 3 / 3)


def check(name, value, exact, tol):
    """|value - exact| <= tol |exact| over every value; prints the worst."""
    value = np.atleast_1d(value)
    err = np.max(np.abs(value - exact)) / abs(exact)
    ok = err <= tol
    print(f"  {name}: {value.min():.6e} .. {value.max():.6e}, closed form {exact:.6e}, max relative error "
          f"{err:.3e} (tolerance {tol:g}) {'ok' if ok else 'FAIL'}")
    return ok


def zero(name, value, bound):
    """|value| <= bound (1e-6 E alpha dT) over every value."""
    worst = np.max(np.abs(value))
    ok = worst <= bound
    print(f"  {name}: max |value| {worst:.3e} = {worst / bound:.3e} x 1e-6 E alpha dT (closed form 0) "
          f"{'ok' if ok else 'FAIL'}")
    return ok


def strain_check(X, u, eps):
    if eps == 0.0:
        umax = np.max(np.abs(u))
        print(f"  max |u| = {umax:.1e} (clamped: 0)")
        return umax == 0.0
    exact = eps * (X - X.min(axis=0))
    err = np.max(np.abs(u - exact)) / (eps * np.max(X - X.min(axis=0)))
    print(f"  max |u - eps (X - X0)| / (eps L) = {err:.3e} with eps = {eps:.6e} (tolerance 5e-3)")
    return err < 5e-3


def j2_case(case, model, kind, dim, X, u, out):
    E, NU = 200e9, 0.3
    K, MU = E / (3 * (1 - 2 * NU)), E / (2 * (1 + NU))
    sy = 100e6 if case == "yield" else 500e6
    aT, small = ALPHA * DT, 1e-6 * E * ALPHA * DT
    theta, vm, ep = out["Dilatation"], out["Von_Mises_Stress"], out["Equivalent_Plastic_Strain"]
    if dim == "3d":
        sigma = K * theta
    elif dim == "plane_stress":
        sigma = E / (2 * (1 - NU)) * (1 - NU) / (1 - 2 * NU) * theta
    else:  # elastic in-plane mean stress K theta + 2 mu tr Q (used where the plane-strain block stays elastic)
        sigma = K * theta + MU * (theta + 3 * aT) / 3
    eps = 0.0 if kind == "clamped" else ((1 + NU) * aT if dim == "plane_strain" else aT)
    vm_exact = {("free", "plane_strain"): E * aT, ("clamped", "plane_stress"): E * aT / (1 - NU)}.get((kind, dim), 0.0)
    mean = 0.0 if kind == "free" else (-E * aT / (1 - NU) if dim == "plane_stress" else -3 * K * aT)
    ep_exact = 0.0
    if case == "yield" and vm_exact > sy:  # perfect plasticity, or eph's linear isotropic hardening
        if dim == "plane_stress":
            kh = 20e9 if model == "eph" else 0.0
            ep_exact = (aT - (1 - NU) * sy / E) / (0.5 + kh * (1 - NU) / E)
            vm_exact = sy + kh * ep_exact
            mean = -vm_exact
        else:
            ep_exact = aT - sy / E
            vm_exact = sy
            eps = NU * sy / E + ep_exact / 2 + aT
            mean = None  # the in-plane stress is 0 by equilibrium (u above); theta is the 3D volume strain
    ok = strain_check(X, u, eps)
    if mean is None:
        ok &= check("Dilatation (3D volume strain -sigma_y / (3 K))", theta, -sy / (3 * K), 1e-2)
    elif mean == 0.0:
        ok &= zero("mean stress", sigma, small)
    else:
        ok &= check("mean stress", sigma, mean, 1e-2)
    ok &= check("Von_Mises_Stress", vm, vm_exact, 1e-2) if vm_exact else zero("Von_Mises_Stress", vm, small)
    ok &= check("Equivalent_Plastic_Strain", ep, ep_exact, 1e-2) if ep_exact else bool(np.all(ep == 0.0))
    if not ep_exact:
        print(f"  Equivalent_Plastic_Strain: max {np.max(ep):.3e} (closed form 0 exactly)")
    return ok


def micro_case(kind, dim, X, u, out):
    K = 100e9
    nu = 1.0 / 3.0 if dim == "plane_stress" else 0.25
    E, a = 3 * K * (1 - 2 * nu), (1 + nu) * ALPHA if dim == "plane_strain" else ALPHA
    V = DX ** 3 if dim == "3d" else DX * DX * 1e-3
    w = out["Stored_Elastic_Energy"] / V
    D = 3 if dim == "3d" else 2
    if kind == "free":
        ok = strain_check(X, u, a * DT)
        return ok & zero("energy-equivalent stress sqrt(2 E w)", np.sqrt(2 * E * w), 1e-6 * E * ALPHA * DT)
    ok = strain_check(X, u, 0.0)
    X = X[:, :D]  # a 2D model's points lie in z = 0
    lo, hi = X.min(axis=0), X.max(axis=0)
    inner = np.all((X - lo >= DELTA - DX / 2) & (hi - X >= DELTA - DX / 2), axis=1)
    if not inner.any():
        print("  no interior point: FAIL")
        return False
    sigma = 2 * w[inner] / (D * (-a * DT))
    closed = -E * ALPHA * DT / (1 - nu) if dim == "plane_stress" else -3 * K * ALPHA * DT
    ratio = lattice_ratio(dim)
    print(f"  {inner.sum()} interior points; lattice S / Q = {ratio:.6f}; continuum closed form {closed:.6e} Pa, "
          f"measured / continuum {sigma.mean() / closed:.6f}")
    return ok & check("interior mean stress (lattice modulus K S / Q)", sigma, closed * ratio, 1e-2)


def main(case, model, kind, dim, path):
    X, u, out = read(path)
    dT = out["Temperature_Change"]
    ok = bool(np.allclose(dT, DT, rtol=0, atol=1e-9))
    print(f"{case} {model} {kind} {dim}: Temperature_Change {dT.min():.9g} .. {dT.max():.9g} (expected {DT})")
    ok &= micro_case(kind, dim, X, u, out) if model == "micro" else j2_case(case, model, kind, dim, X, u, out)
    print("check_thermal_models: PASS" if ok else "check_thermal_models: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:6]))

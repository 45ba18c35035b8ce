#!/usr/bin/env python3
"""Staggered heat in a quasi-static run (NOXQuasiStatic with Solve For Temperature) against closed forms, at every
written step.

free (coupled_qs_free_3d.xml, t_k = 0.25 k s):

temperature: the uniform heating q / l = 1e8 W/m^3 into rho c = 4e6 J/(m^3 K) gives T_k = 300 + 100 t_k, which
             Backward Euler reproduces exactly (a constant source; the uniform field conducts nothing);
displacement: the step's mechanics sees its start's temperature (the staggered split): u_k = alpha (T_k-1 - 300)
             (X - X_min) on every point, free of stress, and u_0 = u_1 = 0. The split's error is this lag of one step:
             the displacement of the same run with the mechanics after the heat would be alpha (T_k - 300) (X - X_min),
             25 % of the final expansion more at the last step here.
Global_Heat:  rho c (T_k - 300) times the block's volume (8 mm)^3 (asserted to 1e-9 relative: the sum of the nodal
             volumes is the box's to round-off).

Tolerances: temperature 1e-9 K (the heat step converges to 1e-10 of its initial residual, the Krylov solve to 1e-12);
displacement 1e-6 of alpha dT L (the mechanics' relative tolerance 1e-10; the free expansion is exact up to it), so
a heat step that missed its source, a mechanics that read the end-of-step temperature, or a lost step shows at
25 % or more.

heating (coupled_qs_heating_plane_stress.xml, t_k = 0.125 k s): a clamped plane-stress J2 block with isotropic
hardening heated by q / l (100 K/s) and by 0.9 of its plastic work, adiabatic. A classical integration of the same
staggered scheme, written here: the mechanics of step k at dT = T_k-1 - 300 gives eps_p,k = max(eps_p,k-1,
(alpha dT - (1 - nu) sigma_y / E) / (1/2 + K (1 - nu) / E)) and von Mises s_k = sigma_y + K eps_p,k; the plastic work
per volume grows by s_k (eps_p,k - eps_p,k-1) (the material's rule: the returned von Mises times the step's plastic
strain); then T_k = T_k-1 + 100 dt + 0.9 dW_p / (rho c). Compared: T, eps_p, von Mises and Dissipated_Energy / V on
every point. The plastic heat is about 30 % of the temperature rise, so a lost or doubled source, or a feedback
one step late, misses by kelvins. Tolerances: 1e-9 relative to each quantity's final value (the uniform state is
exact up to the solvers' tolerances, 1e-10 relative; measured below 1e-12).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
from netCDF4 import Dataset  # noqa: E402

ALPHA, RATE, T0, L = 1e-5, 100.0, 300.0, 0.008


def main_free(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    X = np.stack([np.asarray(d.variables[f"coord{c}"][:]) for c in "xyz"], axis=1)
    times = np.asarray(d.variables["time_whole"][:])
    var = lambda name: np.asarray(d.variables[f"vals_nod_var{nod.index(name) + 1}"][:])  # noqa: E731
    T = var("Temperature")
    u = np.stack([var("Displacement" + c) for c in "XYZ"], axis=2)
    if len(times) != 5 or abs(times[-1] - 1.0) > 1e-12:
        sys.exit(f"FAIL: expected the start and 4 load steps to t = 1, found times {times}")
    scale = ALPHA * RATE * L
    glo = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_glo_var"][:]]
    heat = np.asarray(d.variables["vals_glo_var"][:, glo.index("Global_Heat")])
    heatExact = 4e6 * RATE * times * L ** 3
    worstH = np.max(np.abs(heat - heatExact)) / heatExact[-1]
    print(f"Global_Heat {heat[-1]:.9e} J at t = 1 s (closed form {heatExact[-1]:.9e}), largest error {worstH:.2e} of it")
    worstT = worstU = 0.0
    for k, t in enumerate(times):
        Tk = T0 + RATE * t
        eT = np.max(np.abs(T[k] - Tk))
        tStart = times[k - 1] if k > 0 else times[0]
        uk = ALPHA * RATE * tStart * (X - X.min(axis=0))
        eU = np.max(np.abs(u[k] - uk)) / scale
        worstT, worstU = max(worstT, eT), max(worstU, eU)
        print(f"step {k}: t = {t:.2f} s  T = {T[k].mean():.9f} K (closed form {Tk:.3f}), max |T - exact| = {eT:.2e} K;"
              f"  max |u - alpha dT(t_start)(X - X0)| = {eU:.2e} of alpha dT L")
    ok = worstT <= 1e-9 and worstU <= 1e-6 and worstH <= 1e-9
    print(f"{'PASS' if ok else 'FAIL'}: temperature within {worstT:.2e} K (bound 1e-9), displacement within "
          f"{worstU:.2e} of alpha dT L (bound 1e-6)")
    return 0 if ok else 1


E, NU, SY, KH, BETA, RHOC, RATE_HEAT = 200e9, 0.3, 100e6, 20e9, 0.9, 4000.0, 100.0


def main_heating(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    ele = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_elem_var"][:]]
    times = np.asarray(d.variables["time_whole"][:])
    T = np.asarray(d.variables[f"vals_nod_var{nod.index('Temperature') + 1}"][:])
    elem = lambda name: np.asarray(d.variables[f"vals_elem_var{ele.index(name) + 1}eb1"][:])  # noqa: E731
    node = lambda name: (np.asarray(d.variables[f"vals_nod_var{nod.index(name) + 1}"][:]) if name in nod  # noqa: E731
                         else elem(name))
    ep, vm, W, V = node("Equivalent_Plastic_Strain"), node("Von_Mises_Stress"), node("Dissipated_Energy"), node("Volume")
    if len(times) != 9 or abs(times[-1] - 1.0) > 1e-12:
        sys.exit(f"FAIL: expected the start and 8 load steps to t = 1, found times {times}")
    Tc, epc, wc, vmc = [T0], [0.0], [0.0], [0.0]
    for k in range(1, len(times)):
        dT = Tc[-1] - T0
        e = max(epc[-1], (ALPHA * dT - (1 - NU) * SY / E) / (0.5 + KH * (1 - NU) / E))
        s = SY + KH * e if e > 0 else E * ALPHA * dT / (1 - NU)
        wc.append(wc[-1] + (SY + KH * e) * (e - epc[-1]))
        epc.append(e)
        vmc.append(s)
        Tc.append(Tc[-1] + RATE_HEAT * (times[k] - times[k - 1]) + BETA * (wc[-1] - wc[-2]) / RHOC)
    worst = {}
    for k, t in enumerate(times):
        errs = {"T": np.max(np.abs(T[k] - Tc[k])) / (Tc[-1] - T0), "eps_p": np.max(np.abs(ep[k] - epc[k])) / epc[-1],
                "von Mises": np.max(np.abs(vm[k] - vmc[k])) / vmc[-1],
                "W_p": np.max(np.abs(W[k] / V[-1] - wc[k])) / wc[-1]}
        for key, v in errs.items():
            worst[key] = max(worst.get(key, 0.0), v)
        print(f"step {k}: t = {t:.3f} s  T {T[k].mean():.6f} K (classical {Tc[k]:.6f}; plastic heat "
              f"{BETA * wc[k] / RHOC:.6f} K), eps_p {ep[k].mean():.6e} ({epc[k]:.6e}), von Mises "
              f"{vm[k].mean() / 1e6:.6f} MPa ({vmc[k] / 1e6:.6f}), W_p {np.mean(W[k] / V[-1]):.6e} J/m^3 ({wc[k]:.6e})")
    ok = all(v <= 1e-9 for v in worst.values()) and BETA * wc[-1] / RHOC > 10.0
    print(("PASS" if ok else "FAIL") + ": largest errors relative to the final value: " +
          ", ".join(f"{k} {v:.2e}" for k, v in worst.items()) + f" (bound 1e-9); plastic heat at the end "
          f"{BETA * wc[-1] / RHOC:.3f} K of {Tc[-1] - T0:.3f} K")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main_free(sys.argv[2]) if sys.argv[1] == "free" else main_heating(sys.argv[2]))

#!/usr/bin/env python3
"""Where the biaxial test 2 (d0 = 0, h = 0) loses the uniqueness of its uniform state: the Rudnicki-Rice
localisation condition det(n . C_ep . n) <= 0 (J. Mech. Phys. Solids 23, 1975) along the phase-2 path of the
uniform specimen, and, given a run, the spread of its von Mises stress before and after that time.

The path is the continuum one (small strain): sigma_xx = -P held, eps_zz = 0, the axial strain applied in 20 000
steps of the rate form d sigma = C_ep d eps from the plastic in-plane confinement, with the model's yield
f = J - m (A I + B) and potential g = J - m d0 A I - m B (materials/DruckerPragerPlasticity.hpp, Li & Geng Eq. 38,
compression-positive I and J), C_ep = C - (C:g')(f':C) / (f':C:g') for h = 0. The minimum over in-plane band
normals n of det(Q_ep) / det(Q_e) turns negative at the onset (t = 100 + 2000 x axial strain in the deck's clock).

usage: localisation_check.py [--confining P] [RUN.e --before T0 --after T1 --uniform R0 --localised R1]
  prints the onset; with RUN.e exits 1 unless the relative spread (max - min) / mean of Von_Mises_Stress over all
  points is below R0 at every output time <= T0 and above R1 at some time >= T1, and unless the onset lies in
  (T0, T1) (the run's localisation is the continuum's loss of ellipticity, not a numerical mode).
"""
import argparse
import math
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np

E, NU, PHI, C, M0, P = 30e6, 0.25, 35.0, 60e3, 0.2, 600e3
K, G = E / (3 * (1 - 2 * NU)), E / (2 * (1 + NU))
S = math.sin(math.radians(PHI))
A = 2 * S / (math.sqrt(3) * (3 - S))
B = 6 * C * math.cos(math.radians(PHI)) / (math.sqrt(3) * (3 - S))
I3 = np.eye(3)
CE = (K - 2 * G / 3) * np.einsum("ij,kl->ijkl", I3, I3) + G * (np.einsum("ik,jl->ijkl", I3, I3) +
                                                                np.einsum("il,jk->ijkl", I3, I3))


def yield_f(sig):
    dev = sig - np.trace(sig) / 3 * I3
    return math.sqrt(0.5 * np.sum(dev * dev)) - M0 * (A * -np.trace(sig) + B)


def tangent(sig, d0):
    dev = sig - np.trace(sig) / 3 * I3
    J = math.sqrt(0.5 * np.sum(dev * dev))
    # tension-positive sigma: dJ/dsigma = dev / (2 J), dI/dsigma = -I (I = -tr sigma)
    fp, gp = dev / (2 * J) + M0 * A * I3, dev / (2 * J) + M0 * d0 * A * I3
    cg, fc = np.einsum("ijkl,kl->ij", CE, gp), np.einsum("ij,ijkl->kl", fp, CE)
    return CE - np.einsum("ij,kl->ijkl", cg, fc) / np.sum(fp * cg)


def ellipticity(cep):
    """min over in-plane unit n of det(n.C_ep.n) / det(n.C.n), and that n's angle from x [deg] (a 0.01 deg grid:
    the negative range near the onset is a few tenths of a degree wide)."""
    th = np.linspace(0.0, math.pi, 18001)
    n = np.stack([np.cos(th), np.sin(th), np.zeros_like(th)], axis=1)
    r = np.linalg.det(np.einsum("ai,ijkl,al->ajk", n, cep, n)) / np.linalg.det(np.einsum("ai,ijkl,al->ajk", n, CE, n))
    k = int(np.argmin(r))
    return float(r[k]), math.degrees(th[k])


def onset(P, d0=0.0, strain=0.05, steps=20000, checks=500):
    lo, hi = -P, 0.0  # sigma_zz on the yield surface of the in-plane confinement (sigma_xx = sigma_yy = -P)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (lo, mid) if yield_f(np.diag([-P, -P, mid])) > 0 else (mid, hi)
    sig = np.diag([-P, -P, 0.5 * (lo + hi)])
    de = -strain / steps
    for k in range(steps + 1):
        cep = tangent(sig, d0)
        if k % (steps // checks) == 0:
            r, th = ellipticity(cep)
            if r <= 0.0:
                e = -de * k
                return e, 100 + e / strain * 100, th
        a = np.einsum("ijkl,kl->ij", cep, np.diag([0.0, de, 0.0]))[0, 0]
        b = np.einsum("ijkl,kl->ij", cep, np.diag([1.0, 0.0, 0.0]))[0, 0]
        sig = sig + np.einsum("ijkl,kl->ij", cep, np.diag([-a / b, de, 0.0]))
    return None


def spreads(exo):
    import netCDF4
    d = netCDF4.Dataset(exo)
    names = ["".join(c.decode() for c in row if c).strip() for row in d["name_elem_var"][:].data]
    vm = d[f"vals_elem_var{names.index('Von_Mises_Stress') + 1}eb1"][:]
    t = d["time_whole"][:]
    return [(float(t[k]), float((vm[k].max() - vm[k].min()) / vm[k].mean())) for k in range(len(t)) if vm[k].mean() > 1e3]  # from the first loaded step


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exo", nargs="?")
    ap.add_argument("--confining", type=float, default=P, help="confining pressure [Pa] (test 2: 600e3)")
    ap.add_argument("--before", type=float, default=160.0)
    ap.add_argument("--after", type=float, default=175.0)
    ap.add_argument("--uniform", type=float, default=1e-3)
    ap.add_argument("--localised", type=float, default=1e-2)
    args = ap.parse_args()
    found = onset(args.confining)
    if found is None:
        print("no loss of ellipticity up to the axial strain 0.05")
        return 1
    e, t, th = found
    print(f"continuum onset of localisation (confining {args.confining / 1e3:g} kPa, d0 = 0, h = 0): axial strain {e:.4f}, t = {t:.1f}, band normal "
          f"{th:.1f} deg from x")
    if not args.exo:
        return 0
    rows = spreads(args.exo)
    before = max(r for tt, r in rows if tt <= args.before)
    after = max(r for tt, r in rows if tt >= args.after)
    print(f"{args.exo}: largest spread of von Mises up to t = {args.before:g}: {before:.3g}; from t = {args.after:g}: {after:.3g}")
    ok = before < args.uniform and after > args.localised and args.before < t < args.after
    if not ok:
        print(f"FAIL: expected spread < {args.uniform:g} up to t = {args.before:g}, > {args.localised:g} from "
              f"t = {args.after:g}, and the onset between them")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

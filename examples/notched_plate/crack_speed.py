#!/usr/bin/env python3
"""Crack-tip history and crack speed of a notched-plate run (examples/notched_plate), from its Exodus file.

usage: crack_speed.py RUN.e [--threshold 0.3] [--notch 0.010] [--width 0.040] [--E 200e9 --nu 0.3 --rho 7850]
                      [--check] [--csv OUT.csv]

Crack tip at each output step: the largest x among points whose Damage (share of broken bonds) is at least
the threshold (0.3: a point on a crack face loses about half its bonds in 2D, an intact one next to a single
broken bond far less), ignoring the fictitious layers (y outside the plate). Crack speed: the least-squares
slope of tip x against time over the steps where the tip lies between 25 % and 75 % of the ligament (notch
tip to far edge): the steady part, without initiation and the arrival at the free edge. Compared with the
Rayleigh wave speed of the plane-stress solid, c_R = c_s (0.862 + 1.14 nu) / (1 + nu) (Viktorov's
approximation, within 0.5 % for 0 <= nu <= 0.5), c_s = sqrt(mu / rho): linear elastic fracture mechanics
bounds a mode-I crack's speed by c_R. --check: exit 1 unless the crack crosses (tip within 2 grid spacings
of the far edge) and its speed is below c_R.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
import netCDF4
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from periforge_py.exodus import names  # noqa: E402


def read(path):
    f = netCDF4.Dataset(path)
    x, y = np.asarray(f["coordx"][:]), np.asarray(f["coordy"][:])
    t = np.asarray(f["time_whole"][:])
    if "name_elem_var" in f.variables and "Damage" in names(f, "name_elem_var"):
        k = names(f, "name_elem_var").index("Damage") + 1
        blocks = sorted(v for v in f.variables if v.startswith(f"vals_elem_var{k}eb"))
        damage = np.concatenate([np.asarray(f[v][:]) for v in blocks], axis=1)
    else:
        k = names(f, "name_nod_var").index("Damage") + 1
        damage = np.asarray(f[f"vals_nod_var{k}"][:])
    return x, y, t, damage


def tips(x, y, damage, threshold, height):
    inside = (y >= 0.0) & (y <= height)
    out = []
    for d in damage:
        hit = inside & (d >= threshold)
        out.append(x[hit].max() if hit.any() else np.nan)
    return np.array(out)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("exodus")
    ap.add_argument("--threshold", type=float, default=0.3)
    ap.add_argument("--notch", type=float, default=0.010)
    ap.add_argument("--width", type=float, default=0.040)
    ap.add_argument("--height", type=float, default=0.040)
    ap.add_argument("--E", type=float, default=200e9)
    ap.add_argument("--nu", type=float, default=0.3)
    ap.add_argument("--rho", type=float, default=7850.0)
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--csv")
    a = ap.parse_args()
    x, y, t, damage = read(a.exodus)
    tip = tips(x, y, damage, a.threshold, a.height)
    dx = np.min(np.diff(np.unique(np.round(x, 12))))
    mu = a.E / (2.0 * (1.0 + a.nu))
    cs = np.sqrt(mu / a.rho)
    cr = cs * (0.862 + 1.14 * a.nu) / (1.0 + a.nu)
    if a.csv:
        with open(a.csv, "w") as out:
            out.write("time,crack_tip_x\n")
            for ti, xi in zip(t, tip):
                out.write(f"{ti:.9g},{xi:.9g}\n")
    lig0, lig1 = a.notch + 0.25 * (a.width - a.notch), a.notch + 0.75 * (a.width - a.notch)
    sel = np.isfinite(tip) & (tip >= lig0) & (tip <= lig1)
    crossed = np.isfinite(tip[-1]) and tip[-1] >= a.width - 2.0 * dx
    speed = np.polyfit(t[sel], tip[sel], 1)[0] if sel.sum() >= 2 else float("nan")
    start = t[np.argmax(np.isfinite(tip))] if np.isfinite(tip).any() else float("nan")
    print(f"crack: initiates by t = {start * 1e6:.2f} us, tip at the last step x = {tip[-1] * 1e3:.2f} mm "
          f"(plate width {a.width * 1e3:g} mm): {'crosses' if crossed else 'does NOT cross'}")
    print(f"crack speed {speed:.0f} m/s over {sel.sum()} output steps (tip between {lig0 * 1e3:g} and "
          f"{lig1 * 1e3:g} mm); Rayleigh wave speed c_R = {cr:.0f} m/s (c_s = {cs:.0f} m/s): "
          f"v/c_R = {speed / cr:.2f}")
    if a.check:
        ok = crossed and np.isfinite(speed) and 0.0 < speed < cr
        print("crack_speed: " + ("PASS" if ok else "FAIL"))
        return 0 if ok else 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

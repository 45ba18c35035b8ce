#!/usr/bin/python3
"""Steady heat conduction through a plate with a hole (issue 33, example b): a Periforge run of
examples/thermal/plate_hole_steady*.xml against the CalculiX reference examples/thermal/reference/plate_hole_steady_fe.csv
(scripts/thermal_plate_hole_reference).

The PD temperature at a probe is the bilinear interpolation of the four grid points around it (all four must be in
the body: the probes sit more than a horizon from every surface). Asserted: |T_PD - T_FE| <= 2 K, 2 % of the applied
difference of 100 K (issue 33), at the three probes (hole: 4 mm before the hole's hot side, where the hole disturbs
the field most; mid: mid-way between the hot edge and the hole; far: near the cold bottom corner). Reported, not
asserted: the surface points next to the hole (PD's outermost points against the FE rim at the same angle: the
rim is insulated, so dT/dr = 0 there and the half-spacing offset costs O(dx^2)), the hole's hot-side point and the
line y = 50 mm (the two grid rows beside it averaged: they are mirror images).

usage: check_plate_hole.py RUN.e [--ref CSV] [--png OUT.png]
  --png: the error T_PD - T_FE along y = 50 mm, at the probes and around the hole (matplotlib).
Exits 0 when every probe is within 2 K, 1 otherwise (2 on unreadable input).
"""
import argparse
import csv
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset

HERE = os.path.dirname(os.path.abspath(__file__))
REF = os.path.join(HERE, "reference", "plate_hole_steady_fe.csv")
TOL = 2.0                       # K: 2 % of the applied 100 K (issue 33)
XC, YC, A = 0.05, 0.05, 0.02    # m: the hole


def read_run(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    if "Temperature" not in nod:
        raise ValueError(f"{path}: no nodal variable Temperature (Output Variables)")
    x = np.asarray(d.variables["coordx"][:])
    y = np.asarray(d.variables["coordy"][:])
    T = np.asarray(d.variables[f"vals_nod_var{nod.index('Temperature') + 1}"][-1, :])
    return x, y, T


def read_ref(path):
    with open(path) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    for r in rows:
        r["x"], r["y"], r["T"] = float(r["x_mm"]) * 1e-3, float(r["y_mm"]) * 1e-3, float(r["T_K"])
    return rows


class Grid:
    """The run's points indexed on their square lattice (Rectangle With Holes: uniform spacing)."""

    def __init__(self, x, y, T):
        xs = np.unique(np.round(x, 12))
        self.dx = float(np.min(np.diff(xs)))
        self.x0, self.y0 = float(x.min()), float(y.min())
        self.at = {}
        for i, (a, b) in enumerate(zip(x, y)):
            self.at[(int(round((a - self.x0) / self.dx)), int(round((b - self.y0) / self.dx)))] = i
        self.x, self.y, self.T = x, y, T

    def bilinear(self, px, py):
        fx, fy = (px - self.x0) / self.dx, (py - self.y0) / self.dx
        i, j = int(math.floor(fx + 1e-9)), int(math.floor(fy + 1e-9))
        u, v = fx - i, fy - j
        ids = [self.at.get(k) for k in ((i, j), (i + 1, j), (i, j + 1), (i + 1, j + 1))]
        if any(k is None for k in ids):
            raise ValueError(f"({px * 1e3:g}, {py * 1e3:g}) mm: a neighbouring grid point is missing (outside the body)")
        t = self.T[ids]
        return float((1 - u) * (1 - v) * t[0] + u * (1 - v) * t[1] + (1 - u) * v * t[2] + u * v * t[3])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("exodus")
    ap.add_argument("--ref", default=REF)
    ap.add_argument("--png")
    a = ap.parse_args()
    try:
        x, y, T = read_run(a.exodus)
        ref = read_ref(a.ref)
    except (OSError, ValueError, KeyError, IndexError) as e:
        print(f"check_plate_hole: {e}")
        return 2
    g = Grid(x, y, T)
    plate = (x > 0) & (x < 0.1)   # the fictitious layers lie outside
    print(f"check_plate_hole: {os.path.basename(a.exodus)}: {np.count_nonzero(plate)} plate points, dx = "
          f"{g.dx * 1e3:g} mm; T in [{T[plate].min():.3f}, {T[plate].max():.3f}] K; tolerance {TOL:g} K "
          f"(2 % of 100 K)")
    ok = True
    probes = []
    for r in ref:
        if r["kind"] != "probe":
            continue
        pd = g.bilinear(r["x"], r["y"])
        err = pd - r["T"]
        good = abs(err) <= TOL
        ok &= good
        probes.append((r["x"], r["y"], err, r["name"]))
        print(f"  probe {r['name']:5s} ({r['x_mm']:>5.5s}, {r['y_mm']:>5.5s}) mm: PD {pd:9.4f} K  FE {r['T']:9.4f} K  "
              f"error {err:+7.4f} K ({100 * err / 100.0:+.2f} % of 100 K)  {'ok' if good else 'MISS'}")

    if len(probes) != 3:
        print(f"check_plate_hole: {a.ref} has {len(probes)} probe rows, expected 3")
        return 2

    # Findings (not asserted): the hole's surface points against the FE rim at the same angle.
    rim = [r for r in ref if r["kind"] == "rim"]
    rim_deg = np.array([float(r["name"][3:]) for r in rim])
    rim_T = np.array([r["T"] for r in rim])
    rr = np.hypot(x - XC, y - YC)
    surf = plate & (rr < A + g.dx)
    deg = np.degrees(np.arctan2(y - YC, -(x - XC)))       # 0 at the hot side, 90 at the top
    top = surf & (deg >= 0) & (deg <= 180)
    fe_at = np.interp(deg[top], rim_deg, rim_T)
    e_rim = T[top] - fe_at
    k = int(np.argmax(np.abs(e_rim)))
    print(f"  finding: hole surface ({np.count_nonzero(top)} outermost points, r < a + dx, upper half) against the FE "
          f"rim: max |error| {np.max(np.abs(e_rim)):.3f} K at {deg[top][k]:.0f} deg (PD {T[top][k]:.3f}, "
          f"FE {fe_at[k]:.3f} K), mean |error| {np.mean(np.abs(e_rim)):.3f} K")
    edge = [r for r in ref if r["kind"] == "finding" and r["name"] == "hole_edge"][0]
    hot = surf & (np.abs(y - YC) < g.dx) & (x < XC)
    xe = float(np.mean(x[hot]))
    line = sorted((r["x"], r["T"]) for r in ref if r["kind"] == "line_y50")
    lx, lT = np.array([p[0] for p in line]), np.array([p[1] for p in line])
    fe_e = float(np.interp(xe, lx, lT))
    print(f"  finding: hole's hot side, PD surface points at x = {xe * 1e3:g} mm: {np.mean(T[hot]):.3f} K; FE there "
          f"{fe_e:.3f} K (error {np.mean(T[hot]) - fe_e:+.3f} K), FE on the hole (30, 50) mm {edge['T']:.3f} K")

    # The line y = 50 mm: the two grid rows beside it.
    rows = np.abs(np.abs(y - YC) - g.dx / 2) < 1e-9 * g.dx + 1e-12
    xs = np.unique(np.round(x[rows & plate], 12))
    pdl = np.array([np.mean(T[rows & (np.abs(x - v) < 1e-9)]) for v in xs])
    fel = np.interp(xs, lx, lT)
    el = pdl - fel
    print(f"  finding: line y = 50 mm ({len(xs)} points): max |error| {np.max(np.abs(el)):.3f} K at x = "
          f"{xs[np.argmax(np.abs(el))] * 1e3:g} mm")

    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(1, 2, figsize=(11, 4.2))
        for sel in (xs < XC, xs > XC):
            ax[0].plot(xs[sel] * 1e3, el[sel], "o-", ms=3, color="C0")
        for r in probes:
            ax[0].plot(r[0] * 1e3, r[2], "s", ms=7, label=f"probe {r[3]} ({r[0] * 1e3:g}, {r[1] * 1e3:g}) mm")
        ax[0].set_xlabel("x [mm]")
        ax[0].set_ylabel("T_PD - T_FE [K]")
        ax[0].set_title("error along y = 50 mm (probes: their own y)")
        o = np.argsort(deg[top])
        ax[1].plot(deg[top][o], e_rim[o], "o", ms=3)
        ax[1].set_xlabel("angle on the hole from its hot side [deg]")
        ax[1].set_ylabel("T_PD - T_FE [K]")
        ax[1].set_title("error at the hole's outermost points (upper half)")
        for a_ in ax:
            a_.axhline(TOL, color="r", lw=0.8, ls="--")
            a_.axhline(-TOL, color="r", lw=0.8, ls="--", label="tolerance +-2 K")
            a_.axhline(0.0, color="k", lw=0.5)
            a_.set_ylim(-2.5, 2.5)
            a_.grid(alpha=0.3)
        ax[0].legend(fontsize=8, loc="lower left")
        ax[1].legend(fontsize=8, loc="lower left")
        fig.suptitle(f"{os.path.basename(a.exodus)}: steady conduction, dx = {g.dx * 1e3:g} mm")
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"  wrote {a.png}")
    print("check_plate_hole: PASS" if ok else "check_plate_hole: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

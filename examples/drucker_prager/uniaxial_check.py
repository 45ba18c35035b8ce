#!/usr/bin/env python3
"""End state of a uniaxial_elastic* run (make_uniaxial.py): sigma_yy and sigma_xx over the interior (at least
2 delta from every face), the outer layer (the boundary rows and columns) and the whole 2-delta band, against
the exact uniform state (sigma_yy = -p / F_xx: the Pressure is a dead load on the reference area, P_yy = F_xx
sigma_yy in plane strain; sigma_xx = 0).

usage: uniaxial_check.py RUN.e [--bound R]
  --bound R   exit 1 unless every point's sigma_yy is within R (relative) of the interior mean, and |sigma_xx|
              within R of |interior sigma_yy| (the issue's "boundary rows within 1 % of the interior")
"""
import argparse
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
P = 200e3


def main(a):
    table = subprocess.run([sys.executable, os.path.join(ROOT, "scripts", "exodus_to_csv"), a.exo, "--vars",
                            "DisplacementX,Unrotated_Cauchy_StressXX,Unrotated_Cauchy_StressYY"],
                           check=True, capture_output=True, text=True).stdout.splitlines()
    head = table[1].split(",")
    rows = [dict(zip(head, map(float, line.split(",")))) for line in table[2:]]
    xs, ys = sorted({r["X"] for r in rows}), sorted({r["Y"] for r in rows})
    dx = xs[1] - xs[0]
    two_delta = 2 * 3.015 * dx
    depth = lambda r: min(r["X"] - xs[0], xs[-1] - r["X"], r["Y"] - ys[0], ys[-1] - r["Y"])
    inner = [r for r in rows if depth(r) >= two_delta]
    outer = [r for r in rows if depth(r) < 0.5 * dx]
    band = [r for r in rows if depth(r) < two_delta]
    # F_xx of the uniform state from the interior's lateral stretch (the x displacement's slope).
    n = len(inner)
    mx = sum(r["X"] for r in inner) / n
    fxx = 1 + sum((r["X"] - mx) * r["DisplacementX"] for r in inner) / sum((r["X"] - mx) ** 2 for r in inner)
    syy_in = sum(r["Unrotated_Cauchy_StressYY"] for r in inner) / n
    exact = -P / fxx
    print(f"{a.exo}: {len(rows)} points, dx {dx * 1e3:g} mm; interior {n}, outer layer {len(outer)}, 2-delta band {len(band)}")
    print(f"exact uniform sigma_yy = -p / F_xx = {exact / 1e3:.3f} kPa (F_xx = {fxx:.6f}); interior mean {syy_in / 1e3:.3f} kPa "
          f"({100 * (syy_in / exact - 1):+.3f} %)")
    worst = 0.0
    for label, pts in (("interior", inner), ("outer layer", outer), ("2-delta band", band), ("all points", rows)):
        syy = [r["Unrotated_Cauchy_StressYY"] for r in pts]
        sxx = [r["Unrotated_Cauchy_StressXX"] for r in pts]
        dev = max(abs(v / syy_in - 1) for v in syy)
        lat = max(abs(v) for v in sxx) / abs(syy_in)
        worst = max(worst, dev, lat)
        print(f"  {label:13s}: sigma_yy {min(syy) / 1e3:9.3f} .. {max(syy) / 1e3:9.3f} kPa (max {100 * dev:.3f} % off the "
              f"interior mean), |sigma_xx| <= {max(abs(v) for v in sxx) / 1e3:.3f} kPa ({100 * lat:.3f} %)")
    if a.bound is not None and worst > a.bound:
        print(f"FAIL: a point departs {100 * worst:.3f} % from the interior (bound {100 * a.bound:g} %)")
        return 1
    return 0


if __name__ == "__main__":
    ap = argparse.ArgumentParser()
    ap.add_argument("exo")
    ap.add_argument("--bound", type=float)
    sys.exit(main(ap.parse_args()))

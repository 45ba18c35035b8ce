#!/usr/bin/env python3
"""Thick-walled cylinder under internal pressure, plane strain (issue 16): Periforge's Pressure condition
and the OSB models against closed forms (geometry and references in cylinder_case.py).

  elastic   Elastic, p = 0.3 p_y, NOX: bore and outside radial displacement vs Lame. Bounds: bore 2 %
            (measured -0.96 %), outside 4 % (measured -2.6 %: the truncated families near the free outer
            surface overestimate the dilatation under the hoop stress, the surface effect); a 5 % error in the
            applied force fails both. With 'Surface Correction' = 'Position Aware' (docs/materials.md, "Surface
            correction"): bore within 3 % (measured +1.99 %), outside error in [+1 %, +4 %] (measured +2.90 %;
            the window excludes the uncorrected -2.6 %, so a correction that is not applied fails).
  yield     Elastic Plastic (Continuum normalisation), p from 0.85 to 1.1 p_y in 0.05 p_y steps: no plastic
            strain at the bore probe at 0.95 p_y, some at 1.05 p_y: first yield within 5 %.
  limit     Elastic Plastic on the polar ring (cylinder_case.PolarRing: its material spans exactly a ... b),
            p from 0.50 to 1.06 p_L in 0.04 p_L steps: the twice-elastic-slope collapse pressure (bore
            displacement twice the elastic line's) within 3 % of p_L (measured +0.4 % at 20 rings, -1.9 % at
            40; the 1D J2 finite-element solution (radial_j2.py) gives -1.6 % by the same criterion), and the
            plastic compliance up to 0.94 p_L within 10 % of that FE solution (measured 2.8 % / 7.5 %).
            --rings N changes the resolution (scripts/validate_cylinder runs 40).
The 'Discrete' normalisation gives first yield at about 1.17 p_y here (the bore's von Mises at p_y is
171 MPa for sigma_y = 200 MPa): the check uses 'Continuum', the paper's.

usage: run_cylinder.py [MPIRUN... -np N] PERIFORGE_EXE [--rings N]
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cylinder_case as C  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
import radial_j2  # noqa: E402

ELASTIC = '<Parameter name="Material Model" type="string" value="Elastic"/>'
PLASTIC = f'''<Parameter name="Material Model" type="string" value="Elastic Plastic"/>
      <Parameter name="Yield Stress" type="double" value="{C.SIGMA_Y}"/>
      <Parameter name="Yield Normalization" type="string" value="Continuum"/>'''


def run(cmd, material, t0, t1, steps, p_ref):
    """Runs p(t) = p_ref t from t0 to t1; returns the history rows (one per load step, step 0 dropped)."""
    probed = "Displacement" if "Elastic Plastic" not in material else "Displacement Equivalent_Plastic_Strain"
    rows = C.run_case(cmd, material, t0, t1, steps, f"{p_ref!r}*t",
                      lambda text: text.replace('value="Displacement"/>', f'value="{probed}"/>', 1))
    return [r for r in rows.values() if int(r["step"]) > 0]


def check(failures, ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def elastic(cmd, failures):
    p = 0.3 * C.first_yield_pressure()
    corrected = ELASTIC + '<Parameter name="Surface Correction" type="string" value="Position Aware"/>'
    for material, label, bounds in ((ELASTIC, "", {"Bore": (-0.02, 0.02), "Outside": (-0.04, 0.04)}),
                                    (corrected, " Position Aware", {"Bore": (-0.03, 0.03), "Outside": (0.01, 0.04)})):
        row = run(cmd, material, 0.0, 1.0, 1, p)[-1]
        for probe, r in (("Bore", C.A), ("Outside", C.B)):
            u, ref = float(row[f"Probe_{probe}_DisplacementX"]), C.lame_radial_displacement(p, r)
            lo, hi = bounds[probe]
            check(failures, lo < u / ref - 1 < hi, f"elastic{label} u_r({probe}) = {u:.5g} m, Lame {ref:.5g} m, error "
                  f"{100 * (u / ref - 1):+.2f} % (bounds {100 * lo:+.0f} % ... {100 * hi:+.0f} %)")


def first_yield(cmd, failures):
    rows = run(cmd, PLASTIC, 0.8, 1.1, 6, C.first_yield_pressure())
    eps = {round(float(r["time"]), 6): float(r["Probe_Bore_Equivalent_Plastic_Strain"]) for r in rows}
    first = min(t for t, e in eps.items() if e > 0) if any(e > 0 for e in eps.values()) else None
    check(failures, eps[0.95] == 0.0 and eps[1.05] > 0.0,
          f"first yield at the bore between {max([t for t, e in eps.items() if e == 0], default=0)} and {first} p_y "
          f"(p_y = {C.first_yield_pressure() / 1e6:.2f} MPa; bound: within 5 %)")


def tes_pressure(ps, us):
    """Twice-elastic-slope collapse pressure (ASME VIII-2's criterion): the first pressure at which the
    displacement reaches twice the elastic line's, u/p = 2 (u/p) of the first (elastic) point; linear between
    points. None when the curve never gets there."""
    c0 = us[0] / ps[0]
    r = [u / p / c0 for p, u in zip(ps, us)]
    for k in range(1, len(r)):
        if r[k - 1] < 2.0 <= r[k]:
            return ps[k - 1] + (2.0 - r[k - 1]) * (ps[k] - ps[k - 1]) / (r[k] - r[k - 1]), r
    return None, r


def continuum_curve(ts, r_probe):
    """The 1D J2 finite-element reference (radial_j2.py, no hardening) at p = t p_L: u at r_probe."""
    m = radial_j2.RadialJ2(C.A, C.B, C.E, C.NU, C.SIGMA_Y)
    u = []
    for t in ts:  # in order: each solve starts from the state the previous one committed
        m.solve(t * C.limit_pressure())
        u.append(float(np.interp(r_probe, m.r, m.u)))
    return u


def limit(cmd, failures, rings):
    """Perfect plasticity up to collapse on the polar ring (its material spans exactly a ... b, so p_L is the
    closed form's; on the square lattice the material spans a - dx/2 ... b + dx/2, whose p_L is 5 % higher)."""
    mesh, p_l = C.PolarRing(rings), C.limit_pressure()
    t0, t1, steps = 0.46, 1.06, 15  # 0.04 p_L steps; the first, 0.50 p_L, is below p_y = 0.54 p_L: elastic
    rows = C.run_case(cmd, PLASTIC, t0, t1, steps, f"{p_l!r}*t", mesh=mesh, timeout=600 * (rings / 20) ** 3)
    ts = [round(t, 6) for t in sorted(rows) if int(rows[t]["step"]) > 0]
    u = [float(rows[t]["Probe_Bore_DisplacementX"]) for t in ts]
    p_tes, ratio = tes_pressure(ts, u)
    t_fe = [t for t in ts if t < 0.99] + [0.99]  # the continuum carries up to p_L only
    u_fe = continuum_curve(t_fe, mesh.bore_probe_r)
    p_tes_fe, ratio_fe = tes_pressure(t_fe, u_fe)
    ratio_fe = ratio_fe[:-1]
    print(f"     polar ring, {rings} rings (dr = {mesh.spacing * 1e3:.3g} mm, delta/dr = 3.015): u(bore)/elastic line")
    for k, t in enumerate(ts):
        fe = f"   1D FE {ratio_fe[k]:.3f}" if k < len(ratio_fe) else ""
        print(f"     p = {t:.2f} p_L: {ratio[k]:.3f}{fe}")
    print(f"     twice-elastic-slope pressure: peridynamics {p_tes if p_tes is None else round(p_tes, 4)}, "
          f"1D FE {round(p_tes_fe, 4)} (x p_L = {p_l / 1e6:.2f} MPa)")
    # 3 %: the bound. The criterion's own bias is the 1D FE's distance from p_L (-1.7 %), inside it.
    check(failures, p_tes is not None and abs(p_tes - 1.0) < 0.03,
          f"limit pressure (twice-elastic-slope) {p_tes if p_tes is None else round(p_tes, 4)} p_L: within 3 %")
    # 10 %: contained plasticity (0.54 ... 0.94 p_L) deviates from the local continuum by a resolution-dependent
    # amount at delta/dr = 3.015 (measured max 2.8 % at 20 rings, 7.5 % at 40; likely the bore layer yielding early and
    # the wider horizon stiffening the spreading zone); the bound guards gross errors (a plane-strain or yield-level
    # error of 10 %); a 5 % yield-stress error is caught by the limit pressure above (it moves it 5 %).
    dev = [(ratio[k] / ratio_fe[k] - 1, t) for k, t in enumerate(ts) if 0.5 < t < 0.95]
    worst = max(dev, key=lambda d: abs(d[0]))
    check(failures, abs(worst[0]) < 0.10,
          f"plastic compliance u/elastic line vs 1D FE up to 0.94 p_L: largest deviation "
          f"{100 * worst[0]:+.1f} % at {worst[1]:.2f} p_L (bound 10 %)")


def main(argv):
    rings = int(argv[argv.index("--rings") + 1]) if "--rings" in argv else 20
    cmd = [a for k, a in enumerate(argv[1:], 1) if a != "--rings" and argv[k - 1] != "--rings"]
    failures = []
    elastic(cmd, failures)
    first_yield(cmd, failures)
    limit(cmd, failures, rings)
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

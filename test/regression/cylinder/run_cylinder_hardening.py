#!/usr/bin/env python3
"""The thick-walled cylinder with hardening, loaded past yield and unloaded (issue 16): Periforge's
`Elastic Plastic Hardening` (plane strain, Continuum normalisation, isotropic hardening) against the classical
1D radial J2 solution written in radial_j2.py (geometry in cylinder_case.py).

Load: bore pressure p(t) = 2.5 p_y (1 - |t - 1|), t in [0, 2], 12 NOX steps (6 up, 6 down); p_y = 86.5 MPa,
2.5 p_y = 1.35 p_L of the perfectly plastic ring; isotropic hardening modulus 20 GPa (E/10). The whole ring is
plastic at the peak; the unloading is elastic (1D: no reverse yield; residual hoop stress at the bore -173 MPa).

Compared, with bounds and their reasons (BOUNDS below):
  - residual von Mises stress on the second ring of points (r = a + dx; the bore layer itself has a truncated
    family, the surface effect, and is not compared): the residual stress the issue asks for;
  - the bore's peak and residual radial displacement;
  - no reverse yielding on unloading at r = a + dx (its equivalent plastic strain stays put), as in 1D.

Kinematic hardening (the same load, the kinematic modulus 20 GPa): until 2026-12-06 the run stopped (Newton and
then ADR failed at t = 0.85 on loading or on the first unloading steps): the return mapping treated a hardened point
unloading past its back stress as plastic. It now unloads and reverse-yields at r = a + dx as the 1D solution does;
peak and residual bore displacement are bounded as for the isotropic case. The residual von Mises stress at
r = a + dx is printed, not bounded: it is +59 % of the 1D value because the peak plastic strain there is 39 % below
the 1D one (0.0041 against 0.0066, the same in the isotropic run, where the elastic unloading does not show it), so
the back stress that sets the reverse yield is 81 instead of 133 MPa (docs/verification.md).

usage: run_cylinder_hardening.py PERIFORGE_EXE [MPIRUN... -np N] [--isotropic-only]
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cylinder_case as C  # noqa: E402
import radial_j2 as R  # noqa: E402

PEAK = 2.5          # p_max / p_y
STEPS = 12
MODULUS = 20.0e9
# Measured (np 1 and 2, dx = 0.5 mm, delta = 3.015 dx): see the closing note of issue 16 and docs/validation.md.
BOUNDS = {
    # Measured -8.4 % (np 1 and 2; kinematic the same: monotonic loading). Beyond p_L the displacement is
    # hardening-controlled: du/dp is 3x u/p, so the Pressure layer's resultant on this lattice (the 124 bore points
    # carry 0.987 of p 2 pi a; the count of lattice points in a <= r < a + dx fluctuates with dx) gives -3.9 %; the
    # lattice's plastic zone the rest.
    "peak u(a)": 0.12,
    # Measured -11.2 % (kinematic -12.8 %): the peak's error minus the elastic recovery's (-1 %), relative to a
    # smaller number.
    "residual u(a)": 0.15,
    # Measured -0.5 % (isotropic). A quarter of the 1D von Mises change over one dx (-24 %) at this radius; a 5 %
    # error in the yield stress moves it by about 8 %. Kinematic: not bounded (module docstring).
    "residual vm(a+dx)": 0.05,
}
UNBOUNDED = {("kin", "residual vm(a+dx)")}
VARS = "Displacement Von_Mises_Stress Equivalent_Plastic_Strain"


def material(kind):
    name = "Isotropic" if kind == "iso" else "Kinematic"
    return f'''<Parameter name="Material Model" type="string" value="Elastic Plastic Hardening"/>
      <Parameter name="Yield Stress" type="double" value="{C.SIGMA_Y}"/>
      <Parameter name="{name} Hardening Modulus" type="double" value="{MODULUS}"/>
      <Parameter name="Yield Normalization" type="string" value="Continuum"/>'''


def probe(name, x):
    return (f'<ParameterList name="{name}"><Parameter name="X" type="double" value="{x}"/>'
            f'<Parameter name="Y" type="double" value="0.0"/><Parameter name="Z" type="double" value="0.0"/>'
            f'<Parameter name="Variables" type="string" value="{VARS}"/></ParameterList>\n      ')


def run_periforge(cmd, kind):
    def edit(text):
        text = text.replace('value="Displacement"/>', f'value="{VARS}"/>')
        return text.replace('<ParameterList name="Outside">', probe("Ring2", C.A + C.DX) + '<ParameterList name="Outside">')
    p_max = PEAK * C.first_yield_pressure()
    return C.run_case(cmd, material(kind), 0.0, 2.0, STEPS, f"{p_max!r}*(1-fabs(t-1))", edit)


def reference(kind):
    """The 1D solution at the same load steps: u(a), u(a + dx), von Mises and eps_p at a + dx."""
    K, H = (MODULUS, 0.0) if kind == "iso" else (0.0, MODULUS)
    m = R.RadialJ2(C.A, C.B, C.E, C.NU, C.SIGMA_Y, K, H, elements=400)
    out = {}
    for t in np.linspace(0.0, 2.0, STEPS + 1)[1:]:
        m.solve(PEAK * C.first_yield_pressure() * (1 - abs(t - 1)))
        rg, s = m.gp_r.ravel(), m.sigma.reshape(-1, 3)
        ring2 = [np.interp(C.A + C.DX, rg, s[:, k]) for k in range(3)]
        out[round(t, 6)] = {"u(a)": m.u[0], "vm(a+dx)": R.von_mises(ring2),
                            "ep(a+dx)": np.interp(C.A + C.DX, rg, m.alpha.ravel())}
    return out


def check(failures, ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def compare(cmd, kind, failures):
    pd, ref = run_periforge(cmd, kind), reference(kind)
    ep = {t: float(pd[t]["Probe_Ring2_Equivalent_Plastic_Strain"]) for t in (1.0, 2.0)}
    measured = {"peak u(a)": (float(pd[1.0]["Probe_Bore_DisplacementX"]), ref[1.0]["u(a)"], "m"),
                "residual u(a)": (float(pd[2.0]["Probe_Bore_DisplacementX"]), ref[2.0]["u(a)"], "m"),
                "residual vm(a+dx)": (float(pd[2.0]["Probe_Ring2_Von_Mises_Stress"]), ref[2.0]["vm(a+dx)"], "Pa")}
    for what, (got, want, unit) in measured.items():
        err = got / want - 1
        text = f"{kind} {what} = {got:.4g} {unit}, 1D J2 {want:.4g} {unit}, error {100 * err:+.1f} %"
        if (kind, what) in UNBOUNDED:
            print(f"info {text} (not bounded)")
            continue
        check(failures, abs(err) < BOUNDS[what], f"{text} (bound {100 * BOUNDS[what]:.0f} %)")
    grew = ep[2.0] > ep[1.0] * (1 + 1e-6)
    ref_grew = ref[2.0]["ep(a+dx)"] > ref[1.0]["ep(a+dx)"] * (1 + 1e-6)
    check(failures, grew == ref_grew, f"{kind} reverse yield on unloading at r = a + dx: "
          f"{'yes' if grew else 'no'} (eps_p {ep[1.0]:.4g} -> {ep[2.0]:.4g}), 1D J2 {'yes' if ref_grew else 'no'} "
          f"(eps_p {ref[1.0]['ep(a+dx)']:.4g} -> {ref[2.0]['ep(a+dx)']:.4g})")


def main(argv):
    kinds = ("iso",) if "--isotropic-only" in argv else ("iso", "kin")
    cmd = [a for a in argv[1:] if a != "--isotropic-only"]
    failures = []
    check(failures, R.self_check(), "radial J2 reference: Lame within 1e-4, carries 0.99 p_L, not 1.01 p_L")
    for kind in kinds:
        compare(cmd, kind, failures)
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

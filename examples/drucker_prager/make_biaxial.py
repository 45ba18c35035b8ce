#!/usr/bin/env python3
"""Writes the biaxial plane-strain compression decks of Li & Geng's Table 2, tests 1-4 (seed 003, Sec. 5.3.1):
E 30 MPa, nu 0.25, phi 35 deg, c 60 kPa, m0 0.2, h 0, d0 0, confining stress 400, 600, 800, 1000 kPa, then
axial strain 0.05, 100 load steps each phase (ADR). Band off (NDO band: issue 18 part 2). Tests 5-7 (h > 0 or
d0 = 1) need another phase-1 top law: the closed form below holds for d0 = 0, h = 0 only.

usage: make_biaxial.py   (rewrites biaxial_test2_{coarse,fine}{,_lbc,_lbc_surface}.xml, biaxial_test2_coarse_lbc_t60.xml and
                          biaxial_test2_coarse_lbc_surface_restart.xml, biaxial_test{1,3,4}_fine.xml here)

Specimen: nx x ny points of spacing dx (cell centres from dx/2), plane strain. Left and right faces: the
confining pressure p(t) (Pressure, ramped over t in [0, 100], then held). Bottom row: u_y = 0; its middle
point also u_x = 0. Top row: u_y prescribed in both phases, because a condition cannot switch from a
pressure to a displacement during a run: in phase 1 the top follows the uniform solution of in-plane
hydrostatic confinement (so sigma_yy = sigma_xx = -p(t) in the uniform state), in phase 2 it adds the
axial strain 0.05 (t in [100, 200]). The uniform confinement solution, plane strain, d0 = 0, h = 0
(compression-positive strain e = -eps_xx = -eps_yy, lambda = K - 2G/3):
  elastic    e = p / (2 (lambda + G))                                   until p_y = m0 B / (1/sqrt(12) - 2.5 m0 A)
  plastic    e = (3 p - sqrt(3) m0 B) / (6 K (1 + sqrt(3) m0 A))       (f = 0 of Eq. 38 with eps_zz = 0 and
                                                                          deviatoric flow; linear in p: the
                                                                          flow direction stays (1, 1, -2))
Backward Euler gives the same piecewise-linear e(p) (fixed return direction, linear yield surface).
"""
import math
import os

E, NU, PHI, C, M0 = 30e6, 0.25, 35.0, 60e3, 0.2
CONFINING = {1: 400e3, 2: 600e3, 3: 800e3, 4: 1000e3}  # Table 2 tests 1-4 (d0 = 0, h = 0)
K, G = E / (3 * (1 - 2 * NU)), E / (2 * (1 + NU))
LAM = K - 2 * G / 3
S = math.sin(math.radians(PHI))
A = 2 * S / (math.sqrt(3) * (3 - S))
B = 6 * C * math.cos(math.radians(PHI)) / (math.sqrt(3) * (3 - S))
PY = M0 * B / (1 / math.sqrt(12) - 2.5 * M0 * A)        # yield pressure of the confinement


def top_law(P):
    """The phase-1 top law for confining pressure P: (t_y, elastic e per t, plastic e = a t - b, e(100))."""
    ty = 100 * PY / P
    el = (P / 100) / (2 * (LAM + G))
    pl_a = 3 * (P / 100) / (6 * K * (1 + math.sqrt(3) * M0 * A))
    pl_b = math.sqrt(3) * M0 * B / (6 * K * (1 + math.sqrt(3) * M0 * A))
    return ty, el, pl_a, pl_b, pl_a * 100 - pl_b


def analytic_end(P):
    """End-of-loading von Mises stress: sigma_xx = -P, s_zz = 0, f = 0 (Eq. 38) -> sigma_yy, J."""
    q = (P / 2 + M0 * (1.5 * A * P + B)) / (0.5 - 1.5 * M0 * A)
    return math.sqrt(3) * (q - P) / 2


def deck(name, dx, nx, ny, tol, P=600e3, test=2, lbc=False, t_end=200, restart=0, band=False):
    TY, EL, PL_A, PL_B, E100 = top_law(P)
    BAND_NOTE = ("NDO band on (Surface Correction): no surface effect." if band else
                 "No NDO band (the boundary rows show the surface effect).")
    # The band's difference form needs a stronger stabilisation than the standard form: its linearised force
    # has a growing mode below Hourglass Coefficient 0.2 (test_surface_band, LinearisedForceIsStable; the
    # paper's Eq. 21 term is about 0.2 in this convention). Affine states, like this test's, feel none of it.
    HOURGLASS = 0.25 if band else 0.05
    # With the band the confinement is a follower load (Pressure 'Follower'): a true 600 kPa on the deformed faces,
    # the load the paper's analytic 232.6 kPa assumes (a dead load ends at -P / F_yy = -640.7 kPa, README).
    FOLLOWER = '\n      <Parameter name="Follower" type="bool" value="true"/>' if band else ""
    BAND_PARAM = ('\n      <Parameter name="Surface Correction" type="string" value="NDO Band"/>' if band else "")
    W, H = nx * dx, ny * dx
    L = (ny - 1) * dx                                    # top row to bottom row
    top = (f"if (t &lt;= {TY:.10g}) {{ value = -{L:.10g}*{EL:.10g}*t; }} "
           f"else if (t &lt;= 100) {{ value = -{L:.10g}*({PL_A:.10g}*t - {PL_B:.10g}); }} "
           f"else {{ value = -{L:.10g}*({E100:.10g} + 0.05*(t - 100)/100); }}")
    pres = f"if (t &lt;= 100) {{ value = {P / 100:.10g}*t; }} else {{ value = {P:.10g}; }}"
    cx, cy = W / 2, H / 2
    # lbc: False (off), True (on, the paper's all-elastic start) or the name of a 'Loading Balance Start'
    lbc_line = ('\n      <Parameter name="Loading Balance Correction" type="bool" value="true"/>' if lbc else "")
    # restart n: a Restart list every n steps and the output named rs, as test/regression/restart/run_restart.py wants
    restart_list = (f'  <ParameterList name="Restart">\n    <Parameter name="Checkpoint Frequency" type="int" '
                    f'value="{restart}"/>\n  </ParameterList>\n' if restart else "")
    if isinstance(lbc, str):
        lbc_line += f'\n      <Parameter name="Loading Balance Start" type="string" value="{lbc}"/>'
    bc = lambda n, t, ns, extra: (f'    <ParameterList name="{n}"><Parameter name="Type" type="string" value="{t}"/>\n'
                                  f'      <Parameter name="Node Set" type="string" value="{ns}"/>{extra}</ParameterList>\n')
    coord = lambda c, v: (f'<Parameter name="Coordinate" type="string" value="{c}"/>\n'
                          f'      <Parameter name="Value" type="string" value="{v}"/>')
    val = lambda v: f'<Parameter name="Value" type="string" value="{v}"/>'
    face = lambda n, f: (f'    <ParameterList name="{n}"><Parameter name="Type" type="string" value="Node Set Region"/>'
                         f'<Parameter name="Face" type="string" value="{f}"/></ParameterList>\n')
    return f"""<ParameterList>
  <!-- Written by make_biaxial.py (edit that, not this). Li & Geng (seed 003) Table 2, test {test}: biaxial
       plane-strain compression, {W * 1e3:g} x {H * 1e3:g} mm, dx = {dx * 1e3:g} mm, delta = 3 dx; confining pressure
       {P / 1e3:g} kPa on the left and right faces over t = 0..100, then axial strain 0.05 at the top over t = 100..200;
       the top follows the uniform confinement solution in phase 1 (see make_biaxial.py). {BAND_NOTE}
       Analytic end state: von Mises {analytic_end(P) / 1e3:.1f} kPa everywhere. -->
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Rectangle With Holes"/>
    <Parameter name="Spacing" type="double" value="{dx:.10g}"/>
    <Parameter name="X Length" type="double" value="{W:.10g}"/>
    <Parameter name="Y Length" type="double" value="{H:.10g}"/>
    <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Sandy Loam">
      <Parameter name="Material Model" type="string" value="Drucker Prager Correspondence"/>
      <Parameter name="Density" type="double" value="2000.0"/>
      <Parameter name="Young's Modulus" type="double" value="{E:.10g}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{NU:g}"/>
      <Parameter name="Plane Strain" type="bool" value="true"/>
      <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
      <Parameter name="Hourglass Coefficient" type="double" value="{HOURGLASS}"/>
      <Parameter name="Friction Angle" type="double" value="{PHI:g}"/>
      <Parameter name="Cohesion" type="double" value="{C:g}"/>
      <Parameter name="Initial Hardening Parameter" type="double" value="{M0:g}"/>
      <Parameter name="Hardening Rate" type="double" value="0.0"/>
      <Parameter name="Dilatancy Ratio" type="double" value="0.0"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Specimen">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Sandy Loam"/>
      <Parameter name="Horizon" type="double" value="{3.015 * dx:.10g}"/>{BAND_PARAM}
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
{face("Left", "Min X")}{face("Right", "Max X")}{face("Top", "Max Y")}{face("Bottom", "Min Y")}    <ParameterList name="Bottom Middle"><Parameter name="Type" type="string" value="Node Set Region"/>
      <Parameter name="X Min" type="double" value="{cx - dx / 4:.10g}"/><Parameter name="X Max" type="double" value="{cx + dx / 4:.10g}"/>
      <Parameter name="Y Max" type="double" value="{dx:.10g}"/></ParameterList>
{bc("Confine Left", "Pressure", "Left", val(pres) + FOLLOWER)}{bc("Confine Right", "Pressure", "Right", val(pres) + FOLLOWER)}{bc("Bottom Y", "Prescribed Displacement", "Bottom", coord("y", "0.0"))}{bc("Bottom Middle X", "Prescribed Displacement", "Bottom Middle", coord("x", "0.0"))}{bc("Top Y", "Prescribed Displacement", "Top", coord("y", top))}  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="{t_end:.1f}"/>
    <ParameterList name="Adaptive Dynamic Relaxation">
      <Parameter name="Number of Load Steps" type="int" value="{t_end}"/>
      <Parameter name="Relative Tolerance" type="double" value="{tol:g}"/>{lbc_line}
    </ParameterList>
  </ParameterList>
{restart_list}  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="{"rs" if restart else name}"/>
    <Parameter name="Output Frequency" type="int" value="1"/>
    <Parameter name="Reactions" type="string" value="Top, Bottom"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
      <Parameter name="Von_Mises_Stress" type="bool" value="true"/>
      <Parameter name="Mean_Stress" type="bool" value="true"/>
      <Parameter name="Equivalent_Plastic_Strain" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressXX" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressYY" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressZZ" type="bool" value="true"/>
      <Parameter name="Yield_Function" type="bool" value="true"/>
    </ParameterList>
    <ParameterList name="Probes">
      <ParameterList name="Centre">
        <Parameter name="X" type="double" value="{cx:.10g}"/>
        <Parameter name="Y" type="double" value="{cy:.10g}"/>
        <Parameter name="Variables" type="string" value="Von_Mises_Stress Mean_Stress Equivalent_Plastic_Strain Deformation_GradientXX Deformation_GradientYY Deformation_GradientXY Deformation_GradientYX"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    print(f"A {A:.6g}  B {B:.6g} Pa  yield pressure {PY:.6g} Pa")
    decks = [("biaxial_test2_coarse", 5e-3, 11, 21, 2, False), ("biaxial_test2_fine", 2.5e-3, 21, 41, 2, False)]
    decks += [(f"biaxial_test{n}_fine", 2.5e-3, 21, 41, n, False) for n in (1, 3, 4)]
    # Test 2 with the loading-balance correction (ADR "Loading Balance Correction"; README, lbc_check.py).
    decks += [("biaxial_test2_coarse_lbc", 5e-3, 11, 21, 2, True), ("biaxial_test2_fine_lbc", 2.5e-3, 21, 41, 2, True)]
    # ... and with the set starting from the points on their yield surface (ADR 'Loading Balance Start').
    decks += [("biaxial_test2_coarse_lbc_surface", 5e-3, 11, 21, 2, "Yield Surface"),
              ("biaxial_test2_fine_lbc_surface", 2.5e-3, 21, 41, 2, "Yield Surface")]
    decks = [d + (200,) for d in decks]
    # The regression deck (ctest drucker_biaxial_coarse_lbc_*): the same load steps to t = 60 only (60 % of the
    # confinement: elastic steps with one round, plastic ones with two and three), so that a run stays under 20 s
    # at np 2 on a loaded machine (to t = 110: 17 s at np 1, 44 s at np 2, load average 6).
    decks += [("biaxial_test2_coarse_lbc_t60", 5e-3, 11, 21, 2, True, 60)]
    decks = [d + (0,) for d in decks]
    # The Yield Surface start killed and restarted (run_restart.py kill; README): checkpoints every 40 steps.
    decks += [("biaxial_test2_coarse_lbc_surface_restart", 5e-3, 11, 21, 2, "Yield Surface", 200, 40)]
    decks = [d + (False,) for d in decks]
    # The NDO surface band (Blocks 'Surface Correction'; README): test 2 at both resolutions, tests 1, 3, 4 fine.
    decks += [(f"biaxial_test{n}_{r}_band", dx, nx, ny, n, False, 200, 0, True)
              for n, r, dx, nx, ny in ((2, "coarse", 5e-3, 11, 21), (2, "fine", 2.5e-3, 21, 41), (1, "fine", 2.5e-3, 21, 41),
                                       (3, "fine", 2.5e-3, 21, 41), (4, "fine", 2.5e-3, 21, 41))]
    for name, dx, nx, ny, n, lbc, t_end, restart, band in decks:
        print(f"{name}: confining {CONFINING[n] / 1e3:g} kPa, analytic end von Mises {analytic_end(CONFINING[n]) / 1e3:.2f} kPa")
        with open(os.path.join(here, name + ".xml"), "w") as f:
            f.write(deck(name, dx, nx, ny, 1e-6, CONFINING[n], n, lbc, t_end, restart, band))

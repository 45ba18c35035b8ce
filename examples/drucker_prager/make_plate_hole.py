#!/usr/bin/env python3
"""Writes the decks of Li & Geng's plate with a central hole under compression (seed 003, Sec. 5.3.2, Figs 19-21):
a 100 x 100 mm plane-strain plate, a central hole of 10 mm diameter, Drucker Prager Correspondence with E 30 MPa,
nu 0.25, phi 35 deg, c 60 kPa, h 0, d0 0 (non-associated) and m0 0.2 (the paper's Sec. 5.3.2 does not give m0;
0.2 is Table 2's value for every biaxial test), density 2000 kg/m^3 as the biaxial decks.

usage: make_plate_hole.py   (rewrites the plate_hole_*.xml decks here; plate_hole.md describes them)

Loading. The paper: "a uniform displacement of u_y = 5 mm is applied to the top and bottom boundaries". Read here as
each edge moving u(t) towards the centre (top -u, bottom +u), u = 5 mm at the end: the displacement is given to
each boundary, and the symmetric form keeps the hole at rest. The paper's yield onsets (0.011 mm at point 1,
0.021 mm at point 3) are a few thousandths of that 5 mm, so the decks resolve the first 0.05 mm of u with 50 load
steps of 1 um (`plate_hole_*` decks end there; plate_hole_coarse_band_full continues to 5 mm in 50 more steps of 99 um).
Top and bottom: u_y prescribed, u_x free (frictionless platens; the paper says nothing about u_x) except at the
middle point of each, which holds u_x = 0 (no rigid motion). Vertical sides free.

Grid: `Rectangle With Holes`, `Grid` = `Nodes` (points at 0, dx, ..., 100 mm), so the centre, the hole's left and
upper edges (radius 5 mm a multiple of dx) and the diagonal (x = y) carry points. Monitoring points (hole centre
at (50, 50) mm): P1 (45, 50) mm, the hole's left edge; P2 (50, 55) mm, its upper edge; P3 (42.5, 57.5) mm, on the
plate's diagonal from the centre to the upper-left corner at 1.5 sqrt(2) R = 10.6 mm from the centre (the paper
does not say where; a point near the hole, on the path of its Fig. 22's X-shaped band).
Horizon 3.015 dx; Hourglass Coefficient 0.25 with and without the NDO band (the band needs it:
docs/materials.md; the same value without it so that the two runs differ by the band only).
"""
import os

E, NU, PHI, C, M0, RHO = 30e6, 0.25, 35.0, 60e3, 0.2, 2000.0
L, R = 100e-3, 5e-3
PROBES = {"P1": (45e-3, 50e-3), "P2": (50e-3, 55e-3), "P3": (42.5e-3, 57.5e-3)}
PROBE_VARS = ("Von_Mises_Stress Mean_Stress Equivalent_Plastic_Strain Yield_Function Unrotated_Cauchy_StressXX "
              "Unrotated_Cauchy_StressYY Unrotated_Cauchy_StressZZ Unrotated_Cauchy_StressXY Deformation_GradientXX "
              "Deformation_GradientYY Deformation_GradientXY Deformation_GradientYX")
DU = 1e-6            # u per load step in the first phase [m]
N1 = 50              # first-phase load steps (u to 0.05 mm)


def u_law(steps, sign=1, du=DU):
    """sign * u(t), u per edge, t = load step: du per step to N1 steps, then to 5 mm over the rest."""
    sg = "-" if sign < 0 else ""
    if steps <= N1:
        return f"{sg}{du:.10g}*t"
    rate = (5e-3 - N1 * DU) / (steps - N1)
    return (f"if (t &lt;= {N1}) {{ value = {sg}{DU:.10g}*t; }} "
            f"else {{ value = {sg}({N1 * DU:.10g} + {rate:.10g}*(t - {N1})); }}")


def deck(name, dx, band, steps=N1, tol=1e-6, note="", du=DU, side=None, hourglass=0.25):
    """side: the plate's side [m] (default L); the hole and the monitoring points stay at the same place from
    the plate's centre."""
    L = side or globals()["L"]
    off = (L - globals()["L"]) / 2
    probes_at = {p: (x + off, y + off) for p, (x, y) in PROBES.items()}
    band_param = '\n      <Parameter name="Surface Correction" type="string" value="NDO Band"/>' if band else ""
    u = u_law(steps, 1, du)
    face = lambda n, f: (f'    <ParameterList name="{n}"><Parameter name="Type" type="string" value="Node Set Region"/>'
                         f'<Parameter name="Face" type="string" value="{f}"/></ParameterList>\n')
    mid = lambda n, y0, y1: (f'    <ParameterList name="{n}"><Parameter name="Type" type="string" value="Node Set Region"/>\n'
                             f'      <Parameter name="X Min" type="double" value="{L / 2 - dx / 4:.10g}"/>'
                             f'<Parameter name="X Max" type="double" value="{L / 2 + dx / 4:.10g}"/>\n'
                             f'      <Parameter name="Y Min" type="double" value="{y0:.10g}"/>'
                             f'<Parameter name="Y Max" type="double" value="{y1:.10g}"/></ParameterList>\n')
    bc = lambda n, ns, c, v: (f'    <ParameterList name="{n}"><Parameter name="Type" type="string" value="Prescribed Displacement"/>\n'
                              f'      <Parameter name="Node Set" type="string" value="{ns}"/>'
                              f'<Parameter name="Coordinate" type="string" value="{c}"/>\n'
                              f'      <Parameter name="Value" type="string" value="{v}"/></ParameterList>\n')
    probes = "".join(f'      <ParameterList name="{p}">\n        <Parameter name="X" type="double" value="{x:.10g}"/>\n'
                     f'        <Parameter name="Y" type="double" value="{y:.10g}"/>\n'
                     f'        <Parameter name="Variables" type="string" value="{PROBE_VARS}"/>\n      </ParameterList>\n'
                     for p, (x, y) in probes_at.items())
    return f"""<ParameterList>
  <!-- Written by make_plate_hole.py (edit that, not this). Li & Geng (seed 003) Sec. 5.3.2: plane-strain plate
       {L * 1e3:g} x {L * 1e3:g} mm with a central hole of 10 mm diameter, compressed by the top and bottom edges, each moving
       u(t) = {u.replace("&lt;", "<")} m towards the centre; dx = {dx * 1e3:g} mm; NDO band {"on" if band else "off"}.{note} -->
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Rectangle With Holes"/>
    <Parameter name="Spacing" type="double" value="{dx:.10g}"/>
    <Parameter name="X Length" type="double" value="{L:.10g}"/>
    <Parameter name="Y Length" type="double" value="{L:.10g}"/>
    <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
    <Parameter name="Grid" type="string" value="Nodes"/>
    <ParameterList name="Holes">
      <ParameterList name="Centre Hole">
        <Parameter name="X Center" type="double" value="{L / 2:.10g}"/>
        <Parameter name="Y Center" type="double" value="{L / 2:.10g}"/>
        <Parameter name="Radius" type="double" value="{R:.10g}"/>
      </ParameterList>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Sandy Loam">
      <Parameter name="Material Model" type="string" value="Drucker Prager Correspondence"/>
      <Parameter name="Density" type="double" value="{RHO:g}"/>
      <Parameter name="Young's Modulus" type="double" value="{E:.10g}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{NU:g}"/>
      <Parameter name="Plane Strain" type="bool" value="true"/>
      <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
      <Parameter name="Hourglass Coefficient" type="double" value="{hourglass}"/>
      <Parameter name="Friction Angle" type="double" value="{PHI:g}"/>
      <Parameter name="Cohesion" type="double" value="{C:g}"/>
      <Parameter name="Initial Hardening Parameter" type="double" value="{M0:g}"/>
      <Parameter name="Hardening Rate" type="double" value="0.0"/>
      <Parameter name="Dilatancy Ratio" type="double" value="0.0"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Plate">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Sandy Loam"/>
      <Parameter name="Horizon" type="double" value="{3.015 * dx:.10g}"/>{band_param}
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
{face("Top", "Max Y")}{face("Bottom", "Min Y")}{mid("Top Middle", L - dx / 4, L + dx / 4)}{mid("Bottom Middle", -dx / 4, dx / 4)}{bc("Top Y", "Top", "y", u_law(steps, -1, du))}{bc("Bottom Y", "Bottom", "y", u)}{bc("Top Middle X", "Top Middle", "x", "0.0")}{bc("Bottom Middle X", "Bottom Middle", "x", "0.0")}  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="{steps:.1f}"/>
    <ParameterList name="Adaptive Dynamic Relaxation">
      <Parameter name="Number of Load Steps" type="int" value="{steps}"/>
      <Parameter name="Relative Tolerance" type="double" value="{tol:g}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="{name}"/>
    <Parameter name="Output Frequency" type="int" value="1"/>
    <Parameter name="Reactions" type="string" value="Top, Bottom"/>
    <Parameter name="Applied Displacement" type="string" value="Bottom Y"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
      <Parameter name="Von_Mises_Stress" type="bool" value="true"/>
      <Parameter name="Mean_Stress" type="bool" value="true"/>
      <Parameter name="Equivalent_Plastic_Strain" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressXX" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressYY" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressZZ" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressXY" type="bool" value="true"/>
      <Parameter name="Yield_Function" type="bool" value="true"/>
    </ParameterList>
    <ParameterList name="Probes">
{probes}    </ParameterList>
  </ParameterList>
</ParameterList>
"""


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    decks = [("plate_hole_band", 1.25e-3, True, N1, "", DU), ("plate_hole", 1.25e-3, False, N1, "", DU),
             # the ctest deck: dx = 2.5 mm (the hole's radius 2 dx), 10 steps of 5 um (to 0.05 mm: P1 and P3 yield)
             ("plate_hole_coarse_band", 2.5e-3, True, 10, " Regression deck (ctest drucker_hole_*).", 5e-6),
             ("plate_hole_coarse", 2.5e-3, False, 10, "", 5e-6),
             # the elastic step at dx = 0.625 mm (R = 8 dx): the convergence of the elastic stress at the points
             ("plate_hole_elastic_fine_band", 0.625e-3, True, 1, " One elastic step.", DU),
             ("plate_hole_elastic_fine", 0.625e-3, False, 1, " One elastic step.", DU),
             # to the paper's 5 mm: 50 steps of 1 um, then 50 of 99 um (coarse: 267 s at np 1; plate_hole.md)
             ("plate_hole_coarse_band_full", 2.5e-3, True, 100, "", DU)]
    for name, dx, band, steps, note, du in decks:
        with open(os.path.join(here, name + ".xml"), "w") as f:
            f.write(deck(name, dx, band, steps, 1e-6, note, du))
        print(name)
    # The band at Hourglass Coefficient 1.0: the band's operator has a growing mode at a lattice hole's staircase at
    # 0.25 (test_surface_band, LinearisedForceAroundALatticeHole*; plate_hole.md), which 1.0 damps in these runs.
    with open(os.path.join(here, "plate_hole_band_hg1.xml"), "w") as f:
        f.write(deck("plate_hole_band_hg1", 1.25e-3, True, N1, 1e-6, " Hourglass Coefficient 1.0.", DU, None, 1.0))
    print("plate_hole_band_hg1")
    # The elastic step's convergence with dx at a lower cost: a 40 mm plate with the same hole (d/W = 0.25), R = 4,
    # 8, 16 and 32 dx, band on and off; reference plate_hole_ccx.py --side 0.04 (plate_hole_fe_reference_w40.csv).
    for dx, tag in ((1.25e-3, "r4"), (0.625e-3, "r8"), (0.3125e-3, "r16"), (0.15625e-3, "r32")):
        for band in (True, False):
            name = f"plate_hole_w40_{tag}{'_band' if band else ''}"
            with open(os.path.join(here, name + ".xml"), "w") as f:
                f.write(deck(name, dx, band, 1, 1e-6, " One elastic step, 40 mm plate.", DU, 40e-3))
            print(name)

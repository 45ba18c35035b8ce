#!/usr/bin/env python3
"""Writes the four-point bending decks of Li & Geng (seed 003, Sec. 5.2): a concrete beam with two pre-existing
flaws, damage by stress (Damage Model = Maximum Principal Stress, f_t = 1 MPa, Eqs. 49-51), E 27 GPa, nu 0.18,
dx = 2.5 mm, delta = 3.015 dx, NOXQuasiStatic (Newton-Krylov; ADR needs ~50 times the wall time on a beam in
bending: 5372 ADR iterations for the elastic deck's first step against 2 Newton steps). The paper's Fig. 11 geometry is not in its text; the choice made here
(examples/drucker_prager/four_point_bending.md says why):

  beam 250 x 50 mm (x: length, y: depth), thickness 32.5 mm = 13 layers of 2.5 mm (the paper's 13 layers);
  supports: the bottom row's column at x = 12.5 and x = 237.5 mm (span S = 225 mm): u_y = 0, the left one also
  u_x = 0 (and u_z = 0 in 3D); loads: the top row's column at x = 87.5 and 162.5 mm (a = S/3 = 75 mm from
  each support), u_y = -v(t) prescribed (displacement control), v = 1 um per unit t;
  lower flaw: an edge notch from the bottom face, rising to the right at 45 deg, centreline (105, -5) -> (117.5, 12.5)
  mm; upper flaw: an edge notch from the top face, descending to the left at 45 deg, centreline (145, 55) ->
  (132.5, 37.5) mm (point symmetric to the lower one about the beam's centre): in bending the lower notch's
  tip (its right side, in the tension zone) cracks first and the crack runs upwards; the upper notch's tip (its
  left side) sits in the compression zone until the lower crack has lifted the neutral axis.
  A flaw is a slot of removed points 8 mm wide (holes of radius 4 mm every 1 mm along the centreline): wider than
  the horizon 7.54 mm, so that no bond crosses it (Periforge has no pre-cut bond filter).

Decks written here:
  four_point_bending.xml         3D, 13 layers, the paper-size deck (100 x 20 x 13 grid less the slots)
  four_point_bending_coarse.xml  2D plane strain (one layer, Thickness 32.5 mm), the same plane grid, to v = 60 um
  four_point_bending_coarse_t7.xml  its first 7 load steps (elastic, then the first cracks): the ctest deck
  four_point_elastic_coarse.xml  the coarse deck without flaws and without damage: the elastic check against beam
                                 theory (four_point_check.py)
  four_point_elastic_fine.xml    the same at dx / 2 (how the beam-theory differences change with the grid)
usage: make_four_point.py
"""
import math
import os

E, NU, FT, RHO = 27e9, 0.18, 1e6, 2400.0
DX = 0.0025
L, H, B = 0.250, 0.050, 0.0325
SUPPORTS = (0.0125, 0.2375)
LOADS = (0.0875, 0.1625)
V_RATE = 1e-6  # m per unit t
SLOT_R = 0.004
LOWER = ((0.105, -0.005), (0.1175, 0.0125))
UPPER = ((0.145, 0.055), (0.1325, 0.0375))


def slot_holes(name, a, b, three_d):
    n = int(math.ceil(math.hypot(b[0] - a[0], b[1] - a[1]) / 0.001))
    out = []
    for k in range(n + 1):
        x = a[0] + (b[0] - a[0]) * k / n
        y = a[1] + (b[1] - a[1]) * k / n
        out.append(f'      <ParameterList name="{name} {k}"><Parameter name="X Center" type="double" value="{x:.6g}"/>'
                   f'<Parameter name="Y Center" type="double" value="{y:.6g}"/>'
                   f'<Parameter name="Radius" type="double" value="{SLOT_R:g}"/></ParameterList>')
    return "\n".join(out)


def column(name, x, top, three_d):
    """The grid column at x on the top (y max) or bottom row: one point in 2D, the 13 layers in 3D."""
    y0, y1 = (H - DX, H) if top else (0.0, DX)
    return (f'    <ParameterList name="{name}"><Parameter name="Type" type="string" value="Node Set Region"/>\n'
            f'      <Parameter name="X Min" type="double" value="{x - DX / 2:.6g}"/><Parameter name="X Max" type="double" value="{x + DX / 2:.6g}"/>\n'
            f'      <Parameter name="Y Min" type="double" value="{y0:.6g}"/><Parameter name="Y Max" type="double" value="{y1:.6g}"/></ParameterList>\n')


def pd(name, ns, coord, value):
    return (f'    <ParameterList name="{name}"><Parameter name="Type" type="string" value="Prescribed Displacement"/>\n'
            f'      <Parameter name="Node Set" type="string" value="{ns}"/><Parameter name="Coordinate" type="string" value="{coord}"/>\n'
            f'      <Parameter name="Value" type="string" value="{value}"/></ParameterList>\n')


def deck(name, three_d, flaws, damage, steps, t_end, tol, note):
    plane = "" if three_d else f"""
      <Parameter name="Plane Strain" type="bool" value="true"/>
      <Parameter name="Thickness" type="double" value="{B:g}"/>"""
    if three_d:
        disc = f"""    <Parameter name="Type" type="string" value="Box With Holes"/>
    <Parameter name="Spacing" type="double" value="{DX:g}"/>
    <Parameter name="X Length" type="double" value="{L:g}"/>
    <Parameter name="Y Length" type="double" value="{H:g}"/>
    <Parameter name="Z Length" type="double" value="{B:g}"/>"""
    else:
        disc = f"""    <Parameter name="Type" type="string" value="Rectangle With Holes"/>
    <Parameter name="Spacing" type="double" value="{DX:g}"/>
    <Parameter name="X Length" type="double" value="{L:g}"/>
    <Parameter name="Y Length" type="double" value="{H:g}"/>
    <Parameter name="Thickness" type="double" value="{B:g}"/>"""
    if flaws:
        disc += ("\n    <ParameterList name=\"Holes\">\n" + slot_holes("Lower Flaw", *LOWER, three_d) + "\n" +
                 slot_holes("Upper Flaw", *UPPER, three_d) + "\n    </ParameterList>")
    dmg = f"""  <ParameterList name="Damage Models">
    <ParameterList name="Tension Cut-off">
      <Parameter name="Damage Model" type="string" value="Maximum Principal Stress"/>
      <Parameter name="Tensile Strength" type="double" value="{FT:g}"/>
    </ParameterList>
  </ParameterList>
""" if damage else ""
    dmg_line = '\n      <Parameter name="Damage Model" type="string" value="Tension Cut-off"/>' if damage else ""
    load = f"-{V_RATE:g}*t"
    bcs = (column("Left Support", SUPPORTS[0], False, three_d) + column("Right Support", SUPPORTS[1], False, three_d) +
           column("Left Load", LOADS[0], True, three_d) + column("Right Load", LOADS[1], True, three_d) +
           pd("Left Support Y", "Left Support", "y", "0.0") + pd("Left Support X", "Left Support", "x", "0.0") +
           pd("Right Support Y", "Right Support", "y", "0.0") +
           (pd("Left Support Z", "Left Support", "z", "0.0") if three_d else "") +
           pd("Left Load Y", "Left Load", "y", load) + pd("Right Load Y", "Right Load", "y", load))
    mid = L / 2
    return f"""<ParameterList>
  <!-- Written by make_four_point.py (edit that, not this). {note}
       Li & Geng (seed 003) Sec. 5.2: concrete four-point bending, E = {E / 1e9:g} GPa, nu = {NU:g}, f_t = {FT / 1e6:g} MPa,
       beam {L * 1e3:g} x {H * 1e3:g} mm, thickness {B * 1e3:g} mm, dx = {DX * 1e3:g} mm, delta = 3.015 dx; span {1e3 * (SUPPORTS[1] - SUPPORTS[0]):g} mm,
       loads at x = {LOADS[0] * 1e3:g} and {LOADS[1] * 1e3:g} mm by prescribed displacement {V_RATE * 1e6:g} um per unit t. -->
  <ParameterList name="Discretization">
{disc}
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Concrete">
      <Parameter name="Material Model" type="string" value="Elastic Correspondence"/>
      <Parameter name="Density" type="double" value="{RHO:g}"/>
      <Parameter name="Young's Modulus" type="double" value="{E:g}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{NU:g}"/>{plane}
      <Parameter name="Hourglass Coefficient" type="double" value="0.05"/>
    </ParameterList>
  </ParameterList>
{dmg}  <ParameterList name="Blocks">
    <ParameterList name="Beam">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Concrete"/>{dmg_line}
      <Parameter name="Horizon" type="double" value="{3.015 * DX:.6g}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
{bcs}  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="{t_end:g}"/>
    <ParameterList name="NOXQuasiStatic">
      <Parameter name="Number of Load Steps" type="int" value="{steps}"/>
      <Parameter name="Relative Tolerance" type="double" value="{tol:g}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="{name}"/>
    <Parameter name="Output Frequency" type="int" value="1"/>
    <Parameter name="Reactions" type="string" value="Left Load, Right Load, Left Support, Right Support"/>
    <Parameter name="Reaction Names" type="string" value="LoadL, LoadR, SupportL, SupportR"/>
    <Parameter name="Applied Displacement" type="string" value="Left Load Y"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>{'''
      <Parameter name="Damage" type="bool" value="true"/>''' if damage else ""}
      <Parameter name="Unrotated_Cauchy_StressXX" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressYY" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressXY" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


def main():
    here = os.path.dirname(os.path.abspath(__file__))
    decks = {
        "four_point_bending": deck("four_point_bending", True, True, True, 60, 60, 1e-6,
                                   "The paper-size deck (3D, 13 layers)."),
        "four_point_bending_coarse": deck("four_point_bending_coarse", False, True, True, 60, 60, 1e-6,
                                          "The coarse deck: 2D plane strain, one layer of the paper-size grid."),
        "four_point_bending_coarse_t7": deck("four_point_bending_coarse_t7", False, True, True, 7, 7, 1e-6,
                                             "The coarse deck's first 7 load steps (the ctest: elastic, first cracks)."),
        "four_point_elastic_coarse": deck("four_point_elastic_coarse", False, False, False, 4, 4, 1e-6,
                                          "Elastic check deck: the coarse deck without flaws and damage."),
    }
    global DX
    DX = DX / 2  # the elastic check at half the spacing (not a ctest: 18 s), same beam and loads
    decks["four_point_elastic_fine"] = deck("four_point_elastic_fine", False, False, False, 4, 4, 1e-6,
                                            "Elastic check deck at dx / 2 (not a ctest).")
    DX = DX * 2
    for name, text in decks.items():
        with open(os.path.join(here, name + ".xml"), "w") as f:
            f.write(text)
        print("wrote", name + ".xml")


if __name__ == "__main__":
    main()

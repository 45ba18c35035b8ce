#!/usr/bin/env python3
"""Writes the elastic uniaxial-compression decks of Li & Geng's surface-effect study (seed 003, Sec. 5.1, Fig. 6):
a 36 x 72 mm plane-strain plate, E = 30 MPa, nu = 0.25, 200 kPa on the top face, with and without the NDO band.

Where this differs from the paper, and why: the paper fixes the bottom in both directions, which makes the stress
near the bottom non-uniform in any method (the Poisson expansion is held there), so "boundary rows equal the
interior" would not be a property of the exact solution. Here the bottom is a roller (y held; x held at one
point), so the exact solution is the uniform uniaxial state sigma_yy = -200 kPa (nominal: the Pressure is a dead
load on the reference area), sigma_xx = 0 everywhere, and any departure at the boundary rows is the surface
effect. The material is Drucker Prager Correspondence with a cohesion high enough to stay elastic (the model the
band is for; elastic so that the answer has a closed form). dx = 2 mm (18 x 36 points), delta = 3.015 dx.
uniaxial_check.py compares the boundary rows with the interior.
"""
import os


def deck(name, band):
    dx, W, H, P = 2e-3, 36e-3, 72e-3, 200e3
    band_param = '\n      <Parameter name="Surface Correction" type="string" value="NDO Band"/>' if band else ""
    hourglass = 0.25 if band else 0.05  # the band's stabilisation (docs/materials.md, "NDO surface band")
    return f"""<ParameterList>
  <!-- Written by make_uniaxial.py (edit that, not this). Li & Geng (seed 003) Sec. 5.1: elastic uniaxial compression
       of a {W * 1e3:g} x {H * 1e3:g} mm plane-strain plate, {P / 1e3:g} kPa on the top, roller bottom; NDO band {"on" if band else "off"}.
       Exact solution: sigma_yy = -{P / 1e3:g} kPa, sigma_xx = 0 at every point. -->
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Rectangle With Holes"/>
    <Parameter name="Spacing" type="double" value="{dx:.10g}"/>
    <Parameter name="X Length" type="double" value="{W:.10g}"/>
    <Parameter name="Y Length" type="double" value="{H:.10g}"/>
    <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Elastic Soil">
      <Parameter name="Material Model" type="string" value="Drucker Prager Correspondence"/>
      <Parameter name="Density" type="double" value="2000.0"/>
      <Parameter name="Young's Modulus" type="double" value="30e6"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.25"/>
      <Parameter name="Plane Strain" type="bool" value="true"/>
      <Parameter name="Thickness" type="double" value="{dx:.10g}"/>
      <Parameter name="Hourglass Coefficient" type="double" value="{hourglass}"/>
      <Parameter name="Friction Angle" type="double" value="35"/>
      <Parameter name="Cohesion" type="double" value="1e9"/>
      <Parameter name="Initial Hardening Parameter" type="double" value="1.0"/>
      <Parameter name="Hardening Rate" type="double" value="0.0"/>
      <Parameter name="Dilatancy Ratio" type="double" value="0.0"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Plate">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Elastic Soil"/>
      <Parameter name="Horizon" type="double" value="{3.015 * dx:.10g}"/>{band_param}
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <ParameterList name="Top"><Parameter name="Type" type="string" value="Node Set Region"/><Parameter name="Face" type="string" value="Max Y"/></ParameterList>
    <ParameterList name="Bottom"><Parameter name="Type" type="string" value="Node Set Region"/><Parameter name="Face" type="string" value="Min Y"/></ParameterList>
    <ParameterList name="Bottom Middle"><Parameter name="Type" type="string" value="Node Set Region"/>
      <Parameter name="X Min" type="double" value="{W / 2 - 0.75 * dx:.10g}"/><Parameter name="X Max" type="double" value="{W / 2 + 0.25 * dx:.10g}"/>
      <Parameter name="Y Max" type="double" value="{dx:.10g}"/></ParameterList>
    <ParameterList name="Load"><Parameter name="Type" type="string" value="Pressure"/>
      <Parameter name="Node Set" type="string" value="Top"/><Parameter name="Value" type="string" value="{P / 10:.10g}*t"/></ParameterList>
    <ParameterList name="Bottom Y"><Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="Bottom"/><Parameter name="Coordinate" type="string" value="y"/>
      <Parameter name="Value" type="string" value="0.0"/></ParameterList>
    <ParameterList name="Bottom Middle X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="Bottom Middle"/><Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="0.0"/></ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="10.0"/>
    <ParameterList name="Adaptive Dynamic Relaxation">
      <Parameter name="Number of Load Steps" type="int" value="2"/>
      <Parameter name="Relative Tolerance" type="double" value="1e-08"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="{name}"/>
    <Parameter name="Output Frequency" type="int" value="2"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressXX" type="bool" value="true"/>
      <Parameter name="Unrotated_Cauchy_StressYY" type="bool" value="true"/>
      <Parameter name="Von_Mises_Stress" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""


if __name__ == "__main__":
    here = os.path.dirname(os.path.abspath(__file__))
    for name, band in (("uniaxial_elastic", False), ("uniaxial_elastic_band", True)):
        with open(os.path.join(here, name + ".xml"), "w") as f:
            f.write(deck(name, band))
        print(name)

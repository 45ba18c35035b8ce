"""Thick-walled cylinder under internal pressure, plane strain (issue 16): the deck, its ring mesh and node
sets, written for a run, and the closed forms the runs are judged against. Used by run_cylinder.py.

Geometry: bore a = 10 mm, outside b = 20 mm, square lattice dx = 0.5 mm with points at integer multiples
of dx (so the x and y axes carry points), delta = 3.015 dx, 1 mm thick. The bore's pressure acts on its
layer of points a <= r < a + dx (Type = Pressure, Layer Thickness = dx). Symmetry of the exact solution
holds the points on the axes: u_y = 0 on y = 0, u_x = 0 on x = 0 (rigid-body modes removed)."""
import csv
import math
import os
import shutil
import subprocess
import tempfile

A, B, DX, THICK = 0.010, 0.020, 0.0005, 0.001
HORIZON = 3.015 * DX
E, NU, SIGMA_Y = 200.0e9, 0.3, 200.0e6


def ring_points():
    n = int(round(B / DX))
    pts = []
    for i in range(-n, n + 1):
        for j in range(-n, n + 1):
            x, y = i * DX, j * DX
            if A - 1e-12 <= math.hypot(x, y) <= B + 1e-12:
                pts.append((x, y))
    return pts


def lame_radial_displacement(p, r):
    """Plane strain, elastic: u_r(r) for internal pressure p (Timoshenko & Goodier)."""
    c = p * A * A / (B * B - A * A)
    return c * (1 + NU) / E * ((1 - 2 * NU) * r + B * B / r)


def first_yield_pressure():
    """Von Mises at the bore reaches sigma_y: Lame stresses at r = a with the plane-strain sigma_z."""
    k = A * A / (B * B - A * A)
    s_r, s_t = -1.0, k * (1 + B * B / (A * A))
    s_z = NU * (s_r + s_t)
    vm = math.sqrt(0.5 * ((s_r - s_t) ** 2 + (s_t - s_z) ** 2 + (s_z - s_r) ** 2))
    return SIGMA_Y / vm


def limit_pressure():
    """Perfectly plastic, plane strain, von Mises (Hill): p_L = (2/sqrt 3) sigma_y ln(b/a)."""
    return 2.0 / math.sqrt(3.0) * SIGMA_Y * math.log(B / A)


def write_case(d, material, times, solver_list, pressure_expr):
    """Writes ring.txt, the node-set files and cylinder.xml into d; returns the deck path."""
    pts = ring_points()
    with open(os.path.join(d, "ring.txt"), "w") as f:
        for x, y in pts:
            f.write(f"{x:.9g} {y:.9g} 0 1 {DX * DX * THICK:.9g}\n")
    sets = {"Bore": [k + 1 for k, (x, y) in enumerate(pts) if math.hypot(x, y) < A + DX - 1e-12],
            "On X Axis": [k + 1 for k, (x, y) in enumerate(pts) if abs(y) < 1e-12],
            "On Y Axis": [k + 1 for k, (x, y) in enumerate(pts) if abs(x) < 1e-12]}
    for name, ids in sets.items():
        with open(os.path.join(d, name.replace(" ", "_") + ".txt"), "w") as f:
            f.write("\n".join(map(str, ids)) + "\n")
    probe_x = A  # the bore point on the x axis
    deck = f"""<ParameterList>
  <ParameterList name="Discretization">
    <Parameter name="Type" type="string" value="Text File"/>
    <Parameter name="Input Mesh File" type="string" value="ring.txt"/>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="Steel">{material}
      <Parameter name="Density" type="double" value="7800.0"/>
      <Parameter name="Young's Modulus" type="double" value="{E}"/>
      <Parameter name="Poisson's Ratio" type="double" value="{NU}"/>
      <Parameter name="Plane Strain" type="bool" value="true"/>
      <Parameter name="Thickness" type="double" value="{THICK}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="Ring">
      <Parameter name="Block Names" type="string" value="block_1"/>
      <Parameter name="Material" type="string" value="Steel"/>
      <Parameter name="Horizon" type="double" value="{HORIZON}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <Parameter name="Bore" type="string" value="Bore.txt"/>
    <Parameter name="On X Axis" type="string" value="On_X_Axis.txt"/>
    <Parameter name="On Y Axis" type="string" value="On_Y_Axis.txt"/>
    <ParameterList name="Pressure"><Parameter name="Type" type="string" value="Pressure"/>
      <Parameter name="Node Set" type="string" value="Bore"/>
      <Parameter name="Layer Thickness" type="double" value="{DX}"/>
      <Parameter name="Value" type="string" value="{pressure_expr}"/></ParameterList>
    <ParameterList name="Symmetry Y"><Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="On X Axis"/><Parameter name="Coordinate" type="string" value="y"/>
      <Parameter name="Value" type="string" value="0.0"/></ParameterList>
    <ParameterList name="Symmetry X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>
      <Parameter name="Node Set" type="string" value="On Y Axis"/><Parameter name="Coordinate" type="string" value="x"/>
      <Parameter name="Value" type="string" value="0.0"/></ParameterList>
  </ParameterList>
  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="{times[0]}"/>
    <Parameter name="Final Time" type="double" value="{times[-1]}"/>
    {solver_list}
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output Filename" type="string" value="cylinder"/>
    <ParameterList name="Probes">
      <ParameterList name="Bore"><Parameter name="X" type="double" value="{probe_x}"/><Parameter name="Y" type="double" value="0.0"/>
        <Parameter name="Z" type="double" value="0.0"/><Parameter name="Variables" type="string" value="Displacement"/></ParameterList>
      <ParameterList name="Outside"><Parameter name="X" type="double" value="{B}"/><Parameter name="Y" type="double" value="0.0"/>
        <Parameter name="Z" type="double" value="0.0"/><Parameter name="Variables" type="string" value="Displacement"/></ParameterList>
    </ParameterList>
  </ParameterList>
</ParameterList>
"""
    path = os.path.join(d, "cylinder.xml")
    with open(path, "w") as f:
        f.write(deck)
    return path


def run_case(cmd, material, t0, t1, steps, pressure_expr, edit=lambda text: text):
    """Runs the case with NOX from t0 to t1 in `steps` load steps in a temporary directory; edit(deck text)
    may change the deck first. Returns the history rows keyed by time (rounded to 1e-6)."""
    d = tempfile.mkdtemp(prefix="cylinder")
    try:
        nox = (f'<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" '
               f'value="{steps}"/></ParameterList>')
        deck = write_case(d, material, [t0, t1], nox, pressure_expr)
        text = open(deck).read()
        open(deck, "w").write(edit(text))
        p = subprocess.run(cmd + [deck], cwd=d, capture_output=True, text=True, timeout=600)
        if p.returncode != 0:
            raise SystemExit(f"run failed ({p.returncode}):\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
        return {round(float(r["time"]), 6): r for r in csv.DictReader(open(os.path.join(d, "cylinder.csv")))}
    finally:
        shutil.rmtree(d, ignore_errors=True)

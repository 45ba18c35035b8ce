"""Thick-walled cylinder under internal pressure, plane strain (issue 16): the deck, its ring mesh and node
sets, written for a run, and the closed forms the runs are judged against. Used by run_cylinder.py.

Geometry: bore a = 10 mm, outside b = 20 mm, 1 mm thick, delta = 3.015 x the spacing, on one of two point
clouds:
  LatticeRing  the square lattice dx = 0.5 mm, points at integer multiples of dx inside a <= r <= b. The
               bore's pressure acts on its layer a <= r < a + dx (Layer Thickness = dx). The lattice's material
               spans about a - dx/2 ... b + dx/2 and its bore layer's area is the Gauss-circle count's.
  PolarRing    n rings of width dr = (b - a)/n at r_k = a + (k + 1/2) dr, each with a multiple of 4 points
               at equal angles carrying its exact annulus share as volume: the material spans exactly a ... b.
               The pressure acts on ring 0; Layer Thickness = dr (1 + dr/2a) makes its points' area
               V / thickness sum to the bore's 2 pi a exactly.
Symmetry of the exact solution holds the points on the axes: u_y = 0 on y = 0, u_x = 0 on x = 0 (rigid-body
modes removed)."""
import csv
import math
import os
import shutil
import subprocess
import tempfile

A, B, DX, THICK = 0.010, 0.020, 0.0005, 0.001
E, NU, SIGMA_Y = 200.0e9, 0.3, 200.0e6


class LatticeRing:
    spacing = DX
    layer_thickness = DX
    bore_probe_r = A  # the bore point on the x axis

    def points(self):
        """(x, y, volume, in the bore layer) of every point."""
        n = int(round(B / DX))
        pts = []
        for i in range(-n, n + 1):
            for j in range(-n, n + 1):
                x, y = i * DX, j * DX
                r = math.hypot(x, y)
                if A - 1e-12 <= r <= B + 1e-12:
                    pts.append((x, y, DX * DX * THICK, r < A + DX - 1e-12))
        return pts


class PolarRing:
    def __init__(self, rings):
        self.rings = rings
        self.spacing = (B - A) / rings
        self.layer_thickness = self.spacing * (1 + self.spacing / (2 * A))
        self.bore_probe_r = A + self.spacing / 2

    def points(self):
        dr, pts = self.spacing, []
        for k in range(self.rings):
            r = A + (k + 0.5) * dr
            n = 4 * max(1, round(2 * math.pi * r / dr / 4))
            v = math.pi * ((r + dr / 2) ** 2 - (r - dr / 2) ** 2) / n * THICK
            pts += [(r * math.cos(2 * math.pi * j / n), r * math.sin(2 * math.pi * j / n), v, k == 0)
                    for j in range(n)]
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


def write_case(d, material, times, solver_list, pressure_expr, mesh):
    """Writes ring.txt, the node-set files and cylinder.xml into d; returns the deck path."""
    pts = mesh.points()
    with open(os.path.join(d, "ring.txt"), "w") as f:
        for x, y, v, _ in pts:
            f.write(f"{x:.12g} {y:.12g} 0 1 {v:.12g}\n")
    # A coordinate below 1e-12 m is an axis point (the polar ring's cosines leave ~1e-18 there).
    sets = {"Bore": [k + 1 for k, p in enumerate(pts) if p[3]],
            "On X Axis": [k + 1 for k, p in enumerate(pts) if abs(p[1]) < 1e-12],
            "On Y Axis": [k + 1 for k, p in enumerate(pts) if abs(p[0]) < 1e-12]}
    for name, ids in sets.items():
        with open(os.path.join(d, name.replace(" ", "_") + ".txt"), "w") as f:
            f.write("\n".join(map(str, ids)) + "\n")
    probe_x = mesh.bore_probe_r
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
      <Parameter name="Horizon" type="double" value="{3.015 * mesh.spacing!r}"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Boundary Conditions">
    <Parameter name="Bore" type="string" value="Bore.txt"/>
    <Parameter name="On X Axis" type="string" value="On_X_Axis.txt"/>
    <Parameter name="On Y Axis" type="string" value="On_Y_Axis.txt"/>
    <ParameterList name="Pressure"><Parameter name="Type" type="string" value="Pressure"/>
      <Parameter name="Node Set" type="string" value="Bore"/>
      <Parameter name="Layer Thickness" type="double" value="{mesh.layer_thickness!r}"/>
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


def run_case(cmd, material, t0, t1, steps, pressure_expr, edit=lambda text: text, mesh=LatticeRing(), timeout=600):
    """Runs the case with NOX from t0 to t1 in `steps` load steps in a temporary directory; edit(deck text)
    may change the deck first. Returns the history rows keyed by time (rounded to 1e-6)."""
    d = tempfile.mkdtemp(prefix="cylinder")
    try:
        nox = (f'<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" '
               f'value="{steps}"/></ParameterList>')
        deck = write_case(d, material, [t0, t1], nox, pressure_expr, mesh)
        text = open(deck).read()
        open(deck, "w").write(edit(text))
        p = subprocess.run(cmd + [deck], cwd=d, capture_output=True, text=True, timeout=timeout)
        if p.returncode != 0:
            raise SystemExit(f"run failed ({p.returncode}):\n{p.stdout[-2000:]}\n{p.stderr[-2000:]}")
        return {round(float(r["time"]), 6): r for r in csv.DictReader(open(os.path.join(d, "cylinder.csv")))}
    finally:
        shutil.rmtree(d, ignore_errors=True)

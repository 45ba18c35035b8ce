#!/usr/bin/env python3
"""Independent elastic reference for the plate with a central hole (Li & Geng, seed 003, Sec. 5.3.2): a linear
plane-strain finite-element solution with CalculiX (Debian package calculix-ccx, `ccx`), used by
plate_hole_check.py to check the peridynamic elastic step and to predict the onset of yield.

Problem: 100 x 100 mm plate, hole of radius 5 mm at the centre, E 30 MPa, nu 0.25, plane strain; the top and
bottom edges each move U_REF = 0.01 mm towards the centre (u_y uniform; u_x free: frictionless platens), the
vertical sides free. By symmetry a quarter, x, y in [0, 50] mm from the hole's centre: u_x = 0 on x = 0, u_y = 0 on
y = 0, u_y = -U_REF on y = 50 mm. Mesh: 8-node plane-strain quadrilaterals (CPE8) mapped from the hole to the
square's boundary (the 45 degree ray runs to the corner), graded towards the hole.

usage: plate_hole_ccx.py [--refine K] [--keep]
  writes plate_hole_ccx.inp (K = 1, the committed input) or a refined mesh in a temporary directory, runs ccx and
  writes plate_hole_fe_reference.csv (K = 1) with the stress at the paper's three monitoring points (from the
  hole's centre): point 1 at the hole's left edge (-R, 0); point 2 at its upper edge (0, R); point 3 on the
  plate's diagonal at (-7.5, 7.5) mm (r = 1.5 sqrt(2) R), interpolated along the 45 degree grid line. The quarter
  holds their mirror images (|x|, y), where sigma_xy changes sign. Also the closed form (Kirsch's infinite
  plate) at the same points.
  Stress per unit imposed displacement of one edge (Pa/m): linear elasticity scales.
  --refine K  K times the elements in each direction (a convergence check; prints, writes nothing committed)
"""
import argparse
import math
import os
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
E, NU = 30e6, 0.25
R, HALF = 5e-3, 50e-3        # hole radius, half the plate's side [m]
U_REF = 1e-5                 # imposed displacement of each edge [m]
# the monitoring points from the hole's centre, in the plate (make_plate_hole.py); the quarter model holds their
# mirror images (|x|, y), where sigma_xy changes sign
POINTS = {"P1": (-R, 0.0), "P2": (0.0, R), "P3": (-7.5e-3, 7.5e-3)}


def set_side(side):
    global HALF
    HALF = side / 2


def outer(theta):
    """The square's boundary point on the ray at angle theta (0..pi/2) from the hole's centre."""
    if theta <= math.pi / 4 + 1e-15:
        return HALF, HALF * math.tan(theta)
    return HALF / math.tan(theta), HALF


def mesh(nt, nr, q):
    """Nodes on a (2 nt + 1) x (2 nr + 1) grid (theta index i, radial index j; half indices are the CPE8 midside
    nodes), radial spacing growing by q per element."""
    nodes = {}
    s_of = lambda k: (q ** (k / 2) - 1) / (q ** nr - 1)  # k in half-element units, 0 .. 2 nr
    nid = lambda i, j: i * (2 * nr + 1) + j + 1
    for i in range(2 * nt + 1):
        th = (math.pi / 2) * i / (2 * nt)
        hx, hy = R * math.cos(th), R * math.sin(th)
        ox, oy = outer(th)
        for j in range(2 * nr + 1):
            s = s_of(j)
            x, y = hx + s * (ox - hx), hy + s * (oy - hy)
            if i == 2 * nt:
                x = 0.0
            if i == 0:
                y = 0.0
            nodes[nid(i, j)] = (x, y)
    elems = []
    for a in range(nt):
        for b in range(nr):
            i, j = 2 * a, 2 * b
            # corners counter-clockwise in (x, y): radial index plays x, angle plays y
            c = [nid(i, j), nid(i, j + 2), nid(i + 2, j + 2), nid(i + 2, j)]
            m = [nid(i, j + 1), nid(i + 1, j + 2), nid(i + 2, j + 1), nid(i + 1, j)]
            elems.append(c + m)
    sets = {"SYMX": [nid(2 * nt, j) for j in range(2 * nr + 1)],      # x = 0
            "SYMY": [nid(0, j) for j in range(2 * nr + 1)],           # y = 0
            "TOP": [nid(i, 2 * nr) for i in range(nt, 2 * nt + 1)],   # y = 50 mm
            "DIAG": [nid(nt, j) for j in range(2 * nr + 1)]}          # the 45 degree ray
    return nodes, elems, sets


def write_inp(path, nodes, elems, sets):
    with open(path, "w") as f:
        f.write("** Written by plate_hole_ccx.py (edit that, not this): plane-strain quarter of the plate with a hole,\n"
                f"** E {E:g} Pa, nu {NU:g}, each edge moved {U_REF:g} m towards the centre, CPE8.\n*NODE, NSET=NALL\n")
        for k, (x, y) in sorted(nodes.items()):
            f.write(f"{k},{x:.9e},{y:.9e}\n")
        f.write("*ELEMENT, TYPE=CPE8, ELSET=EALL\n")
        for n, e in enumerate(elems, 1):
            f.write(f"{n}," + ",".join(map(str, e)) + "\n")
        for name in ("SYMX", "SYMY", "TOP"):
            f.write(f"*NSET, NSET={name}\n")
            ids = sets[name]
            for k in range(0, len(ids), 12):
                f.write(",".join(map(str, ids[k:k + 12])) + "\n")
        f.write(f"*MATERIAL, NAME=SOIL\n*ELASTIC\n{E:g},{NU:g}\n*SOLID SECTION, ELSET=EALL, MATERIAL=SOIL\n1.0\n"
                f"*STEP\n*STATIC\n*BOUNDARY\nSYMX,1,1,0.\nSYMY,2,2,0.\nTOP,2,2,{-U_REF:g}\n"
                "*NODE FILE\nU\n*EL FILE\nS\n*END STEP\n")


def read_frd_stress(path):
    """Nodal stresses (extrapolated and averaged by ccx) from the ASCII .frd: {node: (sxx, syy, szz, sxy)}."""
    out, on = {}, False
    for line in open(path):
        if line.startswith(" -4  STRESS"):
            on = True
        elif on and line.startswith(" -3"):
            break
        elif on and line.startswith(" -1"):
            node = int(line[3:13])
            v = [float(line[13 + 12 * k:25 + 12 * k]) for k in range(6)]
            out[node] = (v[0], v[1], v[2], v[3])
    if not out:
        sys.exit(f"plate_hole_ccx.py: no STRESS block in {path}")
    return out


def kirsch(x, y, s=1.0):
    """Infinite plate, remote uniaxial stress s along y (tension positive), hole radius R: (sxx, syy, sxy)."""
    r, t = math.hypot(x, y), math.atan2(y, x) - math.pi / 2  # angle from the load axis
    a2, a4 = (R / r) ** 2, (R / r) ** 4
    srr = s / 2 * (1 - a2) + s / 2 * (1 - 4 * a2 + 3 * a4) * math.cos(2 * t)
    stt = s / 2 * (1 + a2) - s / 2 * (1 + 3 * a4) * math.cos(2 * t)
    srt = -s / 2 * (1 + 2 * a2 - 3 * a4) * math.sin(2 * t)
    ph = math.atan2(y, x)
    c, sn = math.cos(ph), math.sin(ph)
    return (srr * c * c + stt * sn * sn - 2 * srt * sn * c, srr * sn * sn + stt * c * c + 2 * srt * sn * c,
            (srr - stt) * sn * c + srt * (c * c - sn * sn))


def solve(nt, nr, q, workdir, name):
    nodes, elems, sets = mesh(nt, nr, q)
    inp = os.path.join(workdir, name + ".inp")
    write_inp(inp, nodes, elems, sets)
    ccx = shutil.which("ccx")
    if ccx is None:
        sys.exit("plate_hole_ccx.py: ccx not found (apt-get install calculix-ccx)")
    r = subprocess.run([ccx, name], cwd=workdir, capture_output=True, text=True)
    if r.returncode != 0 or not os.path.exists(os.path.join(workdir, name + ".frd")):
        sys.exit("plate_hole_ccx.py: ccx failed:\n" + r.stdout[-2000:] + r.stderr[-2000:])
    st = read_frd_stress(os.path.join(workdir, name + ".frd"))
    res = {}
    for p, (xp, y) in POINTS.items():
        x = abs(xp)
        if p == "P3":  # along the 45 degree ray: linear interpolation in r between its nodes
            ray = sorted((math.hypot(*nodes[n]), n) for n in sets["DIAG"])
            rr = math.hypot(x, y)
            for (r0, n0), (r1, n1) in zip(ray, ray[1:]):
                if r0 <= rr <= r1:
                    w = (rr - r0) / (r1 - r0)
                    res[p] = tuple((1 - w) * a + w * b for a, b in zip(st[n0], st[n1]))
                    break
        else:
            n = min(nodes, key=lambda k: math.hypot(nodes[k][0] - x, nodes[k][1] - y))
            res[p] = st[n]
        if xp < 0:
            res[p] = res[p][:3] + (-res[p][3],)
    return res, len(nodes), len(elems)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--refine", type=int, default=1)
    ap.add_argument("--side", type=float, default=0.1, help="the plate's side [m]; not 0.1: writes "
                    "plate_hole_fe_reference_w<mm>.csv and plate_hole_ccx_w<mm>.inp")
    a = ap.parse_args()
    set_side(a.side)
    tag = "" if abs(a.side - 0.1) < 1e-12 else f"_w{a.side * 1e3:g}"
    k = a.refine
    nt, nr, q = 12 * k, 16 * k, 1.18 ** (1.0 / k)
    tmp = tempfile.mkdtemp(prefix="plate_hole_ccx_")
    res, nn, ne = solve(nt, nr, q, tmp, "plate_hole_ccx")
    if k == 1:
        shutil.copy(os.path.join(tmp, "plate_hole_ccx.inp"), os.path.join(HERE, f"plate_hole_ccx{tag}.inp"))
    shutil.rmtree(tmp)
    # far-field reference stress: uniaxial plane strain under the imposed strain 2 U / L
    s_far = -E / (1 - NU * NU) * 2 * U_REF / (2 * HALF)
    print(f"ccx: {nn} nodes, {ne} CPE8 elements (refine {k}); imposed u = {U_REF:g} m per edge, remote "
          f"sigma_yy (no hole) {s_far:.2f} Pa")
    lines = ["point,x_mm,y_mm,sxx_per_m,syy_per_m,szz_per_m,sxy_per_m,kirsch_sxx_per_m,kirsch_syy_per_m,kirsch_sxy_per_m"]
    for p, (x, y) in POINTS.items():
        sxx, syy, szz, sxy = res[p]
        kx, ky, kxy = kirsch(x, y, s_far)
        print(f"  {p} ({x * 1e3:g}, {y * 1e3:g}) mm: FE sxx {sxx:10.3f} syy {syy:10.3f} szz {szz:10.3f} sxy {sxy:9.3f} Pa;"
              f" Kirsch sxx {kx:9.3f} syy {ky:10.3f} sxy {kxy:9.3f};  FE syy / remote {syy / s_far:.4f}")
        lines.append(f"{p},{x * 1e3:g},{y * 1e3:g}," + ",".join(f"{v / U_REF:.8e}" for v in (sxx, syy, szz, sxy, kx, ky, kxy)))
    if k == 1:
        with open(os.path.join(HERE, f"plate_hole_fe_reference{tag}.csv"), "w") as f:
            f.write("\n".join(lines) + "\n")
        print(f"wrote plate_hole_ccx{tag}.inp, plate_hole_fe_reference{tag}.csv")


if __name__ == "__main__":
    main()

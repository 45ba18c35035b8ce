#!/usr/bin/python3
"""Discretization `Type` = `Exodus` (one point per element of a genesis mesh, Peridigm's rule).

(a) Equivalence with the lattice: a 6x3x3 box of HEX8 elements (numbered x fastest, two element blocks
    1 and 7 split along z, four face node sets, two named and two unnamed) runs the same short Verlet problem as
    a PdQuickGrid deck of the same box (NeighborhoodType Spherical, the same node sets as Node Set Regions,
    same material, horizon and conditions), each at np 1 and np 2. Every run's Displacement, Velocity and
    Force_Density must agree with the lattice np 1 run to round-off, its point coordinates must be the cell
    centres and its Volume the cell volume (closed forms), and the Exodus runs must keep the blocks 1 and 7.
    A 2D QUAD4 mesh with `Thickness` is checked the same way for coordinates and volumes (area * Thickness).
(b) Bad meshes at np 1 and 2: a missing file, a file that is not Exodus, an unknown element type, an inverted
    element (the last one: rank 1's at np 2, so the failure is rank-local), a node set naming node
    num_nodes + 1, a QUAD mesh without `Thickness`. Each must exit non-zero within the timeout, with no crash,
    and with exactly one line of error text on stderr (rank 0 prints the verdict every rank reached; mpirun's
    own dashed banners are not counted) that names the deck and `Input Mesh File` (or `Thickness`).

usage: check_exodus.py PERIFORGE MPIRUN [MPIRUN ARGS...]
Prints what it measures; exits 1 on any miss.
"""
import concurrent.futures
import os
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
import netCDF4

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import write_genesis as wg  # noqa: E402
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import names  # noqa: E402

NX, NY, NZ = 6, 3, 3
ORIGIN = (0.001, -0.0015, 0.0005)
LENGTHS = (0.006, 0.003, 0.003)  # cells of 1 mm
H = np.array(LENGTHS) / np.array([NX, NY, NZ])
CELL_VOLUME = H[0] * H[1] * H[2]
# Node sets of the mesh, ids 1..4: an unnamed one is "nodelist_<id>" (Peridigm's name).
FACES = ("min_x", ("max_x", "right_end"), "min_y", ("min_z", "bottom"))
SET_NAMES = ("nodelist_1", "right_end", "nodelist_3", "bottom")
# The lattice's equivalent regions: the elements touching a face's nodes are the face's layer of cells, the
# points within half a cell of the face's plane.
REGIONS = {"nodelist_1": ("X Max", ORIGIN[0] + 0.5 * H[0] + 0.25 * H[0]),
           "right_end": ("X Min", ORIGIN[0] + LENGTHS[0] - 0.75 * H[0]),
           "nodelist_3": ("Y Max", ORIGIN[1] + 0.75 * H[1]),
           "bottom": ("Z Max", ORIGIN[2] + 0.75 * H[2])}
T_END, DT = 4.0e-7, 2.0e-8  # 20 Verlet steps; stable dt of this lattice is about 1e-7
TIMEOUT = 20  # s per run (each takes 1-3 s); a hang is reported, and 18 runs four at a time stay within ctest's 120 s

# Agreement of the Exodus and the lattice runs. The two clouds differ only by round-off: a centroid from the
# 24-tetrahedron sum is within a few ulp (1e-19 m) of o + (i + 1/2) h, a volume within a few ulp (relative
# 1e-16) of h^3, and np 2 sums ghost forces in another order. The force of a bond is k (|y| - |x|) / |x| with a
# stretch of 1e-4..1e-3: a coordinate error of 1e-16 relative becomes 1e-13..1e-12 of the force, and 20 steps
# carry it into u and v. Bound: 1e-10 of each field's largest magnitude over the run (round-off measures
# 1e-14..1e-13 of it; a wrong volume, a moved point or a missing bond changes a field by 1e-3 or more).
REL_TOL = 1e-10
NP_TOL = 1e-12      # the same cloud at np 1 and 2: only the order of ghost-force sums differs
COORD_TOL = 1e-15   # m: a few ulp of 1e-3 (the exact cell centre against the file's)
VOLUME_TOL = 1e-13  # relative: 24 tetrahedra of volume h^3/24 summed (a few ulp)


def material_blocks(block_names):
    return f"""  <ParameterList name="Materials">
    <ParameterList name="Steel">
      <Parameter name="Material Model" type="string" value="Elastic"/>
      <Parameter name="Density" type="double" value="8000.0"/>
      <Parameter name="Bulk Modulus" type="double" value="160.0e9"/>
      <Parameter name="Shear Modulus" type="double" value="79.3e9"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="All Blocks">
      <Parameter name="Block Names" type="string" value="{block_names}"/>
      <Parameter name="Material" type="string" value="Steel"/>
      <Parameter name="Horizon" type="double" value="{2.1 * H[0]!r}"/>
    </ParameterList>
  </ParameterList>
"""


def conditions():
    bc = [("nodelist_1", "x", "0.0"), ("right_end", "x", f"1.0e-6*t/{T_END!r}"), ("nodelist_3", "y", "0.0"),
          ("bottom", "z", "0.0"), ("right_end", "y", f"2.0e-7*t/{T_END!r}")]
    out = '  <ParameterList name="Boundary Conditions">\n'
    for k, (s, c, v) in enumerate(bc):
        out += (f'    <ParameterList name="BC {k}"><Parameter name="Type" type="string" value="Prescribed Displacement"/>'
                f'<Parameter name="Node Set" type="string" value="{s}"/><Parameter name="Coordinate" type="string" '
                f'value="{c}"/><Parameter name="Value" type="string" value="{v}"/></ParameterList>\n')
    return out + "  </ParameterList>\n"


def regions():
    out = ""
    for name, (bound, value) in REGIONS.items():
        out += (f'    <ParameterList name="{name}"><Parameter name="Type" type="string" value="Node Set Region"/>'
                f'<Parameter name="{bound}" type="double" value="{value!r}"/></ParameterList>\n')
    return out


def solver_output(name):
    return f"""  <ParameterList name="Solver">
    <Parameter name="Initial Time" type="double" value="0.0"/>
    <Parameter name="Final Time" type="double" value="{T_END!r}"/>
    <ParameterList name="Verlet"><Parameter name="Fixed dt" type="double" value="{DT!r}"/></ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Output File Type" type="string" value="ExodusII"/>
    <Parameter name="Output Filename" type="string" value="{name}"/>
    <Parameter name="Output Frequency" type="int" value="5"/>
    <ParameterList name="Output Variables">
      <Parameter name="Displacement" type="bool" value="true"/>
      <Parameter name="Velocity" type="bool" value="true"/>
      <Parameter name="Force_Density" type="bool" value="true"/>
      <Parameter name="Volume" type="bool" value="true"/>
      <Parameter name="Proc_Num" type="bool" value="true"/>
    </ParameterList>
  </ParameterList>
"""


def exodus_deck(mesh, name, extra="", kind="Exodus", blocks="block_1 block_7"):
    """kind: the Discretization Type (check_gmsh.py reads Gmsh meshes of the same box)."""
    return (f'<ParameterList>\n  <ParameterList name="Discretization">\n'
            f'    <Parameter name="Type" type="string" value="{kind}"/>\n'
            f'    <Parameter name="Input Mesh File" type="string" value="{mesh}"/>\n{extra}  </ParameterList>\n'
            + material_blocks(blocks) + conditions() + solver_output(name) + '</ParameterList>\n')


def lattice_deck(name):
    o, L = ORIGIN, LENGTHS
    grid = "".join(f'      <Parameter name="{a} Origin" type="double" value="{o[i]!r}"/>\n' for i, a in enumerate("XYZ"))
    grid += "".join(f'      <Parameter name="{a} Length" type="double" value="{L[i]!r}"/>\n' for i, a in enumerate("XYZ"))
    grid += "".join(f'      <Parameter name="Number Points {a}" type="int" value="{n}"/>\n'
                    for a, n in zip("XYZ", (NX, NY, NZ)))
    bcs = conditions().replace('  <ParameterList name="Boundary Conditions">\n',
                               '  <ParameterList name="Boundary Conditions">\n' + regions(), 1)
    return ('<ParameterList>\n  <ParameterList name="Discretization">\n'
            '    <Parameter name="Type" type="string" value="PdQuickGrid"/>\n'
            '    <Parameter name="NeighborhoodType" type="string" value="Spherical"/>\n'
            f'    <ParameterList name="TensorProduct3DMeshGenerator">\n{grid}    </ParameterList>\n  </ParameterList>\n'
            + material_blocks("block_1") + bcs + solver_output(name) + '</ParameterList>\n')


def quad_deck(mesh, name, thickness, kind="Exodus"):
    t = (f'    <Parameter name="Thickness" type="double" value="{thickness!r}"/>\n' if thickness else "")
    return (f'<ParameterList>\n  <ParameterList name="Discretization">\n'
            f'    <Parameter name="Type" type="string" value="{kind}"/>\n'
            f'    <Parameter name="Input Mesh File" type="string" value="{mesh}"/>\n{t}  </ParameterList>\n'
            '  <ParameterList name="Materials"><ParameterList name="Steel">\n'
            '    <Parameter name="Material Model" type="string" value="Elastic"/>\n'
            '    <Parameter name="Density" type="double" value="8000.0"/>\n'
            '    <Parameter name="Young\'s Modulus" type="double" value="200.0e9"/>\n'
            '    <Parameter name="Poisson\'s Ratio" type="double" value="0.3"/>\n'
            '    <Parameter name="Plane Stress" type="bool" value="true"/>\n'
            f'    <Parameter name="Thickness" type="double" value="{thickness or 0.001!r}"/>\n'
            '  </ParameterList></ParameterList>\n'
            '  <ParameterList name="Blocks"><ParameterList name="B">\n'
            '    <Parameter name="Block Names" type="string" value="block_1"/>\n'
            '    <Parameter name="Material" type="string" value="Steel"/>\n'
            f'    <Parameter name="Horizon" type="double" value="{2.1e-3!r}"/>\n'
            '  </ParameterList></ParameterList>\n'
            '  <ParameterList name="Boundary Conditions">\n'
            '    <ParameterList name="Fix"><Parameter name="Type" type="string" value="Prescribed Displacement"/>'
            '<Parameter name="Node Set" type="string" value="nodelist_1"/><Parameter name="Coordinate" type="string" '
            'value="x"/><Parameter name="Value" type="string" value="0.0"/></ParameterList>\n'
            '  </ParameterList>\n' + solver_output(name).replace(f'value="{T_END!r}"', f'value="{4 * DT!r}"')
            + '</ParameterList>\n')


# ------------------------------------------------------------------------------------------------ running

def run(cmd, cwd):
    """-> (returncode or None on timeout, stdout, stderr, seconds). The runs go four at a time: each mpirun gets
    its own TMPDIR, as Open MPI's session directories of simultaneous jobs under one /tmp can collide
    (ORTE_ERROR_LOG in session_dir.c: seen in one of the first two runs without it)."""
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="pfmpi") as tmp:
        env = dict(os.environ, TMPDIR=tmp)
        try:
            p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=TIMEOUT, env=env)
            return p.returncode, p.stdout, p.stderr, time.monotonic() - start
        except subprocess.TimeoutExpired as e:
            out = e.stdout.decode(errors="replace") if isinstance(e.stdout, bytes) else (e.stdout or "")
            err = e.stderr.decode(errors="replace") if isinstance(e.stderr, bytes) else (e.stderr or "")
            return None, out, err, time.monotonic() - start


def error_text_lines(stderr):
    """stderr's non-empty lines less mpirun's banners (each between two lines of dashes)."""
    lines, inside = [], False
    for line in stderr.splitlines():
        if line.startswith("-----"):
            inside = not inside
            continue
        if not inside and line.strip():
            lines.append(line)
    return lines


# ------------------------------------------------------------------------------------------------ reading

class Result:
    """An output file: per-point fields at each written step, indexed by global id (node_num_map - 1)."""

    def __init__(self, path):
        with netCDF4.Dataset(path) as d:
            d.set_auto_mask(False)
            gid = np.asarray(d["node_num_map"][:]) - 1
            order = np.argsort(gid)
            self.gid = gid[order]
            self.x = np.stack([np.asarray(d[f"coord{a}"][:])[order] for a in "xyz"], axis=1)
            self.time = np.asarray(d["time_whole"][:])
            self.nodal = {n: np.asarray(d[f"vals_nod_var{k + 1}"][:])[:, order]
                          for k, n in enumerate(names(d, "name_nod_var"))}
            # Element variables (Volume, Proc_Num): one SPHERE element per point, blocks in file order; the
            # element's node gives its global id.
            self.blocks = [int(b) for b in d["eb_prop1"][:]]
            self.block_sizes = []
            self.elem = {}
            enames = names(d, "name_elem_var")
            node_of = []
            for b in range(1, len(self.blocks) + 1):
                conn = np.asarray(d[f"connect{b}"][:]).reshape(-1)
                node_of.append(conn - 1)
                self.block_sizes.append(len(conn))
            node_gid = np.asarray(d["node_num_map"][:]) - 1
            elem_gid = node_gid[np.concatenate(node_of)]
            eorder = np.argsort(elem_gid)
            self.block_of = np.concatenate([[bid] * n for bid, n in zip(self.blocks, self.block_sizes)])[eorder]
            for k, n in enumerate(enames):
                parts = []
                for b in range(1, len(self.blocks) + 1):
                    var = f"vals_elem_var{k + 1}eb{b}"
                    parts.append(np.asarray(d[var][:]) if var in d.variables
                                 else np.full((len(self.time), self.block_sizes[b - 1]), np.nan))
                self.elem[n] = np.concatenate(parts, axis=1)[:, eorder]


def cell_centres_3d():
    c = []
    for k in range(NZ):
        for j in range(NY):
            for i in range(NX):
                c.append([ORIGIN[0] + (i + 0.5) * H[0], ORIGIN[1] + (j + 0.5) * H[1], ORIGIN[2] + (k + 0.5) * H[2]])
    return np.array(c)


# ------------------------------------------------------------------------------------------------ (a)

def check_equivalence(exe, mpirun, work, pool):
    failures = []
    mesh = os.path.join(work, "box.g")
    wg.write_box(mesh, NX, NY, NZ, ORIGIN, LENGTHS, faces=FACES, block_of=lambda i, j, k: 7 if k == NZ - 1 else 1)
    jobs = {}
    for kind in ("exodus", "lattice"):
        for np_ in (1, 2):
            d = os.path.join(work, f"{kind}_np{np_}")
            os.makedirs(d)
            text = exodus_deck(mesh, kind) if kind == "exodus" else lattice_deck(kind)
            open(os.path.join(d, f"{kind}.xml"), "w").write(text)
            jobs[(kind, np_)] = pool.submit(run, mpirun + ["-np", str(np_), exe, f"{kind}.xml"], d)
    results = {}
    for (kind, np_), job in jobs.items():
        rc, out, err, secs = job.result()
        path = os.path.join(work, f"{kind}_np{np_}", f"{kind}.e")
        line = next((l for l in out.splitlines() if " points, " in l), "")
        print(f"  {kind:7s} np {np_}: exit {rc} in {secs:.1f} s  {line.strip()}")
        if rc != 0 or not os.path.exists(path):
            failures.append(f"{kind} np {np_}: exit {rc}: {error_text_lines(err)}")
            continue
        results[(kind, np_)] = Result(path)
    if failures:
        return failures

    ref = results[("lattice", 1)]
    centres = cell_centres_3d()
    n = NX * NY * NZ
    for key, r in results.items():
        label = f"{key[0]} np {key[1]}"
        if len(r.gid) != n or not np.array_equal(r.gid, np.arange(n)):
            failures.append(f"{label}: global ids are not 0..{n - 1}")
            continue
        dx = np.abs(r.x - centres).max()
        vol = r.elem["Volume"][0]
        dv = np.abs(vol / CELL_VOLUME - 1.0).max()
        print(f"  {label}: max |x - cell centre| {dx:.2e} m (tol {COORD_TOL:g}), "
              f"max |V / h^3 - 1| {dv:.2e} (tol {VOLUME_TOL:g})")
        if not dx <= COORD_TOL:
            failures.append(f"{label}: coordinates off the cell centres by {dx:.3e} m")
        if not dv <= VOLUME_TOL:
            failures.append(f"{label}: volumes off h^3 by {dv:.3e} (relative)")
        if key[0] == "exodus":
            want = np.array([7 if k == NZ - 1 else 1 for k in range(NZ) for _ in range(NY) for _ in range(NX)])
            sizes = dict(zip(r.blocks, r.block_sizes))
            print(f"  {label}: blocks {sizes}")
            if sorted(r.blocks) != [1, 7] or not np.array_equal(r.block_of, want):
                failures.append(f"{label}: element blocks {sizes}, want 1: {NX * NY * (NZ - 1)}, 7: {NX * NY}")
        if key == ("lattice", 1):
            continue
        if not np.array_equal(r.time, ref.time):
            failures.append(f"{label}: output times {r.time} differ from {ref.time}")
            continue
        worst = []
        for field in ("Displacement", "Velocity", "Force_Density"):
            for a in "XYZ":
                v = field + a
                scale = np.abs(ref.nodal[v]).max()
                diff = np.abs(r.nodal[v] - ref.nodal[v]).max()
                rel = diff / scale if scale > 0 else diff
                worst.append((rel, v, scale))
                if not rel <= REL_TOL:
                    failures.append(f"{label}: {v} differs from the lattice np 1 by {diff:.3e} ({rel:.2e} of "
                                    f"its largest magnitude {scale:.3e}; tol {REL_TOL:g})")
        rel, v, scale = max(worst)
        print(f"  {label} vs lattice np 1: worst {v} {rel:.2e} of its scale {scale:.3e} (tol {REL_TOL:g})")
    # The Exodus runs at np 1 and np 2 differ only by the order of the ghost-force sums: 1e-12 of each field's
    # scale (scripts' verlet_agreement.comp bound for the same kind of comparison).
    e1, e2 = results[("exodus", 1)], results[("exodus", 2)]
    worst = max((np.abs(e2.nodal[v] - e1.nodal[v]).max() / max(np.abs(e1.nodal[v]).max(), 1e-300), v)
                for v in e1.nodal if v.startswith(("Displacement", "Velocity", "Force_Density")))
    print(f"  exodus np 2 vs exodus np 1: worst {worst[1]} {worst[0]:.2e} of its scale (tol {NP_TOL:g})")
    if not worst[0] <= NP_TOL:
        failures.append(f"exodus np 2 vs np 1: {worst[1]} differs by {worst[0]:.3e} of its scale (tol {NP_TOL:g})")
    # The run must have moved: a problem where nothing happens would agree trivially.
    umax = np.abs(ref.nodal["DisplacementX"]).max()
    fmax = np.abs(ref.nodal["Force_DensityX"]).max()
    print(f"  lattice np 1: max |u_x| {umax:.3e} m, max |f_x| {fmax:.3e} N/m^3")
    if not (umax > 1e-8 and fmax > 0):
        failures.append(f"the problem does not load the body (max |u_x| {umax:g}, max |f_x| {fmax:g})")
    return failures


def check_quad(exe, mpirun, work, pool):
    """A 4x2 QUAD4 mesh with Thickness: points at the cell centres (z = 0), volume = area * Thickness."""
    failures = []
    nx, ny, origin, lengths, thick = 4, 2, (0.0, 0.002), (0.004, 0.002), 0.0005
    mesh = os.path.join(work, "quad.g")
    wg.write_quad_mesh(mesh, nx, ny, origin, lengths, faces=("min_x",))
    h = np.array(lengths) / np.array([nx, ny])
    centres = np.array([[origin[0] + (i + 0.5) * h[0], origin[1] + (j + 0.5) * h[1], 0.0]
                        for j in range(ny) for i in range(nx)])
    jobs = {}
    for np_ in (1, 2):
        d = os.path.join(work, f"quad_np{np_}")
        os.makedirs(d)
        open(os.path.join(d, "quad.xml"), "w").write(quad_deck(mesh, "quad", thick))
        jobs[np_] = pool.submit(run, mpirun + ["-np", str(np_), exe, "quad.xml"], d)
    for np_, job in jobs.items():
        rc, out, err, secs = job.result()
        path = os.path.join(work, f"quad_np{np_}", "quad.e")
        if rc != 0 or not os.path.exists(path):
            failures.append(f"quad np {np_}: exit {rc}: {error_text_lines(err)}")
            continue
        r = Result(path)
        dx = np.abs(r.x - centres).max()
        dv = np.abs(r.elem["Volume"][0] / (h[0] * h[1] * thick) - 1.0).max()
        print(f"  quad np {np_}: exit {rc} in {secs:.1f} s, max |x - cell centre| {dx:.2e} m, "
              f"max |V / (area Thickness) - 1| {dv:.2e}")
        if len(r.gid) != nx * ny or not dx <= COORD_TOL or not dv <= VOLUME_TOL:
            failures.append(f"quad np {np_}: {len(r.gid)} points, coordinates off by {dx:.3e}, volumes by {dv:.3e}")
    return failures


# ------------------------------------------------------------------------------------------------ (b)

def error_cases(work):
    """(name, deck text, words the line must hold) for each bad mesh; the files are made here."""
    small = dict(nx=NX, ny=NY, nz=NZ, origin=ORIGIN, lengths=LENGTHS, faces=FACES,
                 block_of=lambda i, j, k: 7 if k == NZ - 1 else 1)
    join = lambda f: os.path.join(work, f)
    wg.write_box(join("foo.g"), elem_type="FOO", **small)
    wg.write_box(join("inverted.g"), invert_element=NX * NY * NZ - 1, **small)
    wg.write_box(join("beyond.g"), node_set_beyond=True, **small)
    wg.write_quad_mesh(join("quad_nothick.g"), 4, 2, (0.0, 0.0), (0.004, 0.002), faces=("min_x",))
    open(join("text.g"), "w").write("# not an Exodus file\n0 0 0 1 1e-9\n")
    mesh_words = ["Input Mesh File"]
    return [
        ("missing mesh file", exodus_deck("no_such_mesh.g", "bad"), mesh_words + ["no_such_mesh.g"]),
        ("not an Exodus file", exodus_deck(join("text.g"), "bad"), mesh_words + ["text.g"]),
        ("unknown element type", exodus_deck(join("foo.g"), "bad"), mesh_words + ["foo.g", "FOO"]),
        ("inverted element", exodus_deck(join("inverted.g"), "bad"), mesh_words + ["inverted.g", f"element {NX * NY * NZ}"]),
        ("node set naming an absent node", exodus_deck(join("beyond.g"), "bad"),
         mesh_words + ["beyond.g", str((NX + 1) * (NY + 1) * (NZ + 1) + 1)]),
        ("QUAD mesh without Thickness", quad_deck(join("quad_nothick.g"), "bad", None), ["Thickness", "quad_nothick.g"]),
    ]


def check_errors(exe, mpirun, work, pool, cases=None):
    """cases: (name, deck text, words) as error_cases gives them (check_gmsh.py passes its own)."""
    failures = []
    jobs = []
    for k, (name, text, words) in enumerate(error_cases(work) if cases is None else cases):
        for np_ in (1, 2):
            d = os.path.join(work, f"error{k}_np{np_}")
            os.makedirs(d)
            open(os.path.join(d, "bad.xml"), "w").write(text)
            jobs.append((name, np_, words, d, pool.submit(run, mpirun + ["-np", str(np_), exe, "bad.xml"], d)))
    for name, np_, words, d, job in jobs:
        rc, out, err, secs = job.result()
        lines = error_text_lines(err)
        problems = []
        if rc is None:
            problems.append(f"hung (no exit in {TIMEOUT} s)")
        elif rc == 0:
            problems.append("exit code 0")
        elif rc < 0 or rc > 128:
            problems.append(f"exit code {rc} (a signal)")
        for crash in ("Segmentation", "terminate called", "Aborted", "signal", "core dumped"):
            if crash in err or crash in out:
                problems.append(f"'{crash}' in the output")
        if len(lines) != 1:
            problems.append(f"{len(lines)} lines of error text (want 1): {lines}")
        msg = lines[0] if lines else ""
        if not msg.startswith("periforge: input error: ") or "bad.xml" not in msg:
            problems.append("the line is not an input error naming bad.xml")
        for w in words:
            if w not in msg:
                problems.append(f"the line lacks '{w}'")
        outputs = [f for f in os.listdir(d) if f.endswith((".e", ".csv"))]
        if outputs:
            problems.append(f"wrote {outputs}")
        print(f"  [{name}] np {np_}: exit {rc} in {secs:.1f} s: {'ok' if not problems else 'FAIL: ' + '; '.join(problems)}"
              f"\n      {msg}")
        failures += [f"{name} np {np_}: {p}" for p in problems]
    return failures


def run_checks(exe, mpirun, prefix, sections):
    """Runs each (title, check(exe, mpirun, work, pool) -> failures) in one temporary directory; -> exit code."""
    start = time.monotonic()
    exe = os.path.abspath(exe)
    failures = []
    with tempfile.TemporaryDirectory(prefix=prefix) as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=4) as pool:
        for title, check in sections:
            print(title)
            failures += check(exe, mpirun, work, pool)
    print(f"{'FAIL' if failures else 'PASS'} ({len(failures)} misses) in {time.monotonic() - start:.1f} s")
    for f in failures:
        print("  MISS: " + f)
    return 1 if failures else 0


def main(exe, mpirun):
    return run_checks(exe, mpirun, "check_exodus_", [
        ("(a) Exodus mesh vs PdQuickGrid lattice, 6x3x3 cells, np 1 and 2:", check_equivalence),
        ("(a') 2D QUAD4 mesh with Thickness:", check_quad),
        ("(b) bad meshes:", check_errors)])


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2:]))

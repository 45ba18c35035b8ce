#!/usr/bin/python3
"""Discretization `Type` = `Gmsh` (MSH 4.1 meshes by Peridigm's element rule, as the Exodus reader applies it).

The meshes are committed (made from the .geo files beside them by gmsh 4.8; the test does not need gmsh).
(a) Equivalence with the lattice: box.msh (ASCII) and box_bin.msh (binary) mesh check_exodus.py's 6x3x3 box with
    hexahedra (volume 1 -> block_1, volume 7 named "top" -> block_7, face groups as its node sets: two unnamed,
    "nodelist_1" and "nodelist_3", two named). They run its Verlet problem (Block Names "block_1 top": the
    alias) and must agree with its PdQuickGrid lattice at np 1 to check_exodus.py's bounds, point by point where
    the points coincide (Gmsh numbers the elements in another order than the lattice: points are matched by
    their coordinates), with the cell centres as coordinates, h^3 as volumes and the blocks 1 and 7.
(a') quad.msh, 4x2 quadrilaterals with Thickness, and box_tet.msh, 1138 tetrahedra of the same box: every
    point at its element's centroid with its area * Thickness or volume, by closed forms on the file's nodes
    (shoelace; corner mean and det / 6) to check_exodus.py's bounds, and the tetrahedra's volumes sum to the box's.
(b) Bad meshes, made here by editing box.msh's text: a missing file, MSH 2.2, an unknown element type, an
    inverted hexahedron, a face element naming a node $Nodes lacks, a 2D mesh without Thickness. Each must stop
    at np 1 and 2 with one input-error line naming the deck, `Input Mesh File` (or `Thickness`) and the mesh.

usage: check_gmsh.py PERIFORGE MPIRUN [MPIRUN ARGS...]
Prints what it measures; exits 1 on any miss.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "exodus"))
import check_exodus as ce  # noqa: E402

BOX_VOLUME = float(np.prod(ce.LENGTHS))


def job(pool, mpirun, exe, work, label, text, np_):
    d = os.path.join(work, label)
    os.makedirs(d)
    open(os.path.join(d, "deck.xml"), "w").write(text)
    return pool.submit(ce.run, mpirun + ["-np", str(np_), exe, "deck.xml"], d)


def result(work, label, name, outcome, failures):
    rc, out, err, secs = outcome
    path = os.path.join(work, label, f"{name}.e")
    print(f"  {label}: exit {rc} in {secs:.1f} s")
    if rc != 0 or not os.path.exists(path):
        failures.append(f"{label}: exit {rc}: {ce.error_text_lines(err)}")
        return None
    return ce.Result(path)


def read_msh(path):
    """An ASCII MSH 4.1 file's nodes {tag: xyz} and element blocks [(dim, type, [[tag, nodes...], ...])]: an
    independent reading of the mesh for the closed forms."""
    words = open(path).read().split("$Nodes")[1].split()
    nodes, at = {}, 4
    for _ in range(int(words[0])):
        n = int(words[at + 3])
        tags = [int(w) for w in words[at + 4:at + 4 + n]]
        xyz = np.array(words[at + 4 + n:at + 4 + 4 * n], dtype=float).reshape(n, 3)
        nodes.update(zip(tags, xyz))
        at += 4 + 4 * n
    words = open(path).read().split("$Elements")[1].split("$EndElements")[0].split()
    blocks, at = [], 4
    for _ in range(int(words[0])):
        dim, etype, n = int(words[at]), int(words[at + 2]), int(words[at + 3])
        k = 1 + {1: 2, 2: 3, 3: 4, 4: 4, 5: 8, 15: 1}[etype]  # tag + nodes (lines ... hexahedra, points)
        rows = [[int(w) for w in words[at + 4 + i * k:at + 4 + (i + 1) * k]] for i in range(n)]
        blocks.append((dim, etype, rows))
        at += 4 + n * k
    return nodes, blocks


def quad_closed_form(path):
    """Each quadrilateral's centroid and area (shoelace formulas on the file's nodes: Gmsh places transfinite
    nodes a few 1e-15 m off the ideal grid, so the reference is the file's own geometry)."""
    nodes, blocks = read_msh(path)
    centres, areas = [], []
    for dim, _, rows in blocks:
        for row in rows if dim == 2 else []:
            p = np.array([nodes[t][:2] for t in row[1:]])
            q = np.roll(p, -1, axis=0)
            cross = p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]
            a = cross.sum() / 2
            centres.append([((p[:, 0] + q[:, 0]) * cross).sum() / (6 * a), ((p[:, 1] + q[:, 1]) * cross).sum() / (6 * a), 0])
            areas.append(a)
    return np.array(centres), np.array(areas)


def tet_closed_form(path):
    """Each tetrahedron's centroid (the mean of its corners) and volume (det / 6) from the file's nodes."""
    nodes, blocks = read_msh(path)
    rows = [row for dim, _, rs in blocks if dim == 3 for row in rs]
    p = np.array([[nodes[t] for t in row[1:]] for row in rows])
    volume = np.linalg.det(p[:, 1:] - p[:, :1]) / 6
    return p.mean(axis=1), volume


def match(points, ref_points):
    """Index into ref_points of each point (nearest); and the largest distance."""
    d = np.linalg.norm(points[:, None, :] - ref_points[None, :, :], axis=2)
    k = d.argmin(axis=1)
    return k, d[np.arange(len(points)), k].max()


def compare_box(label, r, ref, failures):
    centres = ce.cell_centres_3d()
    n = len(centres)
    if len(r.gid) != n:
        failures.append(f"{label}: {len(r.gid)} points, want {n}")
        return
    k, dx = match(r.x, centres)
    dv = np.abs(r.elem["Volume"][0] / ce.CELL_VOLUME - 1.0).max()
    top = centres[k][:, 2] > ce.ORIGIN[2] + 2 * ce.H[2]
    blocks_ok = sorted(r.blocks) == [1, 7] and np.array_equal(r.block_of, np.where(top, 7, 1))
    print(f"  {label}: max |x - cell centre| {dx:.2e} m (tol {ce.COORD_TOL:g}), max |V / h^3 - 1| {dv:.2e} "
          f"(tol {ce.VOLUME_TOL:g}), blocks {dict(zip(r.blocks, r.block_sizes))}")
    if not dx <= ce.COORD_TOL or len(set(k)) != n:
        failures.append(f"{label}: points are not the cell centres (off by {dx:.3e} m)")
        return
    if not dv <= ce.VOLUME_TOL:
        failures.append(f"{label}: volumes off h^3 by {dv:.3e} (relative)")
    if not blocks_ok:
        failures.append(f"{label}: blocks are not 1 (two lower layers) and 7 (top layer)")
    if not np.array_equal(r.time, ref.time):
        failures.append(f"{label}: output times differ from the lattice's")
        return
    worst = (0.0, "")
    for field in ("Displacement", "Velocity", "Force_Density"):
        for a in "XYZ":
            v = field + a
            scale = np.abs(ref.nodal[v]).max()
            rel = np.abs(r.nodal[v] - ref.nodal[v][:, k]).max() / scale
            worst = max(worst, (rel, v))
            if not rel <= ce.REL_TOL:
                failures.append(f"{label}: {v} differs from the lattice by {rel:.2e} of its scale (tol {ce.REL_TOL:g})")
    print(f"  {label} vs lattice np 1: worst {worst[1]} {worst[0]:.2e} of its scale (tol {ce.REL_TOL:g})")


def check_box(exe, mpirun, work, pool):
    failures = []
    runs = {"lattice_np1": (ce.lattice_deck("lattice"), 1, "lattice")}
    for mesh, tag in (("box.msh", "ascii"), ("box_bin.msh", "binary")):
        for np_ in (1, 2):
            deck = ce.exodus_deck(os.path.join(HERE, mesh), "gmsh", kind="Gmsh", blocks="block_1 top")
            runs[f"gmsh_{tag}_np{np_}"] = (deck, np_, "gmsh")
    jobs = {label: job(pool, mpirun, exe, work, label, text, np_) for label, (text, np_, _) in runs.items()}
    results = {label: result(work, label, runs[label][2], j.result(), failures) for label, j in jobs.items()}
    ref = results["lattice_np1"]
    if ref is None:
        return failures
    umax = np.abs(ref.nodal["DisplacementX"]).max()
    print(f"  lattice np 1: max |u_x| {umax:.3e} m")
    if not umax > 1e-8:
        failures.append(f"the problem does not load the body (max |u_x| {umax:g})")
    for label, r in results.items():
        if r is not None and label != "lattice_np1":
            compare_box(label, r, ref, failures)
    return failures


def check_quad_and_tets(exe, mpirun, work, pool):
    failures = []
    thick = 0.0005
    jobs = {}
    for np_ in (1, 2):
        jobs[("quad", np_)] = job(pool, mpirun, exe, work, f"quad_np{np_}",
                                  ce.quad_deck(os.path.join(HERE, "quad.msh"), "quad", thick, kind="Gmsh"), np_)
        jobs[("tet", np_)] = job(pool, mpirun, exe, work, f"tet_np{np_}",
                                 ce.exodus_deck(os.path.join(HERE, "box_tet.msh"), "tet", kind="Gmsh",
                                                blocks="block_1"), np_)
    for (kind, np_), j in jobs.items():
        r = result(work, f"{kind}_np{np_}", kind, j.result(), failures)
        if r is None:
            continue
        vol = r.elem["Volume"][0]
        if kind == "quad":
            centres, areas = quad_closed_form(os.path.join(HERE, "quad.msh"))
            k, dx = match(r.x, centres)
            dv = np.abs(vol / (areas[k] * thick) - 1.0).max()
            print(f"  quad np {np_}: {len(vol)} points, max |x - cell centre| {dx:.2e} m, max |V / (area Thickness)"
                  f" - 1| {dv:.2e}")
            if len(vol) != 8 or not dx <= ce.COORD_TOL or not dv <= ce.VOLUME_TOL:
                failures.append(f"quad np {np_}: {len(vol)} points, coordinates off by {dx:.3e}, volumes by {dv:.3e}")
            continue
        # Closed forms on the file's nodes; and the tetrahedra tile the box: their volumes sum to it up to the
        # round-off of a thousand terms (1e-12 relative).
        centres, volumes = tet_closed_form(os.path.join(HERE, "box_tet.msh"))
        k, dx = match(r.x, centres)
        dvk = np.abs(vol / volumes[k] - 1.0).max()
        dv = abs(vol.sum() / BOX_VOLUME - 1.0)
        print(f"  tet np {np_}: {len(vol)} tetrahedra, max |x - corner mean| {dx:.2e} m, max |V / (det/6) - 1| "
              f"{dvk:.2e}, sum V / box volume - 1 = {dv:.2e} (tol 1e-12)")
        if len(vol) != len(volumes) or len(set(k)) != len(vol) or not dx <= ce.COORD_TOL or not dvk <= ce.VOLUME_TOL \
                or not dv <= 1e-12:
            failures.append(f"tet np {np_}: centroids off by {dx:.3e} m, volumes by {dvk:.3e}, their sum by {dv:.3e}")
    return failures


def bad_meshes(work):
    """(name, deck, words) for each bad mesh, made from box.msh's text."""
    text = open(os.path.join(HERE, "box.msh")).read()
    lines = text.split("\n")
    start = lines.index("$Elements")
    hexes = next(i for i in range(start, len(lines)) if lines[i].startswith("3 ") and len(lines[i].split()) == 4)
    last = next(i for i in range(len(lines) - 1, 0, -1) if len(lines[i].split()) == 9)
    face = next(i for i in range(start + 2, len(lines)) if len(lines[i].split()) == 5)

    def edited(name, index, new):
        changed = list(lines)
        changed[index] = new
        path = os.path.join(work, name)
        open(path, "w").write("\n".join(changed))
        return path

    hexes_words = lines[hexes].split()
    hex_nodes = lines[last].split()
    face_nodes = lines[face].split()
    meshes = {
        "v22.msh": edited("v22.msh", 1, "2.2 0 8"),
        "type99.msh": edited("type99.msh", hexes, " ".join(hexes_words[:2] + ["99"] + hexes_words[3:])),
        "inverted.msh": edited("inverted.msh", last, " ".join([hex_nodes[0]] + hex_nodes[5:9] + hex_nodes[1:5])),
        "absent.msh": edited("absent.msh", face, " ".join(face_nodes[:2] + ["9999"] + face_nodes[3:])),
    }
    deck = lambda mesh: ce.exodus_deck(mesh, "bad", kind="Gmsh", blocks="block_1 top")  # run as bad.xml
    words = ["Input Mesh File"]
    return [
        ("missing mesh file", deck("no_such_mesh.msh"), words + ["no_such_mesh.msh"]),
        ("MSH 2.2", deck(meshes["v22.msh"]), words + ["v22.msh", "2.2", "4.1"]),
        ("unknown element type", deck(meshes["type99.msh"]), words + ["type99.msh", "type 99"]),
        ("inverted element", deck(meshes["inverted.msh"]), words + ["inverted.msh", f"element {hex_nodes[0]}"]),
        ("node set naming an absent node", deck(meshes["absent.msh"]), words + ["absent.msh", "node 9999"]),
        ("2D mesh without Thickness", ce.quad_deck(os.path.join(HERE, "quad.msh"), "bad", None, kind="Gmsh"),
         ["Thickness", "quad.msh"]),
    ]


def main(exe, mpirun):
    return ce.run_checks(exe, mpirun, "check_gmsh_", [
        ("(a) Gmsh hex meshes (ASCII, binary) vs the PdQuickGrid lattice, 6x3x3 cells, np 1 and 2:", check_box),
        ("(a') Gmsh quadrilaterals with Thickness, and tetrahedra:", check_quad_and_tets),
        ("(b) bad meshes:", lambda exe, mpirun, work, pool: ce.check_errors(exe, mpirun, work, pool, bad_meshes(work)))])


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    sys.exit(main(sys.argv[1], sys.argv[2:]))

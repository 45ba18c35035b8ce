#!/usr/bin/python3
"""Write small Exodus II genesis files with netCDF4 (no exodus library needed), for the Exodus discretization's
tests (check_exodus.py).

The file is what seacas' ex_put_* write for a mesh without results: NETCDF3_64BIT_OFFSET ("file_size" = 1),
global attributes api_version / version / floating_point_word_size = 8 / file_size / maximum_name_length = 32,
dimensions len_string, len_line, four, len_name, time_step (unlimited), num_dim, num_nodes, num_elem,
num_el_blk, num_node_sets, num_el_in_blk<k>, num_nod_per_el<k>, num_nod_ns<k>, variables coordx/y/z, coor_names,
eb_status, eb_prop1 (the block ids, attribute name = "ID"), eb_names, connect<k> (attribute elem_type),
attrib<k> (SPHERE blocks), ns_status, ns_prop1, ns_names, node_ns<k>, dist_fact_ns<k>, time_whole.

    write_genesis(path, coords, blocks, node_sets)     the general writer
    box_hex_mesh(nx, ny, nz, origin, lengths, ...)     a structured hex box (elements x fastest), its node sets
    write_box(path, ...)                               box_hex_mesh + write_genesis, with the "bad file" options
    write_quad_mesh(path, nx, ny, origin, lengths)     a 2D mesh of QUAD4 elements

Node and element numbers are 1-based in the file, as Exodus has them; the functions here take 0-based node
indices and add 1 when writing.
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
import netCDF4

LEN_STRING = 33  # MAX_STR_LENGTH + 1
LEN_NAME = 33    # maximum_name_length (32) + 1
LEN_LINE = 81


def _chars(strings, width):
    """list of str -> a (len, width) array of single bytes, NUL padded (netCDF char variable)."""
    out = np.zeros((len(strings), width), dtype="S1")
    for k, s in enumerate(strings):
        b = s.encode()[: width - 1]
        if b:
            out[k, : len(b)] = np.frombuffer(b, dtype="S1")
    return out


class Block:
    """An element block: id, element type name (as written: HEX8, QUAD4, SPHERE, FOO ...), connectivity
    (n_elem x nodes_per_elem, 0-based node indices), optional attributes (n_elem x n_attr), optional name."""

    def __init__(self, block_id, elem_type, connectivity, attributes=None, name=""):
        self.id = int(block_id)
        self.type = elem_type
        self.conn = np.asarray(connectivity, dtype=np.int64).reshape(len(connectivity), -1)
        self.attributes = None if attributes is None else np.asarray(attributes, dtype=np.float64).reshape(len(self.conn), -1)
        self.name = name


class NodeSet:
    """A node set: id, 0-based node indices, optional name ("" = none: Peridigm calls it nodelist_<id>)."""

    def __init__(self, set_id, nodes, name=""):
        self.id = int(set_id)
        self.nodes = np.asarray(nodes, dtype=np.int64).ravel()
        self.name = name


def write_genesis(path, coords, blocks, node_sets=(), title="write_genesis.py"):
    """coords: (num_nodes, num_dim) array, num_dim 2 or 3; blocks: [Block]; node_sets: [NodeSet]."""
    coords = np.asarray(coords, dtype=np.float64)
    num_nodes, num_dim = coords.shape
    num_elem = sum(len(b.conn) for b in blocks)
    d = netCDF4.Dataset(path, "w", format="NETCDF3_64BIT_OFFSET")
    try:
        d.setncattr("api_version", np.float32(8.11))
        d.setncattr("version", np.float32(8.11))
        d.setncattr("floating_point_word_size", np.int32(8))
        d.setncattr("file_size", np.int32(1))
        d.setncattr("maximum_name_length", np.int32(32))
        d.setncattr("int64_status", np.int32(0))
        d.setncattr("title", title)
        d.createDimension("len_string", LEN_STRING)
        d.createDimension("len_line", LEN_LINE)
        d.createDimension("four", 4)
        d.createDimension("len_name", LEN_NAME)
        d.createDimension("time_step", None)
        d.createDimension("num_dim", num_dim)
        d.createDimension("num_nodes", num_nodes)
        d.createDimension("num_elem", num_elem)
        d.createDimension("num_el_blk", len(blocks))
        if node_sets:
            d.createDimension("num_node_sets", len(node_sets))
        d.createVariable("time_whole", "f8", ("time_step",))

        # Element blocks.
        v = d.createVariable("eb_status", "i4", ("num_el_blk",))
        v[:] = np.ones(len(blocks), dtype=np.int32)
        v = d.createVariable("eb_prop1", "i4", ("num_el_blk",))
        v.setncattr("name", "ID")
        v[:] = np.array([b.id for b in blocks], dtype=np.int32)
        v = d.createVariable("eb_names", "S1", ("num_el_blk", "len_name"))
        v[:] = _chars([b.name for b in blocks], LEN_NAME)
        for k, b in enumerate(blocks, start=1):
            d.createDimension(f"num_el_in_blk{k}", len(b.conn))
            d.createDimension(f"num_nod_per_el{k}", b.conn.shape[1])
            v = d.createVariable(f"connect{k}", "i4", (f"num_el_in_blk{k}", f"num_nod_per_el{k}"))
            v.setncattr("elem_type", b.type)
            v[:] = (b.conn + 1).astype(np.int32)
            if b.attributes is not None:
                d.createDimension(f"num_att_in_blk{k}", b.attributes.shape[1])
                v = d.createVariable(f"attrib{k}", "f8", (f"num_el_in_blk{k}", f"num_att_in_blk{k}"))
                v[:] = b.attributes

        # Node sets.
        if node_sets:
            v = d.createVariable("ns_status", "i4", ("num_node_sets",))
            v[:] = np.ones(len(node_sets), dtype=np.int32)
            v = d.createVariable("ns_prop1", "i4", ("num_node_sets",))
            v.setncattr("name", "ID")
            v[:] = np.array([s.id for s in node_sets], dtype=np.int32)
            v = d.createVariable("ns_names", "S1", ("num_node_sets", "len_name"))
            v[:] = _chars([s.name for s in node_sets], LEN_NAME)
            for k, s in enumerate(node_sets, start=1):
                d.createDimension(f"num_nod_ns{k}", len(s.nodes))
                v = d.createVariable(f"node_ns{k}", "i4", (f"num_nod_ns{k}",))
                v[:] = (s.nodes + 1).astype(np.int32)
                v = d.createVariable(f"dist_fact_ns{k}", "f8", (f"num_nod_ns{k}",))
                v[:] = np.ones(len(s.nodes))

        # Coordinates.
        v = d.createVariable("coor_names", "S1", ("num_dim", "len_name"))
        v[:] = _chars(["x", "y", "z"][:num_dim], LEN_NAME)
        for a, axis in enumerate("xyz"[:num_dim]):
            v = d.createVariable(f"coord{axis}", "f8", ("num_nodes",))
            v[:] = coords[:, a]
    finally:
        d.close()


FACES = ("min_x", "max_x", "min_y", "max_y", "min_z", "max_z")


def box_hex_mesh(nx, ny, nz, origin=(0.0, 0.0, 0.0), lengths=(1.0, 1.0, 1.0), faces=(), block_of=None):
    """A structured box of nx*ny*nz HEX8 elements numbered x fastest, then y, then z (the order of PdQuickGrid's
    points), nodes numbered the same way on the (nx+1)(ny+1)(nz+1) grid.

    faces: node sets to make, each a face name of FACES or a (face, name) pair (name "" -> unnamed); set ids
    1, 2, ... in the order given. block_of(i, j, k) -> element block id of cell (i, j, k) (default 1); blocks
    are written in increasing id, each block's elements in the box's order (so the file's element order is the
    box order only when the blocks are contiguous in it, e.g. split along z).
    Returns (coords, blocks, node_sets, cells) where cells lists the (i, j, k) of each element in file order."""
    o = np.asarray(origin, dtype=np.float64)
    h = np.asarray(lengths, dtype=np.float64) / np.array([nx, ny, nz])
    node = lambda i, j, k: i + (nx + 1) * (j + (ny + 1) * k)
    coords = np.zeros(((nx + 1) * (ny + 1) * (nz + 1), 3))
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                coords[node(i, j, k)] = o + h * np.array([i, j, k])
    by_block = {}
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                bid = 1 if block_of is None else int(block_of(i, j, k))
                # Exodus HEX8: the bottom face 0-1-2-3 counter-clockwise seen from above, then the top face.
                conn = [node(i, j, k), node(i + 1, j, k), node(i + 1, j + 1, k), node(i, j + 1, k),
                        node(i, j, k + 1), node(i + 1, j, k + 1), node(i + 1, j + 1, k + 1), node(i, j + 1, k + 1)]
                by_block.setdefault(bid, []).append((conn, (i, j, k)))
    blocks, cells = [], []
    for bid in sorted(by_block):
        blocks.append(Block(bid, "HEX8", [c for c, _ in by_block[bid]]))
        cells += [ijk for _, ijk in by_block[bid]]
    sets = []
    n = (nx, ny, nz)
    for sid, f in enumerate(faces, start=1):
        face, name = (f, "") if isinstance(f, str) else f
        axis = "xyz".index(face[-1])
        at = 0 if face.startswith("min") else n[axis]
        ids = [node(i, j, k) for k in range(nz + 1) for j in range(ny + 1) for i in range(nx + 1)
               if (i, j, k)[axis] == at]
        sets.append(NodeSet(sid, ids, name))
    return coords, blocks, sets, cells


def write_box(path, nx, ny, nz, origin=(0.0, 0.0, 0.0), lengths=(1.0, 1.0, 1.0), faces=(), block_of=None,
              elem_type=None, invert_element=None, node_set_beyond=False):
    """box_hex_mesh written to `path`, optionally broken:
    elem_type: the type name written for every block instead of HEX8 (e.g. "FOO");
    invert_element: index (0-based, file order) of an element whose nodes 0-3 and 4-7 are swapped (negative volume);
    node_set_beyond: the first node set (one is added if there are none) also names node num_nodes + 1.
    Returns (coords, blocks, node_sets, cells) as written."""
    coords, blocks, sets, cells = box_hex_mesh(nx, ny, nz, origin, lengths, faces, block_of)
    if elem_type is not None:
        for b in blocks:
            b.type = elem_type
    if invert_element is not None:
        e = invert_element
        for b in blocks:
            if e < len(b.conn):
                b.conn[e] = np.concatenate([b.conn[e][4:], b.conn[e][:4]])
                break
            e -= len(b.conn)
    if node_set_beyond:
        if not sets:
            sets.append(NodeSet(1, [0]))
        sets[0].nodes = np.append(sets[0].nodes, len(coords))  # 0-based len(coords) is 1-based num_nodes + 1
    write_genesis(path, coords, blocks, sets)
    return coords, blocks, sets, cells


def write_quad_mesh(path, nx, ny, origin=(0.0, 0.0), lengths=(1.0, 1.0), faces=(), num_dim=2):
    """A 2D box of nx*ny QUAD4 elements (counter-clockwise), x fastest; faces as in box_hex_mesh but min/max x, y."""
    o = np.asarray(origin, dtype=np.float64)
    h = np.asarray(lengths, dtype=np.float64) / np.array([nx, ny])
    node = lambda i, j: i + (nx + 1) * j
    coords = np.zeros(((nx + 1) * (ny + 1), num_dim))
    for j in range(ny + 1):
        for i in range(nx + 1):
            coords[node(i, j), :2] = o + h * np.array([i, j])
    conn = [[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)] for j in range(ny) for i in range(nx)]
    sets = []
    for sid, f in enumerate(faces, start=1):
        face, name = (f, "") if isinstance(f, str) else f
        axis = "xy".index(face[-1])
        at = 0 if face.startswith("min") else (nx, ny)[axis]
        sets.append(NodeSet(sid, [node(i, j) for j in range(ny + 1) for i in range(nx + 1) if (i, j)[axis] == at], name))
    write_genesis(path, coords, [Block(1, "QUAD4", conn)], sets)
    return coords, conn, sets


if __name__ == "__main__":
    import sys
    # A quick look: write a 2x1x1 box with two face node sets to the path given.
    write_box(sys.argv[1] if len(sys.argv) > 1 else "box.g", 2, 1, 1, faces=("min_x", ("max_x", "right")))

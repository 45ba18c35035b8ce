#!/usr/bin/env python3
"""Compare two ExodusII files the way Sandia's exodiff does with a .comp command file.

Usage:
  exodiff.py result.e gold.e [file.comp]
  exodiff.py --self-test

Nodes are matched by coordinates (like `exodiff -m`), not by index, so a result written
with a different partition / node order still compares against the gold file. Elements
(Peridigm SPHERE elements, one node each) are matched through their node.

.comp semantics implemented (subset of exodiff's command file):
  DEFAULT TOLERANCE <type> <value> [floor <f>]  tolerance for sections that give none
  COORDINATES <type> <value>                    max coordinate difference of matched nodes
  TIME STEPS <type> <value>                     times must agree step by step
  GLOBAL / NODAL / ELEMENT VARIABLES [<type> <value>] [floor <f>]
      followed by indented lines "<name> [<type> <value>] [floor <f>]":
      - no names listed  -> every variable of that kind is compared with the section tolerance
      - names listed     -> ONLY those are compared (exodiff semantics); a listed name missing
                            from either file is a failure
      - "!name"          -> excluded; if only exclusions are listed, all others are compared
      - "(all)" as a name -> compare all, listed names only override tolerances
  A section keyword absent from the .comp file means that kind is not compared (exodiff).
  Without a .comp file: everything is compared with relative 1e-6 (exodiff's default).
  <type>: absolute | relative | combined | ignore.  relative: |a-b| / max(|a|,|b|);
  combined: |a-b| <= tol * max(1, |a|, |b|); floor: differences |a-b| <= floor always pass.
  '#' starts a comment. Other exodiff keywords are reported and ignored.

Exit status: 0 PASS, 1 FAIL, 2 usage or I/O error.
"""
import os
import sys
from periforge_py.interpreter import use_system_python  # noqa: E402


try:
    import numpy as np
    import netCDF4
except ImportError:
    use_system_python()
    sys.stderr.write("exodiff.py: needs numpy and netCDF4 (Debian: python3-netcdf4)\n")
    sys.exit(2)
from periforge_py.exodus import names as _names  # noqa: E402


class UsageError(Exception):
    pass


# ---------------------------------------------------------------- .comp parsing

SECTIONS = {"GLOBAL VARIABLES": "global", "NODAL VARIABLES": "nodal",
            "ELEMENT VARIABLES": "element"}
TOL_TYPES = ("absolute", "relative", "combined", "ignore")


class Tol:
    def __init__(self, kind="relative", value=1e-6, floor=0.0):
        self.kind, self.value, self.floor = kind, value, floor

    def __repr__(self):
        s = "%s %g" % (self.kind, self.value) if self.kind != "ignore" else "ignore"
        return s + (" floor %g" % self.floor if self.floor else "")

    def measure(self, a, b):
        """Per-entry difference in the tolerance's own metric (compared against value)."""
        a = np.asarray(a, dtype=float)
        b = np.asarray(b, dtype=float)
        d = np.abs(a - b)
        if self.kind == "relative":
            den = np.maximum(np.abs(a), np.abs(b))
            with np.errstate(invalid="ignore", divide="ignore"):
                m = np.where(den > 0, d / np.where(den > 0, den, 1.0), 0.0)
        elif self.kind == "combined":
            m = d / np.maximum(1.0, np.maximum(np.abs(a), np.abs(b)))
        else:
            m = d
        if self.floor > 0:
            m = np.where(d <= self.floor, 0.0, m)
        # NaN in exactly one file is a difference; NaN in both is treated as equal.
        both_nan = np.isnan(a) & np.isnan(b)
        m = np.where(both_nan, 0.0, np.where(np.isnan(m), np.inf, m))
        return m

    def passes(self, maxdiff):
        return self.kind == "ignore" or maxdiff <= self.value


def _is_number(text):
    try:
        float(text)
        return True
    except ValueError:
        return False


def _parse_tol(tokens, where, default=None):
    """Parse '[<type>] <value> [floor <f>]'; returns Tol or default if no value given. A value without a type keeps
    the default's type, as SEACAS exodiff reads it (a type keyword only changes the type before its value)."""
    tol = None
    i = 0
    floor = None
    while i < len(tokens):
        t = tokens[i].lower()
        if t in TOL_TYPES:
            if t == "ignore":
                tol = Tol("ignore", 0.0)
                i += 1
                continue
            if i + 1 >= len(tokens):
                raise UsageError("%s: '%s' needs a value" % (where, t))
            try:
                tol = Tol(t, float(tokens[i + 1]))
            except ValueError:
                raise UsageError("%s: bad tolerance value '%s'" % (where, tokens[i + 1]))
            i += 2
        elif t == "floor":
            if i + 1 >= len(tokens):
                raise UsageError("%s: 'floor' needs a value" % where)
            floor = float(tokens[i + 1])
            i += 2
        elif tol is None and default is not None and _is_number(t):
            tol = Tol(default.kind, float(t), default.floor)
            i += 1
        else:
            raise UsageError("%s: unexpected token '%s'" % (where, tokens[i]))
    if tol is None:
        if default is None:
            return None
        tol = Tol(default.kind, default.value, default.floor)
    if floor is not None:
        tol.floor = floor
    return tol


class CompSpec:
    def __init__(self):
        self.default = Tol("relative", 1e-6)
        self.coord = None       # Tol or None (not compared)
        self.time = None
        # kind -> dict(tol=Tol|None, include={name: Tol|None}, exclude=set(), all=bool)
        self.sections = {}
        self.notes = []

    @classmethod
    def everything(cls):
        c = cls()
        # exodiff's coordinate default is relative; absolute is kinder to coordinates near 0.
        c.coord = Tol("absolute", 1e-6)
        c.time = Tol("relative", 1e-6)
        for k in SECTIONS.values():
            c.sections[k] = dict(tol=c.default, include={}, exclude=set(), all=True)
        return c

    @classmethod
    def parse(cls, path):
        c = cls()
        current = None
        try:
            with open(path) as f:
                lines = f.readlines()
        except OSError as e:
            raise UsageError("cannot read comp file '%s': %s" % (path, e.strerror))
        for lineno, raw in enumerate(lines, 1):
            line = raw.split("#", 1)[0].rstrip()
            if not line.strip():
                continue
            where = "%s:%d" % (path, lineno)
            indented = line[0] in " \t"
            tokens = line.split()
            upper = " ".join(tokens).upper()
            if indented and current is not None:
                name = tokens[0]
                sec = c.sections[current]
                if name.lower() == "(all)":
                    sec["all"] = True
                    continue
                if name.startswith("!"):
                    sec["exclude"].add(name[1:])
                    continue
                sec["include"][name] = ("VAR", tokens[1:], where)  # resolved against the section's tolerance below
                continue
            current = None
            if upper.startswith("DEFAULT TOLERANCE"):
                c.default = _parse_tol(tokens[2:], where, c.default)
            elif upper.startswith("COORDINATES"):
                c.coord = ("COORD", tokens[1:], where)
            elif upper.startswith("TIME STEPS"):
                c.time = ("TIME", tokens[2:], where)
            else:
                for key, kind in SECTIONS.items():
                    if upper.startswith(key):
                        c.sections[kind] = dict(tol=("SEC", tokens[2:], where), include={},
                                                exclude=set(), all=False)
                        current = kind
                        break
                else:
                    c.notes.append("%s: ignored unsupported line '%s'" % (where, line.strip()))
        # Tolerances given without a type fall back to DEFAULT TOLERANCE wherever it appears.
        if isinstance(c.coord, tuple):
            c.coord = _parse_tol(c.coord[1], c.coord[2], c.default)
        if isinstance(c.time, tuple):
            c.time = _parse_tol(c.time[1], c.time[2], c.default)
        for sec in c.sections.values():
            _, toks, where = sec["tol"]
            sec["tol"] = _parse_tol(toks, where, c.default)
            for name, (_, vtoks, vwhere) in list(sec["include"].items()):
                sec["include"][name] = _parse_tol(vtoks, vwhere, sec["tol"])
            if not sec["include"]:
                sec["all"] = True  # a bare section compares everything
        return c


# ---------------------------------------------------------------- Exodus reading

class ExoFile:
    """Just the parts of an Exodus file exodiff needs, read with netCDF4."""

    def __init__(self, path):
        self.path = path
        try:
            ds = netCDF4.Dataset(path, "r")
        except (OSError, IOError) as e:
            raise UsageError("cannot open Exodus file '%s': %s" % (path, e))
        ds.set_auto_mask(False)
        self.ds = ds
        dims = ds.dimensions
        self.num_nodes = len(dims["num_nodes"]) if "num_nodes" in dims else 0
        ndim = len(dims["num_dim"]) if "num_dim" in dims else 3
        if "coordx" in ds.variables:
            cs = [ds.variables["coord" + c][:] for c in "xyz"[:ndim]]
        elif "coord" in ds.variables:
            cs = list(ds.variables["coord"][:])
        else:
            cs = []
        while len(cs) < 3:
            cs.append(np.zeros(self.num_nodes))
        self.coords = np.column_stack(cs).astype(float) if self.num_nodes else np.zeros((0, 3))
        self.times = np.asarray(ds.variables["time_whole"][:], dtype=float) \
            if "time_whole" in ds.variables else np.zeros(0)
        self.nodal_names = _names(ds, "name_nod_var")
        self.elem_names = _names(ds, "name_elem_var")
        self.global_names = _names(ds, "name_glo_var")
        # Element blocks, in file order: block ids and the node (0-based) of each element.
        nblk = len(dims["num_el_blk"]) if "num_el_blk" in dims else 0
        self.block_ids = list(ds.variables["eb_prop1"][:]) if nblk else []
        self.elem_node = []
        self.elem_block = []    # (block index, index in block)
        # Every block's element type and connectivity (0-based nodes; none for an empty block). A file of one-node
        # (SPHERE) elements only pairs elements by their node, as points; any other is compared as SEACAS exodiff
        # compares meshes: the same blocks, their elements in the same order on the same (matched) nodes.
        self.blocks = []
        for b in range(nblk):
            conn = ds.variables.get("connect%d" % (b + 1))
            if conn is None:
                self.blocks.append(("", np.zeros((0, 0), dtype=int)))
                continue
            c = np.asarray(conn[:]).astype(int) - 1
            kind = conn.getncattr("elem_type") if "elem_type" in conn.ncattrs() else ""
            self.blocks.append((str(kind).upper(), c))
        self.spheres = all(c.ndim == 2 and c.shape[1] == 1 for _, c in self.blocks if c.size)
        if self.spheres:
            for b, (_, c) in enumerate(self.blocks):
                for i, n in enumerate(c[:, 0] if c.size else []):
                    self.elem_node.append(int(n))
                    self.elem_block.append((b, i))
        self.elem_node = np.asarray(self.elem_node, dtype=int)
        self.num_blocks = nblk

    def nodal(self, name, step):
        i = self.nodal_names.index(name)
        v = self.ds.variables
        if "vals_nod_var%d" % (i + 1) in v:
            return np.asarray(v["vals_nod_var%d" % (i + 1)][step], dtype=float)
        return np.asarray(v["vals_nod_var"][step, i], dtype=float)

    def element(self, name, step):
        """Values for every element in file element order; NaN where the block lacks it."""
        i = self.elem_names.index(name)
        out = []
        for b in range(self.num_blocks):
            key = "vals_elem_var%deb%d" % (i + 1, b + 1)
            n = len(self.ds.dimensions["num_el_in_blk%d" % (b + 1)])
            if key in self.ds.variables:
                out.append(np.asarray(self.ds.variables[key][step], dtype=float))
            else:
                out.append(np.full(n, np.nan))
        return np.concatenate(out) if out else np.zeros(0)

    def global_var(self, name, step):
        i = self.global_names.index(name)
        return np.asarray([self.ds.variables["vals_glo_var"][step, i]], dtype=float)

    def close(self):
        self.ds.close()


# ---------------------------------------------------------------- matching

def match_nodes(a, b, tol):
    """perm such that b.coords[perm[i]] is a.coords[i]; None if some node has no partner."""
    if a.num_nodes != b.num_nodes:
        return None, "node counts differ (%d vs %d)" % (a.num_nodes, b.num_nodes)
    n = a.num_nodes
    if n == 0:
        return np.zeros(0, dtype=int), None
    if np.allclose(a.coords, b.coords, rtol=0, atol=tol):
        return np.arange(n), None
    try:
        from scipy.spatial import cKDTree
        dist, perm = cKDTree(b.coords).query(a.coords)
    except ImportError:
        # Fallback without scipy: lexicographic sort of rounded coordinates.
        scale = max(tol, 1e-12 * max(1.0, float(np.abs(a.coords).max())))
        ka = np.lexsort(np.round(a.coords / scale).T[::-1])
        kb = np.lexsort(np.round(b.coords / scale).T[::-1])
        perm = np.empty(n, dtype=int)
        perm[ka] = kb
        dist = np.linalg.norm(a.coords - b.coords[perm], axis=1)
    if len(np.unique(perm)) != n:
        return None, "coordinate matching is not one-to-one"
    bad = np.nonzero(dist > max(tol, 0.0))[0]
    if len(bad):
        i = bad[0]
        return None, "node %d at %s has no partner within %g (nearest %g away)" % (
            i + 1, a.coords[i], tol, dist[i])
    return perm, None


def mesh_difference(a, b, perm):
    """SEACAS exodiff's Check_Elmt_Block for files with elements of several nodes: the same block ids in order, each
    with the same element type, count and nodes per element, and the same connectivity element by element (a's nodes
    through the coordinate matching perm). Returns the first difference, or None."""
    if list(a.block_ids) != list(b.block_ids):
        return "element block ids differ (%s vs %s)" % (list(a.block_ids), list(b.block_ids))
    for bid, (ta, ca), (tb, cb) in zip(b.block_ids, a.blocks, b.blocks):
        if ca.shape != cb.shape:
            return "block %d: %s elements vs %s" % (bid, ca.shape, cb.shape)
        if ta != tb:
            return "block %d: element types differ (%s vs %s)" % (bid, ta, tb)
        if ca.size and not np.array_equal(perm[ca], cb):
            e = int(np.nonzero(np.any(perm[ca] != cb, axis=1))[0][0])
            return "block %d: connectivities differ, first at element %d" % (bid, e + 1)
    return None


# ---------------------------------------------------------------- comparison

def compare(result_path, gold_path, comp_path=None, out=sys.stdout):
    spec = CompSpec.parse(comp_path) if comp_path else CompSpec.everything()
    for note in spec.notes:
        print("note: " + note, file=out)
    a = ExoFile(result_path)
    b = ExoFile(gold_path)
    failures = []
    rows = []   # (kind, name, tol, maxdiff, where, ok)

    coord_tol = spec.coord if spec.coord is not None else Tol("absolute", 1e-6)
    match_tol = coord_tol.value if coord_tol.kind == "absolute" else \
        coord_tol.value * max(1.0, float(np.abs(b.coords).max()) if b.num_nodes else 1.0)
    perm, why = match_nodes(a, b, match_tol)
    if perm is None:
        failures.append("nodes: " + why)
    elif spec.coord is not None and a.num_nodes:
        for c, label in enumerate("XYZ"):
            m = spec.coord.measure(a.coords[:, c], b.coords[perm, c])
            i = int(np.argmax(m))
            ok = spec.coord.passes(m[i])
            rows.append(("coord", label, spec.coord, m[i], "node %d" % (i + 1), ok))
            if not ok:
                failures.append("coordinate " + label)

    # Elements: element of result node i <-> element of gold node perm[i].
    eperm = None
    if perm is not None and not (a.spheres and b.spheres):
        why = mesh_difference(a, b, perm)
        if why:
            failures.append(why)
        else:
            eperm = np.arange(sum(len(c) for _, c in b.blocks))
    elif perm is not None and (a.elem_names or b.elem_names):
        if len(a.elem_node) != len(b.elem_node):
            failures.append("element counts differ (%d vs %d)" % (len(a.elem_node), len(b.elem_node)))
        else:
            gold_elem_of_node = np.full(b.num_nodes, -1, dtype=int)
            gold_elem_of_node[b.elem_node] = np.arange(len(b.elem_node))
            eperm = gold_elem_of_node[perm[a.elem_node]]
            if np.any(eperm < 0):
                failures.append("some result elements have no gold element on the matched node")
                eperm = None

    nsteps = len(a.times)
    if len(a.times) != len(b.times):
        failures.append("time step counts differ (%d vs %d)" % (len(a.times), len(b.times)))
        nsteps = min(len(a.times), len(b.times))
    if spec.time is not None and nsteps:
        m = spec.time.measure(a.times[:nsteps], b.times[:nsteps])
        i = int(np.argmax(m))
        ok = spec.time.passes(m[i])
        rows.append(("time", "time", spec.time, m[i], "step %d" % (i + 1), ok))
        if not ok:
            failures.append("times")

    def selected(kind, names_a, names_b):
        sec = spec.sections.get(kind)
        if sec is None:
            return []
        todo = []
        if sec["all"]:
            for n in names_b:
                if n not in sec["exclude"]:
                    todo.append((n, sec["include"].get(n, sec["tol"])))
            for n in names_a:
                if n not in names_b and n not in sec["exclude"] and n not in sec["include"]:
                    failures.append("%s variable %s only in result" % (kind, n))
        for n, t in sec["include"].items():
            if n not in [x for x, _ in todo] and n not in sec["exclude"]:
                todo.append((n, t))
        return todo

    getters = {"nodal": (a.nodal_names, b.nodal_names, lambda f, n, s: f.nodal(n, s)),
               "element": (a.elem_names, b.elem_names, lambda f, n, s: f.element(n, s)),
               "global": (a.global_names, b.global_names, lambda f, n, s: f.global_var(n, s))}
    for kind in ("global", "nodal", "element"):
        names_a, names_b, get = getters[kind]
        for name, tol in selected(kind, names_a, names_b):
            missing = [p for p, names in ((result_path, names_a), (gold_path, names_b))
                       if name not in names]
            if missing:
                failures.append("%s variable %s missing in %s" % (kind, name, ", ".join(missing)))
                rows.append((kind, name, tol, float("nan"), "missing", False))
                continue
            if kind == "nodal" and perm is None or kind == "element" and eperm is None:
                continue
            worst, where = 0.0, "-"
            for s in range(nsteps):
                va, vb = get(a, name, s), get(b, name, s)
                if kind == "nodal":
                    vb = vb[perm]
                elif kind == "element":
                    vb = vb[eperm]
                m = tol.measure(va, vb)
                if m.size:
                    i = int(np.argmax(m))
                    if m[i] > worst or where == "-":
                        label = {"nodal": "node", "element": "elem", "global": "global"}[kind]
                        worst, where = float(m[i]), "step %d %s %d" % (s + 1, label, i + 1)
            ok = tol.passes(worst)
            rows.append((kind, name, tol, worst, where, ok))
            if not ok:
                failures.append("%s %s" % (kind, name))

    print("%-8s %-24s %-28s %-12s %-24s %s" % ("kind", "variable", "tolerance", "max diff",
                                               "at", "status"), file=out)
    for kind, name, tol, d, where, ok in rows:
        print("%-8s %-24s %-28s %-12.4e %-24s %s" % (kind, name, tol, d, where,
                                                     "ok" if ok else "DIFF"), file=out)
    a.close()
    b.close()
    if failures:
        print("exodiff: FAIL (%s)" % "; ".join(failures), file=out)
        return 1
    print("exodiff: PASS", file=out)
    return 0


# ---------------------------------------------------------------- self test

GOLD_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir, os.pardir,
                        "shared", "reference", "peridigm")


def self_test():
    import io
    import shutil
    import tempfile
    candidates = [os.environ.get("PF_PERIDIGM_REF", ""), "/work/shared/reference/peridigm", GOLD_DIR]
    ref = next((c for c in candidates if c and os.path.isdir(c)), None)
    if ref is None:
        print("self-test: Peridigm reference directory not found (set PF_PERIDIGM_REF)")
        return 2
    gold = os.path.join(ref, "Compression_QS_3x2x2", "Compression_QS_3x2x2_gold.e")
    comp = os.path.join(ref, "Compression_QS_3x2x2", "Compression_QS_3x2x2.comp")
    text_gold = os.path.join(ref, "Compression_QS_3x2x2_TextFile",
                             "Compression_QS_3x2x2_TextFile_gold.e")
    tmp = tempfile.mkdtemp(prefix="exodiff_selftest_")
    results = []

    def run(label, expect, *args):
        buf = io.StringIO()
        rc = compare(*args, out=buf)
        ok = rc == expect
        results.append(ok)
        print("%-60s rc=%d expected=%d %s" % (label, rc, expect, "ok" if ok else "WRONG"))
        if not ok:
            print(buf.getvalue())

    def perturbed(name, var, step, index, delta):
        p = os.path.join(tmp, name)
        shutil.copy(gold, p)
        with netCDF4.Dataset(p, "a") as d:
            v = d.variables[var]
            v[step, index] = v[step, index] + delta
        return p

    try:
        run("gold vs gold with .comp", 0, gold, gold, comp)
        run("gold vs gold without .comp", 0, gold, gold)
        # Same problem written with a different node order (Peridigm text-file discretization):
        # exercises coordinate matching and element matching through nodes.
        if os.path.exists(text_gold):
            run("reordered TextFile gold vs QuickGrid gold (.comp)", 0, text_gold, gold, comp)
        # DisplacementX (var 1) tolerance absolute 1e-9: 1e-8 must fail, 1e-10 must pass.
        run("DisplacementX +1e-8 fails", 1, perturbed("dx.e", "vals_nod_var1", 5, 4, 1e-8), gold, comp)
        run("DisplacementX +1e-10 passes", 0, perturbed("dx_small.e", "vals_nod_var1", 5, 4, 1e-10),
            gold, comp)
        # Dilatation (element var 3) absolute 1e-12.
        run("Dilatation +1e-9 fails", 1, perturbed("dil.e", "vals_elem_var3eb1", 20, 0, 1e-9), gold, comp)
        # Proc_Num (element var 2) is not listed in the .comp: exodiff ignores it.
        run("unlisted Proc_Num change ignored", 0,
            perturbed("proc.e", "vals_elem_var2eb1", 3, 3, 1.0), gold, comp)
        run("time shift fails", 1, perturbed_time(gold, tmp), gold, comp)
        coord_moved = os.path.join(tmp, "coord.e")
        shutil.copy(gold, coord_moved)
        with netCDF4.Dataset(coord_moved, "a") as d:
            d.variables["coordx"][0] = d.variables["coordx"][0] + 0.25
        run("moved node fails", 1, coord_moved, gold, comp)
        bad_comp = os.path.join(tmp, "bad.comp")
        with open(bad_comp, "w") as f:
            f.write("NODAL VARIABLES absolute 1e-9\n\tNoSuchVariable\n")
        run("listed variable missing fails", 1, gold, gold, bad_comp)
        # A mesh of QUAD4/TRI3 blocks (Peridigm's interface file): compared as SEACAS compares meshes.
        faces = os.path.join(os.path.dirname(ref), "peridigm-suite", "Interfaces", "Interfaces_gold.e")
        if os.path.exists(faces):
            run("interface mesh gold vs gold", 0, faces, faces)
            swapped = os.path.join(tmp, "swapped.e")
            shutil.copy(faces, swapped)
            with netCDF4.Dataset(swapped, "a") as d:
                c = d.variables["connect1"][:]
                d.variables["connect1"][:] = c[[1, 0] + list(range(2, len(c)))]
            run("interface mesh with two quads swapped fails", 1, swapped, faces)
            aperture = os.path.join(tmp, "aperture.e")
            shutil.copy(faces, aperture)
            with netCDF4.Dataset(aperture, "a") as d:
                d.variables["vals_elem_var1eb2"][1, 5] = 1e-3
            run("interface aperture changed fails", 1, aperture, faces)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("self-test: %s" % ("PASS" if all(results) else "FAIL"))
    return 0 if all(results) else 1


def perturbed_time(gold, tmp):
    import shutil
    p = os.path.join(tmp, "time.e")
    shutil.copy(gold, p)
    with netCDF4.Dataset(p, "a") as d:
        d.variables["time_whole"][3] = d.variables["time_whole"][3] + 1e-10
    return p


def main(argv):
    if len(argv) >= 1 and argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0
    if argv == ["--self-test"]:
        return self_test()
    if len(argv) not in (2, 3) or any(x.startswith("-") for x in argv):
        sys.stderr.write("usage: exodiff.py result.e gold.e [file.comp] | --self-test | --help\n")
        return 2
    for p in argv:
        if not os.path.isfile(p):
            sys.stderr.write("exodiff.py: no such file: %s\n" % p)
            return 2
    try:
        return compare(*argv)
    except UsageError as e:
        sys.stderr.write("exodiff.py: error: %s\n" % e)
        return 2


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

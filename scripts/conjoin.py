#!/usr/bin/env python3
"""Joins time-sequential ExodusII files of one run into one file, as Peridigm's regression tests do with
SEACAS `conjoin` before comparing (e.g. Compression_QS_Explicit_MultiFreqOutput_3x2x2: its two output lists,
a quasi-static and an explicit one, write two files; its gold file is the two joined).

usage: conjoin.py OUT.e IN1.e IN2.e ...
       conjoin.py --exodiff GOLD.e CASE.comp OUT.e IN1.e IN2.e ...   (join, then scripts/exodiff.py OUT GOLD COMP)

The inputs must hold the same mesh (node count and coordinates) and the same variables; OUT is IN1 with the
time steps of each following file appended in order. A step whose time is not above the last one kept is an
error (the files must follow one another in time, as the output lists of successive solvers do).
Exit status: 0 joined (and, with --exodiff, exodiff's status), 2 usage or mismatching inputs.
"""
import os
import shutil
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import exodiff  # noqa: E402  (numpy, netCDF4, and the re-exec under /usr/bin/python3 when they are missing)

np = exodiff.np
netCDF4 = exodiff.netCDF4


class JoinError(Exception):
    pass


def _names(ds, var):
    return exodiff._names(ds, var)


def _timed(ds):
    """The variables indexed by time step, by name."""
    return [v for v in ds.variables if ds.variables[v].dimensions[:1] == ("time_step",)]


def _check_same(a, b, path):
    if a.dimensions["num_nodes"].size != b.dimensions["num_nodes"].size:
        raise JoinError("%s: %d nodes, the first file %d" % (path, b.dimensions["num_nodes"].size,
                                                             a.dimensions["num_nodes"].size))
    for v in ("name_nod_var", "name_elem_var", "name_glo_var"):
        if _names(a, v) != _names(b, v):
            raise JoinError("%s: its %s differ from the first file's (%s vs %s)" % (path, v, _names(b, v),
                                                                                    _names(a, v)))
    for c in ("coordx", "coordy", "coordz"):
        if c in a.variables and not np.array_equal(a[c][:], b[c][:]):
            raise JoinError("%s: its %s differ from the first file's (another mesh or node order)" % (path, c))


def conjoin(out_path, in_paths):
    shutil.copyfile(in_paths[0], out_path)
    with netCDF4.Dataset(out_path, "a") as out:
        for path in in_paths[1:]:
            with netCDF4.Dataset(path, "r") as src:
                _check_same(out, src, path)
                n = out.dimensions["time_step"].size
                times = src["time_whole"][:]
                last = out["time_whole"][n - 1] if n else -np.inf
                if len(times) and times[0] <= last:
                    raise JoinError("%s: its first time %g is not after the last one so far %g" % (path, times[0],
                                                                                                   last))
                for v in _timed(src):
                    if v not in out.variables:
                        raise JoinError("%s: variable %s is not in the first file" % (path, v))
                    out[v][n:n + len(times)] = src[v][:]


def main(argv):
    gold = comp = None
    if argv[:1] == ["--exodiff"]:
        if len(argv) < 3:
            argv = []
        else:
            gold, comp, argv = argv[1], argv[2], argv[3:]
    if len(argv) < 3 or any(a.startswith("-") for a in argv):
        sys.stderr.write("usage: conjoin.py [--exodiff GOLD.e CASE.comp] OUT.e IN1.e IN2.e ...\n")
        return 2
    for p in argv[1:] + [x for x in (gold, comp) if x]:
        if not os.path.isfile(p):
            sys.stderr.write("conjoin.py: no such file: %s\n" % p)
            return 2
    try:
        conjoin(argv[0], argv[1:])
    except JoinError as e:
        sys.stderr.write("conjoin.py: error: %s\n" % e)
        return 2
    return exodiff.main([argv[0], gold, comp]) if gold else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

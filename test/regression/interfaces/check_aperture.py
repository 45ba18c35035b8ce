#!/usr/bin/env python3
"""Construct Interfaces' aperture against its closed form. Runs stretch.xml.in (Peridigm's Interfaces deck with every
point under u = eps t x, eps = 1e-3, load steps at t = 0.5, 1) as stretch.xml beside a copy of Peridigm's mixed
hex/tet mesh, and reads Interfaces.e. (.xml.in: the deck names a mesh only this copy puts beside it, so the
validator of test/regression's decks leaves it alone.)
Under a uniform stretch every pair's aperture |y_R - y_L| - |x_R - x_L| is eps t |x_R - x_L|. Peridigm writes each
output's apertures before it updates them, so output k holds those of output k - 1: 0 at t = 0 and t = 0.5, and
0.5 eps |x_R - x_L| at t = 1. The two elements of a quadrilateral are the two mesh elements holding all four of its
nodes (hex-hex faces); their points are the output's nodes of those element positions. Tolerance: the file stores
float32 (relative 6e-8) of a value computed in double; 1e-6 relative of the expected value.

usage: check_aperture.py DECK MESH EXE NP MPIRUN...
"""
import os
import shutil
import subprocess
import sys
import tempfile
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

deck, mesh, exe, np_ranks, mpirun = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4], sys.argv[5:]
work = tempfile.mkdtemp(prefix="interfaces_aperture_")
try:
    shutil.copy(mesh, work)
    shutil.copy(deck, os.path.join(work, "stretch.xml"))
    run = subprocess.run(mpirun + ["-np", np_ranks, exe, "stretch.xml"], cwd=work, capture_output=True, text=True)
    if run.returncode != 0:
        sys.exit("run failed: " + (run.stderr or run.stdout)[-2000:])
    f = netCDF4.Dataset(os.path.join(work, "Interfaces.e"))
    out = netCDF4.Dataset(os.path.join(work, "stretch.e"))
    g = netCDF4.Dataset(os.path.join(work, os.path.basename(mesh)))
    times = f["time_whole"][:]
    assert np.allclose(times, [0.0, 0.5, 1.0]), times
    ids = g["node_num_map"][:]
    elements = [set(int(ids[k - 1]) for k in row) for b in (1, 2) for row in g["connect%d" % b][:]]
    file_ids = f["node_num_map"][:]
    x = np.stack([out["coordx"][:], out["coordy"][:], out["coordz"][:]], axis=1).astype(float)
    aperture = f["vals_elem_var1eb1"][:].astype(float)
    eps, checked, worst = 1e-3, 0, 0.0
    for k, quad in enumerate(f["connect1"][:]):
        face = set(int(file_ids[n - 1]) for n in quad)
        pair = [e for e, nodes in enumerate(elements) if face <= nodes]
        if np.any(aperture[:2, k] != 0.0):
            sys.exit("interface %d: non-zero aperture %s at t = 0 or 0.5 (the lagged outputs)" % (k + 1, aperture[:2, k]))
        if len(pair) != 2:
            continue
        want = 0.5 * eps * np.linalg.norm(x[pair[1]] - x[pair[0]])
        worst = max(worst, abs(aperture[2, k] - want) / want)
        checked += 1
    print("quadrilaterals checked: %d of %d; worst relative difference %.3g" % (checked, len(aperture[0]), worst))
    tris = f["vals_elem_var1eb2"][:].astype(float)
    if checked < 100 or worst > 1e-6 or np.any(tris[:2] != 0.0) or not np.all(tris[2] > 0.0):
        sys.exit("FAIL")
    print("PASS")
finally:
    shutil.rmtree(work, ignore_errors=True)

#!/usr/bin/env python3
"""Checks compat_user_all.e: the deck's node set "All" (nodes 2 and 5) replaced the built-in set of every
node: at the first output the y velocity is 1 on nodes 2 and 5 and 0 elsewhere (the kick is along y and a
line of points has no y stiffness to first order, so one 1 ns step leaves it as set).
usage: check_compat_user_all.py RUN.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import nodal  # noqa: E402

d = netCDF4.Dataset(sys.argv[1])
ids = np.asarray(d["node_num_map"][:]) if "node_num_map" in d.variables else np.arange(1, 7)
vy = nodal(d, "VelocityY")[0]
want = {1: 0.0, 2: 1.0, 3: 0.0, 4: 0.0, 5: 1.0, 6: 0.0}
ok = True
for i, v in zip(ids, vy):
    if abs(v - want[int(i)]) > 1e-12:  # set values, no arithmetic: exact up to output rounding
        print("node", int(i), "VelocityY", v, "expected", want[int(i)]); ok = False
print("compat_user_all: PASS" if ok else "compat_user_all: FAIL")
sys.exit(0 if ok else 1)

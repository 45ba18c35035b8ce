#!/usr/bin/env python3
"""Checks compat_line.e: weighted volume m = sum omega |xi|^2 V with omega = 1/zeta (ends: 1*1 + 4/2 = 3,
middle: 2), the acceleration equals Force / (rho V), and the two ends moved towards each other (the id 0
in the node set was dropped, ids 1 and 3 kept). usage: check_compat_line.py RUN.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element, nodal  # noqa: E402


d = netCDF4.Dataset(sys.argv[1])
nv = lambda n: nodal(d, n)
ev = lambda n: element(d, n)
ok = True
m = ev("Weighted_Volume")[-1]
if not np.allclose(m, [3.0, 2.0, 3.0], rtol=1e-12):
    print("Weighted_Volume", m, "expected [3, 2, 3]"); ok = False
for c in "XYZ":
    a, f = nv("Acceleration" + c), nv("Force" + c)
    if not np.allclose(a, f / 1000.0, rtol=1e-12, atol=1e-12 * np.abs(f).max()):
        print("Acceleration" + c, "differs from Force/(rho V)"); ok = False
ux = nv("DisplacementX")[-1]
if not (ux[0] > 0 and ux[2] < 0):
    print("ends did not move inwards:", ux); ok = False
if len(d["time_whole"]) != 5:
    print("expected 5 time steps, got", len(d["time_whole"])); ok = False
print("compat_line: PASS" if ok else "compat_line: FAIL")
sys.exit(0 if ok else 1)

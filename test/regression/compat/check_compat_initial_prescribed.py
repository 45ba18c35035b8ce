#!/usr/bin/env python3
"""Checks compat_initial_prescribed.e: the right point's x condition (Apply At Initial Time false, Peridigm's) is 0
in the initial state and 1e-4 from the first step on, its velocity there 1e-4 / dt (dt = 1e-6 s: the step's
rate, as Peridigm's increment (f - u) / dt makes it); its y condition (true) is 2e-5 in every state with zero velocity.
usage: check_compat_initial_prescribed.py RUN.e"""
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
right = 3
ux, uy = nodal(d, "DisplacementX")[:, right], nodal(d, "DisplacementY")[:, right]
vx, vy = nodal(d, "VelocityX")[:, right], nodal(d, "VelocityY")[:, right]
ok = len(ux) == 3
ok = ok and np.array_equal(ux, [0.0, 1e-4, 1e-4]) and np.array_equal(uy, [2e-5, 2e-5, 2e-5])
ok = ok and np.allclose(vx, [0.0, 100.0, 0.0], rtol=1e-12, atol=0) and np.array_equal(vy, [0.0, 0.0, 0.0])
if not ok:
    print("u_x", ux, "expected [0, 1e-4, 1e-4]; u_y", uy, "expected 2e-5 throughout; v_x", vx, "v_y", vy)
print("compat_initial_prescribed: PASS" if ok else "compat_initial_prescribed: FAIL")
sys.exit(0 if ok else 1)

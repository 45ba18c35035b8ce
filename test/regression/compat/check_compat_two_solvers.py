#!/usr/bin/env python3
"""Checks the numbered-list run (compat_two_solvers.xml) against one solver over the same interval
(compat_one_solver.xml): Solver2 continues exactly where Solver1 stopped, Output1 holds the steps up to its
Final Output Step, Output2 those from its Initial Output Step (Solver2's initial state at t = 3e-6 first),
and Global_Kinetic_Energy = sum 1/2 rho V |v|^2 of the reference run's velocities.
usage: check_compat_two_solvers.py TWO_1.e TWO_2.e ONE.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element, global_variable, nodal, variable_names  # noqa: E402

RHO = 1000.0


two1, two2, one = (netCDF4.Dataset(f) for f in sys.argv[1:4])
nv = nodal
glo = lambda d: global_variable(d, "Global_Kinetic_Energy")
ok = True
t1, t2, t = (np.asarray(d["time_whole"][:]) for d in (two1, two2, one))
if not (np.allclose(t1, t[:4], rtol=0, atol=1e-15) and np.allclose(t2, t[3:7], rtol=0, atol=1e-15)):
    print("times", t1, t2, "expected", t[:4], t[3:7]); ok = False
for var in ("Displacement", "Velocity", "Force"):
    for c in "XYZ":
        a, b = nv(two1, var + c), nv(one, var + c)[:4]
        if not np.allclose(a, b, rtol=1e-12, atol=1e-12 * max(1e-30, np.abs(b).max())):
            print(var + c, "of Output1 differs from the one-solver run"); ok = False
V = element(one, "Volume")[0]
vel = np.stack([nv(one, "Velocity" + c) for c in "XYZ"], axis=2)
ke = 0.5 * RHO * (V[None, :] * (vel ** 2).sum(axis=2)).sum(axis=1)
if not np.allclose(glo(two1), ke[:4], rtol=1e-12):
    print("Output1 Global_Kinetic_Energy", glo(two1), "expected", ke[:4]); ok = False
if not np.allclose(glo(two2), ke[3:7], rtol=1e-12):
    print("Output2 Global_Kinetic_Energy", glo(two2), "expected", ke[3:7]); ok = False
if two2.dimensions["num_nodes"].size != 1 or variable_names(two2, "name_nod_var"):
    print("Output2 (globals only) should hold one dummy node and no nodal variables"); ok = False
print("compat_two_solvers: PASS" if ok else "compat_two_solvers: FAIL")
sys.exit(0 if ok else 1)

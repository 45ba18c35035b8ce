#!/usr/bin/env python3
"""Checks Verlet's `Prescribed Velocity` on compat_prescribed_velocity(_rate).e: the two runs move every point
alike (displacements and the free points' velocities bit for bit: the switch changes only what a prescribed
component carries), `Step Rate` writes the held point's velocity 0 and the driven one's 0.5 m/s (its rate
0.5 t, to rounding), and `Half Kick` (Peridigm's) those plus dt/2 (f + b)/rho from the written force density f,
the body force b (-2e7 N/m^3 along y on every point) and rho = 1000 (Peridigm.cpp, executeExplicit: the last
half kick reaches every component).
usage: check_compat_prescribed_velocity.py HALF_KICK.e STEP_RATE.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import nodal  # noqa: E402

kick, rate = netCDF4.Dataset(sys.argv[1]), netCDF4.Dataset(sys.argv[2])
dt, rho, body = 1e-6, 1000.0, {"X": 0.0, "Y": -2e7, "Z": 0.0}
held, driven, free = [0], [3], [1, 2]
ok = True


def fail(msg):
    global ok
    print(msg)
    ok = False


for c in "XYZ":
    if not np.array_equal(nodal(kick, "Displacement" + c), nodal(rate, "Displacement" + c)):
        fail("Displacement%s differs between the runs" % c)
    vk, vr = nodal(kick, "Velocity" + c), nodal(rate, "Velocity" + c)
    if not np.array_equal(vk[:, free], vr[:, free]):
        fail("free points' Velocity%s differ between the runs" % c)
    rate_expected = np.zeros_like(vr)
    if c == "X":
        rate_expected[1:, driven] = 0.5
    fixed = held + (driven if c == "X" else [])
    if not np.allclose(vr[:, fixed], rate_expected[:, fixed], rtol=0, atol=1e-12):  # 0.5 t / dt: rounding only
        fail("Step Rate Velocity%s at prescribed points %s, expected %s" % (c, vr[:, fixed], rate_expected[:, fixed]))
    f = nodal(kick, "Force_Density" + c)
    kick_expected = vr + 0.5 * dt * (f + body[c]) / rho
    kick_expected[0] = 0.0  # the initial state is written before any kick
    if not np.allclose(vk[:, fixed], kick_expected[:, fixed], rtol=1e-12, atol=1e-15):
        fail("Half Kick Velocity%s at prescribed points %s, expected %s" % (c, vk[:, fixed], kick_expected[:, fixed]))
if not np.any(nodal(kick, "VelocityY")[1:, held] != 0.0):
    fail("Half Kick left the held point's VelocityY 0: the test would not see the switch")
print("compat_prescribed_velocity: PASS" if ok else "compat_prescribed_velocity: FAIL")
sys.exit(0 if ok else 1)

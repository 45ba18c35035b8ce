#!/usr/bin/env python3
"""Momentum and friction of two_cubes.xml (two cubes meeting off-centre with friction, no body force, no support):
contact forces act in equal and opposite pairs (core/ShortRangeContact.hpp), so the total momentum sum(rho V v)
keeps its initial value (rho V 125 (20 - 20, 5, 0) with V = 1e-9 m^3) at every written step, to round-off: 1e-10 of
the momentum scale rho V 250 * 20 m/s (the sums of 250 terms of velocities up to tens of m/s in double precision
round at about 1e-14 of it). And the cubes did meet: the contact force was non-zero at some written step and
block 1's mean x velocity changed sign.

usage: check_momentum.py RUN.e
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
import netCDF4  # noqa: E402

from periforge_py import exodus as ef  # noqa: E402

RHO, V, N = 7800.0, 1.0e-9, 125


def main():
    d = netCDF4.Dataset(sys.argv[1])
    p0 = RHO * V * N * np.array([20.0 - 20.0, 5.0, 0.0])
    scale = RHO * V * 2 * N * 20.0
    worst = 0.0
    for c, axis in enumerate("XYZ"):
        p = RHO * V * ef.nodal(d, "Velocity" + axis).sum(axis=1)
        worst = max(worst, np.abs(p - p0[c]).max() / scale)
    touched = np.abs(ef.nodal(d, "Contact_Force_DensityX")).max()
    v1 = ef.nodal(d, "VelocityX")[:, :N].mean(axis=1)
    print("two cubes: worst |p - p0| / (rho V 250 * 20 m/s) = %.3g (bound 1e-10); max |contact force density x| "
          "= %.3g N/m^3; block 1 mean v_x %.4g -> %.4g m/s" % (worst, touched, v1[0], v1[-1]))
    ok = worst < 1e-10 and touched > 0.0 and v1[0] > 0.0 > v1[-1]
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

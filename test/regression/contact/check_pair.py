#!/usr/bin/env python3
"""Two points approaching at +-v0 along x under Peridigm's short-range contact law (pair.xml): while closer than the
contact radius r_c each pushes the other with force density 2 * 9 k (r_c - d) V / (pi h^5) (both ends of the pair,
equal horizons h; core/ShortRangeContact.hpp), a linear spring in the overlap s = r_c - d. Starting at d = r_c,
s'' = -w^2 s with w^2 = 36 k V / (pi h^5 rho), so each velocity is v0 cos(w t) until the points part at w t = pi,
then stays -v0. Checks every written step of the run's Exodus file against that closed form.

usage: check_pair.py RUN.e
Tolerance 1e-5 v0: velocity-Verlet's phase error over the contact, (w dt)^2 / 24 * pi = 5e-7 at w dt = 2e-3,
plus the step at which contact ends (the force switches off within one step: an error up to w dt * v0 = 2e-3 v0
at that one step, which the check leaves out: it skips the written steps within 2 dt of w t = pi).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
import netCDF4  # noqa: E402

from periforge_py import exodus as ef  # noqa: E402

V0, K, H, RHO, VOLUME, DT = 1.0, 2.5e7, 1.5e-3, 7800.0, 2.0e-9, 2.0e-8


def main():
    d = netCDF4.Dataset(sys.argv[1])
    t = np.asarray(d["time_whole"][:])
    v = ef.nodal(d, "VelocityX")
    w = math.sqrt(36.0 * K * VOLUME / (math.pi * H ** 5 * RHO))
    worst, checked = 0.0, 0
    for s in range(len(t)):
        if abs(w * t[s] - math.pi) < 2 * w * DT:
            continue
        exact = V0 * math.cos(w * t[s]) if w * t[s] < math.pi else -V0
        for node, sign in ((0, 1.0), (1, -1.0)):
            worst = max(worst, abs(v[s, node] - sign * exact) / V0)
        checked += 1
    print("pair: w = %.6g 1/s, %d steps checked, worst |v - v0 cos(w t)| / v0 = %.3g (bound 1e-5)" % (w, checked, worst))
    if checked < 50 or worst > 1e-5:
        print("FAIL")
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())

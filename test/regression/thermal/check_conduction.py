#!/usr/bin/env python3
"""Steady conduction in a bar (conduction_bar.xml, last step) against Fourier's closed form T = 300 + 5000 x.

At the free points the flux divergence of the exact field vanishes (each free point's family is whole in x, so the
bond sum of a linear field is 0 by symmetry); the solve stops at |L(T)| <= 1e-3 W/m^3 over the free points, which
leaves |T - T_exact| far below a micro-kelvin. Tolerances: 1e-6 K on T (100 K spread:
1e-8 relative) and 1e-6 of the held layers' largest |Flux_Divergence| at the free points; a wrong bond constant or
ghost exchange moves T by kelvins.
"""
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset


def main(path):
    d = Dataset(path)
    d.set_auto_mask(False)
    nod = ["".join(c.decode() for c in row if c).strip() for row in d.variables["name_nod_var"][:]]
    x = np.asarray(d.variables["coordx"][:])
    T = d.variables[f"vals_nod_var{nod.index('Temperature') + 1}"][-1, :]
    h = d.variables[f"vals_nod_var{nod.index('Flux_Divergence') + 1}"][-1, :]
    exact = 300.0 + 5000.0 * x
    held = (x < x.min() + 0.0031) | (x > x.max() - 0.0031)
    errT = np.max(np.abs(T - exact))
    hmax = np.max(np.abs(h[held]))
    hfree = np.max(np.abs(h[~held]))
    print(f"conduction bar: {np.count_nonzero(~held)} free points, max |T - (300 + 5000 x)| = {errT:.3e} K; "
          f"max |Flux_Divergence| free {hfree:.3e}, held {hmax:.3e} W/m^3")
    ok = errT < 1e-6 and hfree < 1e-6 * hmax and hmax > 0
    print("check_conduction: PASS" if ok else "check_conduction: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

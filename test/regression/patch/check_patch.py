#!/usr/bin/env python3
"""Patch test check: every point of patch_3d.e (last step) must carry u = H x (the deck's field).

Tolerance 1e-6 of max|H x|: the deck's ADR relative residual tolerance is 1e-9 of the reaction;
with the cube's condition number (about (L/dx)^2 ~ 1e2) the displacement error stays well inside
1e-6, while an assembly, ghosting or BC error shows up at the 1e-2 level or more.
"""
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset

H = np.array([[1.0e-3, 2.0e-4, -3.0e-4], [1.0e-4, -5.0e-4, 2.5e-4], [-2.0e-4, 3.0e-4, 7.0e-4]])


def main(path):
    d = Dataset(path)
    names = ["".join(c.decode() for c in row if c) .strip() for row in d.variables["name_nod_var"][:]]
    d.set_auto_mask(False)
    X = np.stack([np.asarray(d.variables[f"coord{c}"][:]) for c in "xyz"], axis=1)
    u = np.stack([d.variables[f"vals_nod_var{names.index('Displacement' + c) + 1}"][-1, :] for c in "XYZ"], axis=1)
    exact = X @ H.T
    err = np.max(np.abs(u - exact)) / np.max(np.abs(exact))
    print(f"patch test: max |u - Hx| / max |Hx| = {err:.3e} over {len(X)} points")
    ok = err < 1e-6
    print("check_patch: PASS" if ok else "check_patch: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

#!/usr/bin/env python3
"""Checks bar_damage_{adr,nox}.xml (quasi-static bond breaking): the bar of bar_3d.xml stretched in 8 steps of
eps = 1e-3 with Critical Stretch 5.5e-3.

  - Damage is exactly 0 everywhere up to step 5: no bond is stretched more than the axial eps <= 5e-3 (the
    lattice's bonds in a uniaxial-stress field stretch by eps cos^2 - nu eps sin^2 <= eps);
  - Damage > 0 at step 6 (eps = 6e-3 > s_c: the near-axial bonds break);
  - the reaction drops at step 6 (an intact bar's would rise by a fifth: R_6 > R_5), because those bonds
    carry no force;
  - Damage never decreases at any point from one step to the next (broken bonds never heal).

usage: check_bar_damage.py RUN.e RUN.csv
"""
import csv
import sys

import os
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np


def damage(path):
    f = netCDF4.Dataset(path)
    names = ["".join(c.decode() for c in row if c) for row in f["name_elem_var"][:].data]
    k = names.index("Damage") + 1
    return np.concatenate([np.asarray(f[v][:]) for v in sorted(f.variables) if v.startswith(f"vals_elem_var{k}eb")],
                          axis=1)


def main():
    d = damage(sys.argv[1])
    rows = list(csv.DictReader(open(sys.argv[2])))
    r = [abs(float(row["Reaction_Right_Layer_X"])) for row in rows]
    fails = []
    if np.any(d[:6] != 0.0):
        fails.append("Damage is not 0 up to step 5 (max %g)" % d[:6].max())
    if not d[6].max() > 0.0:
        fails.append("no bond broke at step 6")
    if not r[6] < r[5]:
        fails.append("the reaction did not drop at step 6 (%g N after %g N)" % (r[6], r[5]))
    if np.any(np.diff(d, axis=0) < 0.0):
        fails.append("Damage decreased somewhere (bonds healed)")
    print("reactions [N]:", ", ".join("%.0f" % x for x in r))
    print("mean Damage per step:", ", ".join("%.4f" % x for x in d.mean(axis=1)))
    for f in fails:
        print("FAIL:", f)
    print("check_bar_damage: " + ("FAIL" if fails else "PASS"))
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Checks Number_Of_Neighbors of bond_filter_{grid,text}.e against a count made here with exact rational
arithmetic: j is a neighbour of i if |x_j - x_i| <= 2.01 and the segment x_i -> x_j crosses neither filter of
the decks by Peridigm's rules (BondFilter.cxx): the meeting parameter t in [0, 1]; the rectangle y = 3,
0 <= x <= 3, -1 <= z <= 4 with closed edges; the disk in y = 1 about (4.5, 1.5) (x, z), radius 1, open rim.
usage: check_bond_filter.py RUN.e"""
import os
import sys
from fractions import Fraction as F

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element  # noqa: E402


def crossing(p, q, plane_y):
    """The point where segment p -> q meets y = plane_y, or None (parallel or outside t in [0, 1])."""
    if q[1] == p[1]:
        return None
    t = (plane_y - p[1]) / (q[1] - p[1])
    if t < 0 or t > 1:
        return None
    return [p[k] + t * (q[k] - p[k]) for k in range(3)]


def cut(p, q):
    x = crossing(p, q, F(3))
    if x is not None and 0 <= x[0] <= 3 and -1 <= x[2] <= 4:
        return True
    x = crossing(p, q, F(1))
    return x is not None and (x[0] - F(9, 2)) ** 2 + (x[2] - F(3, 2)) ** 2 < 1


d = netCDF4.Dataset(sys.argv[1])
xyz = np.stack([np.asarray(d[c][:]) for c in ("coordx", "coordy", "coordz")], axis=1)
pts = [[F(v).limit_denominator(2) for v in row] for row in xyz]  # lattice coordinates are halves
got = element(d, "Number_Of_Neighbors")[0]
h2 = F(201, 100) ** 2
ok, cuts = True, 0
for i, p in enumerate(pts):
    near = [q for k, q in enumerate(pts) if k != i and sum((q[a] - p[a]) ** 2 for a in range(3)) <= h2]
    kept = [q for q in near if not cut(p, q)]
    cuts += len(near) - len(kept)
    if got[i] != len(kept):
        print("point", i + 1, "at", [float(v) for v in p], "Number_Of_Neighbors", got[i], "expected", len(kept))
        ok = False
# The filters must cut something for the comparison to test them: both edge cases occur on this lattice.
ok = ok and cuts > 0
print("check_bond_filter: %d bonds cut; %s" % (cuts, "PASS" if ok else "FAIL"))
sys.exit(0 if ok else 1)

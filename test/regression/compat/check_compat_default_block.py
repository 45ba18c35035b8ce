#!/usr/bin/env python3
"""Checks compat_default_block.e: the "default" group took block_1 (horizon 1.5), block_3 kept its own
(2.5); Horizon is the node's block horizon and Number_Of_Neighbors counts the points within it, by hand:
1 2 2 | 4 3 2. usage: check_compat_default_block.py RUN.e"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element  # noqa: E402


d = netCDF4.Dataset(sys.argv[1])
ids = list(np.asarray(d["eb_prop1"][:]))
ok = True
if ids != [1, 3]:
    print("element blocks", ids, "expected [1, 3]"); ok = False
got = {}
for k, b in enumerate(ids):
    ev = lambda n: element(d, n, k + 1)[0]
    for i, h, nn in zip(ev("ID"), ev("Horizon"), ev("Number_Of_Neighbors")):
        got[int(i)] = (h, nn)
want = {1: (1.5, 1), 2: (1.5, 2), 3: (1.5, 2), 4: (2.5, 4), 5: (2.5, 3), 6: (2.5, 2)}
for i, (h, nn) in want.items():
    if i not in got or abs(got[i][0] - h) > 1e-15 or got[i][1] != nn:
        print("node", i, "Horizon, Number_Of_Neighbors =", got.get(i), "expected", (h, nn)); ok = False
print("compat_default_block: PASS" if ok else "compat_default_block: FAIL")
sys.exit(0 if ok else 1)

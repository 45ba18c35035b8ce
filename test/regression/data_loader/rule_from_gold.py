#!/usr/bin/env python3
"""Which time rule Peridigm's Data Loader follows, read from its suite case alone (no Periforge run): the largest
difference between the gold's Fluid_Concentration and the data file's values by three rules (linear interpolation
between the two file times around each gold time, the previous file time, the nearest one), against the .comp's
tolerance 9.66e-7. Quoted in docs/peridigm.md.

usage: rule_from_gold.py [SUITE_CASE_DIR]   (default ../shared/reference/peridigm-suite/Notched_Plate_Data_Loader)
"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402
from periforge_py import exodus  # noqa: E402

root = os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../..")
case = sys.argv[1] if len(sys.argv) > 1 else os.path.join(root, "../shared/reference/peridigm-suite/Notched_Plate_Data_Loader")
data = netCDF4.Dataset(os.path.join(case, "Notched_Plate_Data_Loader_Meshfree_Fluid_Concentration.e"))
gold = netCDF4.Dataset(os.path.join(case, "Notched_Plate_Data_Loader_gold.e"))
times, values = data["time_whole"][:], exodus.nodal(data, "Fluid_Concentration")
want = exodus.nodal(gold, "Fluid_Concentration")
worst = {"linear": 0.0, "previous": 0.0, "nearest": 0.0}
for j, t in enumerate(gold["time_whole"][:]):
    i = min(max(0, int(np.searchsorted(times, t, side="right")) - 1), len(times) - 2)
    c = (t - times[i]) / (times[i + 1] - times[i])
    by = {"linear": (1 - c) * values[i] + c * values[i + 1], "previous": values[i],
          "nearest": values[i if c < 0.5 else i + 1]}
    for k, v in by.items():
        worst[k] = max(worst[k], float(np.abs(v - want[j]).max()))
for k, v in worst.items():
    print("%-9s max |difference| %.3g" % (k, v))

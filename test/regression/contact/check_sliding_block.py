#!/usr/bin/env python3
"""Checks the sliding block (examples/contact/sliding_block.xml): a block pressed onto a held plate by a body force
of a = 1e5 m/s^2 per mass and sliding with Coulomb friction mu = 0.3 decelerates at mu a (issue 34: within 1 %).
The deceleration is the slope of a straight line fitted to the block's mean velocity (the history's summed
velocity over its 48 points of equal mass) over the run, while it still slides; the contact force the history
writes gives the friction-to-support ratio, mu for every pair, which the tilted pairs' normal forces spread by a
few percent from step to step.

usage: check_sliding_block.py RUN_DIR
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402

MU, ACCEL, POINTS = 0.3, 1.0e5, 48


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(os.path.join(sys.argv[1], "sliding_block_history.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    v = np.array([float(r["Block_Velocity_SumX"]) for r in rows]) / POINTS
    fx = np.array([float(r["Contact_Force_On_block_1_From_block_2_X"]) for r in rows])
    fz = np.array([float(r["Contact_Force_On_block_1_From_block_2_Z"]) for r in rows])
    slope, _ = np.polyfit(t, v, 1)
    ratio = -slope / (MU * ACCEL)
    print("deceleration %.6g m/s^2 = %.6f mu a (bound: within 1e-2 of 1)" % (-slope, ratio))
    print("block speed %.4g -> %.4g m/s; support %.4g..%.4g N (load %.4g N); friction/support %.4f..%.4f" %
          (v[0], v[-1], fz.min(), fz.max(), POINTS * 7800.0 * 1e-9 * ACCEL, (-fx / fz).min(), (-fx / fz).max()))
    ok = abs(ratio - 1.0) < 1e-2 and v.min() > 0.0  # still sliding at the end: friction acts throughout
    if not ok:
        print("FAILED: the deceleration is not mu a within 1 %, or the block stopped")
        sys.exit(1)
    print("sliding block check passed")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Checks the Hertz example (examples/contact/hertz.xml): a rigid sphere (R = 20 mm) driven at 5 m/s into an elastic
steel block, force against indentation against Hertz's rigid sphere on a half-space,
  F = 4/3 E* sqrt(R_c) d^(3/2),  E* = E / (1 - nu^2),
R_c = R + r_c (the sphere's surface as the block's point centres meet it: one contact radius out), d the cap's
travel past the contact surface. Over the loading phase d in [0.4, 1] dx (contact patch radius sqrt(R d) from 2.9
to 4.5 dx; delta/dx = 3.015), F^(2/3) is a straight line in the travel; its slope gives Hertz's modulus
4/3 E* sqrt(R_c) and its zero the contact surface d0 past the first touch of the point centres (the penalty's
overlap and the cap's discreteness: 0.06 dx with the deck's spring; 0.05 dx with a spring 3 times as stiff).
Checks (issue 34: within 5 %): the fitted modulus within 5 % of Hertz's; d0 within [0, 0.1] dx; F within 5 % of
Hertz at d - d0 at every output of the loading phase. Prints F / Hertz with d counted from the first touch, too.

usage: check_hertz.py RUN_DIR
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402

DX, SPEED, R, RC, E, NU = 1.0e-3, 5.0, 20.0e-3, 0.5e-3, 200.0e9, 0.3


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    with open(os.path.join(sys.argv[1], "hertz_history.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    force = -np.array([float(r["Contact_Force_On_block_1_From_block_2_Z"]) for r in rows])  # the block's push back
    d = SPEED * t
    modulus = 4.0 / 3.0 * E / (1.0 - NU ** 2) * np.sqrt(R + RC)
    loading = (d >= 0.4 * DX) & (d <= 1.0 * DX + 1e-12)
    slope, intercept = np.polyfit(d[loading], force[loading] ** (2.0 / 3.0), 1)
    fitted = slope ** 1.5
    d0 = -intercept / slope
    ratio = force[loading] / (modulus * (d[loading] - d0) ** 1.5)
    raw = force[-1] / (modulus * d[-1] ** 1.5)
    print("fitted modulus / Hertz's: %.4f (bound: within 0.05 of 1)" % (fitted / modulus))
    print("contact surface past the first touch: d0 = %.4f dx (bound [0, 0.1])" % (d0 / DX))
    print("F / Hertz(d - d0) over d in [0.4, 1] dx: %.4f .. %.4f (bound: within 0.05 of 1)" % (ratio.min(), ratio.max()))
    print("F / Hertz(d) from the first touch at d = 1 dx: %.4f" % raw)
    ok = abs(fitted / modulus - 1.0) < 0.05 and 0.0 <= d0 <= 0.1 * DX and np.abs(ratio - 1.0).max() < 0.05
    if not ok:
        print("FAILED: not Hertz's force within 5 %")
        sys.exit(1)
    print("Hertz check passed")


if __name__ == "__main__":
    main()

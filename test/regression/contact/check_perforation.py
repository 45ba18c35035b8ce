#!/usr/bin/env python3
"""Checks the perforation example (examples/contact/perforation.xml): a steel sphere through a brittle plate.
- contact keeps the bodies apart: at every frame no sphere point comes closer to a plate point than half the
  contact radius (measured 0.97 r_c; the same deck without its Contact list gives 0.25 r_c over the same frames,
  the sphere passing through at its full speed);
- the sphere perforates the plate: at the end every sphere point is below the plate's bottom face and the sphere
  still moves down, slower than it came (it gave momentum to the plate);
- total momentum (all points) is conserved to round-off at every frame (the only forces are internal).

usage: check_perforation.py RUN_DIR
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
import netCDF4  # noqa: E402

from periforge_py.exodus import nodal  # noqa: E402

RC, V0, DX = 0.4e-3, 300.0, 0.5e-3
RHO_SPHERE, RHO_PLATE = 7700.0, 2200.0


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__)
    ds = netCDF4.Dataset(os.path.join(sys.argv[1], "perforation.e"))
    x = np.stack([np.asarray(ds[c][:], dtype=float) for c in ("coordx", "coordy", "coordz")], axis=1)
    u = np.stack([nodal(ds, "Displacement" + c) for c in "XYZ"], axis=2)
    v = np.stack([nodal(ds, "Velocity" + c) for c in "XYZ"], axis=2)
    sphere = x[:, 2] > 0.0
    mass = np.where(sphere, RHO_SPHERE, RHO_PLATE) * DX ** 3
    p0 = mass[sphere].sum() * V0
    failures = []
    closest, drift = np.inf, 0.0
    for k in range(u.shape[0]):
        y = x + u[k]
        ys, yp = y[sphere], y[~sphere]
        d2 = ((ys[:, None, :] - yp[None, :, :]) ** 2).sum(axis=2)
        closest = min(closest, float(np.sqrt(d2.min())))
        drift = max(drift, float(np.abs((mass[:, None] * v[k]).sum(axis=0)[2] + p0)) / p0)
    print("closest sphere-plate distance over the frames: %.3g m = %.3f r_c (bound > 0.5)" % (closest, closest / RC))
    if closest < 0.5 * RC:
        failures.append("the sphere came through the plate's points")
    # Round-off of sums over 6 680 points and 800 steps of the momentum scale: 1e-10 leaves room.
    print("momentum drift / initial momentum, worst frame: %.3g (bound 1e-10)" % drift)
    if drift > 1e-10:
        failures.append("momentum")
    ys = x[sphere] + u[-1][sphere]
    vz = float(v[-1][sphere, 2].mean())
    print("end: sphere's highest point z = %.3g m (plate bottom -2e-3), mean velocity %.4g m/s (came at %g)" %
          (ys[:, 2].max(), vz, -V0))
    if not (ys[:, 2].max() < -2.0e-3 and -V0 < vz < 0.0):
        failures.append("no perforation")
    if failures:
        print("FAILED: " + ", ".join(failures))
        sys.exit(1)
    print("perforation check passed")


if __name__ == "__main__":
    main()

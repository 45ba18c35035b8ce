#!/usr/bin/env python3
"""Checks the symmetric rod-on-rod Taylor impact (examples/contact/rod_on_rod_coarse.xml) against the same bar on
a rigid wall at twice the speed (examples/taylor_impact/taylor_coarse.xml), which symmetry makes the same problem
(issue 34): each bar's L_f/L0 within 1 % of the wall run's, the total momentum conserved to round-off at every
cloud frame, bar 1's momentum change equal to the impulse of the contact force the history writes, and the energy
balance (kinetic + stored elastic + dissipated + contact springs = initial kinetic) within 1 % at every step.

usage: check_rod_on_rod.py ROD_DIR WALL_DIR  (the run directories of the two decks)
"""
import csv
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np  # noqa: E402
import netCDF4  # noqa: E402

from periforge_py import exodus as exodus_fields  # noqa: E402

L0, RHO, V = 31.75e-3, 2700.0, 200.0  # V: each bar's speed, the wall run's


def nodal(ds, name, step):
    return np.asarray(exodus_fields.nodal(ds, name)[step], dtype=float)


def cloud(path):
    ds = netCDF4.Dataset(path)
    x = np.stack([np.asarray(ds[c][:], dtype=float) for c in ("coordx", "coordy", "coordz")], axis=1)
    return ds, x


def length_ratio(x, uz, bar):
    return 1.0 - (np.ptp(x[bar, 2]) - np.ptp(x[bar, 2] + uz[bar])) / L0


def globals_of(path):
    ds = netCDF4.Dataset(path)
    return {n: np.asarray(exodus_fields.global_variable(ds, n), dtype=float)
            for n in exodus_fields.variable_names(ds, "name_glo_var")}


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    rod, wall = sys.argv[1], sys.argv[2]
    failures = []

    def check(name, value, bound, ok):
        print("%-44s %.6g  (bound %s)" % (name, value, bound))
        if not ok:
            failures.append(name)

    ds, x = cloud(os.path.join(rod, "rod_on_rod_coarse.e"))
    dsw, xw = cloud(os.path.join(wall, "taylor_coarse.e"))
    ref = length_ratio(xw, nodal(dsw, "DisplacementZ", -1), np.ones(len(xw), bool))
    uz = nodal(ds, "DisplacementZ", -1)
    bars = (x[:, 2] > 0, x[:, 2] < 0)
    print("rigid wall L_f/L0 %.6f" % ref)
    for k, bar in enumerate(bars):
        r = length_ratio(x, uz, bar)
        # 1 %: the bound; the two runs differ by the penalty's overlap and the wall's kinematic stop.
        check("bar %d L_f/L0 relative to the wall run" % (k + 1), r / ref - 1.0, "1e-2", abs(r / ref - 1.0) < 1e-2)
    mass = RHO * (6.35e-3 / 8) ** 3  # every point's (the lattice's cell)
    scale = mass * len(x) / 2 * V  # one bar's initial momentum
    worst = max(abs(np.sum(nodal(ds, "VelocityZ", s))) * mass for s in range(len(ds["time_whole"])))
    # Round-off of sums of 4 160 terms of the scale: 1e-10 leaves room for the order of the ranks' sums.
    check("total z momentum / one bar's, worst frame", worst / scale, "1e-10", worst / scale < 1e-10)
    with open(os.path.join(rod, "rod_on_rod_coarse_history.csv")) as f:
        rows = list(csv.DictReader(f))
    t = np.array([float(r["time"]) for r in rows])
    fz = np.array([float(r["Contact_Force_On_block_1_From_block_2_Z"]) for r in rows])
    # Verlet's kick at step n uses the force of the positions of step n, which the row of step n writes.
    impulse = float(np.sum(fz[1:] * np.diff(t)))
    bar1 = bars[0]
    dp = mass * (np.sum(nodal(ds, "VelocityZ", -1)[bar1]) - np.sum(nodal(ds, "VelocityZ", 0)[bar1]))
    # The bar's velocities change by nothing but the contact's kicks, zero once the bars have parted: the two sums
    # differ by round-off over 1 200 steps (1e-9 leaves ample room; a force written at the wrong step gives 1e-2).
    check("bar 1: (dp - contact impulse) / dp", (dp - impulse) / dp, "1e-9", abs((dp - impulse) / dp) < 1e-9)
    g = globals_of(os.path.join(rod, "rod_on_rod_coarse_history.e"))
    terms = ("Global_Strain_Energy", "Global_Dissipated_Energy", "Global_Contact_Energy")
    ke = g["Global_Kinetic_Energy"]
    err = (ke + sum(g[n] for n in terms) - ke[0]) / ke[0]
    print("KE_0 %.6g J, contact energy max %.6g J, dissipated end %.6g J" %
          (ke[0], g["Global_Contact_Energy"].max(), g["Global_Dissipated_Energy"][-1]))
    check("energy balance error / KE_0, worst step", np.abs(err).max(), "1e-2", np.abs(err).max() < 1e-2)
    if failures:
        print("FAILED: " + ", ".join(failures))
        sys.exit(1)
    print("rod-on-rod check passed")


if __name__ == "__main__":
    main()

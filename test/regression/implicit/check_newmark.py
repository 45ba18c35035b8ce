#!/usr/bin/env python3
"""Checks Implicit (Newmark beta = 1/4, gamma = 1/2) runs against independent references.

  check_newmark.py sdof RUN.e DT TOL   the two-point oscillator (sdof_newmark*.xml)
  check_newmark.py bar RUN.e DT TOL    the free line bar (bar_line_newmark.xml): energy only
  check_newmark.py rigid RUN.e DT TOL  the rigidly driven line bar (rigid_bar_newmark.xml)
  check_newmark.py converge VERLET.e COARSE.e FINE.e   the 3D block (block_3d_*.xml) at its last step
  check_newmark.py plastic VERLET.e RUN.e              the yielding block (ep_block_3d_*.xml) at its last step

sdof: two points 2 apart along x, one bond (horizon 2, influence 1, V = 2 each), thrown together at v0 = 1.
By hand from the OSB elastic force state (t = 3 K theta / m x + 15 mu / m e^d, m = |xi|^2 V = 8,
theta = 3 / m |xi| e V = 1.5 e, e^d = e - theta |xi| / 3 = 0), each end's force density is -9 K d for an
end displacement d (e = -2 d), exactly linear since bond and motion are collinear: rho d'' = -9 K d,
omega^2 = 9 K / rho. The trapezoidal rule maps (omega d, v) by a rotation of theta = 2 atan(omega dt / 2)
(the Cayley transform of the exact rotation), so the run must give d_n = v0 / omega sin(n theta),
v_n = v0 cos(n theta), a_n = -omega^2 d_n: period T dt omega / theta, Newmark's elongation.
Both (sdof, bar): total energy sum(rho V v^2 / 2) + sum(Stored_Elastic_Energy) conserved.
rigid: body force rho (A + J t), one end prescribed to u = A t^2/2 + J t^3/6 + J t dt^2/12: the trapezoidal
rule's exact discrete answer for that acceleration (exact for the quadratic part; for a = J t each step's
displacement comes out J dt^3/12 above the cubic's). Every point must follow it, with v = A t + J t^2/2
(exact: the rule integrates a linear acceleration exactly) and no internal force.

Bounds, from the Newton test alone (no fitting): a step converges with |beta dt^2 (rho a - f)|_2 <= TOL,
i.e. it solves the step exactly for a force perturbed by r with |r|_2 <= TOL / (beta dt^2). That moves u by
at most TOL / rho, and v by gamma dt / (beta dt^2) = 2 / dt times that; the step map is a rotation in
(omega d, v), so the errors of N steps add: |d error| <= N TOL / rho sqrt(1 + 4 / (omega dt)^2),
|v error| <= N TOL / rho sqrt(omega^2 + 4 / dt^2). The energy changes by at most the work of r over the
step, |r V|_2 |u_n+1 - u_n|_2, summed. Each bound gets 1e-12 of the scale for rounding (a few hundred
ulps over the run).
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import netCDF4
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import element, nodal  # noqa: E402

K, RHO, V0, BETA, GAMMA = 130.0e9, 7800.0, 1.0, 0.25, 0.5
ROUND = 1e-12


def report(name, err, bound):
    ok = err <= bound
    print("%-34s %.3e  (bound %.3e)  %s" % (name, err, bound, "ok" if ok else "FAIL"))
    return ok


def energy_check(d, dt, tol):
    vol = element(d, "Volume")[0]
    u = nodal(d, "DisplacementX")
    v = nodal(d, "VelocityX")
    w = element(d, "Stored_Elastic_Energy")
    energy = 0.5 * RHO * (vol[None, :] * v * v).sum(axis=1) + w.sum(axis=1)
    du = np.linalg.norm(np.diff(u, axis=0), axis=1)
    work = np.concatenate([[0.0], np.cumsum(tol / (BETA * dt * dt) * vol.max() * du)])
    drift = np.abs(energy - energy[0])
    print("energy: E0 = %.6e J, max |E - E0| / E0 = %.3e over %d steps" % (energy[0], drift.max() / energy[0],
                                                                             len(energy) - 1))
    # work is non-decreasing: its last value bounds every step's drift.
    return report("max |E_n - E_0| [J]", drift.max(), work[-1] + ROUND * energy[0])


def sdof(d, dt, tol):
    omega = math.sqrt(9.0 * K / RHO)
    theta = 2.0 * math.atan(0.5 * omega * dt)
    x = np.asarray(d["coordx"][:])
    left = int(np.argmin(x))
    t = np.asarray(d["time_whole"][:])
    n = np.rint(t / dt)
    ok = report("times are n dt", np.abs(t - n * dt).max(), 1e-12 * t.max())
    ux, vx, ax = nodal(d, "DisplacementX"), nodal(d, "VelocityX"), nodal(d, "AccelerationX")
    amp = V0 / omega
    steps = len(t) - 1
    du = steps * tol / RHO * math.sqrt(1.0 + 4.0 / (omega * dt) ** 2)
    dv = steps * tol / RHO * math.sqrt(omega ** 2 + 4.0 / dt ** 2)
    ok &= report("d_n vs v0/omega sin(n theta) [m]", np.abs(ux[:, left] - amp * np.sin(n * theta)).max(),
                 du + ROUND * amp)
    ok &= report("v_n vs v0 cos(n theta) [m/s]", np.abs(vx[:, left] - V0 * np.cos(n * theta)).max(), dv + ROUND * V0)
    # a = (f + b) / rho: exact within the residual force |r| / rho beyond the displacement error.
    ok &= report("a_n vs -omega^2 d_n [m/s^2]", np.abs(ax[:, left] + omega ** 2 * amp * np.sin(n * theta)).max(),
                 omega ** 2 * du + tol / (BETA * dt * dt) / RHO + ROUND * omega * V0)
    ok &= report("ends move symmetrically [m]", np.abs(ux.sum(axis=1)).max(), du + ROUND * amp)
    # The discrete period from the run alone: d_n+1 + d_n-1 = 2 cos(theta) d_n, fitted by least squares.
    dn = ux[:, left]
    c = (dn[1:-1] * (dn[2:] + dn[:-2])).sum() / (2.0 * (dn[1:-1] ** 2).sum())
    elongation = omega * dt / math.acos(c)
    expected = omega * dt / theta
    print("omega dt = %.4f: period / (2 pi / omega) = %.8f, Newmark's omega dt / (2 atan(omega dt / 2)) = %.8f"
          % (omega * dt, elongation, expected))
    # The fitted phase inherits the displacement error relative to the amplitude.
    ok &= report("period elongation vs formula", abs(elongation - expected) / expected, 10 * (du / amp + ROUND))
    return ok & energy_check(d, dt, tol)


def rigid(d, dt, tol):
    acc, jerk = 1.0e3, 1.0e8
    t = np.asarray(d["time_whole"][:])[:, None]
    ux, vx, fx = nodal(d, "DisplacementX"), nodal(d, "VelocityX"), nodal(d, "Force_DensityX")
    steps = len(t) - 1
    u = acc * t * t / 2 + jerk * t ** 3 / 6 + jerk * t * dt * dt / 12
    v = acc * t + jerk * t * t / 2
    # A converged step is off by at most TOL / rho in u and 2 / dt times that in v; with no stiffness a v error
    # carries into every later u, so N steps give at most N (1 + 2 N) TOL / rho in u.
    du = steps * (1 + 2 * steps) * tol / RHO
    ok = report("u vs A t^2/2 + J t^3/6 + J t dt^2/12 [m]", np.abs(ux - u).max(), du + ROUND * np.abs(u).max())
    # The driven point (smallest x) reports the step's mean rate (u_n+1 - u_n) / dt, as Verlet does.
    x = np.asarray(d["coordx"][:])
    free = x > x.min()
    ok &= report("free v vs A t + J t^2/2 [m/s]", np.abs(vx[:, free] - v).max(),
                 steps * 2.0 / dt * tol / RHO + ROUND * np.abs(v).max())
    rate = np.diff(u[:, 0]) / dt
    ok &= report("driven v vs (u_n+1 - u_n) / dt [m/s]", np.abs(vx[1:, ~free][:, 0] - rate).max(),
                 ROUND * np.abs(v).max() + 4 * np.finfo(float).eps * np.abs(u).max() / dt)
    # Internal force of the residual relative motion: stiffness ~ 9 K per unit relative displacement (sdof).
    ok &= report("internal force density [N/m^3]", np.abs(fx).max(), 9 * K * (2 * du + ROUND * np.abs(u).max()))
    return ok


def last_state(path):
    """Time, and displacement and velocity at the last step, nodes sorted by coordinates (any rank count)."""
    d = netCDF4.Dataset(path)
    x = np.stack([np.asarray(d[c][:]) for c in ("coordx", "coordy", "coordz")], axis=1)
    order = np.lexsort(x.T[::-1])
    u = np.stack([nodal(d, "Displacement" + c)[-1] for c in "XYZ"], axis=1)[order]
    v = np.stack([nodal(d, "Velocity" + c)[-1] for c in "XYZ"], axis=1)[order]
    return float(d["time_whole"][-1]), u, v


def converge(verlet, coarse, fine):
    """A nonlinear 3D body (geometric nonlinearity, 128 points, every bond direction): Newmark at dt and dt/2
    against Verlet at dt/10. The trapezoidal rule is second order, so halving dt must cut the displacement
    error by 4; higher-order terms and Verlet's own error (measured 1.8 % of the fine run's, from Verlet at
    dt/20) move the ratio, bound to 4 +- 10 %. The fine run's error must also be below 1 % of the motion: the
    rule's phase error after time t at the axial mode (omega = 2 pi / 3.2 us from c = sqrt(E / rho), 2 L / c)
    is about omega t (omega dt)^2 / 12 = 0.66 %. Velocities (more high-mode content) are reported only."""
    tv, uv, vv = last_state(verlet)
    tc, uc, vc = last_state(coarse)
    tf, uf, vf = last_state(fine)
    ok = report("same end time [s]", max(abs(tc - tv), abs(tf - tv)), 1e-12 * tv)
    ec, ef = np.linalg.norm(uc - uv), np.linalg.norm(uf - uv)
    print("|u - u_Verlet| / |u|: dt %.3e, dt/2 %.3e; velocity: %.3e, %.3e (ratio %.2f)" % (
        ec / np.linalg.norm(uv), ef / np.linalg.norm(uv), np.linalg.norm(vc - vv) / np.linalg.norm(vv),
        np.linalg.norm(vf - vv) / np.linalg.norm(vv), np.linalg.norm(vc - vv) / np.linalg.norm(vf - vv)))
    ok &= report("|4 - error ratio| (second order)", abs(ec / ef - 4.0), 0.4)
    ok &= report("fine run's relative error", ef / np.linalg.norm(uv), 0.01)
    return ok


def plastic(verlet, run):
    """The yielding block: Implicit at dt = 5e-8 s against Verlet at 1e-8 s, displacement and equivalent plastic
    strain within 1 % (measured 0.28 % and 0.32 %; halving dt from 1e-7 s cuts them by 2.9). The elastic block's
    Newmark error at this dt is 0.39 %; yielding adds no integration error of its own but the timing of the
    yield events. A step that does not commit the material state fails it by far (mutation run by hand: no
    plastic strain in the output, displacement 17 % off)."""
    _, uv, _ = last_state(verlet)
    _, ur, _ = last_state(run)
    ev, er = (last_field(f, "Equivalent_Plastic_Strain") for f in (verlet, run))
    print("max equivalent plastic strain %.3e (Verlet) %.3e (Implicit)" % (ev.max(), er.max()))
    ok = report("displacement |u - u_Verlet| / |u|", np.linalg.norm(ur - uv) / np.linalg.norm(uv), 0.01)
    ok &= report("plastic strain |e - e_Verlet| / |e|", np.linalg.norm(er - ev) / np.linalg.norm(ev), 0.01)
    return ok


def last_field(path, name):
    """A scalar (element or nodal) variable at the last step, nodes sorted by coordinates."""
    d = netCDF4.Dataset(path)
    x = np.stack([np.asarray(d[c][:]) for c in ("coordx", "coordy", "coordz")], axis=1)
    try:
        values = element(d, name)[-1]
    except ValueError:
        values = nodal(d, name)[-1]
    return values[np.lexsort(x.T[::-1])]


def main():
    if len(sys.argv) == 4 and sys.argv[1] == "plastic":
        ok = plastic(*sys.argv[2:4])
        print("PASS" if ok else "FAIL")
        sys.exit(0 if ok else 1)
    if len(sys.argv) == 5 and sys.argv[1] == "converge":
        ok = converge(*sys.argv[2:5])
        print("PASS" if ok else "FAIL")
        sys.exit(0 if ok else 1)
    if len(sys.argv) != 5 or sys.argv[1] not in ("sdof", "bar", "rigid"):
        sys.exit(__doc__)
    d = netCDF4.Dataset(sys.argv[2])
    dt, tol = float(sys.argv[3]), float(sys.argv[4])
    ok = {"sdof": sdof, "bar": energy_check, "rigid": rigid}[sys.argv[1]](d, dt, tol)
    print("PASS" if ok else "FAIL")
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()

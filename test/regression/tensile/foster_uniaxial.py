#!/usr/bin/env python3
"""Independent reference for examples/tensile_8300: Foster, Silling & Chen (2010)'s viscoplastic law integrated
classically under homogeneous uniaxial stress at a constant engineering strain rate (no peridynamics).

Law (the paper's Eqs. 58-59): g = Y (1 + eps_p/eps_0)^(1/n), G = g (1 + epsdot_p/epsdot_0)^(1/m); von Mises yield
|S| = sqrt(2/3) G with radial return (Eq. 50); hypoelastic Cauchy stress rate on the rate of deformation.
Under uniaxial stress sigma (lateral stresses zero) the deviator is sqrt(2/3) sigma along the fixed direction
diag(-1, -1, 2)/sqrt(6), so the radial return is exact along one line and the 3D update collapses to the
classical one-dimensional return: sigma_tr = sigma_n + E d_eps, and if sigma_tr > g(eps_p_n) the plastic
increment dp (= sqrt(2/3) dlambda, also the axial plastic strain increment) is the root of
    sigma_tr - E dp - Y (1 + eps_p_n/eps_0)^(1/n) (1 + dp/(dt epsdot_0))^(1/m) = 0          (Eq. 60's form)
bracketed by [0, (sigma_tr - g)/E] (positive at 0, non-positive at the rate-independent return) and solved by
Brent's method (scipy.optimize.brentq, to 1e-15 relative). The hardening uses eps_p at the step's start and the
rate is implicit, as Eq. 60 writes it.
Kinematics: the axial stretch lambda(t) = 1 + rate t (constant engineering rate, the paper's loading); the
axial rate of deformation is lambdadot/lambda, so each step's strain increment is ln(lambda_{k+1}/lambda_k)
(exact). Green-Lagrange strain E_zz = (lambda^2 - 1)/2; true stress = sigma.
"""
import math

import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from scipy.optimize import brentq

E_MOD, NU = 68.9e9, 0.333
Y, N_EXP, M_EXP, EPS0, RATE0 = 276.0e6, 13.5, 44.0, 0.001, 1000.0


def flow(eps_p, dp, dt):
    return Y * (1.0 + eps_p / EPS0) ** (1.0 / N_EXP) * (1.0 + dp / (dt * RATE0)) ** (1.0 / M_EXP)


def uniaxial(rate=8300.0, strain=0.25, steps=20000):
    """Returns arrays (t, E_green, sigma, eps_p, eps_p_rate) at steps + 1 times."""
    t_end = strain / rate
    dt = t_end / steps
    t = np.linspace(0.0, t_end, steps + 1)
    lam = 1.0 + rate * t
    sig = np.zeros(steps + 1)
    ep = np.zeros(steps + 1)
    epr = np.zeros(steps + 1)
    for k in range(steps):
        d = math.log(lam[k + 1] / lam[k])
        trial = sig[k] + E_MOD * d
        g = flow(ep[k], 0.0, dt)
        if trial <= g:
            sig[k + 1], ep[k + 1], epr[k + 1] = trial, ep[k], 0.0
            continue
        hi = (trial - g) / E_MOD
        dp = brentq(lambda x: trial - E_MOD * x - flow(ep[k], x, dt), 0.0, hi, xtol=1e-300, rtol=1e-15,
                    maxiter=200)
        sig[k + 1] = trial - E_MOD * dp
        ep[k + 1] = ep[k] + dp
        epr[k + 1] = dp / dt
    return t, 0.5 * (lam ** 2 - 1.0), sig, ep, epr


def considere(t, e_green, sig, rate):
    """Green strain of the load maximum: the nominal force sigma A0 / lambda (volume-preserving plastic flow)
    is largest there; past it a neck can grow (Considere's criterion)."""
    lam = 1.0 + rate * t
    k = int(np.argmax(sig / lam))
    return e_green[k], k


if __name__ == "__main__":
    import sys
    t, eg, s, ep, epr = uniaxial()
    ec, k = considere(t, eg, s, 8300.0)
    for target in (0.01, 0.02, 0.05, 0.1, 0.15, 0.2, 0.25):
        i = int(np.searchsorted(eg, target))
        print("E_zz %.3f  sigma %.2f MPa  eps_p %.4f  rate %.0f 1/s" % (eg[i], s[i] / 1e6, ep[i], epr[i]))
    print("load maximum (Considere) at E_zz %.4f, sigma %.2f MPa" % (ec, s[k] / 1e6))
    sys.exit(0)

"""Classical reference for the hardening cylinder (issue 16): a thick-walled cylinder under internal pressure,
plane strain (eps_z = 0), solved in 1D by axisymmetric finite elements with small-strain J2 plasticity and
linear isotropic (K) and Prager kinematic (H) hardening, radial return (Simo & Hughes, Box 3.2) and its
consistent tangent. Written here, independently of src/, as the reference the peridynamic runs are judged
against; its own convergence and the Lame / Hill closed forms are checked by self_check().

Stress and strain are principal triples (rr, tt, zz): the problem has no shear. Uniaxially, the flow stress
is sigma_y + (K + H) eps_p, as Periforge's `Isotropic/Kinematic Hardening Modulus` mean it."""
import math

import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np

GAUSS = (0.5 - 0.5 / math.sqrt(3.0), 0.5 + 0.5 / math.sqrt(3.0))
ONE = np.array([1.0, 1.0, 1.0])
I_DEV = np.eye(3) - np.outer(ONE, ONE) / 3.0


class RadialJ2:
    def __init__(self, a, b, E, nu, sigma_y, K=0.0, H=0.0, elements=400):
        self.a, self.b = a, b
        self.mu, self.kappa = E / (2 * (1 + nu)), E / (3 * (1 - 2 * nu))
        self.sigma_y, self.K, self.H = sigma_y, K, H
        # Elements graded towards the bore, where the gradients are.
        s = np.linspace(0.0, 1.0, elements + 1)
        self.r = a + (b - a) * s ** 1.5
        ne = elements
        self.gp_r = np.array([[self.r[e] + g * (self.r[e + 1] - self.r[e]) for g in GAUSS] for e in range(ne)])
        shape = (ne, 2)
        self.eps_p = np.zeros(shape + (3,))
        self.back = np.zeros(shape + (3,))
        self.alpha = np.zeros(shape)
        self.u = np.zeros(ne + 1)
        self.sigma = np.zeros(shape + (3,))

    def _material(self, eps, eps_p, back, alpha):
        """Radial return at every Gauss point; returns stress, tangent and the updated state."""
        mu, kappa = self.mu, self.kappa
        ee = eps - eps_p
        tr = ee.sum(-1, keepdims=True)
        s_tr = 2 * mu * (ee - tr / 3.0)
        xi = s_tr - back
        norm = np.linalg.norm(xi, axis=-1)
        f = math.sqrt(1.5) * norm - (self.sigma_y + self.K * alpha)
        # A point on the surface at the start of a step is elastic unless the trial state is clearly outside:
        # round-off plasticity would hand an unloading step the soft elastoplastic tangent and diverge.
        dgam = np.where(f > 1e-10 * self.sigma_y, f / (3 * mu + self.K + self.H), 0.0)
        n = xi / np.maximum(norm, 1e-300)[..., None]
        deps_p = math.sqrt(1.5) * dgam[..., None] * n
        eps_p2 = eps_p + deps_p
        back2 = back + (2.0 / 3.0) * self.H * deps_p
        alpha2 = alpha + dgam
        sig = kappa * tr + 2 * mu * (eps - eps_p2 - tr / 3.0)
        theta = 1.0 - 2 * mu * math.sqrt(1.5) * dgam / np.maximum(norm, 1e-300)
        thetab = 1.0 / (1.0 + (self.K + self.H) / (3 * mu)) - (1.0 - theta)
        C = (kappa * np.outer(ONE, ONE) + 2 * mu * theta[..., None, None] * I_DEV
             - 2 * mu * np.where(dgam > 0, thetab, 0.0)[..., None, None] * n[..., :, None] * n[..., None, :])
        return sig, C, eps_p2, back2, alpha2

    def _strains(self, u):
        r0, r1 = self.r[:-1], self.r[1:]
        h = r1 - r0
        eps = np.zeros(self.gp_r.shape + (3,))
        B = np.zeros(self.gp_r.shape + (3, 2))
        for g, xi in enumerate(GAUSS):
            rg = self.gp_r[:, g]
            N = np.stack([(1 - xi) * np.ones_like(h), xi * np.ones_like(h)], -1)
            dN = np.stack([-1 / h, 1 / h], -1)
            B[:, g, 0, :] = dN
            B[:, g, 1, :] = N / rg[:, None]
            eps[:, g, :] = np.einsum("eij,ej->ei", B[:, g], np.stack([u[:-1], u[1:]], -1))
        return eps, B

    def solve(self, p):
        """Equilibrium at bore pressure p from the committed state; commits it. Returns u(a)."""
        u = self.u.copy()
        w = 0.5 * (self.r[1:] - self.r[:-1])
        ndof = len(u)
        for it in range(50):
            eps, B = self._strains(u)
            sig, C, ep, bk, al = self._material(eps, self.eps_p, self.back, self.alpha)
            R = np.zeros(ndof)
            R[0] += p * self.a
            Kt = np.zeros((ndof, ndof))
            for g in range(2):
                wr = (w * self.gp_r[:, g])[:, None]
                fe = -np.einsum("eij,ei->ej", B[:, g], sig[:, g]) * wr
                ke = np.einsum("eki,ekl,elj->eij", B[:, g], C[:, g], B[:, g]) * wr[..., None]
                for A in range(2):
                    np.add.at(R, np.arange(A, ndof - 1 + A), fe[:, A])
                    for Bn in range(2):
                        Kt[np.arange(A, ndof - 1 + A), np.arange(Bn, ndof - 1 + Bn)] += ke[:, A, Bn]
            if np.abs(R).max() <= 1e-10 * self.sigma_y * self.a:  # force per radian, 1e-10 of the yield scale
                break
            u += np.linalg.solve(Kt, R)
        else:
            raise RuntimeError(f"radial J2: no equilibrium at p = {p}")
        self.u, self.eps_p, self.back, self.alpha, self.sigma = u, ep, bk, al, sig
        return u[0]

    def bore_stress(self):
        """(sigma_rr, sigma_tt, sigma_zz) at r = a, extrapolated linearly from the first element's Gauss points."""
        r0, s0, s1 = self.a, self.sigma[0, 0], self.sigma[0, 1]
        g0, g1 = self.gp_r[0]
        return s0 + (s1 - s0) * (r0 - g0) / (g1 - g0)


def von_mises(s):
    return math.sqrt(0.5 * ((s[0] - s[1]) ** 2 + (s[1] - s[2]) ** 2 + (s[2] - s[0]) ** 2))


def self_check():
    """The reference against closed forms: Lame (elastic) and Hill's limit pressure (perfect plasticity)."""
    a, b, E, nu, sy = 0.01, 0.02, 200e9, 0.3, 200e6
    m = RadialJ2(a, b, E, nu, sy)
    p = 50e6
    u = m.solve(p)
    lame = p * a * a / (b * b - a * a) * (1 + nu) / E * ((1 - 2 * nu) * a + b * b / a)
    assert abs(u / lame - 1) < 1e-4, (u, lame)
    m = RadialJ2(a, b, E, nu, sy)
    p_l = 2 / math.sqrt(3) * sy * math.log(b / a)
    for f in np.linspace(0.5, 0.99, 15):
        m.solve(f * p_l)
    try:
        m.solve(1.01 * p_l)
        raise AssertionError("radial J2 carried 1.01 p_L")
    except (RuntimeError, np.linalg.LinAlgError):
        pass
    return True


if __name__ == "__main__":
    print("self check:", self_check())

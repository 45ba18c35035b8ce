#!/usr/bin/env python3
"""Checks a bar in uniaxial stress loaded past yield and back (plastic_bar_*.xml) against the 1D
elastoplastic closed form with linear isotropic (K) and kinematic (H) hardening.

Reference (written here, not taken from Periforge): uniaxial stress of J2 with linear hardening is the 1D
model  f = |sigma - q| - (sigma_y + K alpha),  d eps_p = dg sign,  d alpha = dg,  dq = H dg sign, whose
backward-Euler step is exact for a linear law: dg = f_trial / (E + K + H). It gives sigma(eps) at every
load step and the step in which the reversed load first yields again (kinematic: after an elastic range
of 2 sigma_y, the Bauschinger effect; isotropic: 2 (sigma_y + K alpha_peak)).

Measured from the run (history CSV):
  - the interior: strain between probes Q1 and Q3 on the axis (GAUGE apart), signed von Mises stress and
    equivalent plastic strain of the probe Mid at the bar's centre;
  - the reaction on the right layer, F_x.
Checks (each bound and its reason is in test/regression/plastic_bar.cmake, which passes them):
  1. interior stress: |svm_Mid - sigma_1D(eps_interior)| <= --stress-tol * sigma_y at every step, and in
     the elastic steps svm_Mid / (E eps_interior) within --stiffness-tol of 1;
  2. interior plastic strain at the peak and at the end within --alpha-tol of the closed form's;
  3. reverse yield of the interior point (first step after the peak in which alpha_Mid grows) and of the
     reaction (first step after the peak whose |dF| falls below 90 % of the first unloading step's) each
     within --yield-steps load steps of the closed form's;
  4. reaction: F / (A sigma_1D(eps)) within [--reaction-min, --reaction-max] at every step where
     |sigma_1D| > sigma_y / 2 (the bar's free lateral surfaces carry more than the interior: the OSB
     surface effect, uncorrected as in the paper);
  5. the reaction's hardening slope on the first loading branch (steps after yield up to the peak) within
     --slope-tol of A E (K + H)/(E + K + H).
Exit 0 when every check passes, 1 otherwise, 2 on a usage or file error.
"""
import argparse
import csv
import sys


def closed_form(strains, E, sy, K, H):
    """1D return mapping along the strain path: stress, alpha and 'yielded in this step' per step."""
    ep = alpha = q = 0.0
    out = []
    for eps in strains:
        s_tr = E * (eps - ep)
        xi = s_tr - q
        f = abs(xi) - (sy + K * alpha)
        dg = f / (E + K + H) if f > 0 else 0.0
        sgn = 1.0 if xi >= 0 else -1.0
        ep += dg * sgn
        alpha += dg
        q += H * dg * sgn
        out.append((s_tr - E * dg * sgn, alpha, dg > 0))
    return out


def first_after(flags, start):
    for k in range(start + 1, len(flags)):
        if flags[k]:
            return k
    return None


def main(argv):
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("csv")
    p.add_argument("--area", type=float, required=True, help="cross-section (3D) or width x thickness (2D)")
    p.add_argument("--E", type=float, required=True, help="uniaxial-stress modulus: E in 3D and plane stress")
    p.add_argument("--sy", type=float, required=True)
    p.add_argument("--K", type=float, required=True)
    p.add_argument("--H", type=float, required=True)
    p.add_argument("--rate", type=float, required=True, help="applied strain per unit t on the loading branch")
    p.add_argument("--peak", type=float, required=True, help="t of the reversal")
    p.add_argument("--gauge", type=float, required=True, help="distance between probes Q1 and Q3 [m]")
    p.add_argument("--stress-tol", type=float, required=True)
    p.add_argument("--alpha-tol", type=float, required=True)
    p.add_argument("--stiffness-tol", type=float, default=0.01)
    p.add_argument("--yield-steps", type=int, default=1)
    p.add_argument("--reaction-min", type=float, required=True)
    p.add_argument("--reaction-max", type=float, required=True)
    p.add_argument("--slope-tol", type=float, required=True)
    a = p.parse_args(argv)
    try:
        rows = [r for r in csv.DictReader(open(a.csv)) if float(r["step"]) > 0]
        t = [float(r["time"]) for r in rows]
        F = [float(r["Reaction_Right_X"]) for r in rows]
        eps_int = [(float(r["Probe_Q3_DisplacementX"]) - float(r["Probe_Q1_DisplacementX"])) / a.gauge for r in rows]
        svm = [float(r["Probe_Mid_Signed_Von_Mises_Stress"]) for r in rows]
        alpha = [float(r["Probe_Mid_Equivalent_Plastic_Strain"]) for r in rows]
    except (OSError, KeyError, ValueError) as e:
        sys.stderr.write("check_plastic_bar: error: %s\n" % e)
        return 2
    return 0 if checks(a, t, F, eps_int, svm, alpha) else 1


def checks(a, t, F, eps_int, svm, alpha):
    """Runs checks 1-5, prints one line each; True when all pass."""
    applied = [a.rate * (ti if ti <= a.peak else 2 * a.peak - ti) for ti in t]
    ref = closed_form(applied, a.E, a.sy, a.K, a.H)          # the bar as loaded
    ref_int = closed_form(eps_int, a.E, a.sy, a.K, a.H)      # the interior as strained
    ipeak = max(k for k, ti in enumerate(t) if ti <= a.peak + 1e-9)
    ok = True

    def report(name, passed, text):
        nonlocal ok
        ok &= passed
        print("%-44s %s  %s" % (name, "pass" if passed else "FAIL", text))

    # 1. interior stress against the closed form at the interior strain
    d = [abs(s - r[0]) / a.sy for s, r in zip(svm, ref_int)]
    k = max(range(len(d)), key=d.__getitem__)
    report("interior stress vs sigma_1D", d[k] <= a.stress_tol,
           "max %.3f %% of sigma_y at step %d (%.1f vs %.1f MPa); bound %.2f %%"
           % (100 * d[k], k + 1, svm[k] / 1e6, ref_int[k][0] / 1e6, 100 * a.stress_tol))
    # 1b. interior elastic stiffness: the steps before the closed form first yields
    el = [k for k in range(ipeak) if not ref_int[k][1] > 0]
    st = [svm[k] / (a.E * eps_int[k]) - 1 for k in el]
    kk = max(range(len(st)), key=lambda i: abs(st[i]))
    report("interior elastic stiffness", abs(st[kk]) <= a.stiffness_tol,
           "svm_Mid / (E eps_interior) - 1 up to %+.3f %% (step %d, %d elastic steps); bound %.1f %%"
           % (100 * st[kk], el[kk] + 1, len(el), 100 * a.stiffness_tol))
    # 2. interior plastic strain at the peak and at the end
    for k in (ipeak, len(t) - 1):
        e = abs(alpha[k] - ref_int[k][1]) / ref_int[k][1]
        report("interior alpha at step %d" % (k + 1), e <= a.alpha_tol,
               "%.4e vs %.4e (%+.2f %%); bound %.1f %%" % (alpha[k], ref_int[k][1], 100 * (alpha[k] / ref_int[k][1] - 1),
                                                          100 * a.alpha_tol))
    # 3. reverse yield: closed form, interior point, reaction
    ky = first_after([r[2] for r in ref], ipeak)
    ky_int = first_after([alpha[k] > alpha[k - 1] for k in range(len(alpha))], ipeak)
    dF0 = abs(F[ipeak + 1] - F[ipeak])
    ky_F = first_after([k > ipeak + 1 and abs(F[k] - F[k - 1]) < 0.9 * dF0 for k in range(len(F))], ipeak)
    if ky is None:
        report("reverse yield", False, "the closed form does not yield again on this path")
    else:
        # where the closed form's reversed stress reaches the yield level: eps_peak - elastic range / E
        s_pk, a_pk = ref[ipeak][0], ref[ipeak][1]
        rng = 2 * a.sy + 2 * a.K * a_pk  # q and the isotropic growth: |s_pk - q| = sy + K a_pk on both sides
        print("closed form: peak stress %.1f MPa, elastic range on reversal %.1f MPa, reverse yield at eps = "
              "%.4e (t = %.3f, in step %d)" % (s_pk / 1e6, rng / 1e6, applied[ipeak] - rng / a.E,
                                              a.peak + rng / a.E / a.rate, ky + 1))
        for name, kk in (("reverse yield, interior point", ky_int), ("reverse yield, reaction slope < 90 %", ky_F)):
            report(name, kk is not None and abs(kk - ky) <= a.yield_steps,
                   "step %s vs closed form %d; bound %d step(s)" % (kk + 1 if kk is not None else "none", ky + 1,
                                                                     a.yield_steps))
    # 4. reaction over the closed form's force
    ratios = [(f / (a.area * r[0]), k) for k, (f, r) in enumerate(zip(F, ref)) if abs(r[0]) > 0.5 * a.sy]
    lo, hi = min(ratios), max(ratios)
    report("reaction / (A sigma_1D)", lo[0] >= a.reaction_min and hi[0] <= a.reaction_max,
           "%.4f (step %d) .. %.4f (step %d); bounds [%.3f, %.3f]" % (lo[0], lo[1] + 1, hi[0], hi[1] + 1,
                                                                     a.reaction_min, a.reaction_max))
    # 5. hardening slope of the reaction on the loading branch
    plastic = [k for k in range(1, ipeak + 1) if ref[k][2] and ref[k - 1][2]]
    if plastic:
        k0, k1 = plastic[0], ipeak
        slope = (F[k1] - F[k0]) / (applied[k1] - applied[k0])
        want = a.area * a.E * (a.K + a.H) / (a.E + a.K + a.H)
        e = slope / want - 1
        report("reaction hardening slope", abs(e) <= a.slope_tol,
               "%.4e vs A E (K+H)/(E+K+H) = %.4e N (%+.2f %%, steps %d-%d); bound %.0f %%"
               % (slope, want, 100 * e, k0 + 1, k1 + 1, 100 * a.slope_tol))
    print("check_plastic_bar: PASS" if ok else "check_plastic_bar: FAIL")
    return ok


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

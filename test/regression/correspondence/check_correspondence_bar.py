#!/usr/bin/env python3
"""Checks the Elastic Correspondence bar in uniaxial tension, bar_3d_correspondence.xml, against the closed form.

The ends are driven through fictitious layers with the exact uniaxial-stress field (eps = 1e-3, nu = 0.3), the
lateral faces are free. A correspondence model reproduces an affine field's F exactly at every point (Foster et
al. 2010, Eq. 13), so the bar's response is E eps up to the surface effect of the force state near the free
faces and the layers, and the ADR tolerance (1e-7 relative). Checks, each within 1 % (measured: reaction
+0.18 %, interior strain +0.30 %, sigma_xx +0.16 %): the reaction against E A eps, the strain between the
probes Q1, Q3 (30 mm apart) against eps, the unrotated sigma_xx at Q1 against E eps. A 2 % error in the
stiffness (a wrong modulus or Hooke factor) fails the reaction check; a wrong Poisson ratio in the update
moves it by far more.
usage: check_correspondence_bar.py CSV
"""
import csv
import sys

E, EPS, AREA, GAUGE = 200e9, 1e-3, 4e-4, 0.03


def main(path):
    last = list(csv.DictReader(open(path)))[-1]
    eps = (float(last["Probe_Q3_DisplacementX"]) - float(last["Probe_Q1_DisplacementX"])) / GAUGE
    F = float(last["Reaction_Right_Layer_X"])
    sxx = float(last["Probe_Q1_Unrotated_Cauchy_StressXX"])
    checks = [("reaction", F, E * AREA * EPS), ("interior strain", eps, EPS), ("sigma_xx at Q1", sxx, E * EPS)]
    ok = True
    for name, got, ref in checks:
        err = got / ref - 1
        ok = ok and abs(err) < 0.01
        print(f"{name}: {got:.6e} vs closed form {ref:.6e}: {100 * err:+.3f} %")
    print("check_correspondence_bar:", "ok" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))

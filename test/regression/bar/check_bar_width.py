#!/usr/bin/env python3
"""Axial stiffness of a 2D bar without its free-edge effect: the reactions of two bars that differ only in
width (same length, grid, horizon, loading) differ by E_lattice * dW * t * eps exactly when the interior
is right, because the OSB free-edge excess (uncorrected, as in the paper) is the same for both bars and
cancels. E_lattice is the uniaxial-stress modulus of an interior point of this square lattice, computed
from the lattice's bond moments by check_bar.lattice_modulus (closed form, independent of Periforge);
E' (E in plane stress, E/(1 - nu^2) in plane strain) is printed next to it.
Usage: check_bar_width.py NARROW.csv WIDE.csv --dW m --thickness m --plane stress|strain --E --nu --strain
       --ratio --tol. Exit 0 when |dF / (E_lattice dW t eps) - 1| <= tol, 1 otherwise.
"""
import argparse
import csv
import sys

from check_bar import lattice_modulus


def reaction(path):
    return float(list(csv.DictReader(open(path)))[-1]["Reaction_Right_Layer_X"])


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("narrow")
    p.add_argument("wide")
    for name in ("--dW", "--thickness", "--E", "--nu", "--strain", "--ratio", "--tol"):
        p.add_argument(name, type=float, required=True)
    p.add_argument("--plane", choices=["stress", "strain"], required=True)
    a = p.parse_args()
    dF = reaction(a.wide) - reaction(a.narrow)
    Ep = a.E / (1 - a.nu ** 2) if a.plane == "strain" else a.E
    El = lattice_modulus(2, a.ratio, a.E, a.nu, a.plane)
    want = El * a.dW * a.thickness * a.strain
    err = dF / want - 1
    print(f"reaction difference {dF:.6e} N vs E_lattice dW t eps = {want:.6e} N: {100 * err:+.3f} % (bound "
          f"{100 * a.tol:.2f} %); vs E' dW t eps = {Ep * a.dW * a.thickness * a.strain:.6e} N: "
          f"{100 * (dF / (Ep * a.dW * a.thickness * a.strain) - 1):+.3f} % (E_lattice / E' = {El / Ep:.5f})")
    ok = abs(err) <= a.tol
    print("check_bar_width: PASS" if ok else "check_bar_width: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Runs a NOXQuasiStatic deck with `Verbose` = true and checks that Newton converges quadratically in its
yielding load steps: over the last iterations of each solve, rho_{k+1} <= C rho_k^2, where rho = force residual /
load scale (the solver's own relative measure: residual over tolerance times the Relative Tolerance).

usage: check_quadratic.py --rel REL --C C [--floor F] [--min-pairs N] [--expect-linear] -- CMD...

A pair (k, k+1) is judged when rho_k <= 1e-3 (the asymptotic range: the first iterations of a step are the
globalisation's, not Newton's local rate) and rho_{k+1} > floor (below the floor the residual is round-off and
says nothing about the rate). At least --min-pairs pairs must be judged. --expect-linear inverts the verdict (the
finite-difference Jacobian must miss the bound at least once): so the check is shown to be able to fail.
Exit 0 on success, 1 otherwise; prints every solve's history.
"""
import argparse
import re
import subprocess
import sys

RESID = re.compile(r"force residual ([-+0-9.eE]+) N \(tolerance ([-+0-9.eE]+) N\)")
HEADER = re.compile(r"-- Nonlinear Solver Step (\d+) --")
STEP = re.compile(r"\|\|F\|\| = \S+\s+step = ([-+0-9.eE]+)")
FINAL = re.compile(r"-- Final Status Test Results --")


def histories(text, rel):
    """Per Newton solve, the list of (rho, step length that reached the iterate). NOX prints each iterate's
    status test (our force residual) before its "Nonlinear Solver Step N" header, except the last one, whose
    status comes after "Final Status Test Results"."""
    solves, rho, pending, after_final = [], None, None, False
    for line in text.splitlines():
        m = RESID.search(line)
        if m:
            r, tol = float(m.group(1)), float(m.group(2))
            value = r * rel / tol if tol > 0 else float("nan")
            if after_final:
                if pending is not None:
                    pending[0] = value
                    pending = None
                after_final = False
            else:
                rho = value
            continue
        m = HEADER.search(line)
        if m:
            if int(m.group(1)) == 0:
                solves.append([])
            entry = [rho, None]
            pending = entry if rho is None else None
            rho = None
            if solves:
                solves[-1].append(entry)
            continue
        m = STEP.search(line)
        if m and solves and solves[-1]:
            solves[-1][-1][1] = float(m.group(1))
            continue
        if FINAL.search(line):
            after_final = True
    return [[(r, st) for r, st in s if r is not None] for s in solves if s]


def judge(sol, C, floor, window):
    """(pairs judged, pairs above C, largest ratio), printing each solve."""
    judged, misses, worst = 0, 0, 0.0
    for n, h in enumerate(sol):
        print(f"solve {n + 1}: rho = " + " ".join(f"{r:.2e}" + ("" if st in (None, 0.0, 1.0) else f"(step {st:.2g})")
                                                  for r, st in h))
        for k in range(len(h) - 1):
            (rk, _), (rn, st) = h[k], h[k + 1]
            if rk <= window and rn > floor and st == 1.0:
                ratio = rn / (rk * rk)
                judged += 1
                worst = max(worst, ratio)
                misses += ratio > C
                print(f"  iteration {k}->{k + 1}: rho_k+1 / rho_k^2 = {ratio:.3g}" + ("  > C" if ratio > C else ""))
    return judged, misses, worst


def self_test(C, floor, window):
    """The judge on made-up histories: quadratic (rho_k+1 = rho_k^2) passes, linear (rate 0.05) does not."""
    quad = [[(1e-1, 0.0), (1e-2, 1.0), (1e-4, 1.0), (1e-8, 1.0), (1e-16, 1.0)]]
    lin = [[(1e-2 * 0.05 ** k, 0.0 if k == 0 else 1.0) for k in range(8)]]
    jq, mq, _ = judge(quad, C, floor, window)
    jl, ml, _ = judge(lin, C, floor, window)
    ok = jq > 0 and mq == 0 and jl > 0 and ml > 0
    print("self-test " + ("OK: quadratic passes, linear fails" if ok else "FAILED"))
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--rel", type=float, default=1e-10, help="the deck's Relative Tolerance")
    ap.add_argument("--C", type=float, required=True)
    ap.add_argument("--floor", type=float, default=3e-11)
    ap.add_argument("--window", type=float, default=1e-2)
    ap.add_argument("--min-pairs", type=int, default=3)
    ap.add_argument("--self-test", action="store_true")
    ap.add_argument("cmd", nargs=argparse.REMAINDER)
    a = ap.parse_args()
    if a.self_test:
        return self_test(a.C, a.floor, a.window)
    cmd = a.cmd[1:] if a.cmd and a.cmd[0] == "--" else a.cmd
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        print(p.stdout[-4000:], p.stderr[-4000:])
        print(f"FAIL: the run exited with {p.returncode}")
        return 1
    sol = histories(p.stdout, a.rel)
    if not sol:
        print(p.stdout[-4000:])
        print("FAIL: no Newton residual history in the output (Verbose = true?)")
        return 1
    judged, misses, worst = judge(sol, a.C, a.floor, a.window)
    print(f"{judged} pairs judged, largest rho_k+1 / rho_k^2 = {worst:.3g}, C = {a.C:g}")
    if judged < a.min_pairs:
        print(f"FAIL: fewer than {a.min_pairs} pairs in the asymptotic range")
        return 1
    print("OK" if misses == 0 else f"FAIL: {misses} pairs above C")
    return 0 if misses == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

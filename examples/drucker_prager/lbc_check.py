#!/usr/bin/env python3
"""Loading-balance correction figures of a biaxial run (make_biaxial.py; README, "Loading-balance correction").

usage: lbc_check.py RUN.e [--log RUN.log] [--csv RUN.csv] [--tol T] [--max-violations N] [--against OTHER.e
                    [--bounds U:S:X]] [--expect KEY=V:R ...]

Prints, from RUN.e, the step ends (output steps after step 0) at which some point has Yield_Function > T and how
many (step, point) pairs that is, and the largest Yield_Function of any point at any step end. Yield_Function
is Drucker Prager Correspondence's J / J_yield - 1 at the point's pressure (docs/materials.md): dimensionless,
> 0 outside the yield surface. T defaults to 1e-6, the loading-balance tolerance (src/solvers/YieldRounds.hpp).
From RUN.log (the run's stdout): the LBC rounds per load step (min / median / max; absent without the
correction) and the ADR iterations summed over all steps. From RUN.csv: the centre probe's end von Mises stress.

--against OTHER.e    compare with another run of the same specimen and load steps (e.g. without the correction,
                     or at another np) at every output time both files have: the largest difference of
                     displacement, von Mises stress and equivalent plastic strain over points and steps, and the
                     first step past --bounds; nodes matched by coordinates
--bounds U:S:X       with --against: the bounds of "first step past" (figure first_past, -1: none; check it with
                     --expect first_past=-1:0) on displacement [m], von Mises [Pa] and plastic strain (default
                     5e-8:50:2e-6, test/regression/drucker_prager/np_agreement.comp's, whose comment gives why)
--max-violations N   exit 1 if more than N (step, point) pairs have Yield_Function > T (default: no limit)
--expect KEY=V:R     exit 1 unless figure KEY is within R (relative; absolute if V = 0) of V. Keys: violations,
                     yield_max, rounds_min, rounds_median, rounds_max, iterations, centre_vm, diff_disp,
                     diff_vm, diff_xi, first_past (the first step past --bounds, -1: none), asym_max (the
                     largest left-right asymmetry of u_x, m), asym_first (its first step past 5e-8 m, -1: none)
Exit 0 if every check holds, 1 if one fails, 2 on a usage or read error.
"""
import argparse
import csv
import os
import re
import statistics
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
from periforge_py.exodus import names  # noqa: E402


try:
    import numpy as np
    import netCDF4
except ImportError:
    use_system_python()
    sys.stderr.write("lbc_check.py: needs numpy and netCDF4 (Debian: python3-netcdf4)\n")
    sys.exit(2)


def yield_function(path):
    """Yield_Function per output step (rows) and point (columns, all element blocks)."""
    with netCDF4.Dataset(path) as ds:
        elem = names(ds, "name_elem_var") if "name_elem_var" in ds.variables else []
        if "Yield_Function" not in elem:
            raise SystemExit(f"lbc_check.py: {path}: no element variable Yield_Function (add it to Output Variables)")
        k = elem.index("Yield_Function") + 1
        blocks = sorted(v for v in ds.variables if v.startswith(f"vals_elem_var{k}eb"))
        return np.hstack([np.ma.getdata(ds.variables[b][:]) for b in blocks])


def fields(path):
    """times, and per step and point (sorted by y, then x): ux, uy, von Mises, equivalent plastic strain."""
    with netCDF4.Dataset(path) as ds:
        nod, elem = names(ds, "name_nod_var"), names(ds, "name_elem_var")
        get = lambda v: np.ma.getdata(ds.variables[v][:])
        order = np.lexsort((get("coordx"), get("coordy")))
        out = [get(f"vals_nod_var{nod.index(n) + 1}") for n in ("DisplacementX", "DisplacementY")]
        for n in ("Von_Mises_Stress", "Equivalent_Plastic_Strain"):
            k = elem.index(n) + 1
            out.append(np.hstack([get(b) for b in sorted(v for v in ds.variables if v.startswith(f"vals_elem_var{k}eb"))]))
        # element order = node order here (one SPHERE element per node, written in node order)
        return get("time_whole"), [a[:, order] for a in out]


def compare(a_path, b_path, bounds):
    (ta, fa), (tb, fb) = fields(a_path), fields(b_path)
    n = min(len(ta), len(tb))
    if not np.allclose(ta[:n], tb[:n], rtol=0, atol=1e-12):
        raise SystemExit(f"lbc_check.py: {a_path} and {b_path} have different output times")
    diff = np.stack([np.maximum(abs(fa[0][:n] - fb[0][:n]), abs(fa[1][:n] - fb[1][:n])).max(axis=1),
                     abs(fa[2][:n] - fb[2][:n]).max(axis=1), abs(fa[3][:n] - fb[3][:n]).max(axis=1)], axis=1)
    worst = diff.max(axis=0)
    past = np.nonzero((diff > np.array(bounds)).any(axis=1))[0]
    print(f"against {b_path}, steps 0..{n - 1} (t = {ta[n - 1]:g}): largest difference displacement {worst[0]:.3e} m, "
          f"von Mises {worst[1]:.3e} Pa, equivalent plastic strain {worst[2]:.3e}")
    if len(past):
        s = past[0]
        print(f"  first step past the bounds {bounds}: step {s} (t = {ta[s]:g}): {diff[s][0]:.3e} m, {diff[s][1]:.3e} Pa, "
              f"{diff[s][2]:.3e}; largest before it: {diff[:s].max(axis=0) if s else 'none'}")
    return {"diff_disp": worst[0], "diff_vm": worst[1], "diff_xi": worst[2], "first_past": int(past[0]) if len(past) else -1}


def asymmetry(path):
    """Per step, the largest |u_x(x, y) + u_x(W - x, y)|: the departure from the left-right mirror symmetry the
    specimen and its loads have (make_biaxial.py; the bottom middle point's u_x = 0 lies on the axis)."""
    with netCDF4.Dataset(path) as ds:
        get = lambda v: np.ma.getdata(ds.variables[v][:])
        x, y = get("coordx"), get("coordy")
        ux = get(f"vals_nod_var{names(ds, 'name_nod_var').index('DisplacementX') + 1}")
    w = x.min() + x.max()
    key = {(round(a * 1e7), round(b * 1e7)): k for k, (a, b) in enumerate(zip(x, y))}  # 0.1 um: far below dx
    mirror = [key[(round((w - a) * 1e7), round(b * 1e7))] for a, b in zip(x, y)]
    return abs(ux + ux[:, mirror]).max(axis=1)


def log_figures(path):
    rounds, iterations = [], 0
    for line in open(path):
        m = re.match(r"load step\s+\d+/\d+\s+t = \S+\s+iterations\s+(\d+)(?:\s+LBC rounds\s+(\d+))?", line)
        if m:
            iterations += int(m.group(1))
            if m.group(2):
                rounds.append(int(m.group(2)))
    return rounds, iterations


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("exo")
    ap.add_argument("--log")
    ap.add_argument("--csv")
    ap.add_argument("--tol", type=float, default=1e-6)
    ap.add_argument("--max-violations", type=int)
    ap.add_argument("--against")
    ap.add_argument("--bounds", default="5e-8:50:2e-6")
    ap.add_argument("--expect", action="append", default=[])
    a = ap.parse_args()
    f = yield_function(a.exo)[1:]  # step 0 is the initial state, not a step end
    over = f > a.tol
    fig = {"violations": int(over.sum()), "yield_max": float(f.max())}
    print(f"{a.exo}: {f.shape[0]} step ends x {f.shape[1]} points: {fig['violations']} (step, point) pairs with "
          f"Yield_Function > {a.tol:g}, at {int(over.any(axis=1).sum())} step ends; largest Yield_Function "
          f"{fig['yield_max']:.3e}")
    asym = asymmetry(a.exo)
    past = np.nonzero(asym > 5e-8)[0]  # the np agreement bound on displacement (--bounds)
    fig.update(asym_max=float(asym.max()), asym_first=int(past[0]) if len(past) else -1)
    print(f"left-right asymmetry of u_x: largest {fig['asym_max']:.3e} m (step {int(asym.argmax())}), first step past "
          f"5e-8 m: {fig['asym_first']}")
    ok = True
    if a.max_violations is not None and fig["violations"] > a.max_violations:
        print(f"FAIL: more than {a.max_violations} pairs past the yield tolerance")
        ok = False
    if a.against:
        bounds = [float(v) for v in a.bounds.split(":")]
        fig.update(compare(a.exo, a.against, bounds))
    if a.log:
        rounds, fig["iterations"] = log_figures(a.log)
        print(f"{a.log}: ADR iterations over all steps {fig['iterations']}")
        if rounds:
            fig.update(rounds_min=min(rounds), rounds_median=statistics.median(rounds), rounds_max=max(rounds))
            print(f"{a.log}: LBC rounds per step over {len(rounds)} steps: min {fig['rounds_min']}, median "
                  f"{fig['rounds_median']:g}, max {fig['rounds_max']}, total {sum(rounds)}")
    if a.csv:
        rows = list(csv.DictReader(open(a.csv)))
        fig["centre_vm"] = float(rows[-1]["Probe_Centre_Von_Mises_Stress"])
        print(f"{a.csv}: centre end von Mises {fig['centre_vm'] / 1e3:.3f} kPa")
    for e in a.expect:
        key, rest = e.split("=", 1)
        value, bound = (float(v) for v in rest.split(":"))
        if key not in fig:
            print(f"FAIL: --expect {key}: no such figure from the given files")
            ok = False
            continue
        err = abs(fig[key] - value) / (abs(value) if value != 0 else 1.0)
        if err > bound:
            print(f"FAIL: {key} = {fig[key]:g}, expected {value:g} within {bound:g}")
            ok = False
    print("PASS" if ok else "FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

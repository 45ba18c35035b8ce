#!/usr/bin/python3
"""NOXQuasiStatic's `Predictor` = `Quadratic` (src/solvers/LoadStepping.cpp, predictStep) against `Linear` on the
elastic bar of bar_3d_nox.xml (coarsened to dx = 4 mm), stretched to eps = 4e-3 in four load steps and released
in four, every step solved to a relative tolerance of 1e-10 (its solves end near 1.5e-6 N; the quadratic's
starting residuals are 0.04 N and more, so the solves' errors barely enter them).

The path u(p) of an elastic body is smooth in the load p: the linear predictor leaves the path's second difference
(geometric nonlinearity) as the step's starting residual; the quadratic through the last three solved states
(src/solvers/SolvedStates.hpp) leaves its third difference. NOX's verbose output prints each step's starting
residual norm ("Nonlinear Solver Step 0", ||F||):
- loading step 4 and unloading step 8 (three solved states on one side of the turn before them): the
  quadratic's starting residual at most 1e-2 of the linear's (measured 2.4e-3 and 3.2e-3); a wrong weight in the
  extrapolation leaves a residual of the second difference's size;
- steps 1-3 (fewer than three states) and 5-7 (the load turns between the kept states and the next load; step 5,
  back to the state of step 3, starts converged and is not kept, so step 7's states are steps 3, 4, 6) must predict
  linearly: the same starting residual within a factor 2 (the states differ within the tolerance); a
  quadratic across the turn would extrapolate the wrong branch;
- the written displacements of both runs agree within 1e-8 of their largest value (both converged to 1e-10 of the
  load; the bar's stiffness spread is ~1e2).

usage: check_quadratic_predictor.py PERIFORGE BAR_NOX_DECK
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py import exodus  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

STEPS = 8


def deck(base, predictor):
    text = open(base).read()
    text = re.sub(r'(name="Spacing" type="double" value=")[^"]*', r"\g<1>0.004", text)
    text = re.sub(r'(name="Horizon" type="double" value=")[^"]*', r"\g<1>0.01206", text)
    text = re.sub(r'(name="Final Time" type="double" value=")[^"]*', r"\g<1>%d" % STEPS, text)
    text = re.sub(r'(name="Number of Load Steps" type="int" value=")[^"]*', r"\g<1>%d" % STEPS, text)
    text = re.sub(r'(name="Relative Tolerance" type="double" value=")[^"]*',
                  r'\g<1>1e-10"/><Parameter name="Predictor" type="string" value="%s' % predictor, text)
    # the load rises with t to t = 4 and falls back to 0 at t = 8: each "...*t" boundary value becomes its ramp
    text = re.sub(r'value="([^"]*)\*t"', lambda m: 'value="if (t &lt;= 4) { value = %s*t; } else { value = %s*(8 - t); }"'
                  % (m.group(1), m.group(1)), text)
    text = re.sub(r"<ParameterList name=\"Probes\">.*?</ParameterList>\s*</ParameterList>\s*</ParameterList>",
                  "</ParameterList>", text, flags=re.S)
    if 'value="Quadratic"' not in text and predictor == "Quadratic":
        sys.exit("the deck's Relative Tolerance was not found: the predictor is not set")
    return text


def run(exe, base, predictor, work):
    os.makedirs(work)
    with open(os.path.join(work, "deck.xml"), "w") as f:
        f.write(deck(base, predictor))
    p = subprocess.run([exe, "deck.xml"], cwd=work, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("%s run failed: %s" % (predictor, (p.stdout + p.stderr)[-800:]))
    # NOX's verbose output opens each solve with "Nonlinear Solver Step 0" and its starting ||F|| (the force-density
    # norm), also for a solve that starts converged
    start = [float(r) for r in re.findall(r"-- Nonlinear Solver Step 0 --\s*\n\|\|F\|\| = (\S+)", p.stdout)]
    if len(start) != STEPS:
        sys.exit("%s: %d starting residuals in the verbose output, expected %d" % (predictor, len(start), STEPS))
    d = netCDF4.Dataset(os.path.join(work, "bar_3d_nox.e"))
    u = np.array([exodus.nodal(d, name) for name in ("DisplacementX", "DisplacementY",
                                                                   "DisplacementZ")])
    return start, u


def main():
    exe, base = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as tmp:
        linear, uL = run(exe, base, "Linear", os.path.join(tmp, "linear"))
        quad, uQ = run(exe, base, "Quadratic", os.path.join(tmp, "quadratic"))
    problems = []
    for k in range(STEPS):
        ratio = quad[k] / linear[k] if linear[k] > 0 else float("inf")
        print("step %d: starting ||F|| linear %.4e, quadratic %.4e (ratio %.3e)" % (k + 1, linear[k], quad[k],
                                                                                          ratio))
        step = k + 1
        if step in (4, 8) and not ratio <= 1e-2:
            problems.append("step %d: the quadratic predictor's starting residual is %.3e of the linear's (bound 1e-2)"
                            % (step, ratio))
        if step in (1, 2, 3, 5, 6, 7) and not 0.5 <= ratio <= 2.0:
            problems.append("step %d: the quadratic run should predict linearly here; its starting residual is %.3e "
                            "of the linear's (bound [0.5, 2])" % (step, ratio))
    diff = np.max(np.abs(uQ - uL)) / np.max(np.abs(uL))
    print("largest displacement difference: %.3e of the largest displacement (bound 1e-8)" % diff)
    if not diff <= 1e-8:
        problems.append("the displacements differ by %.3e of their largest value (bound 1e-8)" % diff)
    if problems:
        sys.exit("; ".join(problems))
    print("ok")


if __name__ == "__main__":
    main()

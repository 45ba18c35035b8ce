#!/usr/bin/python3
"""Nonlinear_Solver_Iterations is the NOX solver's real count (src/solvers/NoxQuasiStaticSolver.cpp, summed by
src/output/OutputManager.cpp): the bar of
bar_3d_nox.xml, 3 load steps, run at a loose and at a tight Relative Tolerance. Each written value must be 0 at
the initial state and then the running sum of the NOX steps the solver printed per load step (Peridigm's rule,
executeNOXQuasiStatic: one NOX::Solver::step() per Newton iteration, one for a solve whose initial guess already
passes); the tight run must need more of them than the loose one (the count follows the work, not a constant).
The run's closing "NOX work" line (src/solvers/NewtonWork.hpp, counted where the work happens) must agree with the
per-step lines (NOX's and GMRES' own counts): the same Newton and GMRES totals, one preconditioner build, exactly
one tangent product and one preconditioner application per GMRES iteration (src/solvers/Gmres.hpp makes no other:
none for the initial or an explicit residual, the update from the kept M^-1 v_j, the line search's slope from the
solve's residual; the bar's tangent is the exact one), at least one residual per Newton iteration and per solve.

usage: check_nox_iterations.py PERIFORGE BAR_NOX_DECK
"""
import os
import re
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py import exodus, nox_work  # noqa: E402
import netCDF4  # noqa: E402

LOOSE, TIGHT = 1.0e-3, 1.0e-9


def deck(base, tolerance):
    text = open(base).read()
    text = re.sub(r'(name="Relative Tolerance" type="double" value=")[^"]*', r"\g<1>%g" % tolerance, text)
    text = re.sub(r'(name="Number of Load Steps" type="int" value=")[^"]*', r"\g<1>3", text)
    text = text.replace('<Parameter name="Verbose" type="bool" value="true"/>', "")
    text = re.sub(r"<ParameterList name=\"Probes\">.*?</ParameterList>\s*</ParameterList>\s*</ParameterList>",
                  "</ParameterList>", text, flags=re.S)
    text = text.replace('<ParameterList name="Output Variables">',
                        '<ParameterList name="Output Variables">\n'
                        '      <Parameter name="Nonlinear_Solver_Iterations" type="bool" value="true"/>')
    return text


def run(exe, base, tolerance, work):
    os.makedirs(work)
    with open(os.path.join(work, "deck.xml"), "w") as f:
        f.write(deck(base, tolerance))
    p = subprocess.run([exe, "deck.xml"], cwd=work, capture_output=True, text=True)
    if p.returncode != 0:
        sys.exit("run failed (tolerance %g): %s" % (tolerance, (p.stdout + p.stderr)[-800:]))
    per_step = [int(n) for n in re.findall(r"Newton iterations\s+(\d+)", p.stdout)]
    check_work_line(p.stdout, per_step, tolerance)
    d = netCDF4.Dataset(os.path.join(work, "bar_3d_nox.e"))
    written = [float(x) for x in exodus.global_variable(d, "Nonlinear_Solver_Iterations")]
    return per_step, written


def check_work_line(stdout, per_step, tolerance):
    linear = sum(int(n) for n in re.findall(r"\(linear\s+(\d+)\)", stdout))
    parsed = nox_work.parse(stdout)
    if not parsed:
        sys.exit("tolerance %g: no 'NOX work' line in the output" % tolerance)
    counts, line = parsed
    newton, gmres, residuals, linearisations, products, applications, builds = (counts[k] for k in nox_work.COUNTS)
    problems = []
    if newton != sum(per_step):
        problems.append("Newton iterations %d, the steps printed %d" % (newton, sum(per_step)))
    if gmres != linear:
        problems.append("GMRES iterations %d, the steps printed %d" % (gmres, linear))
    if builds != 1:
        problems.append("%d preconditioner builds (one per run)" % builds)
    if products != gmres or applications != gmres:
        problems.append("%d products and %d preconditioner applications for %d GMRES iterations"
                        % (products, applications, gmres))
    if linearisations != newton:  # one tangent per Newton direction: the products between reuse it
        problems.append("%d linearisations for %d Newton iterations" % (linearisations, newton))
    if residuals < newton + len(per_step):
        problems.append("%d residuals for %d Newton iterations in %d solves" % (residuals, newton, len(per_step)))
    if problems:
        sys.exit("tolerance %g: the NOX work line disagrees: %s" % (tolerance, "; ".join(problems)))
    print("Relative Tolerance %g: %s" % (tolerance, line))


def main():
    exe, base = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    tmp = tempfile.mkdtemp(prefix="nox_iterations_")
    counts = {}
    for tol in (LOOSE, TIGHT):
        per_step, written = run(exe, base, tol, os.path.join(tmp, "tol%g" % tol))
        if len(per_step) != 3 or len(written) != 4:
            sys.exit("tolerance %g: %d load-step lines, %d written steps (expected 3, 4)" % (tol, len(per_step), len(written)))
        expected = [0]
        for n in per_step:  # no load-step cuts or break rounds here: one NOX solve per load step
            expected.append(expected[-1] + max(1, n))
        if written != [float(e) for e in expected]:
            sys.exit("tolerance %g: written %s, expected %s from the printed iterations %s" % (tol, written, expected, per_step))
        counts[tol] = written[-1]
        print("Relative Tolerance %g: NOX iterations per step %s, written %s" % (tol, per_step, written))
    if not counts[TIGHT] > counts[LOOSE]:
        sys.exit("the tighter tolerance took no more NOX steps (%g vs %g)" % (counts[TIGHT], counts[LOOSE]))
    print("ok")


if __name__ == "__main__":
    main()

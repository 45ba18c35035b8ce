#!/usr/bin/env python3
"""Issue 40 (reliability, second pass): each case the issue lists, as a deck edit that must end with one
clear line naming its cause (or run, where the fix is a warning), and leave nothing non-finite in a
final-named file. Every case failed before the fix (an rc-0 run with inf in the Exodus globals, a checkpoint
overwriting the deck or an output's part file, a NOX option silently ignored, an unnamed det F <= 0, ...).

Judged as run_finite_cases.py judges its cases (exit code, one error line holding the words), plus: no
non-finite value in any .e file (read with netCDF4 when installed) and the deck unchanged by the run.

usage: run_runtime_cases.py PERIFORGE_EXE REGRESSION_DIR MPIRUN...
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from run_finite_cases import run_cases  # noqa: E402

try:
    import netCDF4
    import numpy
except ImportError:  # the .e check is skipped; the CSV check stays
    netCDF4 = None

TAYLOR = "restart/restart_taylor.xml"
NOX = "bar/bar_3d_nox.xml"
NEWMARK = "implicit/bar_line_newmark.xml"
SHORT = ('<Parameter name="Final Time" type="double" value="3e-05"/>',
         '<Parameter name="Final Time" type="double" value="1e-06"/>')


def checkpoint(name):
    return ('<Parameter name="Checkpoint Frequency" type="int" value="200"/>',
            '<Parameter name="Checkpoint Frequency" type="int" value="200"/>'
            f'<Parameter name="Checkpoint Filename" type="string" value="{name}"/>')


def nox_option(xml):
    return ('<Parameter name="Number of Load Steps" type="int" value="2"/>',
            '<Parameter name="Number of Load Steps" type="int" value="2"/>' + xml)


def newmark_option(xml):
    return ('<Parameter name="Fixed dt" type="double" value="5.0e-4"/>',
            '<Parameter name="Fixed dt" type="double" value="5.0e-4"/>' + xml)


def output_name(name):
    return ('<Parameter name="Output Filename" type="string" value="rs"/>',
            f'<Parameter name="Output Filename" type="string" value="{name}"/>')


CASES = [
    # name, base deck, edits, rank counts, want exit 0, words
    ("initial velocity -1e300: kinetic energy overflows", TAYLOR,
     [SHORT, ('value="-200"', 'value="-1e300"')], (1, 2), False,
     ["solver failed", "Global_Kinetic_Energy is inf at step 0 (t = 0)", "nothing non-finite is written"]),
    ("initial velocity -1e160: its square overflows", TAYLOR,
     [SHORT, ('value="-200"', 'value="-1e160"')], (1,), False,
     ["solver failed", "Global_Kinetic_Energy is inf"]),
    ("checkpoint named like the Exodus part file", TAYLOR, [SHORT, checkpoint("rs.e.part")], (1, 2), False,
     ["input error", "Restart", "'Checkpoint Filename'", "'rs.e.part', which is Output's 'rs.e.part'"]),
    ("checkpoint named like the deck", TAYLOR, [SHORT, checkpoint("./case.xml")], (1,), False,
     ["input error", "Restart", "which is the input deck"]),
    ("checkpoint named like the lock", TAYLOR, [SHORT, checkpoint("rs.lock")], (1,), False,
     ["input error", "which is Output's 'rs.lock'"]),
    ("checkpoint named like the history", TAYLOR, [SHORT, checkpoint("rs.csv")], (1,), False,
     ["input error", "which is Output's 'rs.csv'"]),
    ("output named '/'", TAYLOR, [SHORT, output_name("/")], (1, 2), False,
     ["input error", "Output", "'Output Filename' = '/' names a directory"]),
    ("output named './'", TAYLOR, [SHORT, output_name("./")], (1,), False,
     ["input error", "'Output Filename' = './' names a directory"]),
    ("NOX Nonlinear Solver 'Magic Based'", NOX,
     [nox_option('<Parameter name="Nonlinear Solver" type="string" value="Magic Based"/>')], (1, 2), False,
     ["input error", "Solver/NOXQuasiStatic", "'Nonlinear Solver' = 'Magic Based' is not one of NOX's"]),
    ("NOX Line Search Method 'Teleport'", NOX,
     [nox_option('<ParameterList name="Line Search"><Parameter name="Method" type="string" value="Teleport"/>'
                 '</ParameterList>')], (1,), False,
     ["input error", "Solver/NOXQuasiStatic/Line Search", "'Method' = 'Teleport'"]),
    ("NOX Direction Method 'Warp'", NOX,
     [nox_option('<ParameterList name="Direction"><Parameter name="Method" type="string" value="Warp"/>'
                 '</ParameterList>')], (1,), False,
     ["input error", "Solver/NOXQuasiStatic/Direction", "'Method' = 'Warp'"]),
    ("both spellings of the iteration limit", NOX,
     [nox_option('<Parameter name="Max Solver Iterations" type="int" value="3"/>'
                 '<Parameter name="Maximum Solver Iterations" type="int" value="3"/>')], (1,), False,
     ["input error", "'Maximum Solver Iterations' or Peridigm's spelling 'Max Solver Iterations', not both"]),
    ("NOX Relative Tolerance 1e-300", NOX,
     [('<Parameter name="Relative Tolerance" type="double" value="1.0e-10"/>',
       '<Parameter name="Relative Tolerance" type="double" value="1e-300"/>')], (1,), False,
     ["input error", "'Relative Tolerance' must be >= 1e-14 (got 1e-300)"]),
    ("material Thickness against the discretization's", "bar/bar_plane_strain.xml",
     [('<Parameter name="Thickness" type="double" value="0.001"/>\n    </ParameterList>\n  </ParameterList>',
       '<Parameter name="Thickness" type="double" value="0.5"/>\n    </ParameterList>\n  </ParameterList>')],
     (1,), False, ["input error", "Materials/Steel", "'Thickness' = 0.5 differs from the Discretization's 0.001"]),
    ("Verlet Safety Factor 2.5", "bar/bar_verlet.xml",
     [('<Parameter name="Fixed dt" type="double" value="5.0e-8"/>',
       '<Parameter name="Safety Factor" type="double" value="2.5"/>')], (1, 2), False,
     ["input error", "Solver/Verlet", "'Safety Factor' = 2.5", "'Allow Unstable Time Step'"]),
    ("Verlet Safety Factor 1e300", "bar/bar_verlet.xml",
     [('<Parameter name="Fixed dt" type="double" value="5.0e-8"/>',
       '<Parameter name="Safety Factor" type="double" value="1e300"/>')], (1,), False,
     ["input error", "'Safety Factor' = 1e+300"]),
    ("wall normal pointing into the body", TAYLOR,
     [SHORT, ('name="Normal Z" type="double" value="1.0"', 'name="Normal Z" type="double" value="-1.0"')], (1, 2),
     False, ["input error", "Boundary Conditions/Anvil", "2028 point(s) of node set 'All' start behind the wall"]),
    ("wall plane through the body", TAYLOR,
     [SHORT, ('name="Point Z" type="double" value="0.000396875"', 'name="Point Z" type="double" value="0.01"')],
     (1,), False, ["input error", "Boundary Conditions/Anvil", "start behind the wall"]),
    # det F <= 0 mid-run names the point, its bonds and the step (an unstable step, allowed).
    ("unstable step allowed: a family turns inside out", TAYLOR,
     [('<Parameter name="Final Time" type="double" value="3e-05"/>',
       '<Parameter name="Final Time" type="double" value="1e-05"/>'),
      ('<Parameter name="Fixed dt" type="double" value="5e-08"/>',
       '<Parameter name="Fixed dt" type="double" value="1e-06"/>'
       '<Parameter name="Allow Unstable Time Step" type="bool" value="true"/>')], (1, 2), False,
     ["material update failed", "det F = ", "at the point at (", "point against their reference direction",
      "in Verlet step 3 (t = 3e-06)"]),
    ("Newmark Beta 1e-300", NEWMARK, [newmark_option('<Parameter name="Beta" type="double" value="1e-300"/>')],
     (1,), False, ["input error", "Solver/Implicit", "'Beta' = 1e-300", "reduce 'Fixed dt'"]),
    ("Newmark Gamma 1e300", NEWMARK, [newmark_option('<Parameter name="Gamma" type="double" value="1e300"/>')],
     (1,), False, ["input error", "Solver/Implicit", "'Gamma' / 2 = 5e+299"]),
    ("Newmark initial velocity 1e300", NEWMARK, [('value="x/12.0"', 'value="1e300"')], (1, 2), False,
     ["solver failed", "Implicit: step 1", "the residual is not finite"]),
    ("Initial Hardening Parameter 1.0000001", "drucker_prager_damage/tension_bar_dp.xml",
     [('name="Initial Hardening Parameter" type="double" value="0.2"',
       'name="Initial Hardening Parameter" type="double" value="1.0000001"')], (1,), False,
     ["input error", "'Initial Hardening Parameter' must be in (0, 1] (got 1.0000001)"]),
    ("cylinder Z Center 1e300", TAYLOR,
     [SHORT, ('<Parameter name="Spacing" type="double" value="0.00079375"/>',
              '<Parameter name="Spacing" type="double" value="0.00079375"/>'
              '<Parameter name="Z Center" type="double" value="1e300"/>')], (1,), False,
     ["input error", "Discretization", "'Z Center' = 1e+300", "double precision"]),
]


def non_finite_exodus(d):
    """Names of the .e files in d with a nan or inf in any variable."""
    bad = []
    if netCDF4 is None:
        return bad
    for f in os.listdir(d):
        if f.endswith(".e"):
            with netCDF4.Dataset(os.path.join(d, f)) as nc:
                for name, var in nc.variables.items():
                    if var.dtype.kind == "f" and not numpy.all(numpy.isfinite(var[:])):
                        bad.append(f"{f}:{name}")
    return bad


def more_problems(d, deck, text):
    problems = [f"non-finite value in {b}" for b in non_finite_exodus(d)]
    if open(deck).read() != text:
        problems.append("the run changed the deck")
    return problems


if __name__ == "__main__":
    cases = [(name, base, edits, None, nps, want_ok, words) for name, base, edits, nps, want_ok, words in CASES]
    sys.exit(run_cases(sys.argv[1], sys.argv[2], sys.argv[3:], cases, more_problems))

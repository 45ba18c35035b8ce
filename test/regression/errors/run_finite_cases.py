#!/usr/bin/env python3
"""Finite state or a clear stop (issue 15, part 3): decks that go non-finite, a Fixed dt far above the
stable step, duplicate and isolated points, a horizon below the spacing. Each case runs at the listed
rank counts and must: exit > 0 (exit 0 for warnings), no signal, exactly one "periforge:" error line on
stderr containing the expected words, and no non-finite number in any CSV left behind (a failed run may
keep the converged steps; nothing non-finite may be written).

usage: run_finite_cases.py PERIFORGE_EXE REGRESSION_DIR MPIRUN...
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

BAD_NUMBER = re.compile(r"(?i)(^|[,\s])[-+]?(nan|inf)")

# A text mesh of six points in a row (test/regression/compat/compat_default_block.txt) plus one line.
ROW = "".join(f"{i} 0 0 {1 if i < 3 else 3} 1.0\n" for i in range(6))

VERLET_ALLOW = ('<Parameter name="Fixed dt" type="double" value="5.0e-8"/>',
                '<Parameter name="Fixed dt" type="double" value="2.1e-6"/>'
                '<Parameter name="Allow Unstable Time Step" type="bool" value="true"/>')
# The deck's conditions as an XML comment: nothing acts on the bar.
REST = [('<ParameterList name="Boundary Conditions">', '<!-- <ParameterList name="Boundary Conditions">'),
        ('</ParameterList>\n  <ParameterList name="Solver">', '</ParameterList> -->\n  <ParameterList name="Solver">')]
INITIAL_INF = ('<ParameterList name="Boundary Conditions">',
               '<ParameterList name="Boundary Conditions">\n    <ParameterList name="Kick">'
               '<Parameter name="Type" type="string" value="Initial Velocity"/>'
               '<Parameter name="Node Set" type="string" value="All"/><Parameter name="Coordinate" type="string" value="x"/>'
               '<Parameter name="Value" type="string" value="1.0/(t-t)"/></ParameterList>')
NAN_AT_HALF = ('value="1.0e-3*x*t"', 'value="1.0e-3*x*t/(t-0.5)*(t-0.5)"')
SQRT_AT_ONE = ('value="1.0e-3*x*t"', 'value="1.0e-3*x*t*sqrt(0.6-t)"')
ASIN_IN_SPACE = ('value="-0.3e-3*(y-0.01)*t/1.0e-5"', 'value="asin(x*500)*t"')
SQRT_MID_RUN = ('value="-0.3e-3*(y-0.01)*t/1.0e-5"', 'value="-0.3e-3*(y-0.01)*t/1.0e-5*sqrt(5.0e-6-t)"')
LOG_CONSTANT = ('value="1.0e-3*x*t"', 'value="1.0e-3*x*t*log(-1.0)"')
SQRT_INFLUENCE = ('<Parameter name="Spacing" type="double" value="0.002"/>',
                  '<Parameter name="Spacing" type="double" value="0.002"/>'
                  '<Parameter name="Influence Function" type="string" value="sqrt(zeta-0.003)"/>')
PRINTF = ('value="1.0e-3*x*t"', 'value="printf(t)*0.0"')

CASES = [
    # name, base deck, edits, mesh text (Text File decks) or None, rank counts, want exit 0, words
    ("Verlet 0/0 boundary value", "bar/bar_verlet.xml",
     [('value="-0.3e-3*(y-0.01)*t/1.0e-5"', 'value="0.0/0.0"')], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left Y/Value", "nan", "t) = ("]),
    ("initial velocity 1.0/(t-t)", "bar/bar_verlet.xml", [INITIAL_INF], None, (1, 2), False,
     ["input error", "Boundary Conditions/Kick/Value", "inf"]),
    ("Verlet Fixed dt 10x the stable step", "bar/bar_verlet.xml",
     [('value="5.0e-8"', 'value="2.1e-6"')], None, (1, 2), False,
     ["input error", "Solver/Verlet", "Fixed dt", "Allow Unstable Time Step"]),
    # Issue 37 part 5: with every point prescribed in every direction nothing can go unstable, so the guard
    # (which counts only points with a free component) lets the same Fixed dt run without the switch.
    ("Verlet Fixed dt 10x, every point prescribed: runs", "bar/bar_verlet.xml",
     [('value="5.0e-8"', 'value="2.1e-6"'),
      ('<Parameter name="Node Set" type="string" value="Left Layer"/><Parameter name="Coordinate" type="string" value="x"/>',
       '<Parameter name="Node Set" type="string" value="All"/><Parameter name="Coordinate" type="string" value="x"/>'),
      ('<Parameter name="Node Set" type="string" value="Left Layer"/><Parameter name="Coordinate" type="string" value="y"/>',
       '<Parameter name="Node Set" type="string" value="All"/><Parameter name="Coordinate" type="string" value="y"/>')],
     None, (1, 2), True, []),
    # A body at rest that nothing moves (the conditions commented out) has only round-off to amplify: a run of 2 steps
    # at 10x (growth (4 r^2)^2 ~ 1.6e5 <= 1e6) runs with a warning (Peridigm's VariableHorizonParsing: 2 steps at 4.3x),
    # its 4 steps to the deck's Final Time (2.5e10) are refused as any other.
    ("Verlet Fixed dt 10x, body at rest, 2 steps: runs", "bar/bar_verlet.xml",
     [('value="5.0e-8"', 'value="2.1e-6"'), *REST, ('value="1.0e-5"/>\n    <ParameterList name="Verlet">',
                                                  'value="4.3e-6"/>\n    <ParameterList name="Verlet">')],
     None, (1, 2), True, ["warning", "nothing moves the body and its 2 step(s)"]),
    ("Verlet Fixed dt 10x, body at rest, 4 steps: refused", "bar/bar_verlet.xml",
     [('value="5.0e-8"', 'value="2.1e-6"'), *REST], None, (1, 2), False,
     ["input error", "Solver/Verlet", "Fixed dt", "Allow Unstable Time Step"]),
    ("Verlet Fixed dt 10x allowed: blows up", "bar/bar_verlet.xml",
     [VERLET_ALLOW, ('value="1.0e-5"/>\n    <ParameterList name="Verlet">', 'value="2.0e-4"/>\n    <ParameterList name="Verlet">')],
     None, (1, 2), False, ["solver failed", "Verlet: non-finite", "at step 74 (t = 0.0001554) at node 79 (0.0785, 0.0005, 0)"]),
    # A load that is not finite at a step's end is named before the quasi-static solver spends its
    # iterations (NOX: its step cuts) on it.
    ("ADR boundary value NaN at t = 0.5", "bar/bar_3d.xml", [NAN_AT_HALF], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left X/Value", "is nan at (x, y, z, t) = (-0.007, 0.001, 0.001, 0.5)"]),
    ("NOX boundary value NaN at t = 0.5", "bar/bar_3d_nox.xml", [NAN_AT_HALF], None, (1,), False,
     ["input error", "Boundary Conditions/Left X/Value", "is nan at (x, y, z, t) = (-0.007, 0.001, 0.001, 0.5)"]),
    # Issue 15 part 2: out-of-domain arguments made Pamgen's RTCompiler abort (exit 134, a backtrace).
    ("ADR sqrt of a negative at t = 1", "bar/bar_3d.xml", [SQRT_AT_ONE], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left X/Value", "is nan at (x, y, z, t) = (-0.007, 0.001, 0.001, 1)",
      "sqrt(-0.4) is undefined"]),
    ("Verlet asin out of range in space", "bar/bar_verlet.xml", [ASIN_IN_SPACE], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left Y/Value", "t) = (-0.0035, 0.0005, 0, 0)", "asin(-1.75) is undefined"]),
    ("Verlet sqrt of a negative mid-run", "bar/bar_verlet.xml", [SQRT_MID_RUN], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left Y/Value", "t) = (-0.0035, 0.0005, 0, 5.05e-06)",
      "sqrt(-5e-08) is undefined"]),
    ("constant log of a negative", "bar/bar_3d.xml", [LOG_CONSTANT], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left X/Value", "log(-1) is undefined"]),
    ("influence function sqrt of a negative", "bar/bar_3d.xml", [SQRT_INFLUENCE], None, (1, 2), False,
     ["input error", "Discretization", "'Influence Function' = 'sqrt(zeta-0.003)' is nan at zeta = 0.002",
      "sqrt(-0.001) is undefined"]),
    ("printf in a boundary value", "bar/bar_3d.xml", [PRINTF], None, (1, 2), False,
     ["input error", "Boundary Conditions/Left X/Value", "'printf' is not available"]),
    ("horizon below the spacing", "bar/bar_3d.xml",
     [('name="Horizon" type="double" value="0.00603"', 'name="Horizon" type="double" value="0.001"')], None, (1, 2), False,
     ["input error", "Blocks/Bar", "Horizon", "spacing"]),
    ("duplicated text-mesh point", "compat/compat_default_block.xml", [], ROW + "2 0 0 3 1.0\n", (1, 2), False,
     ["input error", "Discretization", "points 3 and 7", "(2, 0, 0)"]),
    ("isolated text-mesh point", "compat/compat_default_block.xml", [], ROW + "50 0 0 3 1.0\n", (1, 2), True,
     ["warning", "1 point(s) have no bonds", "point 7"]),
]


def make_deck(reg, base, edits, mesh, d):
    deck = open(os.path.join(reg, base)).read()
    for old, new in edits:
        if old not in deck:
            raise SystemExit(f"test set-up error: '{old[:60]}' not in {base}")
        deck = deck.replace(old, new, 1)
    if mesh is not None:
        open(os.path.join(d, "compat_default_block.txt"), "w").write(mesh)
    path = os.path.join(d, "case.xml")
    open(path, "w").write(deck)
    return path


def problems_of(p, d, want_ok, words):
    # mpirun's own banner lines (np 2) are not ours: judge the "periforge:" lines.
    ours = [l for l in p.stderr.splitlines() if l.startswith("periforge:")]
    errors = [l for l in ours if "warning" not in l]
    msg = (ours if want_ok else errors or [""])[-1] if ours else ""
    found = []
    if want_ok and p.returncode != 0:
        found.append(f"exit code {p.returncode} (want 0)")
    if not want_ok and p.returncode <= 0:
        found.append(f"exit code {p.returncode} (want > 0, not a signal)")
    # (mpirun's "the job has been aborted" after an exit code is not an abort of ours)
    if re.search(r"(?i)signal|SIGABRT|backtrace|core dumped", p.stderr):
        found.append("a signal or abort on stderr")
    if len(errors) != (0 if want_ok else 1):
        found.append(f"{len(errors)} error lines")
    found += [f"message does not contain '{w}'" for w in words if w not in msg]
    if "input error" in words and any(f.endswith((".e", ".csv")) for f in os.listdir(d)):
        found.append("an input error left output files")
    for f in os.listdir(d):
        if f.endswith(".csv") and any(BAD_NUMBER.search(l) for l in open(os.path.join(d, f)).readlines()[1:]):
            found.append(f"{f} holds a non-finite number")
    return found, msg


def run_cases(exe, reg, mpirun, cases, more_problems=None):
    """Runs each case at its rank counts in a fresh directory (beside the deck: the .txt files of its base's
    directory, node sets and meshes); more_problems(d, deck, text) adds a caller's checks. Exit status."""
    failures = total = 0
    for name, base, edits, mesh, nps, want_ok, words in cases:
        for np in nps:
            total += 1
            d = tempfile.mkdtemp()
            try:
                src = os.path.dirname(os.path.join(reg, base))
                for side in os.listdir(src):
                    if side.endswith(".txt"):
                        shutil.copy(os.path.join(src, side), d)
                deck = make_deck(reg, base, edits, mesh, d)
                text = open(deck).read()
                cmd = [exe, deck] if np == 1 else mpirun + ["-np", str(np), exe, deck]
                p = subprocess.run(cmd, cwd=d, capture_output=True, text=True, timeout=240)
                problems, msg = problems_of(p, d, want_ok, words)
                if more_problems:
                    problems += more_problems(d, deck, text)
            finally:
                shutil.rmtree(d, ignore_errors=True)
            print(f"[{name}, np {np}] {'ok' if not problems else 'FAIL: ' + '; '.join(problems)}\n    {msg}")
            failures += bool(problems)
    print(f"{total - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(run_cases(sys.argv[1], sys.argv[2], sys.argv[3:], CASES))

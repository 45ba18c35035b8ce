#!/usr/bin/env python3
"""Semantic mutations of the example decks (issue 40, part 7): valid XML, valid types, hostile values.

Eight small base decks beside this file, each a shrunken copy of an example family (1-3 s at np 1):
  fuzz40_taylor.xml     examples/taylor_impact    Viscoplastic Correspondence, Cylinder, Rigid Wall, Verlet
  fuzz40_band.xml       examples/drucker_prager   Drucker-Prager biaxial test with the NDO surface band, ADR
  fuzz40_lbc.xml        examples/drucker_prager   the same with the Loading Balance Correction, ADR
  fuzz40_fourpoint.xml  examples/drucker_prager   four-point bending, Maximum Principal Stress damage, NOX
  fuzz40_beam.xml       examples/beam_3d          3D cantilever, Elastic Plastic Hardening, NOX
  fuzz40_notched.xml    examples/notched_plate    Critical Stretch damage, Verlet with Safety Factor
  fuzz40_newmark.xml    test/regression/implicit  Implicit (Newmark-beta)
  fuzz40_kinplate.xml   examples/plate_with_hole  kinematic hardening plate under NOXQuasiStatic

Every case is one edit of one base: a semantic mutation (the classes of issue 40: physically extreme
values, output and checkpoint names that collide with the run's own files, NOX option values NOX does not
know, duplicate spellings, a material Thickness contradicting the discretization's, an unbounded Verlet
Safety Factor, rigid walls the body starts behind, Newmark's Beta/Gamma out of range, tolerances below
double precision, ...) or, for about a quarter of the cases, one of generate_decks.OPERATORS (the
syntactic mutations of issue 15). A semantic mutation may carry an expectation: "error" (the deck is
invalid input and must be refused) with the words the error line must contain (the parameter, and where
the bug was a misleading value, the value). The choice is drawn from random.Random(SEED), so a (count,
seed) pair always gives the same cases.

usage: generate_semantic.py OUT_DIR [--count N] [--seed S]
  writes OUT_DIR/<case>.xml and OUT_DIR/index.txt (name, base, expectation, description per line);
  scripts/fuzz imports generate() instead.
"""
import math
import os
import random
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_decks  # noqa: E402
from generate_decks import LIST_CLOSE, PARAM, replace, scan, set_value  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
BASES = ["fuzz40_taylor.xml", "fuzz40_band.xml", "fuzz40_lbc.xml", "fuzz40_fourpoint.xml", "fuzz40_beam.xml",
         "fuzz40_notched.xml", "fuzz40_newmark.xml", "fuzz40_kinplate.xml"]
SEED = 40
COUNT = 320
# Verlet's step without Fixed dt, per unit Safety Factor, of the bases that step that way (measured:
# notched 180 steps of 1.667e-7 s at 0.8; Taylor's stable estimate 6.6e-8 s): for long_run().
UNIT_DT = {"fuzz40_notched.xml": 2.08e-7, "fuzz40_taylor.xml": 6.6e-8}


class Check:
    """What a case must do beyond the general rules: expect "error" (must be refused; the error line must
    contain every word of names) or "any" (either a clean run with finite results or a clean error)."""

    def __init__(self, expect="any", names=()):
        self.expect, self.names = expect, list(names)

    def __str__(self):
        return self.expect + (" naming " + " & ".join(f"'{n}'" for n in self.names) if self.names else "")


ANY = Check()


def error(*names):
    return Check("error", names)


# --- helpers over scan()'s elements -----------------------------------------------------------------------

def params(els, *names):
    return [e for e in els if e.kind == "param" and e.name in names]


def lists(els, *names):
    return [e for e in els if e.kind == "list" and e.name in names]


def value_of(els, name, default=None):
    ps = params(els, name)
    return ps[0].value if ps else default


def top_list(els, name):
    return next(e for e in els if e.kind == "list" and e.path == [name])


def solver_list(els):
    """The solver's sub-list (Verlet, NOXQuasiStatic, Adaptive Dynamic Relaxation, Implicit)."""
    return next(e for e in els if e.kind == "list" and len(e.path) == 2 and e.path[0] == "Solver")


def output_lists(els):
    return [e for e in els if e.kind == "list" and len(e.path) == 1 and e.name.startswith("Output")]


def output_names(text, els):
    """The Output Filename of every output list, in deck order."""
    return [p.value for p in params(els, "Output Filename")]


def insert_into(text, lst, xml):
    """xml inserted as the last child of the list element lst."""
    at = lst.end - len(LIST_CLOSE)
    return replace(text, at, at, xml + "\n  ")


def param_xml(name, type_, value, indent="      "):
    return f'{indent}<Parameter name="{name}" type="{type_}" value="{value}"/>'


def fmt(x):
    return repr(float(x))


def steps_of(text, els):
    """About how many steps (load or time steps) the base takes: for a checkpoint frequency."""
    v = {m.group(1): m.group(3) for m in PARAM.finditer(text)}
    try:
        if "Number of Load Steps" in v:
            return int(v["Number of Load Steps"])
        if "Fixed dt" in v:
            return int(round((float(v["Final Time"]) - float(v.get("Initial Time", "0"))) / float(v["Fixed dt"])))
    except ValueError:
        pass
    return 180


def with_params(text, lst, pairs):
    """Sets (or adds, in the list lst) each (name, type, value)."""
    for name, type_, value in pairs:
        els = scan(text)
        lst = next(e for e in els if e.kind == "list" and e.path == lst.path)
        here = [p for p in els if p.kind == "param" and p.path[:-1] == lst.path and p.name == name]
        if here:
            text = set_value(text, here[0], value)[1]
        else:
            text = insert_into(text, lst, param_xml(name, type_, value))
    return text


# --- semantic mutation operators: (text, rng, els, ctx) -> (description, new text, Check) ----------------

def op_velocity(text, rng, els, ctx):
    """An initial velocity whose square overflows, or that is subnormal (issue 40: inf in the global sums)."""
    v = rng.choice(["1e300", "-1e300", "1e160", "-1e160", "1e-300", "-1e155"])
    ps = [p for p in params(els, "Value") if any(
        q.name == "Type" and q.value == "Initial Velocity" and q.path[:-1] == p.path[:-1] for q in els
        if q.kind == "param")]
    if ps:
        desc, new = set_value(text, rng.choice(ps), v)
        return desc, new, ANY
    if solver_list(els).name not in ("Verlet", "Implicit"):
        raise IndexError
    bc = top_list(els, "Boundary Conditions")
    xml = ('<ParameterList name="Fuzz Kick">\n' + param_xml("Type", "string", "Initial Velocity") + "\n" +
           param_xml("Node Set", "string", "All") + "\n" + param_xml("Coordinate", "string", "y") + "\n" +
           param_xml("Value", "double", v) + "\n    </ParameterList>")
    return f"Boundary Conditions/Fuzz Kick: Initial Velocity y = {v} added", insert_into(text, bc, "  " + xml), ANY


SCALED = ["Density", "Young's Modulus", "Bulk Modulus", "Shear Modulus", "Yield Stress", "Horizon", "Cohesion",
          "Isotropic Hardening Modulus", "Kinematic Hardening Modulus", "Critical Stretch", "Tensile Strength"]


def op_scale(text, rng, els, ctx):
    """A material constant or horizon scaled by 1e100 or 1e-100."""
    p = rng.choice(params(els, *SCALED))
    f = rng.choice([1e100, 1e-100])
    try:
        new = fmt(float(p.value) * f)
    except ValueError:
        raise IndexError
    desc, out = set_value(text, p, new)
    return f"{desc} (x {f:g})", out, ANY


EXTREME = {"Hourglass Coefficient": ["0", "0.0", "1e3"],
           "Reference Plastic Strain Rate": ["1e-300", "1e-30", "1e-10"],
           "Rate Sensitivity Exponent": ["1e-300", "1e300"],
           "Strain Hardening Exponent": ["1e-300", "1e300"],
           "Poisson's Ratio": ["0.5", "0.4999999999", "-0.9999999", "-1"],
           "Friction Angle": ["0", "90", "89.999999", "1e300"],
           "Dilatancy Ratio": ["1e300", "-1"],
           "Tensile Strength": ["1e-300", "0", "1e300"],
           "Critical Stretch": ["1e-300", "1e300"]}


def op_extreme(text, rng, els, ctx):
    """A physically extreme material value: Hourglass 0, a tiny reference strain rate, Poisson 0.5, ..."""
    p = rng.choice(params(els, *EXTREME))
    desc, new = set_value(text, p, rng.choice([v for v in EXTREME[p.name] if v != p.value]))
    return desc, new, ANY


def op_tensile(text, rng, els, ctx):
    """Tensile Strength 1e-300 (issue 40: under NOX minutes of ADR fallback before failing)."""
    p = rng.choice(params(els, "Tensile Strength", "Critical Stretch"))
    desc, new = set_value(text, p, "1e-300")
    return desc, new, ANY


def restart_list(text, els, name, freq):
    """text with a top-level Restart list (Checkpoint Filename = name) before the first output list."""
    first = output_lists(els)[0]
    xml = ('<ParameterList name="Restart">\n' + param_xml("Checkpoint Filename", "string", name, "    ") + "\n" +
           param_xml("Checkpoint Frequency", "int", str(freq), "    ") + "\n  </ParameterList>\n  ")
    return replace(text, first.start, first.start, xml)


def op_checkpoint(text, rng, els, ctx):
    """A Checkpoint Filename naming one of the run's own files (deck, result, .part, lock, status) or none."""
    outs = output_names(text, els)
    out = rng.choice(outs)
    choices = [ctx["deck"], f"{out}.e", f"{out}.e.part", f"{out}.csv.part", f"{out}.lock", f"{out}.csv",
               f"{out}.status", "/", "./", "", ".", ".."]
    name = rng.choice(choices)
    freq = max(1, steps_of(text, els) // 3)
    return (f"Restart/Checkpoint Filename = '{name}' (every {freq} steps; output '{out}')",
            restart_list(text, els, name, freq), error("Checkpoint Filename"))


def op_output_name(text, rng, els, ctx):
    """An Output Filename that is a bare directory, empty, the deck, or another output list's name."""
    ps = params(els, "Output Filename")
    p = rng.choice(ps)
    others = [q.value for q in ps if q is not p]
    choices = ["/", "./", "", ctx["deck"]] + others + [f"{o}.e" for o in others] + [f"{o}.csv" for o in others]
    desc, new = set_value(text, p, rng.choice(choices))
    return desc, new, error("Output Filename")


def op_second_output(text, rng, els, ctx):
    """A second output list whose Output Filename is the first's, or a prefix variant of it."""
    lsts = output_lists(els)
    first, out = lsts[0], output_names(text, els)[0]
    name = rng.choice([out, f"{out}.e", f"{out}.csv", f"{out}.lock", f"{out}.e.part"])
    copy = text[first.start:first.end]
    copy = copy.replace(f'name="Output Filename" type="string" value="{out}"',
                        f'name="Output Filename" type="string" value="{name}"', 1)
    if first.name == "Output":  # Peridigm's numbered lists: Output1, Output2
        copy = copy.replace('<ParameterList name="Output">', '<ParameterList name="Output2">', 1)
        text = replace(text, first.start, first.end, text[first.start:first.end].replace(
            '<ParameterList name="Output">', '<ParameterList name="Output1">', 1) + "\n  " + copy)
        new_list = "Output2"
    else:
        new_list = f"Output{len(lsts) + 1}"
        copy = re.sub(r'<ParameterList name="Output\d*">', f'<ParameterList name="{new_list}">', copy, count=1)
        text = replace(text, lsts[-1].end, lsts[-1].end, "\n  " + copy)
    return (f"second output list {new_list} (a copy of {first.name}) with Output Filename '{name}' beside '{out}'",
            text, error("Output Filename"))


NOX_LISTS = ["NOXQuasiStatic", "QuasiStatic"]


def op_nox_option(text, rng, els, ctx):
    """A NOX option value NOX does not know (issue 40: ignored, every Newton solve 'not converged')."""
    s = solver_list(els)
    if s.name not in NOX_LISTS:
        raise IndexError
    kind = rng.choice(["solver", "line search", "direction", "solver", "line search"])
    if kind == "solver":
        v = rng.choice(["Magic Based", "Magic Based", "Line Search", "line search based", ""])
        return (f"Solver/{s.name}/Nonlinear Solver = '{v}'",
                with_params(text, s, [("Nonlinear Solver", "string", v)]), error("Nonlinear Solver", v) if v
                else error("Nonlinear Solver"))
    if kind == "line search":
        sub, v = "Line Search", rng.choice(["Teleport", "Teleport", "polynomial", "Backtrak"])
    else:
        sub, v = "Direction", rng.choice(["Warp", "Warp", "Newtonn", "Steepest"])
    xml = (f'  <ParameterList name="{sub}">\n' + param_xml("Method", "string", v, "        ") +
           "\n      </ParameterList>")
    return f"Solver/{s.name}/{sub}/Method = '{v}'", insert_into(text, s, xml), error("Method", v)


def op_nox_valid(text, rng, els, ctx):
    """A NOX option value NOX knows: must run or fail cleanly (a solver that may not converge)."""
    s = solver_list(els)
    if s.name not in NOX_LISTS:
        raise IndexError
    sub, v = rng.choice([("Line Search", "Full Step"), ("Line Search", "Backtrack"),
                         ("Direction", "Steepest Descent"), ("Nonlinear Solver", "Trust Region Based"),
                         ("Nonlinear Solver", "Inexact Trust Region Based"), ("Line Search", "More'-Thuente")])
    if sub == "Nonlinear Solver":
        return f"Solver/{s.name}/Nonlinear Solver = '{v}'", with_params(text, s, [(sub, "string", v)]), ANY
    xml = (f'  <ParameterList name="{sub}">\n' + param_xml("Method", "string", v, "        ") +
           "\n      </ParameterList>")
    return f"Solver/{s.name}/{sub}/Method = '{v}'", insert_into(text, s, xml), ANY


def op_duplicate_spelling(text, rng, els, ctx):
    """Both spellings of one option in one list (Maximum Solver Iterations beside Max Solver Iterations)."""
    s = solver_list(els)
    if s.name not in NOX_LISTS:
        raise IndexError
    a, b = rng.choice([("20", "5"), ("30", "30"), ("1", "100")])
    new = with_params(text, s, [("Maximum Solver Iterations", "int", a), ("Max Solver Iterations", "int", b)])
    return (f"Solver/{s.name}: Maximum Solver Iterations = {a} and Max Solver Iterations = {b}", new,
            error("Solver Iterations"))


def op_thickness(text, rng, els, ctx):
    """A material Thickness that contradicts the discretization's."""
    disc = [p for p in params(els, "Thickness") if p.path[0] == "Discretization"]
    mats = [p for p in params(els, "Thickness") if p.path[0] == "Materials"]
    if not disc or not mats:
        raise IndexError
    f = rng.choice([10.0, 0.5, 1e-6, 1.001])
    desc, new = set_value(text, rng.choice(mats), fmt(float(disc[0].value) * f))
    return f"{desc} (Discretization/Thickness {disc[0].value})", new, error("Thickness")


def op_safety(text, rng, els, ctx):
    """Verlet's Safety Factor above the stable bound, zero or negative (Fixed dt removed where given)."""
    s = solver_list(els)
    if s.name != "Verlet":
        raise IndexError
    v = rng.choice(["2.5", "1e300", "0", "-1", "2.5", "1e300", "1.5", "2.5 allowed"])
    fixed = [p for p in params(els, "Fixed dt") if p.path[:-1] == s.path]
    if fixed:
        text = replace(text, fixed[0].start, fixed[0].end, "")
    pairs = [("Safety Factor", "double", v.split()[0])]
    if v.endswith("allowed"):
        pairs.append(("Allow Unstable Time Step", "bool", "true"))
    new = with_params(text, s, pairs)
    check = ANY if v in ("1.5", "2.5 allowed") else error("Safety Factor")
    return (f"Solver/Verlet/Safety Factor = {v}" + (" (Allow Unstable Time Step)" if v.endswith("allowed") else "")
            + (" (Fixed dt removed)" if fixed else ""), new, check)


def op_wall(text, rng, els, ctx):
    """A rigid wall the body starts behind (normal flipped, inside or beyond the body, zero normal), one in
    front with a gap, a second wall beside the bar, or a wall added to a deck without one."""
    walls = [e for e in lists(els, *[x.path[-2] for x in params(els, "Type") if x.value == "Rigid Wall"])]
    if not walls:
        if rng.random() < (0.5 if solver_list(els).name == "Verlet" else 0.85):
            raise IndexError  # mostly the walls of the Taylor deck
        bc = top_list(els, "Boundary Conditions")
        xml = ('  <ParameterList name="Floor">\n' + param_xml("Type", "string", "Rigid Wall") + "\n" +
               param_xml("Point Y", "double", "-0.01") + "\n" + param_xml("Normal Y", "double", "1.0") +
               "\n    </ParameterList>")
        return ("Boundary Conditions/Floor: a Rigid Wall below the body added (solver "
                f"{solver_list(els).name})", insert_into(text, bc, xml), ANY)
    w = walls[0]
    pz = [p for p in params(els, "Point Z") if p.path[:-1] == w.path]
    nz = [p for p in params(els, "Normal Z") if p.path[:-1] == w.path]
    length = float(value_of(els, "Length", "0.0127"))
    kind = rng.choice(["flip", "inside", "beyond", "zero normal", "gap", "second", "second inside"])
    if kind == "flip":
        desc, new = set_value(text, nz[0], "-1.0")
        return desc + " (normal flipped: the body behind the wall)", new, error(w.name)
    if kind == "inside":
        desc, new = set_value(text, pz[0], fmt(length / 2))
        return desc + " (the wall through the middle of the bar)", new, error(w.name)
    if kind == "beyond":
        desc, new = set_value(text, pz[0], fmt(length * 1.5))
        return desc + " (the whole bar behind the wall)", new, error(w.name)
    if kind == "zero normal":
        desc, new = set_value(text, nz[0], "0.0")
        return desc + " (no normal)", new, error(w.name)
    if kind == "gap":
        desc, new = set_value(text, pz[0], "-0.001")
        return desc + " (1.4 mm gap before the impact)", new, ANY
    inside = kind == "second inside"
    px = "0.0" if inside else "0.0029"
    xml = ('  <ParameterList name="Side Wall">\n' + param_xml("Type", "string", "Rigid Wall") + "\n" +
           param_xml("Point X", "double", px) + "\n" + param_xml("Normal X", "double", "-1.0") +
           "\n    </ParameterList>")
    return (f"Boundary Conditions/Side Wall: a second Rigid Wall at x = {px}, normal -x"
            + (" (through the bar's axis)" if inside else " (beside the bar: squeezes it as it spreads)"),
            insert_into(text, top_list(els, "Boundary Conditions"), xml), error("Side Wall") if inside else ANY)


def op_newmark(text, rng, els, ctx):
    """Newmark's Beta or Gamma at 1e-300, 1e300, negative or out of range."""
    p = rng.choice(params(els, "Beta", "Gamma"))
    v = rng.choice({"Beta": ["1e-300", "1e300", "-0.25", "0", "0.6", "0.5"],
                    "Gamma": ["1e300", "-0.5", "0.4", "1e-300", "0.6"]}[p.name])
    valid = (p.name == "Beta" and 0 < float(v) <= 0.5) or (p.name == "Gamma" and float(v) >= 0.5)
    desc, new = set_value(text, p, v)
    return desc, new, ANY if valid else error(p.name)


def op_tolerance(text, rng, els, ctx):
    """A tolerance below what double precision can reach."""
    p = rng.choice(params(els, "Relative Tolerance", "Absolute Tolerance"))
    v = rng.choice(["1e-300", "1e-20", "5e-324"])
    desc, new = set_value(text, p, v)
    return desc, new, error(p.name)


def op_hardening(text, rng, els, ctx):
    """Drucker-Prager's Initial Hardening Parameter just past 1 (issue 40: reported as 'got 1'), 0, 1."""
    p = rng.choice(params(els, "Initial Hardening Parameter"))
    v = rng.choice(["1.0000001", "1.0000001", "0", "1", "1e-300", "-0.2"])
    desc, new = set_value(text, p, v)
    return desc, new, ANY if v in ("1", "1e-300") else error(p.name, v)


def op_cylinder(text, rng, els, ctx):
    """A cylinder centre so far out that the lattice's points coincide (issue 40: named no parameter)."""
    if value_of(els, "Type") != "Cylinder":
        raise IndexError
    name = rng.choice(["Z Center", "Z Center", "Z Center", "X Center", "Y Center"])
    v = rng.choice(["1e300", "1e300", "-1e300", "1e20"])
    disc = top_list(els, "Discretization")
    return f"Discretization/{name} = {v} added", with_params(text, disc, [(name, "double", v)]), error(name)


def op_solver_swap(text, rng, els, ctx):
    """The deck under another solver: the band under Verlet, an ADR deck under NOX, a NOX deck under ADR."""
    s = solver_list(els)
    # Not ADR for the decks whose examples use NOX because ADR takes minutes there (beam, four-point).
    slow = s.name == "NOXQuasiStatic" and value_of(els, "Material Model") != "Elastic Plastic Hardening" or \
        value_of(els, "Type") == "Box With Holes"
    target = rng.choice([t for t in ("Verlet", "NOXQuasiStatic", "Adaptive Dynamic Relaxation")
                         if t != s.name and not (slow and t == "Adaptive Dynamic Relaxation")])
    if s.name == "Implicit":
        raise IndexError
    ft = [p for p in params(els, "Final Time") if p.path == ["Solver", "Final Time"]]
    if target == "Verlet":
        rho = float(value_of(els, "Density", "8000"))
        e = float(value_of(els, "Young's Modulus", value_of(els, "Bulk Modulus", "2e11")))
        dx = float(value_of(els, "Spacing", "0.001"))
        final = 300 * dx / math.sqrt(e / rho)  # a few hundred stable steps
        body = param_xml("Safety Factor", "double", "0.8")
        text = set_value(text, ft[0], f"{final:.3g}")[1]
    else:
        body = (param_xml("Number of Load Steps", "int", "10") + "\n" +
                param_xml("Relative Tolerance", "double", "1e-6"))
    els = scan(text)
    s = solver_list(els)
    xml = f'<ParameterList name="{target}">\n{body}\n    </ParameterList>'
    return (f"Solver/{s.name} replaced by {target}" + (" (Final Time a few hundred steps)" if target == "Verlet"
                                                        else " (10 load steps)"),
            replace(text, s.start, s.end, xml), ANY)


def op_syntactic(text, rng, els, ctx):
    """One of issue 15's syntactic operators (generate_decks.OPERATORS) applied to an example base."""
    op = rng.choice([op for op, weight in generate_decks.OPERATORS for _ in range(weight)])
    desc, new = op(text, rng, els)
    return f"{op.__name__[3:]}: {desc}", new, None


OPERATORS = [(op_velocity, 4), (op_scale, 4), (op_extreme, 4), (op_tensile, 5), (op_checkpoint, 5),
             (op_output_name, 4), (op_second_output, 2), (op_nox_option, 6), (op_nox_valid, 2),
             (op_duplicate_spelling, 3), (op_thickness, 3), (op_safety, 5), (op_wall, 10), (op_newmark, 8),
             (op_tolerance, 3), (op_hardening, 4), (op_cylinder, 6), (op_solver_swap, 2)]
# The share of cases made by op_syntactic (issue 15's operators); the rest draw from OPERATORS, retrying an
# operator that has nothing to act on in the base, so that every base gets its semantic cases.
SYNTACTIC_SHARE = 0.25


class Pick(random.Random):
    """An rng whose choice() takes the first option that one of wanted names (the option itself, or a
    parameter's name or path), else draws as usual: how ISSUE_CASES steer the operators to the issue's values."""

    def __init__(self, wanted, seed):
        super().__init__(seed)
        self.wanted = wanted

    def choice(self, seq):
        for w in self.wanted:
            for x in seq:
                if x == w or getattr(x, "name", None) == w or (hasattr(x, "where") and x.where() == w):
                    return x
        return super().choice(seq)


# The cases issue 40 reports, first in every list (each a test that fails before the fix): base, operator,
# the values it takes ("{deck}": the case's own deck file).
ISSUE_CASES = [
    ("fuzz40_taylor.xml", op_velocity, ["-1e300"]),
    ("fuzz40_taylor.xml", op_velocity, ["-1e160"]),
    ("fuzz40_taylor.xml", op_checkpoint, ["fuzz40_taylor", "fuzz40_taylor.e.part"]),
    ("fuzz40_taylor.xml", op_checkpoint, ["fuzz40_taylor", "{deck}"]),
    ("fuzz40_taylor.xml", op_checkpoint, ["fuzz40_taylor", "fuzz40_taylor.lock"]),
    ("fuzz40_taylor.xml", op_checkpoint, ["fuzz40_taylor", "fuzz40_taylor.csv"]),
    ("fuzz40_taylor.xml", op_output_name, ["Output2/Output Filename", "/"]),
    ("fuzz40_taylor.xml", op_output_name, ["Output2/Output Filename", "./"]),
    ("fuzz40_kinplate.xml", op_nox_option, ["solver", "Magic Based"]),
    ("fuzz40_kinplate.xml", op_nox_option, ["line search", "Teleport"]),
    ("fuzz40_beam.xml", op_nox_option, ["direction", "Warp"]),
    ("fuzz40_kinplate.xml", op_duplicate_spelling, [("20", "5")]),
    ("fuzz40_fourpoint.xml", op_thickness, [10.0]),
    ("fuzz40_notched.xml", op_safety, ["1e300"]),
    ("fuzz40_notched.xml", op_safety, ["2.5"]),
    ("fuzz40_taylor.xml", op_wall, ["flip"]),
    ("fuzz40_taylor.xml", op_wall, ["beyond"]),
    ("fuzz40_taylor.xml", op_wall, ["second"]),
    ("fuzz40_taylor.xml", op_extreme, ["Hourglass Coefficient", "0"]),
    ("fuzz40_taylor.xml", op_extreme, ["Reference Plastic Strain Rate", "1e-30"]),
    ("fuzz40_band.xml", op_solver_swap, ["Verlet"]),
    ("fuzz40_newmark.xml", op_newmark, ["Beta", "1e-300"]),
    ("fuzz40_newmark.xml", op_newmark, ["Gamma", "1e300"]),
    ("fuzz40_newmark.xml", op_velocity, ["1e300"]),
    ("fuzz40_band.xml", op_hardening, ["1.0000001"]),
    ("fuzz40_taylor.xml", op_cylinder, ["Z Center", "1e300"]),
    ("fuzz40_fourpoint.xml", op_tolerance, ["Relative Tolerance", "1e-300"]),
    ("fuzz40_fourpoint.xml", op_tensile, ["Tensile Strength"]),
]


def stiffness(v):
    """The larger of the bulk and shear moduli a parameter dict gives (inf when nu is -1 or 1/2)."""
    try:
        if "Bulk Modulus" in v:
            return max(float(v["Bulk Modulus"]), float(v.get("Shear Modulus", "0")))
        e, nu = float(v["Young's Modulus"]), float(v.get("Poisson's Ratio", "0.25"))
        k = e / (3 * (1 - 2 * nu)) if nu != 0.5 else math.inf
        g = e / (2 * (1 + nu)) if nu != -1 else math.inf
        return max(abs(k), abs(g))
    except (KeyError, ValueError, OverflowError):
        return None


def long_run(text, base):
    """A valid deck that merely runs long (more than 20000 Verlet steps, see generate_decks.long_run), also
    without Fixed dt: the step is then Safety Factor x the stable estimate, which scales with
    sqrt(density / stiffness), the stiffness max(K, G) (Poisson's ratio near -1 or 1/2 makes it huge).
    Counts past 2^31 - 1 steps must be refused, so they stay in."""
    if generate_decks.long_run(text):
        return True
    v = {m.group(1): m.group(3) for m in PARAM.finditer(text)}
    if base not in UNIT_DT or "Fixed dt" in v or '<ParameterList name="Verlet">' not in text:
        return False
    b = {m.group(1): m.group(3) for m in PARAM.finditer(open(os.path.join(HERE, base)).read())}
    try:
        dt = UNIT_DT[base] * float(v.get("Safety Factor", "0.8")) * math.sqrt(
            float(v["Density"]) / float(b["Density"]) * stiffness(b) / stiffness(v))
        steps = (float(v["Final Time"]) - float(v.get("Initial Time", "0"))) / dt
    except (KeyError, ValueError, ZeroDivisionError, OverflowError, TypeError):
        return False
    return 2e4 < steps <= 2 ** 31 - 1


def generate(count=COUNT, seed=SEED):
    """[(case name, base deck, description, deck text, Check or None)], count distinct mutations: first
    ISSUE_CASES (their descriptions end "(issue 40)"), then random ones, the bases in turn."""
    rng = random.Random(seed)
    texts = {b: open(os.path.join(HERE, b), encoding="utf-8").read() for b in BASES}
    ops = [op for op, weight in OPERATORS for _ in range(weight)]
    cases, seen = [], set()
    while len(cases) < count:
        i = len(cases)
        base = ISSUE_CASES[i][0] if i < len(ISSUE_CASES) else BASES[i % len(BASES)]
        text = texts[base]
        name = f"{os.path.splitext(base)[0]}_{i:03d}"
        ctx = {"deck": name + ".xml"}
        syntactic = i >= len(ISSUE_CASES) and rng.random() < SYNTACTIC_SHARE
        for _ in range(1000):
            if i < len(ISSUE_CASES):
                op, r = ISSUE_CASES[i][1], Pick([w.format(**ctx) if isinstance(w, str) else w
                                                 for w in ISSUE_CASES[i][2]], seed)
            else:
                op, r = op_syntactic if syntactic else rng.choice(ops), rng
            try:
                desc, new, check = op(text, r, scan(text), ctx)
            except (IndexError, StopIteration):  # the operator has nothing to act on in this base
                if i < len(ISSUE_CASES):
                    raise
                continue
            if new != text and new not in seen and not long_run(new, base):
                break
            if i < len(ISSUE_CASES):
                raise RuntimeError(f"generate_semantic: issue case {i} ({op.__name__}) is no new case")
        else:
            raise RuntimeError(f"generate_semantic: no new mutation of {base} found")
        seen.add(new)
        kind = "syntactic" if op is op_syntactic else op.__name__[3:]
        cases.append((name, base, f"{kind}: " + " ".join(desc.split()) + (" (issue 40)" if i < len(ISSUE_CASES)
                                                                        else ""), new, check))
    return cases


if __name__ == "__main__":
    generate_decks.write_decks(__doc__, generate, COUNT, SEED,
                               lambda c: f"{c[0]}\t{c[1]}\t{c[4] or 'issue 15 rules'}\t{c[2]}")

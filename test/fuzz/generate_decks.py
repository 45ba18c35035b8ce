#!/usr/bin/env python3
"""Mutated decks for the fuzz test (issue 15): edits a user could make to three small, valid base decks.

Every mutation is one edit of a base deck's text: delete, duplicate or retype a parameter, replace a number
(0, negative, huge, tiny, nan, inf, text, empty, int vs double), misname a model, solver, node set or output
variable, corrupt the XML, break an expression or give it an out-of-domain argument, point a file name
nowhere, ask for sizes the size guard must refuse. The choice is drawn from random.Random(SEED), so a (seed, count) pair always gives the same decks.

usage: generate_decks.py OUT_DIR [--count N] [--seed S]
  writes OUT_DIR/<case>.xml (plus the node-set file the plastic deck needs) and OUT_DIR/index.txt
  (one line per case: its name and what was changed). run_fuzz.py imports generate() instead.
"""
import argparse
import os
import random
import re

HERE = os.path.dirname(os.path.abspath(__file__))
BASES = ["fuzz_verlet.xml", "fuzz_nox.xml", "fuzz_plastic.xml"]
# Files a base deck reads, copied beside every mutated deck.
SIDE_FILES = ["fuzz_plastic_minx.txt"]
SEED = 15
COUNT = 240

PARAM = re.compile(r'<Parameter name="([^"]*)" type="([^"]*)" value="([^"]*)"/>')
LIST_OPEN = re.compile(r'<ParameterList(?: name="([^"]*)")?>')
LIST_CLOSE = "</ParameterList>"


class Element:
    """A <Parameter> or a named <ParameterList> of a deck's text: its path, and where it lies."""

    def __init__(self, kind, path, start, end, type_="", value="", value_span=None):
        self.kind, self.path, self.start, self.end = kind, path, start, end
        self.type, self.value, self.value_span = type_, value, value_span

    @property
    def name(self):
        return self.path[-1]

    def where(self):
        return "/".join(self.path)


def scan(text):
    """Every parameter and named sub-list of the deck, in order (the root list has no name)."""
    elements, stack = [], []
    token = re.compile(PARAM.pattern + "|" + LIST_OPEN.pattern + "|" + re.escape(LIST_CLOSE))
    for m in token.finditer(text):
        if m.group(0).startswith("<Parameter "):
            elements.append(Element("param", [e.name for e in stack if e] + [m.group(1)], m.start(), m.end(),
                                    m.group(2), m.group(3), m.span(3)))
        elif m.group(0) == LIST_CLOSE:
            opened = stack.pop()
            if opened:
                opened.end = m.end()
        else:
            named = m.group(4) is not None
            e = Element("list", [x.name for x in stack if x] + [m.group(4)], m.start(), -1) if named else None
            stack.append(e)
            if e:
                elements.append(e)
    return elements


def replace(text, start, end, new):
    return text[:start] + new + text[end:]


def set_value(text, p, value):
    return f"{p.where()}: value '{p.value}' -> '{value}'", replace(text, p.value_span[0], p.value_span[1], value)


# --- mutation operators: each returns (description, new text) or None when it does not apply -------------

NUMBERS = ["0", "-1", "-0.5", "1e300", "-1e300", "1e-300", "5e-324", "nan", "inf", "-inf", "abc", "", " ",
           "1.0.0", "1,5", "0x1p3", "1e", "2.5", "1e3", "2147483648", "-2147483649", "+7", "1 2", "1e400"]


def op_number(text, rng, els):
    ps = [p for p in els if p.kind == "param" and p.type in ("double", "int")]
    p = rng.choice(ps)
    return set_value(text, p, rng.choice(NUMBERS))


def op_delete_param(text, rng, els):
    p = rng.choice([e for e in els if e.kind == "param"])
    return f"{p.where()}: deleted", replace(text, p.start, p.end, "")


def op_delete_list(text, rng, els):
    e = rng.choice([e for e in els if e.kind == "list"])
    return f"{e.where()}: sub-list deleted", replace(text, e.start, e.end, "")


def op_duplicate(text, rng, els):
    e = rng.choice([e for e in els if e.kind == "param"] + [e for e in els if e.kind == "list"][:6])
    copy = text[e.start:e.end]
    if e.kind == "param" and rng.random() < 0.5 and e.type in ("double", "int"):
        copy = copy.replace(f'value="{e.value}"', 'value="3"')
    return f"{e.where()}: given twice", replace(text, e.end, e.end, "\n" + copy)


TYPES = ["double", "int", "string", "bool", "float", "Array(double)", "", "DOUBLE"]


def op_type(text, rng, els):
    p = rng.choice([e for e in els if e.kind == "param"])
    t = rng.choice([t for t in TYPES if t != p.type])
    s = text.index(f'type="{p.type}"', p.start)
    return f"{p.where()}: type '{p.type}' -> '{t}'", replace(text, s, s + len(f'type="{p.type}"'), f'type="{t}"')


def op_bool(text, rng, els):
    ps = [e for e in els if e.kind == "param" and e.type == "bool"]
    return set_value(text, rng.choice(ps), rng.choice(["maybe", "1", "0", "TRUE", "yes", "", "false "]))


# Names a user could get wrong: the parameter whose value is a name, and wrong names for it.
WRONG_NAMES = {
    "Material Model": ["Elastc", "Viscoplastic", "elastic", "Elastic Plastic Hardening ", ""],
    "Material": ["Stel", "steel", ""],
    "Node Set": ["Nowhere", "Left layer", "All Nodes", "", "1 2 3"],
    "Coordinate": ["w", "X", "xy", "", "3"],
    "Block Names": ["block_2", "block_0", "block_1 block_1", "blk", "", "default"],
    "Type": ["Node Set", "Box", "Prescribed Velocity", "Rectangle", "", "PdQuickGrid"],
    "Fictitious Layers": ["Middle", "Left Left", "Front", ";", "Left,Right,Top"],
    "Face": ["Min W", "min y", "Max Z", ""],
    "Influence Function": ["Cubic", "1.0/zeta", "zeta/(zeta-zeta)", "foo(zeta)", "1.0/(horizon-horizon)", ""],
    "Variables": ["Foo", "Displacement Strain", "", "Velocity,,Force", "Equivalent_Plastic_Strain"],
    "Reactions": ["Nowhere", ", ,", "Left Layer, Left Layer", ""],
    "Reaction Names": ["L", "Left, Left", "", "Left, Right, Extra"],
    "Applied Displacement": ["Nowhere", "Clamp Y", ""],
    "Output Filename": ["no/such/dir/out", "", ".", "a b", "../fuzz_out", "-e", "sub/"],
    "Output File Type": ["Exodus", "CSV", ""],
    "NeighborhoodType": ["Cubic", ""],
    "Yield Normalization": ["Both", ""],
    "Min X Node Set": ["missing_nodes.txt", "/no/such/file", ".", "0 1 2", "1 2 x", "", "99999"],
    "Max X Node Set": ["missing_nodes.txt", "-1 -2", "1.5", "", "100000000000"],
}


def op_name(text, rng, els):
    ps = [e for e in els if e.kind == "param" and e.name in WRONG_NAMES]
    p = rng.choice(ps)
    return set_value(text, p, rng.choice([n for n in WRONG_NAMES[p.name] if n != p.value]))


def op_rename(text, rng, els):
    """A misspelt parameter or sub-list name (solver, material, output variable, ...)."""
    e = rng.choice([e for e in els if e.name])
    wrong = rng.choice([e.name + "s", e.name.lower(), e.name[:-1], e.name.replace(" ", "_"), "Adaptive Dynamic Relax",
                        "Verlet2", "Solver0", "Output Variable", "Strain_Energy", "Damage Models", "Contact"])
    s = text.index(f'name="{e.name}"', e.start)
    return f"{e.where()}: renamed '{wrong}'", replace(text, s, s + len(f'name="{e.name}"'), f'name="{wrong}"')


EXPRESSIONS = ["1.0/(t-t)", "t*", "foo(t)", "0.0/0.0", "", "value = ;", "x*y*z*t*1e300*1e300",
               "if (t) { value = 1; }", "t^", "1e400*t", "t/(t-0.5)", "exp(1000*t+1000)", "((t)",
               "value = x; value = y;", "pow(t, -1)", "t &amp;&amp;", "gamma(-t)", "atan2(0, 0)*t",
               "1.0e-3*x*t;;", "value = 1.0e-3*x*t", "zeta*t", "x = 3; value = x*t;", "1.0.0*t", "1e-400*t",
               "99999999999*t", "1ee5*t", ".e5*t"]
# Out-of-domain arguments made Pamgen's RTCompiler assert (SIGABRT, exit 134) when evaluated, until issue 15
# part 2 (src/core/Expression.cpp) turned them into input errors.
DOMAIN_ERRORS = ["1.0e-3*x*sqrt(0.6-t)", "log(t-1)", "acos(2+t)", "asin(t-3)", "log10(-t)"]


def op_expression(text, rng, els):
    ps = [e for e in els if e.kind == "param" and e.name == "Value"]
    return set_value(text, rng.choice(ps), rng.choice(EXPRESSIONS))


def op_domain(text, rng, els):
    ps = [e for e in els if e.kind == "param" and e.name == "Value"]
    return set_value(text, rng.choice(ps), rng.choice(DOMAIN_ERRORS))


def op_xml(text, rng, els):
    kind = rng.choice(["truncate", "drop close", "extra open", "bad entity", "open quote", "garbage", "empty",
                       "second root", "no root", "bad attribute", "binary", "mismatched tag"])
    if kind == "truncate":
        cut = rng.randrange(1, len(text) - 1)
        return f"XML truncated at byte {cut}", text[:cut]
    if kind == "drop close":
        closes = [m.start() for m in re.finditer(re.escape(LIST_CLOSE), text)]
        c = rng.choice(closes)
        return f"XML: </ParameterList> at byte {c} deleted", replace(text, c, c + len(LIST_CLOSE), "")
    if kind == "extra open":
        e = rng.choice(els)
        return f"XML: unclosed <ParameterList> before {e.where()}", replace(text, e.start, e.start, '<ParameterList name="X">')
    if kind == "bad entity":
        p = rng.choice([e for e in els if e.kind == "param"])
        return set_value(text, p, rng.choice(["&foo;", "&", "&#0;", "&#xFFFFFFFF;", "<"]))
    if kind == "open quote":
        p = rng.choice([e for e in els if e.kind == "param"])
        return f"XML: unterminated quote in {p.where()}", replace(text, p.value_span[1], p.value_span[1] + 1, "")
    if kind == "garbage":
        return "XML: not XML at all", "Discretization: Type = PdQuickGrid\n"
    if kind == "empty":
        return "XML: empty file", ""
    if kind == "second root":
        return "XML: two root elements", text + "\n<ParameterList></ParameterList>\n"
    if kind == "no root":
        body = text.strip()[len("<ParameterList>"):-len(LIST_CLOSE)]
        return "XML: root <ParameterList> removed", body
    if kind == "bad attribute":
        p = rng.choice([e for e in els if e.kind == "param"])
        return f"XML: {p.where()}: attribute 'value' -> 'valeu'", replace(text, p.value_span[0] - 7, p.value_span[0] - 1, "valeu=")
    if kind == "binary":
        pos = rng.randrange(len(text))
        return f"XML: bytes \\xff\\xfe\\x00 inserted at {pos}", replace(text, pos, pos, "\udcff\udcfe\x00")
    e = rng.choice([e for e in els if e.kind == "param"])
    return f"XML: {e.where()}: <Parameter ... /> -> <Parameter ...></Param>", replace(text, e.end - 2, e.end, "></Param>")


# Sizes the size guard (docs/input.md, "Size and memory guard") must refuse, or counts that must be rejected.
HUGE = {"Number Points X": ["100000", "2147483647", "1000000000000", "0", "-5"],
        "Number Points Y": ["100000", "65536"], "Number Points Z": ["2147483647", "46341"],
        "Number of Load Steps": ["2000000000", "10000001", "100000000000", "0"],
        "Spacing": ["1e-7", "1e-9", "1e-300", "1e300"], "Horizon": ["1.0", "1e10", "1e-12", "1e300"],
        "X Length": ["1e300", "1e-300", "0.0401"], "Output Frequency": ["0", "2147483647", "-1"],
        "Maximum Iterations": ["2147483647", "1"], "Maximum Solver Iterations": ["1", "100000"],
        "Final Time": ["1e300", "1e-300", "0", "-1"], "Fixed dt": ["1e-300", "5e-324", "1e300", "1e-7"],
        "Initial Time": ["1e300", "2.0", "-1e300"], "Radius": ["1e3", "1e-300"], "Thickness": ["1e-300", "1e300"],
        "Relative Tolerance": ["1e-300", "1e300"], "Maximum Memory": ["1", "1e300"]}


def op_size(text, rng, els):
    ps = [e for e in els if e.kind == "param" and e.name in HUGE]
    p = rng.choice(ps)
    return set_value(text, p, rng.choice(HUGE[p.name]))


def op_file(text, rng, els):
    """A mesh or node-set file that is missing, a directory, or unreadable."""
    path = rng.choice(["no_such_mesh.txt", "/no/such/dir/mesh.txt", ".", "/", "", "fuzz_plastic_minx.txt",
                       "fuzz_plastic.xml"])
    disc = next(e for e in els if e.kind == "list" and e.path == ["Discretization"])
    body = ('<ParameterList name="Discretization">\n    <Parameter name="Type" type="string" value="Text File"/>\n'
            f'    <Parameter name="Input Mesh File" type="string" value="{path}"/>\n  </ParameterList>')
    return f"Discretization: Text File with Input Mesh File '{path}'", replace(text, disc.start, disc.end, body)


OPERATORS = [(op_number, 5), (op_delete_param, 3), (op_delete_list, 2), (op_duplicate, 2), (op_type, 3),
             (op_bool, 1), (op_name, 4), (op_rename, 2), (op_expression, 3), (op_xml, 3), (op_size, 3),
             (op_file, 1), (op_domain, 2)]


def long_run(text):
    """A valid deck that merely runs long (more than 20000 Verlet steps of its Fixed dt, e.g. a Final Time of
    2.5 s instead of 2e-6 s) is no fuzz case: under the timeout it would count as a hang. Counts past 2^31 - 1
    steps are input errors (SolverInput.cpp) and stay in."""
    v = {m.group(1): m.group(3) for m in PARAM.finditer(text)}
    try:
        steps = (float(v["Final Time"]) - float(v.get("Initial Time", "0"))) / float(v["Fixed dt"])
    except (KeyError, ValueError, ZeroDivisionError):
        return False
    return 2e4 < steps <= 2 ** 31 - 1


def generate(count=COUNT, seed=SEED):
    """[(case name, base deck, description, deck text)], count distinct mutations, the same every time."""
    rng = random.Random(seed)
    bases = [(b, open(os.path.join(HERE, b), encoding="utf-8").read()) for b in BASES]
    ops = [op for op, weight in OPERATORS for _ in range(weight)]
    cases, seen = [], set()
    while len(cases) < count:
        base, text = bases[len(cases) % len(bases)]
        op = rng.choice(ops)
        try:
            desc, new = op(text, rng, scan(text))
        except IndexError:  # the operator has nothing to act on in this deck (rng.choice of an empty list)
            continue
        if new == text or new in seen or long_run(new):
            continue
        seen.add(new)
        name = f"{os.path.splitext(base)[0]}_{len(cases):03d}"
        cases.append((name, base, f"{op.__name__[3:]}: {desc}", new))
    return cases


def write_case(directory, name, text):
    """The deck and the files it may read; surrogate escapes stand for raw (non-UTF-8) bytes."""
    path = os.path.join(directory, name + ".xml")
    with open(path, "wb") as f:
        f.write(text.encode("utf-8", "surrogateescape"))
    for side in SIDE_FILES:
        with open(os.path.join(HERE, side), "rb") as src, open(os.path.join(directory, side), "wb") as dst:
            dst.write(src.read())
    return path


def write_decks(doc, generate_cases, count, seed, index_line):
    """The command line of a deck generator: OUT_DIR [--count N] [--seed S]; writes every case's deck and
    OUT_DIR/index.txt, one index_line(case) per case (case: generate_cases(count, seed)'s tuples)."""
    ap = argparse.ArgumentParser(description=doc.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("--count", type=int, default=count)
    ap.add_argument("--seed", type=int, default=seed)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "index.txt"), "w") as index:
        for case in generate_cases(a.count, a.seed):
            write_case(a.out, case[0], case[3])
            index.write(index_line(case) + "\n")


if __name__ == "__main__":
    write_decks(__doc__, generate, COUNT, SEED, lambda c: f"{c[0]}\t{c[1]}\t{c[2]}")

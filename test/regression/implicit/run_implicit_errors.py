#!/usr/bin/env python3
"""Bad Implicit solver input: each case must stop with one line naming the file and the parameter, like the
other user-facing errors (errors/run_error_cases.py, whose runner this reuses on its base deck).

usage: run_implicit_errors.py PERIFORGE_EXE BASE_DECK   (BASE_DECK: test/regression/bar/bar_3d.xml)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "errors"))
import run_error_cases  # noqa: E402

ADR = r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>'


def implicit(params):
    return [(ADR, '<ParameterList name="Implicit">' + params + '</ParameterList>')]


def p(name, value, kind="double"):
    return '<Parameter name="%s" type="%s" value="%s"/>' % (name, kind, value)


CASES = [
    ("Implicit without Fixed dt", implicit(p("Beta", "0.25")), ["Solver/Implicit", "Fixed dt", "missing"]),
    ("Implicit Beta above 1/2", implicit(p("Fixed dt", "0.1") + p("Beta", "0.6")),
     ["Solver/Implicit", "'Beta'", "(0, 0.5]", "0.6"]),
    ("Implicit Beta zero (explicit Newmark is not served)", implicit(p("Fixed dt", "0.1") + p("Beta", "0")),
     ["Solver/Implicit", "'Beta'", "(0, 0.5]"]),
    ("Implicit Gamma below 1/2", implicit(p("Fixed dt", "0.1") + p("Gamma", "0.4")),
     ["Solver/Implicit", "'Gamma'", ">= 0.5"]),
    ("Implicit Fixed dt beyond the run", implicit(p("Fixed dt", "2.0")), ["Solver/Implicit", "'Fixed dt'", "no step"]),
    ("Implicit unknown parameter", implicit(p("Fixed dt", "0.1") + p("Number of Load Steps", "2", "int")),
     ["Solver/Implicit", "Number of Load Steps"]),
]

if __name__ == "__main__":
    run_error_cases.CASES = CASES
    sys.exit(run_error_cases.main(sys.argv[1], sys.argv[2]))

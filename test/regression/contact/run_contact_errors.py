#!/usr/bin/env python3
"""Bad Contact input: each case must stop with one line naming the file and the parameter, no crash and no output,
like the other user-facing errors (errors/run_error_cases.py, whose runner this reuses on its base deck).

usage: run_contact_errors.py PERIFORGE_EXE BASE_DECK   (BASE_DECK: test/regression/contact/pair.xml)
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "errors"))
import run_error_cases  # noqa: E402

CONTACT_CASES = [
    ("contact interaction with a block the mesh lacks",
     [('<ParameterList name="Self Contact">', '<ParameterList name="Pair"><Parameter name="First Block" type="string" '
       'value="block_1"/><Parameter name="Second Block" type="string" value="block_7"/>')],
     ["Contact/Interactions/Pair", "block_7"]),
    ("contact interaction with a block that is not a block name",
     [('<ParameterList name="Self Contact">', '<ParameterList name="Pair"><Parameter name="First Block" type="string" '
       'value="block_1"/><Parameter name="Second Block" type="string" value="Block1"/>')],
     ["Contact/Interactions/Pair", "Block1"]),
    ("negative contact radius",
     [('name="Contact Radius" type="double" value="2.0e-3"', 'name="Contact Radius" type="double" value="-2.0e-3"')],
     ["Contact/Models/Spring", "Contact Radius"]),
    ("search radius below the contact radius",
     [('name="Search Radius" type="double" value="3.0e-3"', 'name="Search Radius" type="double" value="1.0e-3"')],
     ["Contact/Models/Spring", "Search Radius"]),
    ("interaction names an unknown contact model",
     [('<Parameter name="Contact Model" type="string" value="Spring"/>',
       '<Parameter name="Contact Model" type="string" value="Sprng"/>')],
     ["Contact/Interactions/Self Contact", "Sprng"]),
    ("horizon given to a contact model",
     [('<Parameter name="Spring Constant"', '<Parameter name="Horizon" type="double" value="1.0e-3"/><Parameter name="Spring Constant"')],
     ["Contact/Models/Spring", "Horizon"]),
    ("missing search frequency",
     [('<Parameter name="Search Frequency" type="int" value="10"/>', '')],
     ["Contact", "Search Frequency"]),
    ("friction function for the constant-friction law",
     [('<Parameter name="Spring Constant"', '<Parameter name="Friction Coefficient" type="string" value="0.1*t"/>'
       '<Parameter name="Spring Constant"')],
     ["Contact/Models/Spring", "Friction Coefficient"]),
    ("contact with a quasi-static solver",
     [('<ParameterList name="Verlet">.*?</ParameterList>', '<ParameterList name="Adaptive Dynamic Relaxation">'
       '<Parameter name="Number of Load Steps" type="int" value="2"/></ParameterList>')],
     ["Contact", "Verlet"]),
]

if __name__ == "__main__":
    run_error_cases.CASES = CONTACT_CASES
    sys.exit(run_error_cases.main(sys.argv[1], sys.argv[2]))

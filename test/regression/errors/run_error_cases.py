#!/usr/bin/env python3
"""User-facing error tests: each bad deck must make `periforge` exit non-zero with one line on stderr
that names the input file and the offending parameter, without a crash (no signal, no abort) and
without writing an Exodus or CSV file that could pass for a result, within 30 s.

usage: run_error_cases.py PERIFORGE_EXE BASE_DECK
BASE_DECK is a valid 3D deck (test/regression/bar/bar_3d.xml); every case edits a copy of it.
"""
import os
import re
import subprocess
import sys
import tempfile
import time

CASES = [
    # name, (pattern, replacement) edits, words the message must contain
    ("unknown parameter",
     [('<Parameter name="Density"', '<Parameter name="Densty" type="double" value="1"/>\n      <Parameter name="Density"')],
     ["Densty"]),
    ("unknown sub-list",
     [('<ParameterList name="Solver">', '<ParameterList name="Solvr"></ParameterList>\n  <ParameterList name="Solver">')],
     ["Solvr"]),
    ("unknown damage model",
     [('<ParameterList name="Blocks">', '<ParameterList name="Damage Models"><ParameterList name="D">'
       '<Parameter name="Damage Model" type="string" value="Critical Energy"/></ParameterList></ParameterList>\n'
       '  <ParameterList name="Blocks">')],
     ["Damage Models/D", "Critical Energy"]),
    ("block names an undefined damage model",
     [('<Parameter name="Material" type="string" value="Steel"/>',
       '<Parameter name="Material" type="string" value="Steel"/><Parameter name="Damage Model" type="string" value="Brittle"/>')],
     ["Damage Model", "Brittle"]),
    ("damage model on a material that does not break bonds",
     [('<ParameterList name="Blocks">', '<ParameterList name="Damage Models"><ParameterList name="Brittle">'
       '<Parameter name="Damage Model" type="string" value="Critical Stretch"/>'
       '<Parameter name="Critical Stretch" type="double" value="0.01"/></ParameterList></ParameterList>\n'
       '  <ParameterList name="Blocks">'),
      ('<Parameter name="Material" type="string" value="Steel"/>',
       '<Parameter name="Material" type="string" value="Steel"/><Parameter name="Damage Model" type="string" value="Brittle"/>'),
      ('<Parameter name="Material Model" type="string" value="Elastic"/>',
       '<Parameter name="Material Model" type="string" value="Elastic Correspondence"/>'
       '<Parameter name="Hourglass Coefficient" type="double" value="0.05"/>')],
     ["Damage Model", "does not break bonds"]),
    ("missing material",
     [('<Parameter name="Material" type="string" value="Steel"/>', '<Parameter name="Material" type="string" value="Stel"/>')],
     ["Stel"]),
    ("negative horizon",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="double" value="-0.006"/>')],
     ["Horizon"]),
    ("empty node set",
     [('<ParameterList name="Left X">', '<ParameterList name="Nowhere">\n      <Parameter name="Type" type="string" value="Node Set Region"/>\n'
       '      <Parameter name="X Min" type="double" value="5.0"/>\n    </ParameterList>\n'
       '    <ParameterList name="On Nowhere"><Parameter name="Type" type="string" value="Prescribed Displacement"/>\n'
       '      <Parameter name="Node Set" type="string" value="Nowhere"/><Parameter name="Coordinate" type="string" value="x"/>\n'
       '      <Parameter name="Value" type="string" value="0.0"/></ParameterList>\n    <ParameterList name="Left X">')],
     ["Nowhere"]),
    # (Node-set ids the mesh lacks are dropped with a warning, as Peridigm does: no longer an error.)
    ("influence function that does not compile",
     [('<ParameterList name="Discretization">', '<ParameterList name="Discretization">\n    <Parameter name="Influence Function" type="string" value="1.0/(zeta"/>')],
     ["Influence Function", "1.0/(zeta"]),
    ("plain and numbered solver lists together",
     [('<ParameterList name="Solver">', '<ParameterList name="Solver2"></ParameterList>\n  <ParameterList name="Solver">')],
     ["Solver2", "not both"]),
    ("numbered solver list with a leading zero",
     [('<ParameterList name="Solver">', '<ParameterList name="Solver01"></ParameterList>\n  <ParameterList name="Solver">')],
     ["Solver01", "leading zero"]),
    ("empty Output Filename",
     [('<Parameter name="Output Filename" type="string" value="bar_3d"/>', '<Parameter name="Output Filename" type="string" value=""/>')],
     ["Output", "Output Filename", "empty"]),
    ("probe outside the body",
     [('<Parameter name="X" type="double" value="0.075"/>', '<Parameter name="X" type="double" value="0.2"/>')],
     ["Output/Probes/Q3", "outside the body"]),
    ("Final Output Step below 1",
     [('<Parameter name="Output Filename" type="string" value="bar_3d"/>', '<Parameter name="Output Filename" type="string" value="bar_3d"/>\n    <Parameter name="Final Output Step" type="int" value="0"/>')],
     ["Final Output Step"]),
    ("Loading Balance Correction on a material without it",
     [('<Parameter name="Relative Tolerance" type="double" value="1.0e-7"/>',
       '<Parameter name="Relative Tolerance" type="double" value="1.0e-7"/>'
       '<Parameter name="Loading Balance Correction" type="bool" value="true"/>')],
     ["Solver/Adaptive Dynamic Relaxation", "'Loading Balance Correction'", "block_1", "Steel"]),
    ("Time Steps that do not increase",
     [(r'<Parameter name="Final Time" type="double" value="1.0"/>\s*<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="QuasiStatic"><Parameter name="Time Steps" type="string" value="0.0 0.5 0.4"/></ParameterList>'),
      (r'<Parameter name="Initial Time" type="double" value="0.0"/>', '')],
     ["Time Steps", "increase"]),
    ("Time Steps entry that is not a number",
     [(r'<Parameter name="Final Time" type="double" value="1.0"/>\s*<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="QuasiStatic"><Parameter name="Time Steps" type="string" value="0.0 0.5 one"/></ParameterList>'),
      (r'<Parameter name="Initial Time" type="double" value="0.0"/>', '')],
     ["Time Steps", "one"]),
    ("Final Time that is not the last of the Time Steps",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="QuasiStatic"><Parameter name="Time Steps" type="string" value="0.0 0.5 0.9"/></ParameterList>')],
     ["Final Time", "Time Steps", "0.9"]),
    # Interface Aware damage on one block and another model on the rest: per-bond thresholds are not implemented.
    ("Interface Aware beside another damage model",
     [('<ParameterList name="Blocks">', '<ParameterList name="Damage Models"><ParameterList name="IA">'
       '<Parameter name="Damage Model" type="string" value="Interface Aware"/>'
       '<Parameter name="Critical Stretch" type="double" value="0.01"/></ParameterList><ParameterList name="CS">'
       '<Parameter name="Damage Model" type="string" value="Critical Stretch"/>'
       '<Parameter name="Critical Stretch" type="double" value="0.01"/></ParameterList></ParameterList>\n'
       '  <ParameterList name="Blocks"><ParameterList name="Rest">'
       '<Parameter name="Block Names" type="string" value="default"/><Parameter name="Material" type="string" value="Steel"/>'
       '<Parameter name="Horizon" type="double" value="0.00603"/><Parameter name="Damage Model" type="string" value="CS"/>'
       '</ParameterList>'),
      ('<Parameter name="Material" type="string" value="Steel"/>\n',
       '<Parameter name="Material" type="string" value="Steel"/><Parameter name="Damage Model" type="string" value="IA"/>\n')],
     ["Blocks/Rest", "Interface Aware", "Critical Stretch"]),
    # Peridigm's QuasiStatic 'Adaptive Load-Stepping' (docs/peridigm.md): its lists are checked when the deck is read.
    ("adaptive load stepping without its maxima",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="QuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<Parameter name="Absolute Tolerance" type="double" value="1e-3"/>'
       '<ParameterList name="Adaptive Load-Stepping">'
       '<Parameter name="Maximum total load step reductions" type="int" value="5"/>'
       '</ParameterList></ParameterList>')],
     ["Adaptive Load-Stepping", "Maximum load step reductions in one step"]),
    ("Switch to Verlet without a time step",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="QuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<Parameter name="Absolute Tolerance" type="double" value="1e-3"/>'
       '<ParameterList name="Adaptive Load-Stepping">'
       '<Parameter name="Maximum load step reductions in one step" type="int" value="1"/>'
       '<Parameter name="Maximum total load step reductions" type="int" value="5"/>'
       '<ParameterList name="Switch to Verlet"><Parameter name="Output Frequency" type="int" value="10"/>'
       '<Parameter name="Safety Factr" type="double" value="0.6"/></ParameterList>'
       '</ParameterList></ParameterList>')],
     ["Switch to Verlet", "Safety Factr"]),
    # Issue 20: the linear solver list's choices are checked when the deck is read, not at the first solve.
    ("Krylov method other than GMRES",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<ParameterList name="Direction"><ParameterList name="Newton"><ParameterList name="Linear Solver">'
       '<Parameter name="Aztec Solver" type="string" value="CG"/></ParameterList></ParameterList></ParameterList>'
       '</ParameterList>')],
     ["Linear Solver", "Aztec Solver", "CG"]),
    ("unknown preconditioner",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<ParameterList name="Direction"><ParameterList name="Newton"><ParameterList name="Linear Solver">'
       '<Parameter name="Preconditioner" type="string" value="AMG"/></ParameterList></ParameterList></ParameterList>'
       '</ParameterList>')],
     ["Linear Solver", "Preconditioner", "AMG"]),
    ("ML's parameter sub-list",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<ParameterList name="Direction"><ParameterList name="Newton"><ParameterList name="Linear Solver">'
       '<ParameterList name="ML"><Parameter name="max levels" type="int" value="3"/></ParameterList>'
       '</ParameterList></ParameterList></ParameterList></ParameterList>')],
     ["Linear Solver", "'ML'", "MueLu"]),
    # Issue 35: MueLu's refusal used to read as a step that did not converge (silent fall-back to ADR).
    ("MueLu parameter MueLu does not take",
     [(r'<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<ParameterList name="NOXQuasiStatic"><Parameter name="Number of Load Steps" type="int" value="2"/>'
       '<ParameterList name="Direction"><ParameterList name="Newton"><ParameterList name="Linear Solver">'
       '<ParameterList name="MueLu"><Parameter name="coarse: maxsize" type="int" value="30"/></ParameterList>'
       '</ParameterList></ParameterList></ParameterList></ParameterList>')],
     ["Linear Solver", "preconditioner could not be built", "coarse: maxsize"]),
    ("unsupported Peridigm output variable",
     [('<ParameterList name="Output Variables">', '<ParameterList name="Output Variables">\n      <Parameter name="Strain_Energy" type="bool" value="true"/>')],
     ["Strain_Energy", "not supported"]),
    ("tensor output no material of the run computes",
     [('<ParameterList name="Output Variables">', '<ParameterList name="Output Variables">\n      <Parameter name="Rotation_Tensor" type="bool" value="true"/>')],
     ["Output/Output Variables", "Rotation_Tensor", "not computed"]),
    ("probe naming a whole tensor",
     [('<Parameter name="Variables" type="string" value="Displacement"/>',
       '<Parameter name="Variables" type="string" value="Displacement Deformation_Gradient"/>')],
     ["Output/Probes/Q3", "Deformation_Gradient", "one component"]),
    ("contact energy without a Contact list",
     [('<ParameterList name="Output Variables">', '<ParameterList name="Output Variables">\n      <Parameter name="Global_Contact_Energy" type="bool" value="true"/>')],
     ["Output/Output Variables", "Global_Contact_Energy", "needs a Contact list"]),
    ("heat global without a heat capacity",
     [('<ParameterList name="Output Variables">', '<ParameterList name="Output Variables">\n      <Parameter name="Global_Heat" type="bool" value="true"/>')],
     ["Output/Output Variables", "Global_Heat", "Specific Heat Capacity"]),
    ("acceleration from a quasi-static solver",
     [('<ParameterList name="Output Variables">', '<ParameterList name="Output Variables">\n      <Parameter name="Acceleration" type="bool" value="true"/>')],
     ["Acceleration", "Verlet"]),
    ("unreadable mesh",
     [(r'<Parameter name="Type" type="string" value="Box With Holes"/>.*?<Parameter name="Fictitious Layers" type="string" value="Left Right"/>',
       '<Parameter name="Type" type="string" value="Text File"/>\n    <Parameter name="Input Mesh File" type="string" value="no_such_mesh.txt"/>'),
      # the layers' node sets belong to the generator this case replaces
      (r'  <ParameterList name="Boundary Conditions">.*?\n  </ParameterList>\n', '')],
     ["no_such_mesh.txt"]),
    ("2D material on a 3D grid",
     [('<Parameter name="Poisson\'s Ratio" type="double" value="0.3"/>', '<Parameter name="Poisson\'s Ratio" type="double" value="0.3"/>\n'
       '      <Parameter name="Plane Stress" type="bool" value="true"/>\n      <Parameter name="Thickness" type="double" value="0.001"/>')],
     ["Steel", "2D"]),
    # Numbers are read whole (Teuchos alone would read "0.003abc" as 0.003 and an int "2.5" as 2).
    ("number with trailing text",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="double" value="0.00603abc"/>')],
     ["Horizon", "0.00603abc", "not a number"]),
    ("int that is not an integer",
     [('<Parameter name="Number of Load Steps" type="int" value="2"/>', '<Parameter name="Number of Load Steps" type="int" value="2.5"/>')],
     ["Number of Load Steps", "2.5", "not an integer"]),
    ("infinite number",
     [('<Parameter name="Density" type="double" value="8000.0"/>', '<Parameter name="Density" type="double" value="inf"/>')],
     ["Density", "finite"]),
    ("sub-list given twice",
     [('<ParameterList name="Materials">', '<ParameterList name="Materials"></ParameterList>\n  <ParameterList name="Materials">')],
     ["Materials", "twice"]),
    ("value outside the declared range",
     [('<Parameter name="Density" type="double" value="8000.0"/>', '<Parameter name="Density" type="double" value="-8000.0"/>')],
     ["Materials/Steel", "Density", "positive"]),
    ("unknown material model",
     [('<Parameter name="Material Model" type="string" value="Elastic"/>', '<Parameter name="Material Model" type="string" value="Elastc"/>')],
     ["Elastc"]),
    # Memory and size guard: refused from the deck's estimate before the cloud is built (docs/input.md,
    # "Size and memory guard"), in well under a second instead of std::bad_alloc after tens of seconds.
    ("spacing that makes more points than 32-bit ids",
     [('<Parameter name="Spacing" type="double" value="0.002"/>', '<Parameter name="Spacing" type="double" value="1e-7"/>')],
     ["Discretization", "32-bit", "'Spacing'"]),
    ("Number Points beyond 32-bit ids",
     [(r'<Parameter name="Type" type="string" value="Box With Holes"/>.*?<Parameter name="Fictitious Layers" type="string" value="Left Right"/>',
       '<Parameter name="Type" type="string" value="PdQuickGrid"/>\n    <ParameterList name="TensorProduct3DMeshGenerator">\n'
       '      <Parameter name="X Origin" type="double" value="0"/><Parameter name="Y Origin" type="double" value="0"/>\n'
       '      <Parameter name="Z Origin" type="double" value="0"/><Parameter name="X Length" type="double" value="0.1"/>\n'
       '      <Parameter name="Y Length" type="double" value="0.1"/><Parameter name="Z Length" type="double" value="0.001"/>\n'
       '      <Parameter name="Number Points X" type="int" value="100000"/><Parameter name="Number Points Y" type="int" value="100000"/>\n'
       '      <Parameter name="Number Points Z" type="int" value="1"/>\n    </ParameterList>'),
      (r'  <ParameterList name="Boundary Conditions">.*?\n  </ParameterList>\n', '')],
     ["Discretization", "32-bit", "'Number Points'"]),
    # Peridigm's string Horizon, an expression in x, y, z (docs/input.md, Blocks): a model with one horizon per block
    # refuses it; a value <= 0 at a point is named with the point.
    ("horizon expression with a model of one horizon per block",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="string" value="0.00603 + 0.01*x"/>'),
      ('<Parameter name="Spacing" type="double" value="0.002"/>',
       '<Parameter name="Spacing" type="double" value="0.002"/><Parameter name="Layer Width" type="double" value="0.00603"/>')],
     ["Blocks/Bar", "'Horizon' is an expression", "(Elastic)", "only the correspondence models"]),
    ("horizon expression not positive at a point",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="string" value="0.00603 - 0.1*x"/>'),
      ('<Parameter name="Spacing" type="double" value="0.002"/>',
       '<Parameter name="Spacing" type="double" value="0.002"/><Parameter name="Layer Width" type="double" value="0.00603"/>'),
      ('value="Elastic"/>', 'value="Elastic Correspondence"/><Parameter name="Hourglass Coefficient" type="double" value="0.02"/>')],
     ["Blocks/Bar", "'Horizon' = '0.00603 - 0.1*x' is", "at the point (", "of block_1", "positive and finite"]),
    ("horizon expression with a heat term of one horizon per block",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="string" value="0.00603 + 0.01*x"/>'),
      ('<Parameter name="Spacing" type="double" value="0.002"/>',
       '<Parameter name="Spacing" type="double" value="0.002"/><Parameter name="Layer Width" type="double" value="0.00603"/>'),
      ('value="Elastic"/>', 'value="Elastic Correspondence"/><Parameter name="Hourglass Coefficient" type="double" value="0.02"/>'
                            '<Parameter name="Thermal Conductivity" type="double" value="50"/>')],
     ["Blocks/Bar", "'Horizon' is an expression", "heat terms", "one horizon per block"]),
    ("horizon as long as the bar",
     [('<Parameter name="Horizon" type="double" value="0.00603"/>', '<Parameter name="Horizon" type="double" value="1.0"/>')],
     ["Discretization", "bonds", "'Horizon'"]),
    ("Maximum Memory below the estimate",
     [('<ParameterList name="Discretization">', '<Parameter name="Maximum Memory" type="double" value="1e6"/>\n  <ParameterList name="Discretization">')],
     ["'Maximum Memory' (1 MB)", "'Spacing'"]),
    ("load steps whose times would fill the memory",
     [('<Parameter name="Number of Load Steps" type="int" value="2"/>', '<Parameter name="Number of Load Steps" type="int" value="2000000000"/>')],
     ["Number of Load Steps", "10000000"]),
    ("load steps beyond an int",
     [('<Parameter name="Number of Load Steps" type="int" value="2"/>', '<Parameter name="Number of Load Steps" type="int" value="100000000000"/>')],
     ["Number of Load Steps", "100000000000"]),
    # The Pressure condition (issue 16): acts along the surface normal, on a surface layer only.
    ("Coordinate given for a Pressure",
     [('<ParameterList name="Left X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>',
       '<ParameterList name="Left X"><Parameter name="Type" type="string" value="Pressure"/>')],
     ["Boundary Conditions/Left X", "'Coordinate' does not apply to a Pressure"]),
    ("Layer Thickness given for a displacement",
     [('<ParameterList name="Left X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>',
       '<ParameterList name="Left X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>'
       '<Parameter name="Layer Thickness" type="double" value="0.001"/>')],
     ["Boundary Conditions/Left X", "'Layer Thickness' applies to a Pressure, Heat Flux or Convection only"]),
    ("Pressure on points inside the body",
     [('<ParameterList name="Left X">', '<ParameterList name="Push"><Parameter name="Type" type="string" value="Pressure"/>'
       '<Parameter name="Node Set" type="string" value="All"/><Parameter name="Value" type="string" value="1.0e6"/></ParameterList>\n'
       '    <ParameterList name="Left X">')],
     ["Boundary Conditions/Push", "is not on a surface"]),
    ("Follower given for a displacement",
     [('<ParameterList name="Left X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>',
       '<ParameterList name="Left X"><Parameter name="Type" type="string" value="Prescribed Displacement"/>'
       '<Parameter name="Follower" type="bool" value="true"/>')],
     ["Boundary Conditions/Left X", "'Follower' applies to a Pressure only"]),
    ("follower Pressure without the NDO band",
     [('<ParameterList name="Left X">', '<ParameterList name="Push"><Parameter name="Type" type="string" value="Pressure"/>'
       '<Parameter name="Node Set" type="string" value="Left Layer"/><Parameter name="Value" type="string" value="1.0e6"/>'
       '<Parameter name="Follower" type="bool" value="true"/></ParameterList>\n'
       '    <ParameterList name="Left X">')],
     ["Boundary Conditions/Push", "'Follower' = true needs the NDO band"]),
    # Found by the fuzz test (test/fuzz, docs/verification.md): each ended in a signal, a library's message
    # naming no parameter, a message cut short at a NUL, or a silently truncated run.
    ("bool that is not a bool",
     [('<Parameter name="Displacement" type="bool" value="true"/>', '<Parameter name="Displacement" type="bool" value="maybe"/>')],
     ["Output/Output Variables", "'Displacement' = 'maybe'", "not a bool"]),
    ("type Periforge does not read",
     [('<Parameter name="Density" type="double"', '<Parameter name="Density" type="Array(double)"')],
     ["Materials/Steel", "'Density'", "Array(double)"]),
    ("NUL character in a value",
     [('<Parameter name="Material" type="string" value="Steel"/>', '<Parameter name="Material" type="string" value="St&#0;eel"/>')],
     ["Blocks/Bar", "'Material'", "St\\x00eel", "not text"]),
    ("bytes that are not UTF-8 in a name",
     [('<Parameter name="Density"', '<Parameter name="Dens\udcffity"')],
     ["Materials/Steel", "parameter name", "Dens\\xffity", "not text"]),
    ("empty input file", [(r"\A.*\Z", "")], ["the input file is empty"]),
    ("number beyond the double range in an expression",
     [(r'value="1\.0e-3\*x\*t"', 'value="1.0e400*x*t"')],
     ["Boundary Conditions/Left X/Value", "'1.0e400' is out of range"]),
    ("malformed number in an expression (SIGABRT in Pamgen before)",
     [(r'value="1\.0e-3\*x\*t"', 'value="1.0.0e-3*x*t"')],
     ["Boundary Conditions/Left X/Value", "'1.0.0e-3' is not a number"]),
    ("malformed number in an influence function",
     [('<ParameterList name="Discretization">', '<ParameterList name="Discretization">\n    <Parameter name="Influence Function" type="string" value="1..0/zeta"/>')],
     ["Discretization/Influence Function", "'1..0' is not a number"]),
    ("Verlet steps beyond 32 bits (ran one step and said done before)",
     [(r'<Parameter name="Final Time" type="double" value="1.0"/>\s*<ParameterList name="Adaptive Dynamic Relaxation">.*?</ParameterList>',
       '<Parameter name="Final Time" type="double" value="1.0e12"/>\n    <ParameterList name="Verlet"><Parameter name="Fixed dt" type="double" value="1.0e-7"/></ParameterList>')],
     ["Solver/Verlet", "'Fixed dt'", "1e+19 steps", "2147483647"]),
    # The Temperature field and the thermal solvers (issue 33).
    ("thermal expansion without a temperature",
     [('<Parameter name="Density"', '<Parameter name="Thermal Expansion Coefficient" type="double" value="1e-5"/>\n'
       '      <Parameter name="Density"')],
     ["Materials/Steel", "Temperature"]),
    ("coordinate on a temperature condition",
     [('<ParameterList name="Left X">', '<ParameterList name="Heat"><Parameter name="Type" type="string" '
       'value="Prescribed Temperature"/><Parameter name="Node Set" type="string" value="All"/><Parameter '
       'name="Coordinate" type="string" value="x"/><Parameter name="Value" type="string" value="300"/></ParameterList>\n'
       '    <ParameterList name="Left X">')],
     ["Boundary Conditions/Heat", "Coordinate"]),
    ("temperature output without the field",
     [('<Parameter name="Displacement" type="bool" value="true"/>',
       '<Parameter name="Displacement" type="bool" value="true"/><Parameter name="Temperature" type="bool" value="true"/>')],
     ["Temperature", "Prescribed Temperature"]),
    ("damage model's thermal coefficient differs from the material's",
     [('<Parameter name="Density"', '<Parameter name="Thermal Expansion Coefficient" type="double" value="1e-5"/>\n'
       '      <Parameter name="Density"'),
      ('<ParameterList name="Blocks">', '<ParameterList name="Damage Models"><ParameterList name="Brittle">'
       '<Parameter name="Damage Model" type="string" value="Critical Stretch"/>'
       '<Parameter name="Critical Stretch" type="double" value="0.01"/>'
       '<Parameter name="Thermal Expansion Coefficient" type="double" value="2e-5"/></ParameterList></ParameterList>\n'
       '  <ParameterList name="Blocks">'),
      ('<Parameter name="Material" type="string" value="Steel"/>',
       '<Parameter name="Material" type="string" value="Steel"/><Parameter name="Damage Model" type="string" value="Brittle"/>')],
     ["Damage Models/Brittle", "Thermal Expansion Coefficient"]),
    ("solve for pressure",
     [('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Pressure" type="bool" value="true"/>')],
     ["Solver", "Solve For Pressure"]),
    ("solve for temperature with a mechanics solver",
     [('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Temperature" type="bool" value="true"/>')],
     ["Solver", "Solve For Temperature"]),
    ("Verlet solving temperature without a thermal term",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="Verlet">'),
      ('<Parameter name="Relative Tolerance" type="double" value="1.0e-7"/>', ''),
      ('<Parameter name="Number of Load Steps" type="int" value="2"/>', ''),
      ('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Temperature" type="bool" value="true"/>')],
     ["Solver/Verlet", "Solve For Temperature", "Specific Heat Capacity"]),
    ("Verlet conducting without heat capacity",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="Verlet">'),
      ('<Parameter name="Relative Tolerance" type="double" value="1.0e-7"/>', ''),
      ('<Parameter name="Number of Load Steps" type="int" value="2"/>', ''),
      ('<Parameter name="Density"', '<Parameter name="Thermal Conductivity" type="double" value="45.0"/>\n      <Parameter name="Density"'),
      ('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Temperature" type="bool" value="true"/>')],
     ["Solver/Verlet", "heat capacity", "Specific Heat Capacity"]),
    ("NOXQuasiStatic solving temperature without a thermal term",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="NOXQuasiStatic">'),
      ('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Temperature" type="bool" value="true"/>')],
     ["Solver/NOXQuasiStatic", "Solve For Temperature", "Specific Heat Capacity"]),
    ("NOXQuasiStatic conducting without heat capacity",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="NOXQuasiStatic">'),
      ('<Parameter name="Density"', '<Parameter name="Thermal Conductivity" type="double" value="45.0"/>\n      <Parameter name="Density"'),
      ('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Temperature" type="bool" value="true"/>')],
     ["Solver/NOXQuasiStatic", "heat capacity", "Specific Heat Capacity"]),
    ("NOXQuasiStatic without the displacement",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="NOXQuasiStatic">'),
      ('<Parameter name="Final Time" type="double" value="1.0"/>',
       '<Parameter name="Final Time" type="double" value="1.0"/><Parameter name="Solve For Displacement" type="bool" value="false"/>')],
     ["Solver", "Solve For Displacement", "NOXQuasiStatic"]),
    ("Taylor-Quinney without a specific heat",
     [('<Parameter name="Material Model" type="string" value="Elastic"/>',
       '<Parameter name="Material Model" type="string" value="Elastic Correspondence"/>'
       '<Parameter name="Hourglass Coefficient" type="double" value="0.05"/>'
       '<Parameter name="Taylor-Quinney Coefficient" type="double" value="0.9"/>')],
     ["Taylor-Quinney Coefficient", "Specific Heat Capacity"]),
    ("Convection without its coefficient",
     [('<ParameterList name="Left X">', '<ParameterList name="Cool"><Parameter name="Type" type="string" value="Convection"/>'
       '<Parameter name="Node Set" type="string" value="All"/><Parameter name="Ambient Temperature" type="string" value="300.0"/>'
       '</ParameterList>\n    <ParameterList name="Left X">')],
     ["Boundary Conditions/Cool", "Heat Transfer Coefficient"]),
    ("Heat Flux without a value",
     [('<ParameterList name="Left X">', '<ParameterList name="Heat"><Parameter name="Type" type="string" value="Heat Flux"/>'
       '<Parameter name="Node Set" type="string" value="All"/></ParameterList>\n    <ParameterList name="Left X">')],
     ["Boundary Conditions/Heat", "Value"]),
    ("Diffusion on a 2D discretization",
     [('<Parameter name="Type" type="string" value="Box With Holes"/>', '<Parameter name="Type" type="string" value="Rectangle With Holes"/>'),
      ('<Parameter name="Z Length" type="double" value="0.02"/>', '<Parameter name="Thickness" type="double" value="0.002"/>'),
      ('<Parameter name="Material Model" type="string" value="Elastic"/>.*?</ParameterList>',
       '<Parameter name="Material Model" type="string" value="Diffusion"/>'
       '<Parameter name="Coefficient" type="double" value="1.0"/></ParameterList>')],
     ["Materials/Steel", "3D only"]),
    ("ImplicitDiffusion without conduction",
     [('<ParameterList name="Adaptive Dynamic Relaxation">', '<ParameterList name="ImplicitDiffusion">'),
      ('<Parameter name="Relative Tolerance" type="double" value="1.0e-7"/>', '')],
     ["Solver/ImplicitDiffusion", "conducts heat"]),
    ("mechanics solver over a Diffusion-only body",
     [('<Parameter name="Material Model" type="string" value="Elastic"/>.*?</ParameterList>',
       '<Parameter name="Material Model" type="string" value="Diffusion"/>'
       '<Parameter name="Coefficient" type="double" value="1.0"/></ParameterList>')],
     ["Solver", "force model"]),
    ("bond-associated correspondence with a higher gradient order",
     [('<Parameter name="Material Model" type="string" value="Elastic"/>',
       '<Parameter name="Material Model" type="string" value="Elastic Bond Associated Correspondence"/>'
       '<Parameter name="Gradient Order Of Accuracy" type="int" value="2"/>')],
     ["Materials/Steel", "Gradient Order Of Accuracy"]),
    ("hypoelastic correspondence without its Actual Horizon",
     [('<Parameter name="Material Model" type="string" value="Elastic"/>',
       '<Parameter name="Material Model" type="string" value="Elastic Hypoelastic Correspondence"/>')],
     ["Materials/Steel", "Actual Horizon"]),
]


def main(exe, base):
    text = open(base).read()
    failures = 0
    for name, edits, words in CASES:
        deck = text
        for pat, rep in edits:
            new = re.sub(pat, lambda _m: rep, deck, count=1, flags=re.S)
            if new == deck:
                print(f"[{name}] test set-up error: pattern not found in base deck: {pat[:60]}")
                failures += 1
            deck = new
        with tempfile.TemporaryDirectory() as d:
            path = os.path.join(d, "bad.xml")
            open(path, "wb").write(deck.encode("utf-8", "surrogateescape"))
            start = time.monotonic()
            p = subprocess.run([exe, path], cwd=d, capture_output=True, text=True, timeout=300)
            elapsed = time.monotonic() - start
            lines = [l for l in p.stderr.splitlines() if l.strip()]
            msg = lines[-1] if lines else ""
            outputs = [f for f in os.listdir(d) if f.endswith((".e", ".csv"))]
            problems = []
            if p.returncode <= 0:
                problems.append(f"exit code {p.returncode} (want > 0, not a signal)")
            if len(lines) != 1:
                problems.append(f"{len(lines)} stderr lines (want 1)")
            if "bad.xml" not in msg:
                problems.append("message does not name the input file")
            for w in words:
                if w not in msg:
                    problems.append(f"message does not contain '{w}'")
            if elapsed > 30.0:
                problems.append(f"took {elapsed:.1f} s (want < 30 s)")
            if outputs:
                problems.append(f"wrote output files {outputs}")
            status = "ok" if not problems else "FAIL: " + "; ".join(problems)
            print(f"[{name}] {status}\n    {msg}")
            failures += bool(problems)
    print(f"{len(CASES) - failures} passed, {failures} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

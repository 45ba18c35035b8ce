#!/usr/bin/env python3
"""The history-column options of Output (docs/input.md, Output): "Reaction Names" renames the reaction
columns of "Reactions" entry by entry, "Applied Displacement" adds the column Applied_Displacement = the
value of a space-independent Prescribed Displacement condition at each output time.

usage: check_output_columns.py PERIFORGE_EXE DECK (test/regression/examples/columns.xml)
1. the deck as given: header is exactly time, step, Applied_Displacement, Reaction_Left_{X,Y,Z},
   Reaction_Far_End_{X,Y,Z}; Applied_Displacement = 0, 1e-5, -1e-5 at t = 0, 1, 2 (the expression), and
   the left and right x reactions balance (the bar is in equilibrium);
2. without the two options the columns are the historical ones (Reaction_Left_Layer_X, ...), no
   Applied_Displacement column;
3. error cases: each exits non-zero with one line naming the file and the parameter, and writes no CSV.
"""
import csv
import os
import subprocess
import sys
import tempfile

exe, deck = sys.argv[1], sys.argv[2]
base = open(deck).read()
failures = []

RN = '<Parameter name="Reaction Names" type="string" value="Left, Far End"/>'
AD = '<Parameter name="Applied Displacement" type="string" value="Pull Right"/>'


def run(text, name):
    d = tempfile.mkdtemp(prefix="pf_columns_")
    path = os.path.join(d, name + ".xml")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.run([exe, path], cwd=d, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    return p, d, path


def read(d):
    with open(os.path.join(d, "columns.csv")) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in r] for r in rows[1:]]


def check(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg)
    if not cond:
        failures.append(msg)


# 1. both options
p, d, _ = run(base, "columns")
check(p.returncode == 0, "deck with both options runs (rc %d) %s" % (p.returncode, p.stderr.strip()[-300:]))
if p.returncode == 0:
    head, rows = read(d)
    want = ["time", "step", "Applied_Displacement", "Reaction_Left_X", "Reaction_Left_Y", "Reaction_Left_Z",
            "Reaction_Far_End_X", "Reaction_Far_End_Y", "Reaction_Far_End_Z"]
    check(head == want, "header %s" % head)
    ad = [r[2] for r in rows]
    check(len(rows) == 3 and all(abs(a - b) <= 1e-18 for a, b in zip(ad, [0.0, 1e-5, -1e-5])),
          "Applied_Displacement = 0, 1e-5, -1e-5 (got %s)" % ad)
    if len(rows) == 3:
        fl, fr = rows[1][3], rows[1][6]
        check(fl < 0 < fr and abs(fl + fr) <= 1e-3 * abs(fr),
              "tension at t = 1: Reaction_Left_X = %.6g, Reaction_Far_End_X = %.6g balance" % (fl, fr))
        check(rows[2][3] > 0 > rows[2][6], "compression at t = 2 flips both signs")

# 2. neither option: historical names
p, d, _ = run(base.replace(RN, "").replace(AD, ""), "columns")
check(p.returncode == 0, "deck without the options runs")
if p.returncode == 0:
    head, _ = read(d)
    check(head[:5] == ["time", "step", "Reaction_Left_Layer_X", "Reaction_Left_Layer_Y", "Reaction_Left_Layer_Z"]
          and "Applied_Displacement" not in head and "Reaction_Right_Layer_X" in head,
          "historical column names without the options: %s" % head[:6])

# 3. errors
CASES = [
    ("Reaction Names count", base.replace(RN, RN.replace("Left, Far End", "Left")), ["Reaction Names", "1", "2"]),
    ("Reaction Names without Reactions",
     base.replace('<Parameter name="Reactions" type="string" value="Left Layer, Right Layer"/>', ""),
     ["Reaction Names", "Reactions"]),
    ("Reaction Names repeated", base.replace(RN, RN.replace("Left, Far End", "Left, Left")), ["Reaction Names", "Left"]),
    ("Reaction Names empty entry", base.replace(RN, RN.replace("Left, Far End", "Left,  ")), ["Reaction Names", "empty"]),
    ("Applied Displacement unknown", base.replace(AD, AD.replace("Pull Right", "Pull Rite")), ["Applied Displacement", "Pull Rite"]),
    ("Applied Displacement on a node set",
     base.replace(AD, AD.replace("Pull Right", "Left Layer")), ["Applied Displacement", "Left Layer"]),
    ("Applied Displacement space-dependent",
     base.replace(AD, AD.replace("Pull Right", "Shear Right")), ["Applied Displacement", "Shear Right", "x, y or z"]),
    ("Applied Displacement wrong type", base.replace(AD, AD.replace('type="string" value="Pull Right"', 'type="double" value="1.0"')),
     ["Applied Displacement"]),
]
for name, text, words in CASES:
    p, d, path = run(text, "bad")
    lines = [l for l in p.stderr.strip().splitlines() if l.strip()]
    msg = lines[-1] if lines else ""
    ok = p.returncode not in (0,) and p.returncode > 0 and path in msg and all(w in msg for w in words) \
        and not os.path.exists(os.path.join(d, "columns.csv"))
    check(ok, "%s: rc %d, '%s'" % (name, p.returncode, msg))

print("check_output_columns: %s" % ("PASS" if not failures else "FAIL (%d)" % len(failures)))
sys.exit(1 if failures else 0)

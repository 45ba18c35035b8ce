#!/usr/bin/python3
"""A Text File mesh is read in byte ranges, one per rank (src/model/DistributedCloud.hpp): a bad line held by
the last rank must be named by its line in the whole file, and every rank must stop with that one message
(no hang, no partial run). A good mesh with comments in every rank's range must run, its probe at the point
with the lowest id among the nearest.

usage: text_file_ranks.py BASE_DECK PERIFORGE MPIRUN [MPIRUN ARGS...]
"""
import os
import re
import subprocess
import sys
import tempfile

BAD_LINE = 61  # of 65 lines (a comment, then 64 points): in the last range at np 2 and 3


def mesh(bad):
    lines = ["# x y z block_id volume"]
    for k in range(4):
        for j in range(4):
            for i in range(4):
                lines.append(f"{0.002 * i} {0.002 * j} {0.002 * k} 1 8e-9" + ("  # corner" if i == j == 0 else ""))
    if bad:
        lines[BAD_LINE - 1] = "0.1 0.2 1 8e-9"  # four numbers
    return "\n".join(lines) + "\n"


def deck(base):
    text = open(base).read()
    text = re.sub(r'<Parameter name="Type" type="string" value="Box With Holes"/>.*?'
                  r'<Parameter name="Fictitious Layers" type="string" value="Left Right"/>',
                  '<Parameter name="Type" type="string" value="Text File"/>\n'
                  '    <Parameter name="Input Mesh File" type="string" value="mesh.txt"/>', text, count=1, flags=re.S)
    text = re.sub(r'  <ParameterList name="Boundary Conditions">.*?\n  </ParameterList>\n', '', text, count=1, flags=re.S)
    # One probe equidistant from the 8 points of the cell [0.002, 0.004]^3: the lowest id, 22, must win on
    # every rank count (the nearest point is found rank by rank, then agreed).
    return re.sub(r'<ParameterList name="Probes">.*?\n    </ParameterList>',
                  '<ParameterList name="Probes"><ParameterList name="Q"><Parameter name="X" type="double" value="0.003"/>'
                  '<Parameter name="Y" type="double" value="0.003"/><Parameter name="Z" type="double" value="0.003"/>'
                  '<Parameter name="Variables" type="string" value="Displacement"/></ParameterList>\n    </ParameterList>',
                  text, count=1, flags=re.S)


def main(base, exe, mpirun):
    failures = 0
    for np in (2, 3):
        for bad in (True, False):
            with tempfile.TemporaryDirectory() as d:
                open(os.path.join(d, "mesh.txt"), "w").write(mesh(bad))
                open(os.path.join(d, "ranks.xml"), "w").write(deck(base))
                try:
                    p = subprocess.run(mpirun + ["-np", str(np), exe, "ranks.xml"], cwd=d, capture_output=True,
                                       text=True, timeout=120)
                except subprocess.TimeoutExpired:
                    print(f"np {np} {'bad' if bad else 'good'} mesh: FAIL: hung (no exit in 120 s)")
                    failures += 1
                    continue
                errors = [l for l in p.stderr.splitlines() if "input error" in l]
                problems = []
                if bad:
                    if p.returncode == 0:
                        problems.append("exit code 0")
                    if not errors or any(l != errors[0] for l in errors):
                        problems.append(f"want one message, got {errors}")
                    elif f"mesh.txt:{BAD_LINE}:" not in errors[0] or "ranks.xml" not in errors[0]:
                        problems.append(f"message does not name ranks.xml and mesh.txt:{BAD_LINE}: {errors[0]}")
                elif p.returncode != 0 or "64 points" not in p.stdout or "probe Q: node 22 at (0.002, 0.002, 0.002)" not in p.stdout:
                    problems.append(f"good mesh: exit {p.returncode}, stdout {p.stdout[-300:]!r} stderr {p.stderr[-300:]!r}")
                print(f"np {np} {'bad' if bad else 'good'} mesh: {'ok' if not problems else 'FAIL: ' + '; '.join(problems)}"
                      + (f"\n    {errors[0]}" if errors else ""))
                failures += bool(problems)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2], sys.argv[3:]))

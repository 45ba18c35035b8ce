#!/usr/bin/env python3
"""run_if_cpu_has.py FLAG CMD...: runs CMD if /proc/cpuinfo lists FLAG, else exits 77 (ctest's skip
code for these tests), so a test of the AVX2 build is skipped, not failed, on a CPU without AVX2."""
import subprocess
import sys

flag, cmd = sys.argv[1], sys.argv[2:]
try:
    with open("/proc/cpuinfo") as f:
        flags = next((line.split(":", 1)[1].split() for line in f if line.startswith("flags")), [])
except OSError:
    flags = []
if flag not in flags:
    print("run_if_cpu_has.py: this CPU has no %s; skipped" % flag)
    sys.exit(77)
sys.exit(subprocess.call(cmd))

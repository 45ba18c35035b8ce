#!/usr/bin/env python3
"""ctest render_paraview (issue 37): scripts/render_paraview draws the tutorial's elastic plate with ParaView.

usage: run_render_paraview.py REPO_DIR PERIFORGE_EXE

Without pvpython on the PATH: one line and exit 77 (ctest SKIPPED; ParaView is not a dependency). With it: run
examples/tutorial/plate_elastic.xml in a scratch folder, render Dilatation and Displacement offscreen, and require
each PNG to show a colour map (more than 50 distinct colours: a blank or one-colour frame fails), and an unknown
variable to end with status 2.
"""
import os
import shutil
import subprocess
import sys
import tempfile


def colours(png):
    import matplotlib.image as mpimg
    import numpy as np
    pixels = mpimg.imread(png)
    return len(np.unique(pixels.reshape(-1, pixels.shape[-1]), axis=0))


def main():
    repo, exe = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
    pvpython = shutil.which("pvpython")
    if not pvpython:
        print("render_paraview: SKIPPED: pvpython (ParaView's Python) is not on the PATH")
        return 77
    script = os.path.join(repo, "scripts", "render_paraview")
    scratch = tempfile.mkdtemp(prefix="pf_render_")
    problems = []
    try:
        shutil.copy(os.path.join(repo, "examples", "tutorial", "plate_elastic.xml"), scratch)
        subprocess.run([exe, "plate_elastic.xml"], cwd=scratch, check=True, timeout=120)
        for var in ("Dilatation", "Displacement"):
            out = os.path.join(scratch, var + ".png")
            run = subprocess.run([pvpython, "--force-offscreen-rendering", script, "plate_elastic.e", var, "-o", out],
                                 cwd=scratch, timeout=300)
            if run.returncode != 0 or not os.path.exists(out):
                problems.append("%s: render_paraview exited %d" % (var, run.returncode))
            elif colours(out) <= 50:
                problems.append("%s: %s shows %d colours: no colour map drawn" % (var, out, colours(out)))
        bad = subprocess.run([pvpython, "--force-offscreen-rendering", script, "plate_elastic.e", "No_Such"],
                             cwd=scratch, timeout=300)
        if bad.returncode != 2:
            problems.append("an unknown variable exited %d, not 2" % bad.returncode)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    for p in problems:
        print("render_paraview: " + p, file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

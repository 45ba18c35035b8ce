#!/usr/bin/env python3
"""scripts/plot_field and scripts/plot_history (issue 21 part 6) on a run made here: the pictures exist,
are not blank, and show the field's values in display units (the range plot_field reports equals the
range read from the Exodus file with netCDF4, times 1e3 for mm); a 3D body is cut to one layer; bad
arguments exit 2 with one line.

usage: run_plot_scripts.py PERIFORGE_EXE SCRIPTS_DIR DECK_2D DECK_3D
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import netCDF4  # noqa: E402
import numpy as np  # noqa: E402

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def run_deck(exe, deck, d, name):
    text = open(deck).read()
    text = re.sub(r'<Parameter name="Output Filename" type="string" value="[^"]*"/>',
                  f'<Parameter name="Output Filename" type="string" value="{name}"/>', text)
    path = os.path.join(d, name + ".xml")
    open(path, "w").write(text)
    subprocess.run([exe, path], cwd=d, check=True, capture_output=True)
    return os.path.join(d, name + ".e")


def plot(scripts, *args, cwd):
    return subprocess.run([sys.executable, os.path.join(scripts, "plot_field")] + list(args), cwd=cwd,
                          capture_output=True, text=True)


def not_blank(png):
    img = mpimg.imread(png)
    return img.shape[0] > 100 and img.shape[1] > 100 and float(np.std(img[..., :3])) > 0.05


def main(exe, scripts, deck2d, deck3d):
    d = tempfile.mkdtemp(prefix="plots")
    try:
        e2 = run_deck(exe, deck2d, d, "two")
        p = plot(scripts, e2, "Displacement", "-o", "u.png", cwd=d)
        ds = netCDF4.Dataset(e2)
        ux, uy, uz = (np.asarray(ds.variables[f"vals_nod_var{k}"][-1, :]) for k in (1, 2, 3))
        mag = np.sqrt(ux ** 2 + uy ** 2 + uz ** 2) * 1e3
        m = re.search(r"Displacement: (\S+) to (\S+) mm, (\d+) points", p.stdout)
        check(p.returncode == 0 and m is not None, f"plot_field 2D exit {p.returncode}: {p.stdout.strip()}")
        if m:
            check(abs(float(m.group(2)) - mag.max()) <= 1e-5 * mag.max() and int(m.group(3)) == len(mag),
                  f"2D |u| range in mm {m.group(1)}..{m.group(2)} matches the file's {mag.min():.6g}..{mag.max():.6g}")
        check(os.path.exists(os.path.join(d, "u.png")) and not_blank(os.path.join(d, "u.png")), "2D picture is not blank")
        p = plot(scripts, e2, "--all", "-o", "fields", cwd=d)
        names = sorted(os.listdir(os.path.join(d, "fields"))) if p.returncode == 0 else []
        check("Dilatation.png" in names and "Displacement.png" in names, f"--all wrote {names}")
        for args, words in ((["Nope"], "no variable 'Nope'"), (["Displacement", "--step", "99"], "--step 99"),
                            (["Displacement", "--section", "q=1"], "--section")):
            p = plot(scripts, e2, *args, cwd=d)
            lines = p.stderr.strip().splitlines()
            check(p.returncode == 2 and len(lines) == 1 and words in lines[0], f"{args}: exit {p.returncode}, {lines}")
        e3 = run_deck(exe, deck3d, d, "three")
        p = plot(scripts, e3, "DisplacementX", "--section", "z=0.01", "-o", "x.png", cwd=d)
        z = np.asarray(netCDF4.Dataset(e3).variables["coordz"][:])
        layer = int(np.sum(np.isclose(z, z[np.argmin(np.abs(z - 0.01))])))
        m = re.search(r"(\d+) points", p.stdout)
        check(p.returncode == 0 and m and int(m.group(1)) == layer and layer < len(z),
              f"3D section z = 0.01 draws its layer of {layer} of {len(z)} points: {p.stdout.strip()}")
        h = subprocess.run([sys.executable, os.path.join(scripts, "plot_history"), os.path.join(d, "two.csv"),
                            "--x", "time", "--y", "step", "--label", "bar", "-o", os.path.join(d, "h.png")],
                           capture_output=True, text=True)
        check(h.returncode == 0 and not_blank(os.path.join(d, "h.png")), f"plot_history: {h.stdout.strip()}")
        sys.path.insert(0, scripts)
        from plot_units import label_of
        check(label_of("Reaction_Left_X") == "Reaction Left X [kN]" and
              label_of("Probe_A_Signed_Von_Mises_Stress") == "Probe A Signed Von Mises Stress [MPa]" and
              label_of("Applied_Displacement") == "Applied Displacement [mm]", "history axis labels carry units")
    finally:
        shutil.rmtree(d, ignore_errors=True)
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(*sys.argv[1:5]))

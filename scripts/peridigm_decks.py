"""Peridigm-compatible variants of the benchmark kernel decks, and running Peridigm on them.

Used by `scripts/bench --peridigm PATH` (docs/benchmark-log.md, "Peridigm side by side") and
`scripts/peridigm_side_by_side` (docs/peridigm.md). Both codes then run the *same* deck file:
  - the initial velocity acts on the node set `All Node Set`, a file of all 1-based ids (Peridigm has no
    built-in set of every node; Periforge's kernel decks use its built-in `All`);
  - `Yield Normalization = Discrete` (Periforge only) is dropped: Peridigm's `Continuum` yield value, the default
    of both;
  - `Elastic Plastic Hardening` gets Peridigm's `Hardening Modulus` H_P instead of the paper's isotropic /
    kinematic moduli (Peridigm has only its own law), and `Apply Shear Correction Factor` as asked;
  - output: the variables both codes write for the model (Displacement, Velocity, Force_Density, Dilatation,
    Weighted_Volume; Lambda for the plastic models; Surface_Correction_Factor for hardening).
"""
import os
import re
import subprocess
import time

NODE_SET = "All Node Set"
NODE_SET_FILE = "all_nodes.txt"


def peridigm_variant(text, hardening_modulus=None, shear_correction=None, output_frequency=None,
                     final_time=None):
    """The deck text made Peridigm-readable (see the module docstring). Returns (text, model name)."""
    model = re.search(r'name="Material Model" type="string" value="([^"]*)"', text).group(1)
    # Node set: Peridigm's "<name> Node Set" string parameter naming a file of ids.
    text = text.replace('<ParameterList name="Boundary Conditions">',
                        '<ParameterList name="Boundary Conditions">\n    <Parameter name="%s" type="string" '
                        'value="%s"/>' % (NODE_SET, NODE_SET_FILE), 1)
    text = text.replace('<Parameter name="Node Set" type="string" value="All"/>',
                        '<Parameter name="Node Set" type="string" value="%s"/>' % NODE_SET)
    # Periforge-only parameters and the comments that explain them.
    text = re.sub(r'\n *<!--(?:(?!-->).)*?(Yield Normalization|shear correction factor)(?:(?!-->).)*?-->', "", text,
                  flags=re.S)
    text = re.sub(r'\n *<Parameter name="Yield Normalization"[^>]*/>', "", text)
    if model == "Elastic Plastic Hardening":
        if hardening_modulus is None:
            raise ValueError("Elastic Plastic Hardening needs a Hardening Modulus for Peridigm")
        text = re.sub(r'\n *<Parameter name="(Isotropic|Kinematic) Hardening Modulus"[^>]*/>', "", text)
        text = re.sub(r'\n *<Parameter name="Apply Shear Correction Factor"[^>]*/>', "", text)
        scf = "true" if shear_correction is None or shear_correction else "false"
        text = re.sub(r'(\n *)(<Parameter name="Yield Stress"[^>]*/>)',
                      r'\1\2\1<Parameter name="Hardening Modulus" type="double" value="%.6g"/>'
                      r'\1<Parameter name="Apply Shear Correction Factor" type="bool" value="%s"/>'
                      % (hardening_modulus, scf), text)
    outs = ["Displacement", "Velocity", "Force_Density", "Dilatation", "Weighted_Volume"]
    if model != "Elastic":
        outs.append("Lambda")
    if model == "Elastic Plastic Hardening":
        outs.append("Surface_Correction_Factor")
    body = "\n".join('      <Parameter name="%s" type="bool" value="true"/>' % v for v in outs)
    text = re.sub(r'(<ParameterList name="Output Variables">)(.*?)(\n *</ParameterList>)',
                  lambda m: m.group(1) + "\n" + body + m.group(3), text, flags=re.S)
    if output_frequency is not None:
        text = re.sub(r'(name="Output Frequency" type="int" value=")[^"]*"', r'\g<1>%d"' % output_frequency, text)
    if final_time is not None:
        text = re.sub(r'(name="Final Time" type="double" value=")[^"]*"', r'\g<1>%.10g"' % final_time, text)
    return text, model


def points_of(text):
    """Number of points of a PdQuickGrid deck (product of Number Points X/Y/Z)."""
    n = 1
    for c in "XYZ":
        n *= int(re.search(r'name="Number Points %s" type="int" value="(\d+)"' % c, text).group(1))
    return n


def write_variant(deck_path, workdir, stem, **kw):
    """Writes the Peridigm-compatible variant of deck_path as workdir/stem.xml (output name stem) and the node
    set file beside it. Returns the path of the deck."""
    with open(deck_path) as f:
        text, _ = peridigm_variant(f.read(), **kw)
    text = re.sub(r'(name="Output Filename" type="string" value=")[^"]*"', r'\g<1>%s"' % stem, text)
    with open(os.path.join(workdir, NODE_SET_FILE), "w") as f:
        f.write("# every node, 1-based (scripts/peridigm_decks.py)\n")
        f.write("\n".join(str(i) for i in range(1, points_of(text) + 1)) + "\n")
    out = os.path.join(workdir, stem + ".xml")
    with open(out, "w") as f:
        f.write(text)
    return out


def run_timed(cmd_exe, deck, np_, workdir):
    """Runs `cmd_exe deck` on np_ ranks under /usr/bin/time -v (one file per rank). Returns
    (returncode, stdout+stderr, wall s of the whole run, sum of peak RSS bytes, sum of CPU s)."""
    rss = os.path.join(workdir, "rss")
    wrapper = ["sh", "-c", '/usr/bin/time -v -o "%s.${OMPI_COMM_WORLD_RANK:-0}" "%s" "%s"' % (rss, cmd_exe, deck)]
    cmd = ["mpirun", "--allow-run-as-root", "--oversubscribe", "--bind-to", "core", "-np", str(np_)] + wrapper
    t0 = time.time()
    p = subprocess.run(cmd, cwd=workdir, capture_output=True, text=True)
    total = time.time() - t0
    peak, cpu = 0, 0.0
    if p.returncode == 0:
        for r in range(np_):
            with open("%s.%d" % (rss, r)) as f:
                t = f.read()
            peak += int(re.search(r"Maximum resident set size \(kbytes\): (\d+)", t).group(1)) * 1024
            cpu += float(re.search(r"User time \(seconds\): ([\d.]+)", t).group(1))
            cpu += float(re.search(r"System time \(seconds\): ([\d.]+)", t).group(1))
    return p.returncode, p.stdout + p.stderr, total, peak, cpu


def parse_peridigm(out):
    """Peridigm's timing table (printed at the end of a run): {'total_s', 'solve_s', 'internal_force_s'} where
    found (Peridigm's 'Total', 'Verlet'/'QuasiStatic'/'NOXQuasiStatic' solve and 'Internal Force' rows)."""
    info = {}
    for key, pat in (("total_s", r"^\s*Total\s+([\d.eE+-]+)"),
                     ("internal_force_s", r"^\s*Internal Force\s+([\d.eE+-]+)"),
                     ("solve_s", r"^\s*(?:Verlet|QuasiStatic|NOXQuasiStatic)\s+([\d.eE+-]+)")):
        m = re.search(pat, out, flags=re.M)
        if m:
            info[key] = float(m.group(1))
    return info

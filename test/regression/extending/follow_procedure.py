#!/usr/bin/env python3
"""Follows docs/extending.md's procedure (the block between `<!-- extending-procedure: begin -->` and `end`) in a
scratch copy of the sources and checks its outcome (issue 37): the copied model's unit tests run and pass, its
deck gives the original model's history byte for byte (the same code under another name), and docs/input.md is
current. Every line of the block runs as written (bash, stop at the first failing line), except that `cmake` is a
shell function here: `cmake -S ...` does nothing and `cmake --build` compiles only the sources the block added or
changed, with the flags of the suite's build, and relinks periforge, periforge-parameters and unit_tests against
its core library (objects given before the library take the place of its members), so that the check costs
seconds rather than a second full build. A block that changes a header other sources include cannot be followed
this way and fails with that reason.

usage: follow_procedure.py SOURCE_DIR BUILD_DIR REFERENCE_CSV
       follow_procedure.py --partial-build SOURCE_DIR BUILD_DIR SCRATCH_DIR   (the `cmake --build` of the block)
"""
import filecmp
import os
import re
import shlex
import shutil
import subprocess
import sys
import tempfile

MODEL_SUITE = "PairSpring"  # the unit-test suite the block's copy declares
DECK_DIR = "test/regression/pair_spring"
DECK_CSV = "bar_3d_microelastic.csv"  # the copied deck keeps the original's Output Filename
BEGIN, END = "<!-- extending-procedure: begin -->", "<!-- extending-procedure: end -->"


def fail(message):
    print("follow_procedure: " + message)
    sys.exit(1)


def procedure(source):
    text = open(os.path.join(source, "docs", "extending.md")).read()
    if BEGIN not in text or END not in text:
        fail("docs/extending.md has no block between %s and %s" % (BEGIN, END))
    block = text.split(BEGIN, 1)[1].split(END, 1)[0].strip()
    lines = block.splitlines()
    if not lines or not lines[0].startswith("```") or not lines[-1].startswith("```"):
        fail("the procedure is not one fenced code block")
    return "\n".join(lines[1:-1]) + "\n"


def copy_sources(source, scratch):
    top = lambda d, names: [n for n in names if d == source and (n.startswith("build") or n == ".git")]
    shutil.copytree(source, scratch, ignore=top, symlinks=True)


def flags(make_file, source, scratch):
    """The compile flags of a CMake target (its flags.make), include paths moved to the scratch copy."""
    values = {}
    for line in open(make_file):
        m = re.match(r"(CXX_DEFINES|CXX_INCLUDES|CXX_FLAGS) = (.*)", line)
        if m:
            values[m.group(1)] = m.group(2)
    args = []
    for key in ("CXX_DEFINES", "CXX_INCLUDES", "CXX_FLAGS"):
        for a in shlex.split(values.get(key, "")):
            if a.startswith("-I") and (a[2:] == source or a[2:].startswith(source + os.sep)):
                a = "-I" + scratch + a[2 + len(source):]
            args.append(a)
    return args


def changed_files(source, scratch):
    """Sources the block added or changed under src/, materials/, apps/, test/unit/: (new, modified)."""
    new, modified = [], []
    for top in ("src", "materials", "apps", os.path.join("test", "unit")):
        for dirpath, _, names in os.walk(os.path.join(scratch, top)):
            for n in names:
                if not n.endswith((".cpp", ".hpp")):
                    continue
                rel = os.path.relpath(os.path.join(dirpath, n), scratch)
                original = os.path.join(source, rel)
                if not os.path.exists(original):
                    new.append(rel)
                elif not filecmp.cmp(original, os.path.join(scratch, rel), shallow=False):
                    modified.append(rel)
    return new, modified


def compile_all(files, compile_flags, scratch, out_dir):
    objects = []
    for rel in files:
        obj = os.path.join(out_dir, rel.replace(os.sep, "_") + ".o")
        cmd = ["c++"] + compile_flags + ["-c", os.path.join(scratch, rel), "-o", obj]
        print("  compile " + rel, flush=True)
        if subprocess.run(cmd).returncode != 0:
            fail("compiling %s failed" % rel)
        objects.append(obj)
    return objects


def relink(link_dir, link_txt, target, output, extra, drop):
    """Runs a target's link line with the extra objects before the first static library and the dropped ones out."""
    args = shlex.split(open(link_txt).read())
    args = [a for a in args if os.path.basename(a) not in drop]
    at = next(i for i, a in enumerate(args) if a.endswith(".a"))
    args[at:at] = extra
    out = args.index("-o")
    if args[out + 1] != target:
        fail("unexpected link line in %s" % link_txt)
    args[out + 1] = output
    print("  link " + os.path.relpath(output), flush=True)
    if subprocess.run(args, cwd=link_dir).returncode != 0:
        fail("linking %s failed" % target)


def partial_build(source, build, scratch):
    new, modified = changed_files(source, scratch)
    headers = [f for f in modified if f.endswith(".hpp")]
    if headers:
        fail("the procedure changes %s, which other sources include: a partial build cannot follow it" % headers)
    cpp = [f for f in new + modified if f.endswith(".cpp")]
    core = [f for f in cpp if f.startswith(("src" + os.sep, "materials" + os.sep))]
    tests = [f for f in cpp if f.startswith(os.path.join("test", "unit") + os.sep)]
    if [f for f in cpp if f not in core + tests]:
        fail("the procedure changes %s: only core sources and unit tests are followed" % sorted(set(cpp) - set(core + tests)))
    out = os.path.join(scratch, "build")
    objects = os.path.join(out, "partial")
    os.makedirs(os.path.join(out, "test"), exist_ok=True)
    os.makedirs(objects, exist_ok=True)
    cmake_files = os.path.join(build, "CMakeFiles")
    core_objects = compile_all(core, flags(os.path.join(cmake_files, "periforge_core_objects.dir", "flags.make"),
                                           source, scratch), scratch, objects)
    test_dir = os.path.join(build, "test", "CMakeFiles", "unit_tests.dir")
    test_objects = compile_all(tests, flags(os.path.join(test_dir, "flags.make"), source, scratch), scratch, objects)
    for app in ("periforge", "periforge-parameters"):
        relink(build, os.path.join(cmake_files, app + ".dir", "link.txt"), app, os.path.join(out, app),
               core_objects, set())
    replaced = {os.path.basename(f) + ".o" for f in modified if f in tests}
    relink(os.path.join(build, "test"), os.path.join(test_dir, "link.txt"), "unit_tests",
           os.path.join(out, "test", "unit_tests"), test_objects + core_objects, replaced)


def shim(source, build, scratch):
    me = os.path.abspath(__file__)
    return ('cmake() {\n'
            '  if [ "$1" = "--build" ]; then\n'
            '    %s %s --partial-build %s %s %s\n'
            '  else echo "(follow_procedure: configure step, nothing to do)"; fi\n'
            '}\n' % tuple(shlex.quote(a) for a in (sys.executable, me, source, build, scratch)))


def follow(source, build, reference_csv):
    with tempfile.TemporaryDirectory() as tmp:
        scratch = os.path.join(tmp, "src")
        copy_sources(source, scratch)
        script = "set -euo pipefail\n" + shim(source, build, scratch) + procedure(source)
        print("running docs/extending.md's procedure in a scratch copy", flush=True)
        if subprocess.run(["bash", "-c", script], cwd=scratch).returncode != 0:
            fail("a step of the procedure failed (above)")
        tests = subprocess.run([os.path.join(scratch, "build", "test", "unit_tests"), "--gtest_filter=%s.*" % MODEL_SUITE],
                               cwd=os.path.join(build, "test"), capture_output=True, text=True)
        ran = re.search(r"\[==========\] (\d+) tests? from", tests.stdout)
        if tests.returncode != 0 or not ran or int(ran.group(1)) == 0:
            fail("the copy's unit tests (%s.*) did not pass: %s" % (MODEL_SUITE, tests.stdout[-600:]))
        print("  %s unit tests of %s pass" % (ran.group(1), MODEL_SUITE))
        docs = subprocess.run([sys.executable, os.path.join(scratch, "scripts", "generate_input_docs"), "--check",
                               "--exe", os.path.join(scratch, "build", "periforge-parameters"),
                               "--doc", os.path.join(scratch, "docs", "input.md")], capture_output=True, text=True)
        if docs.returncode != 0:
            fail("docs/input.md is not current after the procedure: " + (docs.stdout + docs.stderr)[-400:])
        csv = os.path.join(scratch, DECK_DIR, DECK_CSV)
        if not os.path.exists(csv):
            fail("the procedure's deck wrote no %s" % csv)
        if not filecmp.cmp(csv, reference_csv, shallow=False):
            fail("the copy's deck history differs from the original model's (%s)" % reference_csv)
        print("  the copy's deck history equals Microelastic's byte for byte; docs/input.md is current")


def main():
    if len(sys.argv) == 5 and sys.argv[1] == "--partial-build":
        partial_build(*[os.path.abspath(a) for a in sys.argv[2:5]])
    elif len(sys.argv) == 4:
        follow(*[os.path.abspath(a) for a in sys.argv[1:4]])
    else:
        fail(__doc__.split("usage:")[1].strip())


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""Run every command of docs/tutorial.md in a scratch folder (issue 37): the doc cannot drift from the code.

usage: run_tutorial.py REPO_DIR BUILD_DIR

The ```sh blocks run in order as one bash script (set -e -o pipefail: the first failing command fails the test,
named on stderr) with PERIFORGE_DIR = REPO_DIR and PATH = BUILD_DIR:REPO_DIR/scripts:PATH, which is what the
tutorial's ```sh setup block sets up by hand (not run). A line `! CMD` (a command that must fail) fails the
test when CMD succeeds. ```sh paraview blocks run only when pvpython is on the
PATH (the ctest render_paraview covers the script). Every ```xml block must appear, whitespace aside, in one of
examples/tutorial/*.xml. The scratch folder is a fresh temporary directory, removed afterwards.
"""
import glob
import os
import re
import shutil
import subprocess
import sys
import tempfile

BLOCK = re.compile(r"^```(\w+)([^\n]*)\n(.*?)^```\s*$", re.S | re.M)


def squash(text):
    return " ".join(text.split())


def main():
    repo, build = (os.path.abspath(p) for p in sys.argv[1:3])
    doc = open(os.path.join(repo, "docs", "tutorial.md")).read()
    decks = [squash(open(p).read()) for p in glob.glob(os.path.join(repo, "examples", "tutorial", "*.xml"))]
    problems, script = [], ["set -e -o pipefail",
                            "trap 'echo \"tutorial: command failed (status $?): $BASH_COMMAND\" >&2' ERR"]
    has_pvpython = shutil.which("pvpython") is not None
    for lang, tag, body in BLOCK.findall(doc):
        tag = tag.strip()
        if lang == "xml" and not any(squash(body) in d for d in decks):
            problems.append("docs/tutorial.md: an xml excerpt is in no examples/tutorial deck:\n" + body)
        if lang != "sh" or tag == "setup":
            continue
        if tag == "paraview" and not has_pvpython:
            print("tutorial: pvpython not found: the ParaView block is not run")
            continue
        # bash -e ignores a failing `! cmd`: the doc's expected refusals must fail the test when they succeed
        script.append(re.sub(r"^! (.*)$", r"if \1; then echo 'tutorial: expected to fail: \1' >&2; false; fi", body,
                             flags=re.M))
    if sum(1 for lang, tag, _ in BLOCK.findall(doc) if lang == "sh" and tag.strip() == "") < 5:
        problems.append("docs/tutorial.md: fewer sh blocks than expected: is the fence syntax right?")
    env = dict(os.environ, PERIFORGE_DIR=repo,
               PATH=os.pathsep.join([build, os.path.join(repo, "scripts"), os.environ.get("PATH", "")]),
               OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1")
    scratch = tempfile.mkdtemp(prefix="pf_tutorial_")
    try:
        run = subprocess.run(["bash", "-c", "\n".join(script)], cwd=scratch, env=env, timeout=240)
        if run.returncode != 0:
            problems.append("a tutorial command failed (status %d): see above" % run.returncode)
        made = ["reaction.png", "displacement.png", "dilatation.png", "reaction_hardening.png", "plastic_strain.png",
                "plate_hardening.csv", "plate_hardening.e"]
        for name in made:
            if not os.path.exists(os.path.join(scratch, "first_run", name)):
                problems.append("the tutorial did not make first_run/" + name)
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    for p in problems:
        print("tutorial: " + p, file=sys.stderr)
    print("tutorial: %s" % ("FAILED" if problems else "all commands ran"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

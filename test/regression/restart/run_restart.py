#!/usr/bin/env python3
"""Restart from a checkpoint (issue 15, part 7) at given rank counts, each case in its own temporary directory
under a timeout (a hang fails the test instead of stalling the suite).

usage: run_restart.py kill DECK NP_KILL NP_RESTART EXE MPIRUN... [-- COMPARE_CSV_ARGS... [-- EXODIFF_COMP]]
       run_restart.py refuse DECK NP EXE MPIRUN...

kill: an uninterrupted reference run at NP_RESTART; a run at NP_KILL killed with SIGKILL (every rank) once its
first checkpoint exists and before it ends, leaving .part files and a stale lock; then `--restart rs.restart` at
NP_RESTART. Same rank counts: the restarted run's rs.csv and rs.e must equal the reference's byte for byte.
Different ones: the rows up to the checkpoint must equal the killed run's byte for byte, and the whole history
must agree with the reference within COMPARE_CSV_ARGS (scripts/compare_csv) and rs.e within the EXODIFF_COMP
command file (scripts/exodiff.py): summation order differs between rank counts, so the rows after the checkpoint
carry the round-off that separates uninterrupted np 1 and np 2 runs (the tolerances state it).

refuse: a truncated, a corrupt, a foreign (another deck's) checkpoint, a file that is no checkpoint and a missing
one each end every rank with one 'periforge:' line naming the file, a non-zero exit that is not a signal, and no
output file touched.  DECK writes rs.{csv,e} and rs.restart (Output Filename rs, a Restart list).
"""
import os
import re
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from process_kill import kill_every_rank  # noqa: E402

LIMIT = 240  # seconds for any one run; ctest's TIMEOUT is larger
HERE = os.path.dirname(os.path.abspath(__file__))
SCRIPTS = os.path.join(HERE, "..", "..", "..", "scripts")
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


def run(cmd, cwd):
    p = subprocess.run(cmd, cwd=cwd, capture_output=True, text=True, timeout=LIMIT)
    return p.returncode, p.stdout, p.stderr


def reference(cmd, deck, work):
    ref = os.path.join(work, "reference")
    os.mkdir(ref)
    code, _, err = run(cmd + [deck], ref)
    check(code == 0, "the reference run failed (%d): %s" % (code, err[-300:]))
    return ref


def killed_run(cmd, deck, work, direct):
    """Starts the run, SIGKILLs every rank as soon as its first checkpoint exists; returns the run directory."""
    run_dir = os.path.join(work, "run")
    os.mkdir(run_dir)
    p = subprocess.Popen(cmd + [deck], cwd=run_dir, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                         start_new_session=True)
    checkpoint = os.path.join(run_dir, "rs.restart")
    end = time.time() + LIMIT
    while time.time() < end and p.poll() is None and not os.path.exists(checkpoint):
        time.sleep(0.01)
    kill_every_rank(p, direct, LIMIT)
    check(os.path.exists(checkpoint), "the killed run wrote no checkpoint")
    check(not os.path.exists(os.path.join(run_dir, "rs.csv")), "the run ended before it was killed")
    check(os.path.exists(os.path.join(run_dir, "rs.lock")), "the killed run left no stale lock to take over")
    return run_dir


def rows(path):
    return open(path).read().splitlines()


def same_bytes(a, b, what):
    check(open(a, "rb").read() == open(b, "rb").read(), "%s differs from the uninterrupted run's" % what)


def case_kill(deck, np_kill, np_restart, exe, mpirun, csv_args, comp):
    with tempfile.TemporaryDirectory() as work:
        ref = reference(command(exe, mpirun, np_restart), deck, work)
        run_dir = killed_run(command(exe, mpirun, np_kill), deck, work, not mpirun)
        part = rows(os.path.join(run_dir, "rs.csv.part"))
        code, out, err = run(command(exe, mpirun, np_restart) + [deck, "--restart", "rs.restart"], run_dir)
        check(code == 0, "the restarted run failed (%d): %s" % (code, err[-400:]))
        m = re.search(r"restart from rs.restart after step (\d+)", out)
        check(m is not None, "no 'restart from ... after step' line: %r" % out[-300:])
        if problems:
            return
        step = int(m.group(1))
        last = int(float(rows(os.path.join(ref, "rs.csv"))[-1].split(",")[1]))
        print("    killed after the checkpoint of step %d (last step %d), restarted at np %d" % (step, last, np_restart))
        check(0 < step < last, "the checkpoint's step %d is not between the first and the last" % step)
        left = sorted(f for f in os.listdir(run_dir) if f.startswith("rs.") and f not in ("rs.csv", "rs.e", "rs.restart"))
        check(left == [], "the restarted run left %s" % left)
        result = os.path.join(run_dir, "rs.csv")
        if np_kill == np_restart:
            same_bytes(result, os.path.join(ref, "rs.csv"), "rs.csv")
            same_bytes(os.path.join(run_dir, "rs.e"), os.path.join(ref, "rs.e"), "rs.e")
            return
        # The killed run's complete rows up to the checkpoint (a kill may cut its last row short).
        width = len(part[0].split(","))
        upto = [r for r in part[1:] if len(r.split(",")) == width and float(r.split(",")[1]) <= step]
        check(rows(result)[:len(upto) + 1] == part[:1] + upto, "the rows up to the checkpoint are not the killed run's")
        p = subprocess.run([sys.executable, os.path.join(SCRIPTS, "compare_csv"), result, os.path.join(ref, "rs.csv")] +
                           csv_args, capture_output=True, text=True)
        print(p.stdout[-1500:])
        check(p.returncode == 0, "rs.csv differs from the uninterrupted run beyond the tolerances")
        p = subprocess.run(["/usr/bin/python3", os.path.join(SCRIPTS, "exodiff.py"), os.path.join(run_dir, "rs.e"),
                            os.path.join(ref, "rs.e"), comp], capture_output=True, text=True)
        print(p.stdout[-1500:])
        check(p.returncode == 0, "rs.e differs from the uninterrupted run beyond the tolerances")


def refused(cmd, work, checkpoint, words, what):
    code, _, err = run(cmd + ["--restart", checkpoint], work)
    lines = [l for l in err.splitlines() if l.startswith("periforge:")]
    print("    %s: %s" % (what, lines[0] if lines else "(no periforge line)"))
    check(code > 0, "%s: exit code %d (want > 0, not a signal)" % (what, code))
    check(len(lines) == 1, "%s: %d 'periforge:' lines on stderr (want 1): %r" % (what, len(lines), err[-400:]))
    for w in words:
        check(bool(lines) and w in lines[0], "%s: the message lacks %r" % (what, w))
    for bad in ("terminate called", "Abort", "backtrace", "MPI_ABORT", "Signal:"):
        check(bad not in err, "%s: stderr mentions %r" % (what, bad))


def case_refuse(deck, np, exe, mpirun):
    cmd = command(exe, mpirun, np)
    with tempfile.TemporaryDirectory() as work:
        # The deck shortened to 200 steps with a checkpoint every 50: these cases need a checkpoint, not a long run.
        short = open(deck).read().replace('name="Final Time" type="double" value="2.0e-4"',
                                          'name="Final Time" type="double" value="1.0e-5"')
        short = re.sub(r'(name="Checkpoint Frequency" type="int" value=")\d+', r"\g<1>50", short)
        open(os.path.join(work, "deck.xml"), "w").write(short)
        code, _, err = run(cmd + ["deck.xml"], work)
        check(code == 0, "the good run failed (%d): %s" % (code, err[-300:]))
        good = open(os.path.join(work, "rs.restart"), "rb").read()
        before = {n: open(os.path.join(work, n), "rb").read() for n in ("rs.csv", "rs.e")}
        open(os.path.join(work, "truncated.restart"), "wb").write(good[: len(good) // 2])
        flipped = bytearray(good)
        flipped[len(good) // 2] ^= 0x40
        open(os.path.join(work, "corrupt.restart"), "wb").write(bytes(flipped))
        # Another deck: the same bar with another Young's modulus writes its own checkpoint.
        text = short.replace('value="200.0e9"', 'value="210.0e9"')
        os.mkdir(os.path.join(work, "other"))
        open(os.path.join(work, "other", "deck.xml"), "w").write(text)
        code, _, err = run(cmd + ["deck.xml"], os.path.join(work, "other"))
        check(code == 0, "the other deck's run failed (%d): %s" % (code, err[-300:]))
        base = cmd + ["deck.xml"]
        refused(base, work, "truncated.restart", ["truncated.restart", "truncated"], "truncated")
        refused(base, work, "corrupt.restart", ["corrupt.restart", "corrupt"], "corrupt")
        refused(base, work, "deck.xml", ["deck.xml", "not a Periforge checkpoint"], "not a checkpoint")
        refused(base, work, "missing.restart", ["missing.restart", "cannot open"], "missing")
        refused(base, work, "other/rs.restart", ["other/rs.restart", "another deck", "Young's Modulus"], "another deck")
        after = {n: open(os.path.join(work, n), "rb").read() for n in ("rs.csv", "rs.e")}
        check(after == before, "a refused restart touched rs.csv or rs.e")
        left = sorted(f for f in os.listdir(work) if f.startswith("rs.") and f not in ("rs.csv", "rs.e", "rs.restart"))
        check(left == [], "a refused restart left %s" % left)


def command(exe, mpirun, np):
    return [exe] if not mpirun else mpirun + ["-np", str(np), exe]


def main():
    args = sys.argv[1:]
    case = args.pop(0)
    groups = [[]]
    for a in args:
        if a == "--":
            groups.append([])
        else:
            groups[-1].append(a)
    head = groups[0]
    deck = os.path.abspath(head[0])
    if case == "kill":
        np_kill, np_restart, exe, mpirun = int(head[1]), int(head[2]), head[3], head[4:]
        csv_args = groups[1] if len(groups) > 1 else []
        comp = groups[2][0] if len(groups) > 2 else ""
        case_kill(deck, np_kill, np_restart, exe, mpirun, csv_args, comp)
        label = "kill np %d -> restart np %d" % (np_kill, np_restart)
    else:
        np, exe, mpirun = int(head[1]), head[2], head[3:]
        case_refuse(deck, np, exe, mpirun)
        label = "refuse np %d" % np
    print("%s %s: %s" % (os.path.basename(deck), label, "PASS" if not problems else "FAIL\n  " + "\n  ".join(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

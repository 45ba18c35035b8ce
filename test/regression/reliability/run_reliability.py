#!/usr/bin/env python3
"""One reliability case of issue 15 (parts 1 and 6) at a given number of ranks: a failure that happens on
rank 0 only, a signal, or a second run on the same output name must end every rank promptly (no hang: ctest's
TIMEOUT and ours), with one 'periforge:' line, a non-zero exit that is not a signal, and never a partial result
under the result's name: the previous run's rel.csv / rel.e stay byte-identical.

usage: run_reliability.py CASE NP EXE DECK MPIRUN...   (DECK: rel_bar.xml, writing 'rel')
"""
import hashlib
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), ".."))
from process_kill import kill_every_rank, ranks  # noqa: E402

LIMIT = 45  # seconds for any one run; ctest's TIMEOUT is 60
problems = []


def check(ok, what):
    if not ok:
        problems.append(what)


def deck(work, base, name="rel", final="1.0e-5", frequency="10"):
    """The base deck with another Output Filename / Final Time / Output Frequency, written into work."""
    text = open(base).read()
    text = text.replace('value="rel"', 'value="%s"' % name)
    text = re.sub(r'(name="Final Time" type="double" value=")[^"]*', r"\g<1>" + final, text)
    text = re.sub(r'(name="Output Frequency" type="int" value=")[^"]*', r"\g<1>" + frequency, text)
    path = os.path.join(work, "deck_%s_%s.xml" % (name.replace("/", "_"), final))
    open(path, "w").write(text)
    return path


def long_deck(work, base, name="rel"):
    return deck(work, base, name, final="2.0e-3", frequency="200")  # 40000 steps, a row every 200


def run(cmd, work, prefix=()):
    p = subprocess.run(list(prefix) + cmd, cwd=work, capture_output=True, text=True, timeout=LIMIT)
    return p.returncode, p.stderr


def one_line(code, stderr, words, want_code=None):
    lines = [l for l in stderr.splitlines() if l.startswith("periforge:")]
    check(code > 0 and (want_code is None or code == want_code),
          "exit code %d (want %s, not a signal)" % (code, want_code or "> 0"))
    check(len(lines) == 1, "%d 'periforge:' lines on stderr (want 1): %r" % (len(lines), stderr[-400:]))
    for w in words:
        check(bool(lines) and w in lines[0], "message does not contain %r: %r" % (w, lines[:1]))
    for bad in ("terminate called", "Abort", "backtrace", "MPI_ABORT", "Signal:"):
        check(bad not in stderr, "stderr mentions %r" % bad)
    print("    " + (lines[0] if lines else "(no periforge line)"))


def digest(work, names=("rel.csv", "rel.e")):
    return {n: hashlib.sha256(open(os.path.join(work, n), "rb").read()).hexdigest() for n in names}


def previous_result(cmd, work, base):
    """A completed run: rel.csv and rel.e, and nothing else of 'rel'."""
    code, err = run(cmd + [deck(work, base)], work)
    check(code == 0, "the good run failed (%d): %s" % (code, err[-300:]))
    left = sorted(f for f in os.listdir(work) if f.startswith("rel.") and f not in ("rel.csv", "rel.e"))
    check(left == [], "a successful run left %s" % left)
    return digest(work)


def untouched(work, before):
    check(digest(work) == before, "the previous rel.csv / rel.e changed")


def status(work):
    path = os.path.join(work, "rel.status")
    return open(path).read().strip() if os.path.exists(path) else ""


def start(cmd, work, path):
    return subprocess.Popen(cmd + [path], cwd=work, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True,
                            start_new_session=True)


def wait_rows(work, rows, p):
    """Until rel.csv.part has `rows` data rows (the run is under way)."""
    part = os.path.join(work, "rel.csv.part")
    end = time.time() + LIMIT
    while time.time() < end and p.poll() is None:
        if os.path.exists(part) and open(part).read().count("\n") > rows:
            return True
        time.sleep(0.05)
    check(False, "the long run never wrote %d rows (exit %s)" % (rows, p.poll()))
    return False


def case_missing_dir(cmd, work, base):
    code, err = run(cmd + [deck(work, base, name="no_such_dir/rel")], work)
    one_line(code, err, [".xml", "Output Filename", "no_such_dir/rel"])
    check(not os.path.exists(os.path.join(work, "no_such_dir")), "a directory was created")


def case_exodus_is_dir(cmd, work, base):
    os.mkdir(os.path.join(work, "rel.e"))
    code, err = run(cmd + [deck(work, base)], work)
    one_line(code, err, [".xml", "Output Filename", "rel.e", "is a directory"])
    check(not any(f.startswith("rel.") and f != "rel.e" for f in os.listdir(work)), "files were written")


def case_disk_full(cmd, work, base):
    """Rank 0's writes fail mid-run (file size limit, SIGXFSZ ignored: EFBIG as on a full disk)."""
    before = previous_result(cmd, work, base)
    # Inside mpirun's launch (which resets signal actions), around periforge only.
    limited = cmd[:-1] + ["bash", "-c", 'trap "" XFSZ; ulimit -f 1000; exec "$@"', "limited", cmd[-1]]
    code, err = run(limited + [long_deck(work, base)], work)
    one_line(code, err, ["rel.e.part"])
    untouched(work, before)
    check(status(work).startswith("failed after step"), "rel.status: %r" % status(work))
    check(not os.path.exists(os.path.join(work, "rel.lock")), "rel.lock left behind")


def case_live_lock(cmd, work, base):
    """A lock held by a live run of this program (a process named periforge: a copy of sleep) is refused;
    one held by a live process of another program (this script) is stale and taken over (issue 40)."""
    before = previous_result(cmd, work, base)
    lock = os.path.join(work, "rel.lock")
    fake = os.path.join(work, "periforge")
    shutil.copy(shutil.which("sleep"), fake)
    other = subprocess.Popen([fake, "60"])
    try:
        open(lock, "w").write("%d\n" % other.pid)
        code, err = run(cmd + [deck(work, base)], work)
        one_line(code, err, [".xml", "Output Filename", "another run (pid %d)" % other.pid, "rel.lock"])
        untouched(work, before)
        check(open(lock).read() == "%d\n" % other.pid, "the other run's lock was touched")
        check(not os.path.exists(os.path.join(work, "rel.csv.part")), "the refused run wrote rel.csv.part")
    finally:
        other.kill()
        other.wait()
    open(lock, "w").write("%d\n" % os.getpid())
    code, err = run(cmd + [deck(work, base)], work)
    check(code == 0, "a lock holding the PID of another program was not taken over: %s" % err.strip()[-200:])
    check(not os.path.exists(lock), "rel.lock left behind")


def case_concurrent(cmd, work, base, direct):
    """A real second run while the first one writes: refused; the first one is then stopped."""
    first = start(cmd, work, long_deck(work, base))
    if wait_rows(work, 1, first):
        code, err = run(cmd + [deck(work, base)], work)
        one_line(code, err, ["another run", "rel.lock"])
    for pid in ranks(first, direct):
        os.kill(pid, signal.SIGTERM)
    first.communicate(timeout=LIMIT)
    check(not os.path.exists(os.path.join(work, "rel.csv")), "rel.csv presented as a result")


def case_sigterm(cmd, work, base, direct):
    """SIGTERM to one rank (the last): every rank stops at the same step, exit 143, marked interrupted."""
    before = previous_result(cmd, work, base)
    p = start(cmd, work, long_deck(work, base))
    if wait_rows(work, 2, p):
        os.kill(ranks(p, direct)[-1], signal.SIGTERM)
    _, err = p.communicate(timeout=LIMIT)
    one_line(p.returncode, err, ["stopped by SIGTERM"], want_code=143)
    untouched(work, before)
    check(status(work).startswith("interrupted after step"), "rel.status: %r" % status(work))
    check(os.path.exists(os.path.join(work, "rel.e.part")), "rel.e.part missing")
    check(not os.path.exists(os.path.join(work, "rel.lock")), "rel.lock left behind")


def case_sigkill(cmd, work, base, direct):
    """kill -9 of every rank: the previous result survives; the next run takes the dead run's lock over."""
    before = previous_result(cmd, work, base)
    p = start(cmd, work, long_deck(work, base))
    if wait_rows(work, 2, p):
        kill_every_rank(p, direct, LIMIT)
    else:
        p.communicate(timeout=LIMIT)
    untouched(work, before)
    check(status(work).startswith("running (pid"), "rel.status: %r" % status(work))
    check(os.path.exists(os.path.join(work, "rel.lock")), "no stale rel.lock to take over")
    after = previous_result(cmd, work, base)
    check(after == before, "the rerun's result differs from the first run's")


def plate_deck(work, base, steps):
    """The coarse plate (NOX, one load step per unit time) cut to its first `steps` load steps, writing 'rel'."""
    text = open(base).read()
    text = re.sub(r'(name="Output Filename" type="string" value=")[^"]*', r"\g<1>rel", text)
    text = re.sub(r'(name="Final Time" type="double" value=")[^"]*', r"\g<1>%d.0" % steps, text)
    text = re.sub(r'(name="Number of Load Steps" type="int" value=")[^"]*', r"\g<1>%d" % steps, text)
    path = os.path.join(work, "plate_%d.xml" % steps)
    open(path, "w").write(text)
    return path


def case_plate_sigkill(cmd, work, base, direct):
    """The issue's case: a run of the coarse plate killed mid-way (kill -9, every rank) leaves the previous
    result byte-identical (base: test/regression/plate/plate_iso_coarse_nox.xml)."""
    code, err = run(cmd + [plate_deck(work, base, 3)], work)
    check(code == 0, "the good run failed (%d): %s" % (code, err[-300:]))
    before = digest(work)
    p = start(cmd, work, plate_deck(work, base, 120))
    if wait_rows(work, 3, p):
        kill_every_rank(p, direct, LIMIT)
    else:
        p.communicate(timeout=LIMIT)
    untouched(work, before)
    check(status(work).startswith("running (pid"), "rel.status: %r" % status(work))
    check(os.path.exists(os.path.join(work, "rel.csv.part")), "no rel.csv.part of the killed run")


def main():
    case, np, exe, base = sys.argv[1], int(sys.argv[2]), sys.argv[3], os.path.abspath(sys.argv[4])
    mpirun = sys.argv[5:]
    direct = not mpirun
    cmd = [exe] if direct else mpirun + ["-np", str(np), exe]
    cases = {"missing_dir": case_missing_dir, "exodus_is_dir": case_exodus_is_dir, "disk_full": case_disk_full,
             "live_lock": case_live_lock}
    with tempfile.TemporaryDirectory() as work:
        if case in cases:
            cases[case](cmd, work, base)
        else:
            {"concurrent": case_concurrent, "sigterm": case_sigterm, "sigkill": case_sigkill,
             "plate_sigkill": case_plate_sigkill}[case](
                cmd, work, base, direct)
    print("%s np %d: %s" % (case, np, "PASS" if not problems else "FAIL\n  " + "\n  ".join(problems)))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())

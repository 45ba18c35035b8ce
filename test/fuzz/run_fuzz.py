#!/usr/bin/env python3
"""Fuzz test (issue 15): runs the mutated decks of generate_decks.py and fails on any crash, hang, unclear
error or bad output. Each deck runs in its own temporary directory under a 30 s timeout.

Classes (docs/verification.md, "Fuzz test"):
  ok           exit 0, stderr holds only "periforge: warning: " lines, no non-finite number in a CSV;
  clean error  exit 1..127 and exactly one error line on stderr, the last "periforge:" line, of the form
               "periforge: input error: <deck>: ..." or "periforge: error: <deck>: ..." (names the deck) or
               "periforge: solver failed: ..." / "periforge: material update failed: ..." (names the solver,
               step and node); every other line of ours is a warning, and no <name>.e / <name>.csv was
               left (a failed run keeps only .part files);
  crash        killed by a signal (exit < 0 or >= 128), or abort/backtrace/uncaught-exception text;
  slow         still running after the timeout, and stopped by SIGTERM within 15 s with its one line (not
               a failure: a valid deck that runs long, now stopped as a user would);
  hang         still running after the timeout and not stopped by SIGTERM (killed with its process group);
  unclear      any other non-zero exit: no error line, several, one naming nothing, stray stderr text;
  bad output   exit 0 with a non-finite number in a CSV, or result files left by a failed run.

usage: run_fuzz.py PERIFORGE [--count N] [--seed S] [--np K] [--subset M] [--only CASE] [--keep DIR]
                   [--jobs J] [--verbose] [-- MPIRUN...]
  --subset M   run M cases spread evenly over the list (for the np 2 run);
  --only CASE  run one case (reproduce a failure: its name is printed with the failure);
  --keep DIR   where failing cases' directories are kept (default fuzz_failures in the working directory);
  --verbose    print every case: class, description, the last line of stderr.
"""
import argparse
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import generate_decks  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "regression"))
from process_kill import ranks  # noqa: E402

TIMEOUT = 30.0
STOP_GRACE = 15.0  # seconds a timed-out run has to stop on SIGTERM before it counts as a hang
FAILING = ("crash", "hang", "unclear", "bad output")
CRASH_TEXT = re.compile(r"terminate called|Assertion|Segmentation|Aborted|core dumped|[Bb]acktrace|"
                        r"(?i:signal)|MPI_ABORT|Throw number|Throw test|what\(\):|double free|corrupted")
# An error line must be readable text in Periforge's words, whole: no replacement or control characters,
# no C++/Teuchos internals, not ending in a colon or an opened quote (a message cut at a NUL byte).
GARBLED = re.compile("[\ufffd\x00-\x08\x0b-\x1f]")
LIBRARY_TEXT = re.compile(r"XMLObject|Teuchos|std::|converter|::")
CUT_SHORT = re.compile(r"(:|= '|\s')$")
BAD_NUMBER = re.compile(r"(?i)(^|[,\s])[-+]?(nan|inf)")
# Open MPI's start-up probes network transports (UCX, OFI) and, as a singleton, starts a daemon: ~0.5 s
# per run. One rank needs no transport but "self" and no daemon; np 2 on one node needs shared memory.
# Results do not depend on the transport.
FAST_MPI = {1: {"OMPI_MCA_ess_singleton_isolated": "1", "OMPI_MCA_pml": "ob1", "OMPI_MCA_btl": "self",
                "OMPI_MCA_mtl": "^ofi"},
            2: {"OMPI_MCA_pml": "ob1", "OMPI_MCA_btl": "self,vader", "OMPI_MCA_mtl": "^ofi"}}


def classify(code, out, err, deck, files, np):
    """(class, reason) of one run; files: the names left in the case's directories."""
    if code is None:
        return "hang", f"still running after {TIMEOUT:.0f} s"
    if code < 0 or code >= 128:
        return "crash", f"exit code {code}"
    m = CRASH_TEXT.search(out + err)
    if m:
        return "crash", f"'{m.group(0)}' in the output"
    lines = [l for l in err.splitlines() if l.strip()]
    ours = [l for l in lines if l.startswith("periforge: ")]
    # At np > 1 mpirun adds its own banner when a rank exits non-zero; at np 1 nothing else may appear.
    stray = [l for l in lines if not l.startswith("periforge: ")] if np == 1 else []
    errors = [l for l in ours if not l.startswith("periforge: warning: ")]
    results = [f for f in files if f.endswith((".e", ".csv"))]
    if code == 0:
        if errors or stray:
            return "unclear", f"exit 0 with stderr line '{(errors + stray)[0]}'"
        bad = [f for f, text in files.items() if f.endswith(".csv") and any(
            BAD_NUMBER.search(l) for l in text.splitlines()[1:])]
        return ("bad output", f"non-finite number in {bad[0]}") if bad else ("ok", "")
    if len(errors) != 1 or ours[-1] != errors[0]:
        return "unclear", f"{len(errors)} error lines (want 1, the last)"
    if stray:
        return "unclear", f"stray stderr line '{stray[0]}'"
    clean = re.match(r"periforge: (input error|error): " + re.escape(deck) + r": \S", errors[0]) or \
        re.match(r"periforge: (solver failed|material update failed): \S", errors[0])
    if not clean:
        return "unclear", "the error line names neither the deck nor a solver failure"
    if GARBLED.search(errors[0]):
        return "unclear", "the error line holds bytes that are not text"
    if LIBRARY_TEXT.search(errors[0]):
        return "unclear", "the error line is a library's message (names no parameter)"
    if CUT_SHORT.search(errors[0]):
        return "unclear", "the error line is cut short"
    if results:
        return "bad output", f"a failed run left {results}"
    return "clean error", ""


def run_case(exe, mpirun, np, name, text, root, timeout=None):
    """Runs one deck in root/name/run (a level down, so that '../x' output names stay inside root/name)."""
    case_dir = os.path.join(root, name)
    run_dir = os.path.join(case_dir, "run")
    os.makedirs(run_dir)
    deck = generate_decks.write_case(run_dir, name, text)
    cmd = [exe, os.path.basename(deck)] if np == 1 else mpirun + ["-np", str(np), exe, os.path.basename(deck)]
    env = dict(FAST_MPI[min(np, 2)], **os.environ)
    # Isolated singletons all take job id 0, hence one session directory under /tmp, which the first to
    # finish removes under the others' feet (orte_init fails): each run gets its own.
    env["OMPI_MCA_orte_tmpdir_base"] = case_dir
    start = time.monotonic()
    p = subprocess.Popen(cmd, cwd=run_dir, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         start_new_session=True)
    stopped = False
    try:
        out, err = p.communicate(timeout=timeout or TIMEOUT)
        code = p.returncode
    except subprocess.TimeoutExpired:
        # A run still going is asked to stop as a user would (SIGTERM to the group). One that stops within
        # STOP_GRACE s with its "stopped by SIGTERM" line is slow, not hung; one that does not is killed: a hang.
        # Under mpirun the ranks are signalled, not mpirun (which would kill them before they reach a poll).
        for pid in ranks(p, np == 1):
            try:
                os.kill(pid, signal.SIGTERM)
            except ProcessLookupError:
                pass
        try:
            out, err = p.communicate(timeout=STOP_GRACE)
            # mpirun reports a rank's exit code 143 as its own (or as 1 with its banner): the line decides there.
            stopped = (p.returncode == 128 + signal.SIGTERM or np > 1) and b"stopped by SIGTERM" in err
            code = p.returncode if stopped else None
        except subprocess.TimeoutExpired:
            os.killpg(p.pid, signal.SIGKILL)  # mpirun and its ranks are in the group
            out, err = p.communicate()
            code = None
    elapsed = time.monotonic() - start
    for stream, data in (("stdout.txt", out), ("stderr.txt", err)):  # kept with the deck if it fails
        with open(os.path.join(case_dir, stream), "wb") as f:
            f.write(data)
    out, err = out.decode("utf-8", "replace"), err.decode("utf-8", "replace")
    files = {}
    for d, _, names in os.walk(case_dir):
        for f in names:
            if f.endswith((".e", ".csv")):
                with open(os.path.join(d, f), "rb") as fh:
                    files[f] = fh.read().decode("utf-8", "replace") if f.endswith(".csv") else ""
    if stopped:
        return "slow", f"still running after {timeout or TIMEOUT:.0f} s; stopped by SIGTERM", elapsed, err
    kind, reason = classify(code, out, err, os.path.basename(deck), files, np)
    return kind, reason, elapsed, err


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("exe")
    ap.add_argument("--count", type=int, default=generate_decks.COUNT)
    ap.add_argument("--seed", type=int, default=generate_decks.SEED)
    ap.add_argument("--np", type=int, default=1)
    ap.add_argument("--subset", type=int, default=0)
    ap.add_argument("--only", default="")
    ap.add_argument("--keep", default="fuzz_failures")
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--verbose", action="store_true")
    argv = sys.argv[1:]
    split = argv.index("--") if "--" in argv else len(argv)
    a = ap.parse_args(argv[:split])
    a.mpirun = argv[split + 1:]
    cases = generate_decks.generate(a.count, a.seed)
    if a.subset:
        cases = [cases[i * len(cases) // a.subset] for i in range(a.subset)]
    if a.only:
        cases = [c for c in cases if c[0] == a.only]
    start = time.monotonic()
    root = tempfile.mkdtemp(prefix="fuzz_")
    with ThreadPoolExecutor(max_workers=a.jobs) as pool:
        results = list(pool.map(lambda c: run_case(a.exe, a.mpirun, a.np, c[0], c[3], root), cases))
    counts = {k: 0 for k in ("ok", "clean error", "slow") + FAILING}
    for (name, base, desc, _), (kind, reason, elapsed, err) in zip(cases, results):
        counts[kind] += 1
        if a.verbose:
            last = (err.strip().splitlines() or [""])[-1]
            print(f"[{kind}] {name} {desc}\n    {last}")
        if kind in FAILING:
            kept = os.path.join(os.path.abspath(a.keep), f"np{a.np}", name)
            shutil.rmtree(kept, ignore_errors=True)
            shutil.copytree(os.path.join(root, name), kept)
            tail = "\n      ".join(err.strip().splitlines()[-4:])
            print(f"{kind.upper()}: {name} ({base}) {desc}\n    {reason}; {elapsed:.1f} s; deck kept in {kept}/run (output in {kept})\n"
                  f"    reproduce: {sys.argv[0]} {a.exe} --np {a.np} --only {name}\n      {tail}")
    shutil.rmtree(root, ignore_errors=True)
    slow = sorted(zip((r[2] for r in results), (c[0] for c in cases)), reverse=True)[:3]
    print(f"{len(cases)} decks at np {a.np} (seed {a.seed}): " + ", ".join(f"{v} {k}" for k, v in counts.items())
          + f"; {time.monotonic() - start:.1f} s; slowest " + ", ".join(f"{n} {t:.1f} s" for t, n in slow))
    return 1 if any(counts[k] for k in FAILING) else 0


if __name__ == "__main__":
    sys.exit(main())

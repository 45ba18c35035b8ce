"""Killing a periforge run the way a user or a scheduler does, for the reliability and restart tests:
find its ranks (the process itself, or mpirun's children), SIGKILL them, and wait until they are dead."""
import os
import signal
import subprocess
import time


def ranks(p, direct):
    """The periforge processes: the launched one (direct) or mpirun's children."""
    if direct:
        return [p.pid]
    out = subprocess.run(["pgrep", "-P", str(p.pid)], capture_output=True, text=True).stdout.split()
    return [int(x) for x in out]


def gone(pids, limit):
    """Until the killed processes have died (a zombie counts as dead, as for the lock), at most limit s."""
    end = time.time() + limit
    for pid in pids:
        while time.time() < end:
            try:
                state = open("/proc/%d/stat" % pid).read().rsplit(")", 1)[1].split()[0]
            except (OSError, IndexError):
                break
            if state == "Z":
                break
            time.sleep(0.02)


def kill_every_rank(p, direct, limit):
    """kill -9 of every rank of the run p; returns once they are dead (p itself is reaped too)."""
    killed = ranks(p, direct)
    for pid in killed:
        try:
            os.kill(pid, signal.SIGKILL)
        except ProcessLookupError:  # it ended on its own meanwhile: the caller's checks will say so
            pass
    p.communicate(timeout=limit)
    gone(killed, limit)
    return killed

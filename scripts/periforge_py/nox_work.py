"""Reads the "NOX work:" line every Newton-Krylov run ends with (src/solvers/NewtonWork.cpp, NewtonWork::summary()): the
deterministic counts of the run's work, by name."""
import re

COUNTS = ("Newton", "GMRES", "residuals", "linearisations", "products", "applications", "builds")
_LINE = re.compile(r"NOX work: (\d+) Newton iterations, (\d+) GMRES iterations; (\d+) residuals .*?, (\d+) "
                   r"linearisations .*?, (\d+) tangent products .*?, (\d+) preconditioner applications .*?, (\d+) "
                   r"preconditioner builds")


def parse(stdout):
    """(counts by the names of COUNTS, the line as printed) of the first "NOX work:" line in stdout; None if none."""
    m = _LINE.search(stdout)
    if not m:
        return None
    return dict(zip(COUNTS, (int(g) for g in m.groups()))), m.group(0)

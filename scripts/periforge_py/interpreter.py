"""The interpreter the scripts need: numpy, netCDF4 and matplotlib are Debian packages (python3-numpy, ...), seen by
/usr/bin/python3 only. A script started by another python3 found first on PATH (a pyenv or venv) re-runs itself
under /usr/bin/python3 instead of failing on an import; PF_NO_REEXEC stops a second switch."""
import os
import sys

SYSTEM_PYTHON = "/usr/bin/python3"


def use_system_python():
    """Re-executes the running script under /usr/bin/python3 unless it already runs there (call before numpy)."""
    if os.environ.get("PF_NO_REEXEC") or not os.path.exists(SYSTEM_PYTHON):
        return
    if os.path.realpath(sys.executable) == os.path.realpath(SYSTEM_PYTHON):
        return
    os.environ["PF_NO_REEXEC"] = "1"
    os.execv(SYSTEM_PYTHON, [SYSTEM_PYTHON] + sys.argv)

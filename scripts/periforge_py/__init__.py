"""Periforge's Python helpers, shared by every script in scripts/, test/ and examples/ (docs/extending.md, "Scripts"):
interpreter (run under Debian's /usr/bin/python3, which has numpy, netCDF4 and matplotlib), exodus (read an
Exodus II file's variables by name) and nox_work (the counts of a Newton-Krylov run's closing "NOX work:" line). A script outside scripts/ puts this folder's parent on sys.path first."""

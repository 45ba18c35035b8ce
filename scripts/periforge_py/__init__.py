"""Periforge's Python helpers, shared by every script in scripts/, test/ and examples/ (docs/extending.md, "Scripts"):
interpreter (run under Debian's /usr/bin/python3, which has numpy, netCDF4 and matplotlib) and exodus (read an
Exodus II file's variables by name). A script outside scripts/ puts this folder's parent on sys.path first."""

"""Reads an Exodus II file (netCDF4) by variable name: the names of a char-array list (name_nod_var, name_elem_var,
name_glo_var, eb_names, ns_names, ...) and the values of nodal, element and global variables over all steps."""
from .interpreter import use_system_python

use_system_python()  # numpy and netCDF4 are Debian's: a script that reads Exodus runs under /usr/bin/python3
import numpy as np  # noqa: E402


def names(ds, key):
    """The strings of the char array `key` (trailing NULs and blanks dropped); [] when the file has none."""
    if key not in ds.variables:
        return []
    rows = np.ma.getdata(ds.variables[key][:])
    # numpy reads a NUL char as b"": put it back, or the bytes a writer left after the terminator (Peridigm's
    # VariableHorizonParsing gold: "Number_Of_Neighbors\0\0\0\0?\xfa...") would join the name.
    return [b"".join(c if c else b"\0" for c in r).split(b"\0", 1)[0].decode("ascii", "replace").strip() for r in rows]


variable_names = names  # the name the compat checks use


def nodal(ds, name):
    """Nodal variable `name`, all steps: array (steps, nodes)."""
    return np.asarray(ds["vals_nod_var%d" % (names(ds, "name_nod_var").index(name) + 1)][:])


def element(ds, name, block=1):
    """Element variable `name` of element block `block` (1-based), all steps: array (steps, elements)."""
    return np.asarray(ds["vals_elem_var%deb%d" % (names(ds, "name_elem_var").index(name) + 1, block)][:])


def global_variable(ds, name):
    """Global variable `name`, all steps."""
    return np.asarray(ds["vals_glo_var"][:])[:, names(ds, "name_glo_var").index(name)]

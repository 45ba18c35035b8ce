"""Reads variables of an Exodus II file (netCDF4) by name, for the compat checks of this folder."""
import numpy as np


def variable_names(d, key):
    """Names stored in the char array `key` (e.g. name_nod_var); empty if the file has none."""
    return [b"".join(x for x in row if x).decode() for row in d[key][:].data] if key in d.variables else []


def nodal(d, name):
    """Nodal variable `name`, all steps: array (steps, nodes)."""
    return np.asarray(d["vals_nod_var%d" % (variable_names(d, "name_nod_var").index(name) + 1)][:])


def element(d, name, block=1):
    """Element variable `name` of element block `block` (1-based), all steps: array (steps, elements)."""
    return np.asarray(d["vals_elem_var%deb%d" % (variable_names(d, "name_elem_var").index(name) + 1, block)][:])


def global_variable(d, name):
    """Global variable `name`, all steps."""
    return np.asarray(d["vals_glo_var"][:])[:, variable_names(d, "name_glo_var").index(name)]

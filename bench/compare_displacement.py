#!/usr/bin/env python3
"""Max |u_a - u_b| of two Exodus files of the same deck (points in global-id order), over all output steps, at the
last one and at steps 20, 60, 100, against max |u|. Used for docs/benchmark-log.md, "Consistent tangent of the J2 models".
usage: bench/compare_displacement.py A.e B.e"""
import sys
import numpy as np
import netCDF4 as nc

def disp(path):
    d = nc.Dataset(path)
    names = [''.join(c.decode() for c in n if c) for n in d.variables['name_nod_var'][:]]
    u = np.stack([np.asarray(d.variables[f'vals_nod_var{names.index(c) + 1}'][:]) for c in ('DisplacementX', 'DisplacementY')], -1)
    # points in global-id order
    ids = np.asarray(d.variables['node_num_map'][:]) if 'node_num_map' in d.variables else np.arange(u.shape[1])
    return u[:, np.argsort(ids), :]

a, b = disp(sys.argv[1]), disp(sys.argv[2])
diff = np.abs(a - b)
print(f"steps {a.shape[0]}, points {a.shape[1]}")
print(f"max |du| over all steps: {diff.max():.3e} m (max |u| {np.abs(a).max():.3e} m)")
print(f"max |du| at the last step: {diff[-1].max():.3e} m; max |u| there {np.abs(a[-1]).max():.3e} m")
print(f"max |du| at the peaks (steps 20, 60, 100): " + ", ".join(f"{diff[k].max():.3e}" for k in (20, 60, 100) if k < a.shape[0]))

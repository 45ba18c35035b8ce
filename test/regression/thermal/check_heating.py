#!/usr/bin/env python3
"""Plastic heating in the Taylor bar. adiabatic (taylor_adiabatic.xml, and taylor_adiabatic_j2.xml with the OSB J2
model): the heat the Temperature field holds,
sum rho c (T - T_0) V, against beta times the plastic work the material integrated (Global_Dissipated_Energy), at
every written step. conducting (taylor_conducting.xml): the same (the bar is insulated and the bond rule conserves
heat: its constant is symmetric in i and j), and in both the total energy with the heat, kinetic + stored + heat +
(1 - beta) W_p + wall loss, against the initial kinetic energy (1 %, the issue's).

Without conduction each point's temperature rises by beta dW_p / (rho c V) per step (materials/PlasticHeating.hpp),
so the two sums agree to round-off: the tolerance 1e-6 of beta W_p (the issue's) leaves room for the Exodus
file's double values and the sums' order, nothing else. A missing or double-counted step, a wrong volume or a
source spread over the wrong dt misses it by a whole step's share or more. Also printed: the energy balance
(kinetic + stored + plastic work + wall loss against the initial kinetic energy, within 1 %: the Taylor example's
own measure) and the hottest point (the impact face).
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.interpreter import use_system_python  # noqa: E402
use_system_python()
import numpy as np
from netCDF4 import Dataset
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../scripts"))
from periforge_py.exodus import names  # noqa: E402

RHO, C, BETA = 2700.0, 896.0, 0.9


def main(mode, path):  # mode: adiabatic or conducting (the same checks; named for the report)
    d = Dataset(path)
    d.set_auto_mask(False)
    nod, glo = names(d, "name_nod_var"), names(d, "name_glo_var")
    ele = names(d, "name_elem_var") if "name_elem_var" in d.variables else []

    def nodal(name, k):
        if name in nod:
            return np.asarray(d.variables[f"vals_nod_var{nod.index(name) + 1}"][k, :])
        blocks = sorted(v for v in d.variables if v.startswith(f"vals_elem_var{ele.index(name) + 1}eb"))
        return np.concatenate([np.asarray(d.variables[b][k, :]) for b in blocks])

    g = np.asarray(d.variables["vals_glo_var"][:])
    times = np.asarray(d.variables["time_whole"][:])
    ke0 = g[0, glo.index("Global_Kinetic_Energy")]
    worst_heat, worst_energy = 0.0, 0.0
    for k, t in enumerate(times):
        wp = g[k, glo.index("Global_Dissipated_Energy")]
        heat = np.sum(RHO * C * nodal("Temperature_Change", k) * nodal("Volume", k))
        total = sum(g[k, glo.index(n)] for n in ("Global_Kinetic_Energy", "Global_Strain_Energy",
                                                 "Global_Wall_Energy_Loss")) + heat + (1 - BETA) * wp
        rel = abs(heat - BETA * wp) / max(BETA * wp, 1e-300) if wp > 0 else abs(heat)
        worst_heat = max(worst_heat, rel)
        worst_energy = max(worst_energy, abs(total - ke0) / ke0)
        print(f"t = {t * 1e6:6.2f} us: plastic work {wp:9.4f} J, heat {heat:9.4f} J, |heat - beta W_p| / (beta W_p) = "
              f"{rel:.2e}, max T rise {np.max(nodal('Temperature_Change', k)):7.2f} K, energy error {abs(total - ke0) / ke0:.2e}")
    heat_tol = 1e-6
    ok = worst_heat <= heat_tol and worst_energy <= 1e-2 and g[-1, glo.index("Global_Dissipated_Energy")] > 0.1 * ke0
    print(f"worst heat error {worst_heat:.2e} (tolerance {heat_tol:g}), worst energy error {worst_energy:.2e} "
          f"(tolerance 1e-2)")
    print("check_heating: PASS" if ok else "check_heating: FAIL")
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main(sys.argv[1], sys.argv[2]))

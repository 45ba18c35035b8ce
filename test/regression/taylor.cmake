# Taylor impact (issue 17): the coarse bar of examples/taylor_impact (8 points across, 200 m/s, Viscoplastic
# Correspondence against a Rigid Wall, Verlet) at np = 1 and 2. check_taylor.py states every bound and its
# reason: L_f/L0 and D_f/D0 against closed-form bands, kinetic energy, wall force and impulse = momentum
# change, and np 1 against np 2 within round-off.
foreach(np 1 2)
  periforge_run(taylor_coarse_np${np} ${PROJECT_SOURCE_DIR}/examples/taylor_impact/taylor_coarse.xml ${np})
endforeach()
periforge_check(taylor_coarse_check "taylor_coarse_np1;taylor_coarse_np2"
  ${PY} ${REG}/taylor/check_taylor.py ${CMAKE_CURRENT_BINARY_DIR}/regression/taylor_coarse_np2
  ${CMAKE_CURRENT_BINARY_DIR}/regression/taylor_coarse_np1)
# The same bar with Viscoplastic Bond Associated Correspondence (issue 36), np 2 only: its force is summed per bond
# pair (f_i += T V_j, f_j -= T V_i), so np 1 and np 2 agree to round-off, not bit for bit. The same bounds.
periforge_run(taylor_coarse_bond_associated_np2
  ${PROJECT_SOURCE_DIR}/examples/taylor_impact/taylor_coarse_bond_associated.xml 2)
periforge_check(taylor_coarse_bond_associated_check taylor_coarse_bond_associated_np2
  ${PY} ${REG}/taylor/check_taylor.py --stem taylor_coarse_bond_associated
  ${CMAKE_CURRENT_BINARY_DIR}/regression/taylor_coarse_bond_associated_np2)
# The stored velocity sweeps (docs/data/taylor_sweep_{8,20}.csv, examples/taylor_impact/README.md): every L_f/L0
# in the Wilkins-Guinan band at its speed, both ratios monotonic in the speed, the bar off the wall, the energy
# balance within 1 % (check_sweep.py states each bound).
foreach(across 8 20)
  add_test(NAME taylor_sweep_${across}_check
    COMMAND ${PY} ${REG}/taylor/check_sweep.py ${PROJECT_SOURCE_DIR}/docs/data/taylor_sweep_${across}.csv)
  set_tests_properties(taylor_sweep_${across}_check PROPERTIES LABELS "regression")
endforeach()

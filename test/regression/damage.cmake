# Bond damage (Critical Stretch). The notched plate (examples/notched_plate, coarse: 6794 points, Verlet, 30 us)
# at np 1 and 2: the same crack at every output step (np1_vs_np2.comp: Damage exactly equal), the crack
# crosses the plate and runs slower than the Rayleigh wave speed (crack_speed.py --check). Peridigm's own
# bond-breaking decks are in peridigm.cmake.
set(NOTCHED ${PROJECT_SOURCE_DIR}/examples/notched_plate)
foreach(np 1 2)
  periforge_run(notched_plate_coarse_np${np} ${NOTCHED}/notched_plate_coarse.xml ${np})
endforeach()
set(NOTCHED_BIN ${CMAKE_CURRENT_BINARY_DIR}/regression)
periforge_check(notched_plate_coarse_np1_vs_np2 "notched_plate_coarse_np1;notched_plate_coarse_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${NOTCHED_BIN}/notched_plate_coarse_np2/notched_plate_coarse.e
  ${NOTCHED_BIN}/notched_plate_coarse_np1/notched_plate_coarse.e ${REG}/damage/np1_vs_np2.comp)
periforge_check(notched_plate_coarse_crack notched_plate_coarse_np2
  ${PY} ${NOTCHED}/crack_speed.py ${NOTCHED_BIN}/notched_plate_coarse_np2/notched_plate_coarse.e --check)

# Quasi-static breaking (solvers/BreakRounds.hpp): the 3D bar stretched past s_c, by ADR (np 1) and by NOX
# (np 2). check_bar_damage.py: no break while every stretch is below s_c, breaks and a load drop once the axial
# stretch passes it, no healing; nox_vs_adr.comp: both solvers break the same bonds and find the same equilibria.
periforge_run(bar_damage_adr_np1 ${REG}/damage/bar_damage_adr.xml 1)
periforge_run(bar_damage_nox_np2 ${REG}/damage/bar_damage_nox.xml 2)
foreach(run bar_damage_adr_np1:bar_damage_adr bar_damage_nox_np2:bar_damage_nox)
  string(REPLACE ":" ";" rd ${run})
  list(GET rd 0 name)
  list(GET rd 1 stem)
  periforge_check(${name}_check ${name}
    ${PY} ${REG}/damage/check_bar_damage.py ${NOTCHED_BIN}/${name}/${stem}.e ${NOTCHED_BIN}/${name}/${stem}.csv)
endforeach()
periforge_check(bar_damage_nox_vs_adr "bar_damage_adr_np1;bar_damage_nox_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${NOTCHED_BIN}/bar_damage_nox_np2/bar_damage_nox.e
  ${NOTCHED_BIN}/bar_damage_adr_np1/bar_damage_adr.e ${REG}/damage/nox_vs_adr.comp)

# Restart with broken bonds: killed after a checkpoint that carries a crack, restarted at the same rank count,
# the same rs.e and rs.csv as an uninterrupted run, byte for byte (restart.cmake's harness).
add_test(NAME restart_notched_kill_np1_np1
         COMMAND ${PY} ${PROJECT_SOURCE_DIR}/test/regression/restart/run_restart.py kill ${REG}/damage/restart_notched.xml
                 1 1 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_notched_kill_np1_np1 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 1)

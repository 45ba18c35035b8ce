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

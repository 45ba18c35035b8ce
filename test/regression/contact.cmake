# Contact (issue 34; model/ContactForce.hpp, docs/contact.md). Peridigm's contact decks are in peridigm.cmake.
set(CONTACT_BIN ${CMAKE_CURRENT_BINARY_DIR}/regression)
foreach(np 1 2)
  # Two points meeting head-on: velocity v0 cos(w t) while in contact, closed form (check_pair.py); at np 2 each
  # point's partner is a moving ghost of the other rank.
  periforge_run(contact_pair_np${np} ${REG}/contact/pair.xml ${np})
  periforge_check(contact_pair_np${np}_check contact_pair_np${np}
    ${PY} ${REG}/contact/check_pair.py ${CONTACT_BIN}/contact_pair_np${np}/pair.e)
  # Two cubes meeting off-centre with friction: total momentum conserved to round-off, the cubes rebound.
  periforge_run(contact_two_cubes_np${np} ${REG}/contact/two_cubes.xml ${np})
  periforge_check(contact_two_cubes_np${np}_momentum contact_two_cubes_np${np}
    ${PY} ${REG}/contact/check_momentum.py ${CONTACT_BIN}/contact_two_cubes_np${np}/two_cubes.e)
endforeach()
periforge_check(contact_two_cubes_np1_vs_np2 "contact_two_cubes_np1;contact_two_cubes_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CONTACT_BIN}/contact_two_cubes_np2/two_cubes.e
  ${CONTACT_BIN}/contact_two_cubes_np1/two_cubes.e ${REG}/contact/np_agreement.comp)

# Restart with contact forces acting: killed after a checkpoint, restarted at the same rank count, the same rs.e and
# rs.csv as an uninterrupted run, byte for byte (restart.cmake's harness).
foreach(np 1 2)
  add_test(NAME restart_contact_kill_np${np}_np${np}
           COMMAND ${PY} ${PROJECT_SOURCE_DIR}/test/regression/restart/run_restart.py kill ${REG}/contact/restart_contact.xml
                   ${np} ${np} ${PERIFORGE_EXE} ${MPIRUN})
  set_tests_properties(restart_contact_kill_np${np}_np${np} PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS ${np})
endforeach()

# The Contact list's input errors: one line naming the file and the parameter, no output.
add_test(NAME contact_input_errors COMMAND ${PY} ${REG}/contact/run_contact_errors.py ${PERIFORGE_EXE} ${REG}/contact/pair.xml)
set_tests_properties(contact_input_errors PROPERTIES LABELS "regression")

# Symmetric rod-on-rod Taylor impact (examples/contact): two bars at +-200 m/s through the contact law against the
# same bar on the rigid wall at 200 m/s (taylor.cmake's run): L_f/L0 within 1 %, momentum, contact impulse, and the
# energy balance with the contact springs' energy within 1 % at every step (check_rod_on_rod.py).
periforge_run(contact_rod_on_rod_np2 ${PROJECT_SOURCE_DIR}/examples/contact/rod_on_rod_coarse.xml 2)
periforge_check(contact_rod_on_rod_check "contact_rod_on_rod_np2;taylor_coarse_np2"
  ${PY} ${REG}/contact/check_rod_on_rod.py ${CONTACT_BIN}/contact_rod_on_rod_np2 ${CONTACT_BIN}/taylor_coarse_np2)

# A block sliding on a held plate with Coulomb friction (examples/contact/sliding_block.xml): its deceleration is
# mu times its load per mass within 1 % (check_sliding_block.py), at np 2 (np 1 as well until session 26)
# (issue 37: a deck runs at one rank count unless np 1 and 2 test different code).
foreach(np 2)
  periforge_run(contact_sliding_block_np${np} ${PROJECT_SOURCE_DIR}/examples/contact/sliding_block.xml ${np})
  periforge_check(contact_sliding_block_np${np}_check contact_sliding_block_np${np}
    ${PY} ${REG}/contact/check_sliding_block.py ${CONTACT_BIN}/contact_sliding_block_np${np})
endforeach()

# A steel sphere through a brittle plate (examples/contact/perforation.xml): contact keeps the sphere off the plate's
# points and fragments, the sphere perforates and slows, total momentum is conserved (check_perforation.py).
periforge_run(contact_perforation_np2 ${PROJECT_SOURCE_DIR}/examples/contact/perforation.xml 2)
periforge_check(contact_perforation_check contact_perforation_np2
  ${PY} ${REG}/contact/check_perforation.py ${CONTACT_BIN}/contact_perforation_np2)

# Hertz: a rigid sphere driven into an elastic block (examples/contact/hertz.xml; its 36 000-point mesh is written
# into the run directory by make_hertz --setup, not stored): force against indentation within 5 % of Hertz's over
# the loading phase (check_hertz.py). About 30 s at np 2.
set(HERTZ_DIR ${CONTACT_BIN}/contact_hertz_np2)
periforge_run(contact_hertz_np2 ${HERTZ_DIR}/hertz.xml 2
  LAUNCHER ${PY} ${PROJECT_SOURCE_DIR}/examples/contact/make_hertz --setup ${PROJECT_SOURCE_DIR}/examples/contact/hertz.xml
           ${HERTZ_DIR})
periforge_check(contact_hertz_check contact_hertz_np2 ${PY} ${REG}/contact/check_hertz.py ${HERTZ_DIR})

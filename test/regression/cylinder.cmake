# Thick-walled cylinder under internal pressure, plane strain (issue 16): the Pressure condition and the
# OSB models against Lame's elastic solution, the first-yield pressure and the limit pressure (twice-elastic-slope, polar ring;
# the 40-ring limit pressure is scripts/validate_cylinder). Bounds and their reasons: run_cylinder.py.
# The closed forms at np 1 (75 s of the suite's CPU at np 2); the Pressure condition across two ranks is checked
# by cylinder_hardening_np2 below.
add_test(NAME cylinder_pressure_np1
         COMMAND ${PY} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cylinder/run_cylinder.py ${PERIFORGE_EXE})
set_tests_properties(cylinder_pressure_np1 PROPERTIES LABELS "regression" PROCESSORS 1 TIMEOUT 300)
# Elastic Plastic Hardening (isotropic, then kinematic) loaded past p_L and unloaded, against a 1D radial J2 solution written in
# the test (radial_j2.py). Bounds and reasons: run_cylinder_hardening.py. At np 2 (np 1 as well until session 26;
# issue 37: a deck runs at one rank count unless np 1 and 2 test different code).
add_test(NAME cylinder_hardening_np2
         COMMAND ${PY} ${CMAKE_CURRENT_SOURCE_DIR}/regression/cylinder/run_cylinder_hardening.py
                 ${MPIRUN} -np 2 ${PERIFORGE_EXE})
set_tests_properties(cylinder_hardening_np2 PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 300)

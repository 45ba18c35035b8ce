# Newton's quadratic convergence with the consistent tangent of the OSB J2 models (issue 19 part 4): a small
# plane-stress plate with a hole, mixed hardening, four yielding load steps by NOXQuasiStatic at np = 2
# (tangent/plate_quadratic.xml, Verbose). check_quadratic.py reads NOX's residual history and requires
# rho_k+1 <= C rho_k^2 (rho = force residual / load scale) for every full Newton step with rho_k <= 1e-2 (the
# local range) and rho_k+1 > 3e-11 (ten times the residual's round-off floor: converged steps end at
# rho = 3e-12 to 1.2e-11, where the ratio says nothing), at least 3 such pairs.
# C = 5: the ratio is the problem's own nonlinearity constant (|J^-1| |J'| / 2 in the load-scaled norm); measured
# 0.38-1.5 over the 4 judged pairs (steps 2-4), stable from rho_k = 1e-3 down to 1.4e-5; 5 leaves 3x room for
# another platform's round-off, while any linear rate q fails it from rho_k < q / 5 on (an elastic or lagged
# tangent: q ~ 0.1-0.7 at these states, test PlasticTangent.MatchesCentralDifferences). The finite-difference
# Jacobian (Jacobian = Finite Difference, step 1e-7 of the shortest bond) also passes on this deck: its relative
# error ~5e-6 shows only below rho ~ 1e-5 (step 4: ratio 0.86 against 0.54), near the round-off floor.
# tangent_quadratic_check_selftest: the same judge rejects a made-up linearly converging history (rate 0.05)
# and accepts a quadratic one -- the check can fail.
set(TQ_WD ${CMAKE_CURRENT_BINARY_DIR}/regression/tangent_quadratic_convergence)
file(MAKE_DIRECTORY ${TQ_WD})
add_test(NAME tangent_quadratic_convergence
  COMMAND ${PY} ${REG}/tangent/check_quadratic.py --rel 1e-10 --C 5 --floor 3e-11 --window 1e-2 --min-pairs 3
          -- ${MPIRUN} -np 2 ${PERIFORGE_EXE} ${REG}/tangent/plate_quadratic.xml
  WORKING_DIRECTORY ${TQ_WD})
set_tests_properties(tangent_quadratic_convergence PROPERTIES LABELS "regression" PROCESSORS 2)
add_test(NAME tangent_quadratic_check_selftest
  COMMAND ${PY} ${REG}/tangent/check_quadratic.py --C 5 --floor 3e-11 --window 1e-2 --self-test)
set_tests_properties(tangent_quadratic_check_selftest PROPERTIES LABELS "regression")

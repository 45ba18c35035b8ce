# The Implicit solver (Newmark-beta, Newton-Krylov per step; docs/input.md, "Solver").
# Peridigm's CompressionImplicit_2x1x1 against its gold file within its .comp tolerances, np = 1 and 2 (as
# peridigm.cmake registers Peridigm's other decks).
set(PERIDIGM_REF ${PERIFORGE_SHARED_DIR}/reference/peridigm)
foreach(np 1 2)
  set(deck CompressionImplicit_2x1x1)
  periforge_run(peridigm_${deck}_np${np} ${PERIDIGM_REF}/${deck}/${deck}.xml ${np})
  periforge_check(peridigm_${deck}_np${np}_vs_gold peridigm_${deck}_np${np}
    ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/peridigm_${deck}_np${np}/${deck}.e
    ${PERIDIGM_REF}/${deck}/${deck}_gold.e ${PERIDIGM_REF}/${deck}/${deck}.comp)
endforeach()

# Independent references (check_newmark.py states the bounds): the two-point oscillator against the closed
# form of the trapezoidal rule (displacement, velocity, acceleration, period elongation, energy) at
# omega dt = 0.245 and at 6.1 (three times Verlet's limit); the free line bar's energy at np = 1 and 2; the bar
# driven rigidly by a time-dependent body force and a prescribed end against the rule's discrete trajectory
# (both conditions evaluated at each step's end time).
set(IMP ${REG}/implicit)
set(implicit_cases "sdof_newmark sdof 2.0e-5 1.0e-12" "sdof_newmark_large_dt sdof 5.0e-4 1.0e-10"
                   "bar_line_newmark bar 5.0e-4 1.0e-9" "rigid_bar_newmark rigid 1.0e-4 1.0e-10")
foreach(case ${implicit_cases})
  separate_arguments(c UNIX_COMMAND "${case}")
  list(GET c 0 deck)
  list(GET c 1 kind)
  list(GET c 2 dt)
  list(GET c 3 tol)
  set(nps 1)
  if(kind STREQUAL "bar")
    set(nps 1 2)
  endif()
  foreach(np ${nps})
    periforge_run(implicit_${deck}_np${np} ${IMP}/${deck}.xml ${np})
    periforge_check(implicit_${deck}_np${np}_check implicit_${deck}_np${np}
      ${PY} ${IMP}/check_newmark.py ${kind} ${CMAKE_CURRENT_BINARY_DIR}/regression/implicit_${deck}_np${np}/${deck}.e ${dt} ${tol})
  endforeach()
endforeach()

# A 3D block (every bond direction, geometric nonlinearity) in free vibration: Newmark at dt (np 1) and dt/2
# (np 2) converges at second order to Verlet at dt/10 (check_newmark.py converge).
periforge_run(implicit_block_3d_verlet_np1 ${IMP}/block_3d_verlet.xml 1)
periforge_run(implicit_block_3d_newmark_coarse_np1 ${IMP}/block_3d_newmark_coarse.xml 1)
periforge_run(implicit_block_3d_newmark_fine_np2 ${IMP}/block_3d_newmark_fine.xml 2)
set(blk ${CMAKE_CURRENT_BINARY_DIR}/regression/implicit_block_3d)
periforge_check(implicit_block_3d_converges_to_verlet
  "implicit_block_3d_verlet_np1;implicit_block_3d_newmark_coarse_np1;implicit_block_3d_newmark_fine_np2"
  ${PY} ${IMP}/check_newmark.py converge ${blk}_verlet_np1/block_3d_verlet.e
  ${blk}_newmark_coarse_np1/block_3d_newmark_coarse.e ${blk}_newmark_fine_np2/block_3d_newmark_fine.e)

# The same block yielding (Elastic Plastic): Implicit at dt/2 (np 2) against Verlet at dt/10, displacement and
# plastic strain within 1 % (check_newmark.py plastic: the material state committed once per converged step).
periforge_run(implicit_ep_block_3d_verlet_np1 ${IMP}/ep_block_3d_verlet.xml 1)
periforge_run(implicit_ep_block_3d_newmark_np2 ${IMP}/ep_block_3d_newmark.xml 2)
periforge_check(implicit_ep_block_3d_vs_verlet "implicit_ep_block_3d_verlet_np1;implicit_ep_block_3d_newmark_np2"
  ${PY} ${IMP}/check_newmark.py plastic ${CMAKE_CURRENT_BINARY_DIR}/regression/implicit_ep_block_3d_verlet_np1/ep_block_3d_verlet.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/implicit_ep_block_3d_newmark_np2/ep_block_3d_newmark.e)

# Bad Implicit input: one line naming the file and the parameter.
add_test(NAME implicit_input_errors COMMAND ${PY} ${IMP}/run_implicit_errors.py ${PERIFORGE_EXE} ${REG}/bar/bar_3d.xml)
set_tests_properties(implicit_input_errors PROPERTIES LABELS "regression")

# Restart (run_restart.py, as restart.cmake's Verlet and NOX cases): restart_implicit.xml killed after its first
# checkpoint and restarted ends with the uninterrupted run's rs.csv and rs.e byte for byte (np 1): the
# checkpoint carries the Newmark acceleration besides u, v and the material state.
add_test(NAME restart_implicit_kill_np1_np1
         COMMAND ${PY} ${REG}/restart/run_restart.py kill ${REG}/restart/restart_implicit.xml 1 1 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_implicit_kill_np1_np1 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 1)

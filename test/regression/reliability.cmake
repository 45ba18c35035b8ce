# Issue 15, parts 1 and 6: a failure on rank 0 only, a signal, or a second run on the same output name ends
# every rank promptly with one line and a non-zero exit, and never presents a partial result (the previous
# rel.csv / rel.e stay byte-identical). Each case runs in its own temporary directory, under a timeout: a
# hang fails the test instead of stalling the suite. At np 2, where a failure on one rank must end the other
# (np 1 as well until session 26: the same code on one rank) (issue 37: a deck runs at one rank count unless np 1 and 2 test different code).
set(REL ${CMAKE_CURRENT_SOURCE_DIR}/regression/reliability)
foreach(np 2)
  foreach(case missing_dir exodus_is_dir disk_full live_lock concurrent sigterm sigkill)
    add_test(NAME reliability_${case}_np${np}
             COMMAND ${PY} ${REL}/run_reliability.py ${case} ${np} ${PERIFORGE_EXE} ${REL}/rel_bar.xml ${MPIRUN})
    set_tests_properties(reliability_${case}_np${np} PROPERTIES TIMEOUT 60 LABELS "regression" PROCESSORS ${np})
  endforeach()
endforeach()

# The issue's own case: the coarse plate (NOX) killed with kill -9 mid-way leaves the previous result untouched.
foreach(np 2)
  add_test(NAME reliability_plate_sigkill_np${np}
           COMMAND ${PY} ${REL}/run_reliability.py plate_sigkill ${np} ${PERIFORGE_EXE}
                   ${CMAKE_CURRENT_SOURCE_DIR}/regression/plate/plate_iso_coarse_nox.xml ${MPIRUN})
  set_tests_properties(reliability_plate_sigkill_np${np} PROPERTIES TIMEOUT 120 LABELS "regression" PROCESSORS ${np})
endforeach()

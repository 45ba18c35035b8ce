# Issue 15, part 7: restart from a checkpoint. A run killed with SIGKILL between two checkpoints and restarted
# with `--restart` ends with the same rs.csv and rs.e as an uninterrupted run: byte for byte at the same rank
# count (Verlet and NOXQuasiStatic), within the stated np 1 vs np 2 round-off when written at np 2 and
# restarted at np 1 (the rows up to the checkpoint still byte for byte). A truncated, corrupt, foreign or
# missing checkpoint gives one line and a non-zero exit at np 1 and 2 (run_restart.py). Each case runs in
# its own temporary directory under a timeout: a hang fails the test instead of stalling the suite.
set(RST ${CMAKE_CURRENT_SOURCE_DIR}/regression/restart)
# CSV bounds for np 2 -> 1. Bar (Verlet): about 5x the uninterrupted np 1 vs np 2 differences (max over all
# rows): reactions 2.1e-8 N (of 4.7e3 N; the Y ones are zero but for round-off), displacement 6.2e-17 m (of
# 7e-5), dilatation 3.2e-15 (of 4e-4). Plate (NOX, relative tolerance 1e-7, so iterates differ within it):
# the tolerance carried to each column, 1e-7 of its largest value: reactions 4e-3 N (the force residual
# bound itself, 1e-7 of the 4e4 N load), stress 70 Pa (of 7e8), displacement of the driven layer 2.5e-11 m
# (of the plate's 2.5e-4); plastic strain 1e-9 (of 5e-3; 1e-7 of it would be 5e-10, the looser bound kept
# from before). Measured np 1 vs np 2, Epetra/ML then Tpetra/MueLu (issue 20): reactions 8.6e-5 / 4.3e-4 N,
# probe stress 3.4 / 14.9 Pa, plastic strain 1.3e-10 / 9.8e-11, driven layer 3.7e-12 / 1.0e-11 m. Time,
# step and the applied displacement: exact. The plate writes Nonlinear_Solver_Iterations, carried by the checkpoint
# (a restart that counted from 0 again failed restart_plate_kill_np1_np1's byte-for-byte rs.e).
set(restart_bar_tols --default abs:1e-7 --tol time=abs:0 --tol step=abs:0
    --tol Probe_Q1_DisplacementX=abs:3e-16 --tol Probe_Q1_DisplacementY=abs:3e-16 --tol Probe_Q1_DisplacementZ=abs:0
    --tol Probe_Q3_DisplacementX=abs:3e-16 --tol Probe_Q3_DisplacementY=abs:3e-16 --tol Probe_Q3_DisplacementZ=abs:0
    --tol Probe_Q1_Dilatation=abs:2e-14)
set(restart_plate_tols --default abs:4e-3 --tol time=abs:0 --tol step=abs:0 --tol Applied_Displacement=abs:0
    --tol Probe_A_Signed_Von_Mises_Stress=abs:70 --tol Probe_B_Signed_Von_Mises_Stress=abs:70
    --tol Probe_A_Equivalent_Plastic_Strain=abs:1e-9 --tol Probe_B_Equivalent_Plastic_Strain=abs:1e-9
    --tol Probe_Applied_DisplacementX=abs:2.5e-11 --tol Probe_Applied_DisplacementY=abs:2.5e-11
    --tol Probe_Applied_DisplacementZ=abs:0)
foreach(deck bar plate)
  if(deck STREQUAL "bar")
    set(file ${RST}/restart_bar.xml)
  else()
    set(file ${RST}/restart_plate_nox.xml)
  endif()
  add_test(NAME restart_${deck}_kill_np1_np1
           COMMAND ${PY} ${RST}/run_restart.py kill ${file} 1 1 ${PERIFORGE_EXE} ${MPIRUN})
  add_test(NAME restart_${deck}_kill_np2_np1
           COMMAND ${PY} ${RST}/run_restart.py kill ${file} 2 1 ${PERIFORGE_EXE} ${MPIRUN}
                   -- ${restart_${deck}_tols} -- ${RST}/${deck}_np.comp)
  set_tests_properties(restart_${deck}_kill_np1_np1 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 1)
  set_tests_properties(restart_${deck}_kill_np2_np1 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 2)
endforeach()
# Issue 19: the checkpoint passes through rank 0 chunk by chunk both ways (parallel/ChunkedGather). Written at
# np 1 and restarted at np 2, the plate's per-bond plastic history reaches each rank's bonds by the chunked
# scatter (np 2 -> 1 above covers the chunked gather of two ranks); the same bounds as np 2 -> 1.
add_test(NAME restart_plate_kill_np1_np2
         COMMAND ${PY} ${RST}/run_restart.py kill ${RST}/restart_plate_nox.xml 1 2 ${PERIFORGE_EXE} ${MPIRUN}
                 -- ${restart_plate_tols} -- ${RST}/plate_np.comp)
set_tests_properties(restart_plate_kill_np1_np2 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 2)
# NOXQuasiStatic's own carried state (LoadStepping.hpp, CarriedState) in the checkpoint: the quadratic predictor's last
# three solved states (src/solvers/SolvedStates.hpp) and `First Solve Forcing`'s last contraction. The NOX plate with
# `Predictor` = `Quadratic` and `First Solve Forcing` 0.1 killed and restarted at np 1 ends byte for byte as the
# uninterrupted run (a state lost at the restart would start the next steps from another prediction or solve them to
# another Krylov tolerance).
file(READ ${RST}/restart_plate_nox.xml plate_deck)
string(REPLACE "<Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1.0e-7\"/>"
       "<Parameter name=\"Relative Tolerance\" type=\"double\" value=\"1.0e-7\"/><Parameter name=\"Predictor\" type=\"string\" value=\"Quadratic\"/><Parameter name=\"First Solve Forcing\" type=\"double\" value=\"0.1\"/>"
       quadratic_deck "${plate_deck}")
if(quadratic_deck STREQUAL plate_deck)
  message(FATAL_ERROR "restart.cmake: restart_plate_nox.xml has no Relative Tolerance 1.0e-7 to put the options after")
endif()
file(WRITE ${CMAKE_CURRENT_BINARY_DIR}/regression/restart_plate_nox_own_state.xml "${quadratic_deck}")
add_test(NAME restart_plate_own_state_kill_np1_np1
         COMMAND ${PY} ${RST}/run_restart.py kill ${CMAKE_CURRENT_BINARY_DIR}/regression/restart_plate_nox_own_state.xml 1 1
                 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_plate_own_state_kill_np1_np1 PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS 1)
# At np 2, where every rank must end with the line (np 1 as well until session 26) (issue 37: a deck runs at one rank count unless np 1 and 2 test different code).
foreach(np 2)
  add_test(NAME restart_refused_np${np}
           COMMAND ${PY} ${RST}/run_restart.py refuse ${RST}/restart_bar.xml ${np} ${PERIFORGE_EXE} ${MPIRUN})
  set_tests_properties(restart_refused_np${np} PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS ${np})
endforeach()

# A Rigid Wall (issue 17) across a restart: the wall has no state of its own, the points on it carry their
# velocities; the Taylor bar killed after its first checkpoint (step 200 of 600, in contact) and restarted
# ends with rs.csv (the wall's reaction) and rs.e byte for byte equal to an uninterrupted run, at np 2 (np 1 too
# until session 24: the same property on one rank, 19 s of the suite; np 1 byte-for-byte restarts stay covered by
# the bar, the NOX plate and the thermal Taylor bar).
foreach(np 2)
  add_test(NAME restart_taylor_kill_np${np}_np${np}
           COMMAND ${PY} ${RST}/run_restart.py kill ${RST}/restart_taylor.xml ${np} ${np} ${PERIFORGE_EXE} ${MPIRUN})
  set_tests_properties(restart_taylor_kill_np${np}_np${np} PROPERTIES TIMEOUT 300 LABELS "regression" PROCESSORS ${np})
endforeach()

# The partition model (scripts/comm_model, docs/benchmark-log.md "Ghost points and communication"): periforge's start-up
# line (owned and ghost points per rank, ranks a rank receives from) equals the model's exact lattice count for a
# 20^3 cube, delta = 3.015 dx, at np 2, 4 and 8, so the model's np 64 and 1024 figures rest on the same geometry.
# Exact equality: both count lattice points.
foreach(np 2 4 8)
  add_test(NAME partition_model_np${np}
           COMMAND ${PY} ${PROJECT_SOURCE_DIR}/scripts/comm_model --n 20 --np ${np}
                   --check-run ${MPIRUN} -np ${np} ${PERIFORGE_EXE} ${REG}/partition/cube_20.xml
           WORKING_DIRECTORY ${CMAKE_CURRENT_BINARY_DIR})
  set_tests_properties(partition_model_np${np} PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 120)
endforeach()

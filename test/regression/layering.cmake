# Architecture checks (issue 14): one-way includes between the source folders and the adapters' limits,
# the size limits of production code, and docs/input.md's tables current with the declared specs.
periforge_check(layering_one_way ""  ${PY} ${PROJECT_SOURCE_DIR}/scripts/check_layers ${PROJECT_SOURCE_DIR})
periforge_check(sizes_within_limits "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/check_sizes ${PROJECT_SOURCE_DIR})
periforge_check(architecture_checks_can_fail "" ${PY} ${CMAKE_CURRENT_SOURCE_DIR}/architecture/checks_can_fail.py
  ${PROJECT_SOURCE_DIR})
periforge_check(input_docs_current "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/generate_input_docs --check
  --exe $<TARGET_FILE:periforge-parameters> --doc ${PROJECT_SOURCE_DIR}/docs/input.md)

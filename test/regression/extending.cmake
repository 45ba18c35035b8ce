# docs/extending.md's procedure (a copy of Microelastic as "Pair Spring"), run as written in a scratch copy of the
# sources (issue 37): the copy's unit tests pass, its deck's history equals bar_3d_microelastic_np1's byte for byte
# and docs/input.md is current; a step deleted from the doc fails it. ~25 s: only the files the procedure adds or
# changes are compiled, against this build (follow_procedure.py says how).
periforge_check(extending_doc_procedure bar_3d_microelastic_np1
  ${PY} ${REG}/extending/follow_procedure.py ${PROJECT_SOURCE_DIR} ${CMAKE_BINARY_DIR}
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_microelastic_np1/bar_3d_microelastic.csv)

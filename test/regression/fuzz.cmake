# Fuzz test (issue 15): 240 mutated decks (seed 15) of the three small decks in test/fuzz (96 of them, evenly spread, in ctest; 160 until session 24), each run in its
# own directory under a 30 s timeout; any crash, hang, unclear error or non-finite result fails the test and
# is printed with its mutation and the command that reproduces it (docs/verification.md, "Fuzz test").
# The cases run two at a time (PROCESSORS 2); an evenly spread subset runs again at np 2, where every rank
# must end with the same one line.
set(FUZZ ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)
add_test(NAME fuzz_decks COMMAND ${PY} ${FUZZ}/run_fuzz.py ${PERIFORGE_EXE} --jobs 2 --subset 96
         --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures)
set_tests_properties(fuzz_decks PROPERTIES LABELS "regression" TIMEOUT 400 PROCESSORS 2)
add_test(NAME fuzz_decks_np2 COMMAND ${PY} ${FUZZ}/run_fuzz.py ${PERIFORGE_EXE} --np 2 --subset 16
         --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures -- ${MPIRUN})
set_tests_properties(fuzz_decks_np2 PROPERTIES LABELS "regression" TIMEOUT 400 PROCESSORS 2)

# Fuzz driver (issue 40, part 7): scripts/fuzz runs mutations of eight small decks shrunk from the example
# families (test/fuzz/generate_semantic.py, seed 40: physically extreme values, output and checkpoint names
# colliding with the run's own files, unknown NOX values, duplicate spellings, rigid walls the body starts
# behind, Newmark out of range, ... and a quarter of issue 15's syntactic operators), each in its own
# directory, and fails on any crash, hang, non-finite value in a final-named .csv or .e, rc-0 run with
# corrupted or nonsensical results (or writing outside its directory, or accepting an input the mutation
# made invalid), or error that does not name its cause (docs/verification.md, "Fuzz driver (issue 40)").
# CI runs a sample spread over the mutation kinds, issue 40's own cases first: 16 at np 1 (two at a time)
# and 8 at np 2; the full 320 at np 1 and 2 run by hand (scripts/fuzz --np 1,2 --jobs 2). (40 and 12 until session
# 23, 24 until session 24: the suite's time on a fresh machine, issue 37.)
add_test(NAME fuzz_examples COMMAND ${PY} ${PROJECT_SOURCE_DIR}/scripts/fuzz --exe ${PERIFORGE_EXE} --np 1
         --sample 16 --jobs 2 --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures/examples)
set_tests_properties(fuzz_examples PROPERTIES LABELS "regression" TIMEOUT 300 PROCESSORS 2)
add_test(NAME fuzz_examples_np2 COMMAND ${PY} ${PROJECT_SOURCE_DIR}/scripts/fuzz --exe ${PERIFORGE_EXE} --np 2
         --sample 8 --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures/examples -- ${MPIRUN})
set_tests_properties(fuzz_examples_np2 PROPERTIES LABELS "regression" TIMEOUT 300 PROCESSORS 2)

# Fuzz test (issue 15): 240 mutated decks (seed 15) of the three small decks in test/fuzz, each run in its
# own directory under a 30 s timeout; any crash, hang, unclear error or non-finite result fails the test and
# is printed with its mutation and the command that reproduces it (docs/verification.md, "Fuzz test").
# The cases run two at a time (PROCESSORS 2); an evenly spread subset runs again at np 2, where every rank
# must end with the same one line.
set(FUZZ ${CMAKE_CURRENT_SOURCE_DIR}/fuzz)
add_test(NAME fuzz_decks COMMAND ${PY} ${FUZZ}/run_fuzz.py ${PERIFORGE_EXE} --jobs 2
         --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures)
set_tests_properties(fuzz_decks PROPERTIES LABELS "regression" TIMEOUT 400 PROCESSORS 2)
add_test(NAME fuzz_decks_np2 COMMAND ${PY} ${FUZZ}/run_fuzz.py ${PERIFORGE_EXE} --np 2 --subset 24
         --keep ${CMAKE_CURRENT_BINARY_DIR}/fuzz_failures -- ${MPIRUN})
set_tests_properties(fuzz_decks_np2 PROPERTIES LABELS "regression" TIMEOUT 400 PROCESSORS 2)

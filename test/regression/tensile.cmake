# Tensile specimen at 8300 1/s (issue 17; examples/tensile_8300): the coarse deck (6 points across, to an
# engineering strain of 0.12) at np = 1 and 2. check_tensile.py compares the gauge section's true stress
# against Green-Lagrange strain with Foster's law integrated classically under uniaxial stress (its reasons are
# in the script): the period means within 1.5 % between E_zz 0.01 and Considere's point (measured -0.46 % here,
# -0.38 % at 10 across, the paper's 3 840 points, -0.37 % at 20). np 1 against np 2 within round-off (np_agreement.comp: the
# runs are not bit-identical, the reason is in that file).
foreach(np 1 2)
  periforge_run(tensile_coarse_np${np} ${PROJECT_SOURCE_DIR}/examples/tensile_8300/tensile_coarse.xml ${np})
endforeach()
periforge_check(tensile_coarse_check tensile_coarse_np2
  ${PY} ${REG}/tensile/check_tensile.py ${CMAKE_CURRENT_BINARY_DIR}/regression/tensile_coarse_np2/tensile_coarse.e
  --strain 0.12 --tol 0.015)
periforge_check(tensile_coarse_np1_vs_np2 "tensile_coarse_np1;tensile_coarse_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/tensile_coarse_np2/tensile_coarse.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/tensile_coarse_np1/tensile_coarse.e ${REG}/tensile/np_agreement.comp)
# The stored 20-across history (docs/data/tensile_8300_20.csv, examples/tensile_8300/README.md) against the same
# reference: measured -0.37 %; bound 0.5 % (the 6/10/20-across spread is 0.1 %, so the stored numbers cannot
# drift unnoticed).
add_test(NAME tensile_20_history_check COMMAND ${PY} ${REG}/tensile/check_tensile.py
  ${PROJECT_SOURCE_DIR}/docs/data/tensile_8300_20.csv --tol 0.005)
set_tests_properties(tensile_20_history_check PROPERTIES LABELS "regression")

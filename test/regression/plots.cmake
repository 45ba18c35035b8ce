# scripts/plot_field and scripts/plot_history on runs made by the test (issue 21 part 6).
add_test(NAME plot_scripts
         COMMAND ${PY} ${CMAKE_CURRENT_SOURCE_DIR}/regression/plots/run_plot_scripts.py ${PERIFORGE_EXE}
                 ${PROJECT_SOURCE_DIR}/scripts ${CMAKE_CURRENT_SOURCE_DIR}/regression/reliability/rel_bar.xml
                 ${CMAKE_CURRENT_SOURCE_DIR}/regression/bar/bar_3d.xml)
set_tests_properties(plot_scripts PROPERTIES LABELS "regression" TIMEOUT 120)

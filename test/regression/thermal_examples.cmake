# examples/thermal (issue 33): steady heat conduction through a plate with a hole (plate_hole_steady_coarse.xml,
# dx = 1 mm, ImplicitDiffusion) against the committed CalculiX reference (examples/thermal/reference/
# plate_hole_steady_fe.csv, scripts/thermal_plate_hole_reference; ccx is not needed here): the temperature at three
# probes within 2 K, 2 % of the applied 100 K. Measured (np 1 and 2 alike): errors -0.58, -0.54, +0.52 K, mostly the
# held layers' effective edge 0.8 dx outside the plate (examples/thermal/README.md). Uses periforge_run /
# periforge_check from core.cmake (sorts before this file).
set(THERMAL_EX ${PROJECT_SOURCE_DIR}/examples/thermal)
foreach(np 1 2)
  set(name thermal_plate_hole_coarse_np${np})
  periforge_run(${name} ${THERMAL_EX}/plate_hole_steady_coarse.xml ${np})
  periforge_check(${name}_check ${name}
    ${PY} ${THERMAL_EX}/check_plate_hole.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/plate_hole_steady_coarse.e)
endforeach()
# Example (a): transient conduction in a 40 x 4 mm plane-stress bar whose end is raised by 100 K (bar_erfc.xml,
# Verlet, thermal only) against the semi-infinite solid's erfc solution: within 1 % of the rise at the points a
# horizon from the insulated sides (measured 0.57 %, the sides' surface effect; check_bar_erfc.py). np 2.
periforge_run(thermal_bar_erfc_np2 ${THERMAL_EX}/bar_erfc.xml 2)
periforge_check(thermal_bar_erfc_np2_check thermal_bar_erfc_np2
  ${PY} ${THERMAL_EX}/check_bar_erfc.py ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_bar_erfc_np2/bar_erfc.e)

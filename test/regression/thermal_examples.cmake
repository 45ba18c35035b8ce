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

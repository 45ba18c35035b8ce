# Elastic Correspondence bar in uniaxial tension, 3D, ADR, np = 1 and 2: reaction, interior strain and stress
# against E eps (check_correspondence_bar.py states the bounds), and the two runs against each other.
foreach(np 1 2)
  periforge_run(bar_3d_correspondence_np${np} ${REG}/correspondence/bar_3d_correspondence.xml ${np})
  periforge_check(bar_3d_correspondence_np${np}_check bar_3d_correspondence_np${np}
    ${PY} ${REG}/correspondence/check_correspondence_bar.py
    ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_correspondence_np${np}/bar_3d_correspondence.csv)
endforeach()
periforge_check(bar_3d_correspondence_np1_vs_np2 "bar_3d_correspondence_np1;bar_3d_correspondence_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_correspondence_np2/bar_3d_correspondence.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_correspondence_np1/bar_3d_correspondence.e ${REG}/bar/np_agreement.comp)

# The same bar with a horizon that varies by point (3.015 dx, then 3.515 dx beyond the middle): the gather and the
# one-pass sums side by side across the ranks' ghosts; np 1 and 2 agree (the sum itself: unit test PointHorizon).
foreach(np 1 2)
  periforge_run(bar_3d_correspondence_two_horizons_np${np} ${REG}/correspondence/bar_3d_correspondence_two_horizons.xml ${np})
endforeach()
periforge_check(bar_3d_correspondence_two_horizons_np1_vs_np2
  "bar_3d_correspondence_two_horizons_np1;bar_3d_correspondence_two_horizons_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_correspondence_two_horizons_np2/bar_3d_correspondence_two_horizons.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_correspondence_two_horizons_np1/bar_3d_correspondence_two_horizons.e
  ${REG}/bar/np_agreement.comp)

# Viscoplastic Correspondence cube with every point prescribed (uniaxial strain at 1e3 1/s): the time reaches
# the material only through the solver; the centre's and the corner's histories against an independent radial
# return (check_vp_affine.py, 1e-8). Verlet (np 1 and 2) and ADR load steps.
foreach(case vp_affine_verlet_np1 vp_affine_verlet_np2 vp_affine_adr_np1)
  string(REGEX REPLACE "_np([0-9])$" "" deck ${case})
  string(REGEX REPLACE "^.*_np" "" np ${case})
  periforge_run(${case} ${REG}/correspondence/${deck}.xml ${np})
  periforge_check(${case}_check ${case}
    ${PY} ${REG}/correspondence/check_vp_affine.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}/${deck}.csv)
endforeach()

# Restart: the same cube under Verlet killed (SIGKILL) after its first checkpoint and restarted ends with the
# uninterrupted run's rs.csv and rs.e byte for byte: the points' committed time (Viscoplastic_Time, node
# history) comes back from the checkpoint, so the first step after the restart has the right dt.
add_test(NAME restart_vp_affine_kill_np1_np1
         COMMAND ${PY} ${REG}/restart/run_restart.py kill ${REG}/correspondence/vp_affine_restart.xml 1 1
                 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_vp_affine_kill_np1_np1 PROPERTIES LABELS "regression" TIMEOUT 600)

# A singular shape tensor (a 3D model on one layer of points): one 'input error' line naming a point, at np 1
# and 2, within the timeout (no rank left waiting).
foreach(np 1 2)
  set(wd ${CMAKE_CURRENT_BINARY_DIR}/regression/correspondence_singular_shape_np${np})
  file(MAKE_DIRECTORY ${wd})
  add_test(NAME correspondence_singular_shape_np${np}
           COMMAND ${MPIRUN} -np ${np} ${PERIFORGE_EXE} ${REG}/correspondence/singular_shape.xml WORKING_DIRECTORY ${wd})
  set_tests_properties(correspondence_singular_shape_np${np} PROPERTIES LABELS "regression" PROCESSORS ${np} TIMEOUT 60
    PASS_REGULAR_EXPRESSION "input error: [^ ]*singular_shape.xml: correspondence model: the shape tensor K of the point at \\([^)]*\\) is singular")
endforeach()

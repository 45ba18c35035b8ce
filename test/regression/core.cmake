# Regression tests of the core pipeline (issue 2). Each run gets its own working directory because
# decks name their output relative to it. Python checks run with Debian's python3 (numpy, netCDF4).
set(PY /usr/bin/python3)
set(REG ${CMAKE_CURRENT_SOURCE_DIR}/regression)

# Tests whose command names a file under PERIFORGE_SHARED_DIR (third-party reference data, absent from a
# user's clone) run through needs_shared: skipped with one line without the data, failed instead when
# PERIFORGE_REQUIRE_SHARED=1 (.ci/run). periforge_shared_guard sets OUT to the wrapper (or to nothing).
function(periforge_shared_guard out)
  set(${out} "" PARENT_SCOPE)
  foreach(arg ${ARGN})
    string(FIND "${arg}" "${PERIFORGE_SHARED_DIR}" at)
    if(at EQUAL 0)
      set(${out} ${CMAKE_CURRENT_SOURCE_DIR}/regression/shared/needs_shared ${PERIFORGE_SHARED_DIR} PARENT_SCOPE)
      return()
    endif()
  endforeach()
endfunction()
function(periforge_mark_shared name guard)
  if(guard)
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77 LABELS "regression;shared")
  endif()
endfunction()

# periforge_run(NAME DECK NP [EXE exe] [LAUNCHER cmd...]): runs DECK at NP ranks in
# build/test/regression/NAME as a fixture; EXE replaces periforge, LAUNCHER runs before mpirun.
function(periforge_run name deck np)
  cmake_parse_arguments(PARSE_ARGV 3 run "" "EXE" "LAUNCHER")
  if(NOT run_EXE)
    set(run_EXE ${PERIFORGE_EXE})
  endif()
  set(wd ${CMAKE_CURRENT_BINARY_DIR}/regression/${name})
  file(MAKE_DIRECTORY ${wd})
  periforge_shared_guard(guard ${deck})
  add_test(NAME ${name} COMMAND ${guard} ${run_LAUNCHER} ${MPIRUN} -np ${np} ${run_EXE} ${deck} WORKING_DIRECTORY ${wd})
  set_tests_properties(${name} PROPERTIES FIXTURES_SETUP ${name} LABELS "regression" PROCESSORS ${np})
  periforge_mark_shared(${name} "${guard}")
endfunction()

function(periforge_check name fixtures)
  periforge_shared_guard(guard ${ARGN})
  add_test(NAME ${name} COMMAND ${guard} ${ARGN})
  set_tests_properties(${name} PROPERTIES FIXTURES_REQUIRED "${fixtures}" LABELS "regression")
  periforge_mark_shared(${name} "${guard}")
endfunction()

# Patch test: affine field reproduced in the interior, np = 1 and 2.
foreach(np 1 2)
  periforge_run(patch_3d_np${np} ${REG}/patch/patch_3d.xml ${np})
  periforge_check(patch_3d_np${np}_check patch_3d_np${np}
    ${PY} ${REG}/patch/check_patch.py ${CMAKE_CURRENT_BINARY_DIR}/regression/patch_3d_np${np}/patch_3d.e)
  # The same with partial volumes (Discretization "Partial Volume").
  periforge_run(patch_3d_pv_np${np} ${REG}/patch/patch_3d_pv.xml ${np})
  periforge_check(patch_3d_pv_np${np}_check patch_3d_pv_np${np}
    ${PY} ${REG}/patch/check_patch.py ${CMAKE_CURRENT_BINARY_DIR}/regression/patch_3d_pv_np${np}/patch_3d_pv.e)
endforeach()

# Bars in uniaxial tension (3D, plane stress, plane strain), np = 1 and 2, and np agreement.
# 3D: reaction within 1 % of E A eps, measured +0.90 % (docs/verification.md: the lattice's -15 % along an
# axis and the free surfaces' +18 % nearly cancel); a stiffness error of 2 % either way gives +2.9 or -1.1 % and
# fails. 2D: the 8 % bound below is a guard on the whole bar; the stiffness itself is checked to 0.5 % by the
# width difference further down.
set(bar_3d_args --dim 3 --area 4e-4 --ratio 3.015 --reaction-against classical --tol 0.01)
# 2D: the reaction is checked against the lattice-consistent modulus: the square lattice's fourth moment
# at delta = 3.015 dx is anisotropic (modulus along an axis 2.3-2.5 % above E'), and the OSB free-edge
# effect adds ~7 % more on a 20-point-wide strip (uncorrected, see docs/verification.md). The bound
# stays 8 %: a sign or factor error in the 2D constants moves it by tens of percent.
set(bar_plane_stress_args --dim 2 --plane stress --area 2e-5 --ratio 3.015 --reaction-against lattice --tol 0.08)
set(bar_plane_strain_args --dim 2 --plane strain --area 2e-5 --ratio 3.015 --reaction-against lattice --tol 0.08)
foreach(case bar_3d bar_plane_stress bar_plane_strain)
  foreach(np 1 2)
    periforge_run(${case}_np${np} ${REG}/bar/${case}.xml ${np})
    periforge_check(${case}_np${np}_check ${case}_np${np}
      ${PY} ${REG}/bar/check_bar.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}_np${np}/${case}.csv
      ${${case}_args} --E 200e9 --nu 0.3 --strain 1e-3)
  endforeach()
  periforge_check(${case}_np1_vs_np2 "${case}_np1;${case}_np2"
    ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}_np2/${case}.e
    ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}_np1/${case}.e ${REG}/bar/np_agreement.comp)
endforeach()

# 2D axial stiffness without the free-edge effect: each 2D bar again 10 mm wider (np = 1); the difference of
# the two reactions is E_lattice dW t eps whatever the edges add (check_bar_width.py). Measured +0.097 %
# (plane stress) and +0.065 % (plane strain) against the lattice modulus from the lattice's bond moments
# (E_lattice / E' = 1.0227 / 1.0250 at delta = 3.015 dx, the square lattice's anisotropy). Bound 0.5 %: each
# reaction carries ADR's stopping error (1e-7 relative) and the two bars' ends differ by the extra 10 mm of
# layer; a 2 % error of the stiffness fails by 1.5 %-points.
foreach(plane stress strain)
  periforge_run(bar_plane_${plane}_wide_np1 ${REG}/bar/bar_plane_${plane}_wide.xml 1)
  periforge_check(bar_plane_${plane}_width_stiffness "bar_plane_${plane}_np1;bar_plane_${plane}_wide_np1"
    ${PY} ${REG}/bar/check_bar_width.py ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_plane_${plane}_np1/bar_plane_${plane}.csv
    ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_plane_${plane}_wide_np1/bar_plane_${plane}_wide.csv
    --dW 0.01 --thickness 0.001 --plane ${plane} --E 200e9 --nu 0.3 --strain 1e-3 --ratio 3.015 --tol 0.005)
endforeach()

# Explicit dynamics: np = 1 and np = 2 agree to round-off with a fixed dt.
foreach(np 1 2)
  periforge_run(bar_verlet_np${np} ${REG}/bar/bar_verlet.xml ${np})
endforeach()
periforge_check(bar_verlet_np1_vs_np2 "bar_verlet_np1;bar_verlet_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_verlet_np2/bar_verlet.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_verlet_np1/bar_verlet.e ${REG}/bar/verlet_agreement.comp)

# User-facing errors.
add_test(NAME input_errors COMMAND ${PY} ${REG}/errors/run_error_cases.py ${PERIFORGE_EXE} ${REG}/bar/bar_3d.xml)
set_tests_properties(input_errors PROPERTIES LABELS "regression")
# A Text File read in byte ranges, one per rank (issue 19 part 1): a bad line in the last rank's range is named
# by its line in the whole file on every rank, at np 2 and 3; a good mesh runs.
add_test(NAME text_file_ranks COMMAND ${PY} ${REG}/errors/text_file_ranks.py ${REG}/bar/bar_3d.xml ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(text_file_ranks PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 600)
# Finite state or a clear stop (issue 15 part 3): non-finite states, unstable Fixed dt, duplicate and
# isolated points, horizon below the spacing; np 1 and 2.
add_test(NAME finite_state_errors COMMAND ${PY} ${REG}/errors/run_finite_cases.py ${PERIFORGE_EXE} ${REG} ${MPIRUN})
set_tests_properties(finite_state_errors PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 600)
# Issue 40: every case of the second reliability pass (inf in the Exodus globals, a checkpoint named like the
# run's own files, NOX options ignored, unbounded Safety Factor, unnamed det F <= 0, a body behind its wall,
# unstable Newmark, misleading bounds) ends with one line naming its cause; no non-finite value in a .e file.
add_test(NAME runtime_failure_errors COMMAND ${PY} ${REG}/errors/run_runtime_cases.py ${PERIFORGE_EXE} ${REG} ${MPIRUN})
set_tests_properties(runtime_failure_errors PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 600)

# Tool self-tests.
# exodiff's self-test compares Peridigm's gold files with each other (shared reference data: skipped without it).
add_test(NAME exodiff_self_test COMMAND ${CMAKE_COMMAND} -E env PF_PERIDIGM_REF=${PERIFORGE_SHARED_DIR}/reference/peridigm
  ${CMAKE_CURRENT_SOURCE_DIR}/regression/shared/needs_shared ${PERIFORGE_SHARED_DIR}/reference/peridigm
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py --self-test)
add_test(NAME compare_csv_self_test COMMAND ${PY} ${PROJECT_SOURCE_DIR}/scripts/compare_csv --self-test)
set_tests_properties(exodiff_self_test compare_csv_self_test PROPERTIES LABELS "tools")
set_tests_properties(exodiff_self_test PROPERTIES LABELS "tools;shared" SKIP_RETURN_CODE 77)

# Tolerances of every coarse plate history against its gold (plate.cmake, examples.cmake).
# Measured on the isotropic plate (plate.cmake) as np = 2 vs the np = 1 gold:
# ADR stops each step at 1e-5 of the load norm, two partitions stop at different iterates and the plastic
# history carries the difference along the cycle: reaction 0.56 N (of 4e4 N), stress 1.5e4 Pa (of 9e8),
# plastic strain 8.5e-8 (of 1e-2). Bounds about 4x: 2 N, 6e4 Pa (1e-4 sigma_y), 4e-7. Applied_Displacement
# is the deck's expression evaluated at t: exact to round-off (1e-12 m). The driven-layer probe follows the
# prescribed u_x exactly; its u_y (free) gets 5e-9 m like the isotropic plate.
set(plate_tols --default abs:2.0 --tol time=abs:1e-12 --tol step=abs:0 --tol Applied_Displacement=abs:1e-12
  --tol Probe_A_Signed_Von_Mises_Stress=abs:6e4 --tol Probe_B_Signed_Von_Mises_Stress=abs:6e4
  --tol Probe_A_Equivalent_Plastic_Strain=abs:4e-7 --tol Probe_B_Equivalent_Plastic_Strain=abs:4e-7
  --tol Probe_Applied_DisplacementX=abs:1e-12 --tol Probe_Applied_DisplacementY=abs:2.5e-8
  --tol Probe_Applied_DisplacementZ=abs:1e-12)

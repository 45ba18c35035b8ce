# The bond kernels give the same bits on every instruction set (OsbBondLoops.hpp: fixed 8-lane partial
# sums, no FMA contraction). On an AVX-512 machine the dispatching build runs only its AVX-512 clone, so
# periforge-isa-baseline and periforge-isa-avx2 (CMakeLists.txt, kernels compiled for one instruction set)
# run the code of the other two copies, and each deck's Exodus output must match the dispatching build's
# exactly (same_bits.comp). Decks: J2 with mixed hardening in 3D (Verlet), plane stress and plane strain
# (ADR); elastic Verlet (the fused kernel); elastic NOX (dilatation, force and derivative kernels: a 40 mm
# bar, one load step, 1.6 s instead of bar_3d_nox's 8.5 s per build);
# partial volumes; the thermal J2 kernel (osbJ2ThermalForce: plane strain past yield, 3D with the shear correction).
if(NOT PERIFORGE_KERNEL_ISAS)
  return()
endif()
set(isa_cases
  j2_cube_verlet   ${REG}/kernel_isa/j2_cube_verlet.xml
  j2_plane_stress  ${REG}/kernel_isa/j2_plane_stress.xml
  j2_plane_strain  ${REG}/kernel_isa/j2_plane_strain.xml
  bar_verlet       ${REG}/bar/bar_verlet.xml
  elastic_nox      ${REG}/kernel_isa/elastic_nox.xml
  patch_3d_pv      ${REG}/patch/patch_3d_pv.xml
  thermal_j2_plane_strain ${REG}/thermal/thermal_yield_free_ep_plane_strain.xml
  thermal_j2_3d    ${REG}/thermal/thermal_free_eph_3d.xml)
list(LENGTH isa_cases n)
math(EXPR last "${n} - 1")
foreach(k RANGE 0 ${last} 2)
  math(EXPR kd "${k} + 1")
  list(GET isa_cases ${k} case)
  list(GET isa_cases ${kd} deck)
  get_filename_component(out ${deck} NAME_WE)
  periforge_run(isa_${case}_dispatch ${deck} 1)
  foreach(isa ${PERIFORGE_KERNEL_ISAS})
    set(name isa_${case}_${isa})
    set(flag sse4_2)
    if(isa STREQUAL "avx2")
      set(flag avx2)
    endif()
    periforge_run(${name} ${deck} 1 EXE $<TARGET_FILE:periforge-isa-${isa}>
                  LAUNCHER ${PY} ${REG}/kernel_isa/run_if_cpu_has.py ${flag})
    set_tests_properties(${name} PROPERTIES SKIP_RETURN_CODE 77)
    periforge_check(${name}_same_bits "isa_${case}_dispatch;${name}"
      ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/${out}.e
      ${CMAKE_CURRENT_BINARY_DIR}/regression/isa_${case}_dispatch/${out}.e ${REG}/kernel_isa/same_bits.comp)
  endforeach()
endforeach()

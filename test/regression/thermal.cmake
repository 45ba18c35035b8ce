# The Temperature field (issue 33): thermal expansion of the Elastic solid (3D, plane stress, plane strain) and of
# Elastic Correspondence (3D, plane strain) against the closed forms of linear thermoelasticity (free and clamped
# blocks) and steady conduction (ImplicitDiffusion)
# against Fourier's linear profile, np 1 and 2.
foreach(np 1 2)
  foreach(kind free clamped)
    foreach(dim 3d plane_stress plane_strain corr_3d corr_plane_strain)
      set(name thermal_${kind}_${dim}_np${np})
      # The Elastic blocks are examples/thermal's example (c); the correspondence ones are tests only.
      set(deckdir ${REG}/thermal)
      if(NOT dim MATCHES "^corr")
        set(deckdir ${PROJECT_SOURCE_DIR}/examples/thermal/blocks)
      endif()
      periforge_run(${name} ${deckdir}/thermal_${kind}_${dim}.xml ${np})
      periforge_check(${name}_check ${name}
        ${PY} ${REG}/thermal/check_thermal.py ${kind} ${dim} ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/thermal_${kind}_${dim}.e)
    endforeach()
  endforeach()
  periforge_run(conduction_bar_np${np} ${REG}/thermal/conduction_bar.xml ${np})
  periforge_check(conduction_bar_np${np}_check conduction_bar_np${np}
    ${PY} ${REG}/thermal/check_conduction.py ${CMAKE_CURRENT_BINARY_DIR}/regression/conduction_bar_np${np}/conduction_bar.e)
endforeach()
# Thermal expansion of Elastic Plastic, Elastic Plastic Hardening and Microelastic (3D, plane stress, plane strain)
# against the same closed forms, heated within the elastic range (sigma_y 500 MPa), and Elastic Plastic (and, once,
# Elastic Plastic Hardening) heated past yield (sigma_y 100 MPa): free blocks stress-free with no plastic flow, clamped
# 3D and plane-strain blocks hydrostatic, a clamped plane-stress block and a free plane-strain one (sigma_zz) on the
# perfectly plastic (hardening) closed forms; np 1 and 2 (check_thermal_models.py).
foreach(np 1 2)
  foreach(model ep eph micro)
    foreach(kind free clamped)
      foreach(dim 3d plane_stress plane_strain)
        set(name thermal_${kind}_${model}_${dim}_np${np})
        periforge_run(${name} ${REG}/thermal/thermal_${kind}_${model}_${dim}.xml ${np})
        periforge_check(${name}_check ${name} ${PY} ${REG}/thermal/check_thermal_models.py elastic ${model} ${kind}
          ${dim} ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/thermal_${kind}_${model}_${dim}.e)
      endforeach()
    endforeach()
  endforeach()
  foreach(case free_ep_3d free_ep_plane_stress free_ep_plane_strain clamped_ep_3d clamped_ep_plane_stress
          clamped_ep_plane_strain clamped_eph_plane_stress)
    string(REGEX MATCH "^[a-z]+" kind ${case})
    string(REGEX MATCH "ep[h]?" model ${case})
    string(REGEX REPLACE "^[a-z]+_ep[h]?_" "" dim ${case})
    set(name thermal_yield_${case}_np${np})
    periforge_run(${name} ${REG}/thermal/thermal_yield_${case}.xml ${np})
    periforge_check(${name}_check ${name} ${PY} ${REG}/thermal/check_thermal_models.py yield ${model} ${kind} ${dim}
      ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/thermal_yield_${case}.e)
  endforeach()
endforeach()
# Transient conduction (ImplicitDiffusion, Backward Euler) against Fourier's decaying mode, 3D, plane stress, plane
# strain, np 1 and 2.
foreach(np 1 2)
  foreach(dim 3d plane_stress plane_strain)
    set(name thermal_transient_${dim}_np${np})
    periforge_run(${name} ${REG}/thermal/transient_${dim}.xml ${np})
    periforge_check(${name}_check ${name}
      ${PY} ${REG}/thermal/check_transient.py ${dim} ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/transient_${dim}.e)
  endforeach()
endforeach()
# Explicit conduction (Verlet with Solve For Temperature, thermal only: Solve For Displacement false; Fixed dt 1.1
# times the field's stable step, so 2 sub-steps per step) against the same Fourier mode, np 1 and 2.
foreach(np 1 2)
  foreach(dim 3d plane_stress plane_strain)
    set(name thermal_transient_explicit_${dim}_np${np})
    periforge_run(${name} ${REG}/thermal/transient_explicit_${dim}.xml ${np})
    periforge_check(${name}_check ${name}
      ${PY} ${REG}/thermal/check_transient.py ${dim} ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/transient_explicit_${dim}.e)
  endforeach()
endforeach()
# Plastic heating in the Taylor bar (Viscoplastic Correspondence, Taylor-Quinney 0.9): adiabatic, heat = beta W_p to
# 1e-6 at np 1 and 2 and the two runs alike; with conduction sub-cycled in each Verlet step, the energy balance.
foreach(np 1 2)
  periforge_run(thermal_taylor_adiabatic_np${np} ${REG}/thermal/taylor_adiabatic.xml ${np})
  periforge_check(thermal_taylor_adiabatic_np${np}_check thermal_taylor_adiabatic_np${np}
    ${PY} ${REG}/thermal/check_heating.py adiabatic
    ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_taylor_adiabatic_np${np}/taylor_adiabatic.e)
endforeach()
periforge_check(thermal_taylor_adiabatic_np1_vs_np2 "thermal_taylor_adiabatic_np1;thermal_taylor_adiabatic_np2"
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py
  ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_taylor_adiabatic_np2/taylor_adiabatic.e
  ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_taylor_adiabatic_np1/taylor_adiabatic.e ${REG}/thermal/np_agreement.comp)
# The same checks for the OSB J2 model's plastic work and stored energy (Elastic Plastic Hardening, to 20 us), np 2.
periforge_run(thermal_taylor_adiabatic_j2_np2 ${REG}/thermal/taylor_adiabatic_j2.xml 2)
periforge_check(thermal_taylor_adiabatic_j2_np2_check thermal_taylor_adiabatic_j2_np2
  ${PY} ${REG}/thermal/check_heating.py adiabatic
  ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_taylor_adiabatic_j2_np2/taylor_adiabatic_j2.e)
periforge_run(thermal_taylor_conducting_np2 ${REG}/thermal/taylor_conducting.xml 2)
periforge_check(thermal_taylor_conducting_np2_check thermal_taylor_conducting_np2
  ${PY} ${REG}/thermal/check_heating.py conducting
  ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_taylor_conducting_np2/taylor_conducting.e)
# Heat Flux and Convection on the end layers of an insulated bar: the steady balance T_R = T_amb + q / h, implicit
# (ImplicitDiffusion, 12 x 12 mm section) and explicit (Verlet thermal only, 4 x 4 mm section, to steady state).
foreach(np 1 2)
  foreach(run surface_heat_bar:implicit surface_heat_bar_explicit:explicit)
    string(REPLACE ":" ";" parts ${run})
    list(GET parts 0 deck)
    list(GET parts 1 kind)
    periforge_run(thermal_${deck}_np${np} ${REG}/thermal/${deck}.xml ${np})
    periforge_check(thermal_${deck}_np${np}_check thermal_${deck}_np${np}
      ${PY} ${REG}/thermal/check_surface_heat.py ${kind} ${CMAKE_CURRENT_BINARY_DIR}/regression/thermal_${deck}_np${np}/${deck}.e)
  endforeach()
endforeach()
# A coupled run (mechanics, conduction, plastic heating, softening) killed after a checkpoint and restarted ends
# byte-identical to the uninterrupted run, np 1.
add_test(NAME restart_thermal_taylor_kill_np1_np1
         COMMAND ${PY} ${REG}/restart/run_restart.py kill ${REG}/thermal/taylor_restart.xml 1 1 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_thermal_taylor_kill_np1_np1 PROPERTIES LABELS "regression" TIMEOUT 600)
# The same for the quasi-static coupled path (NOXQuasiStatic with Solve For Temperature on the coarse plate with a
# hole, J2 with thermal expansion, conduction and plastic heating): killed after step 15's checkpoint, restarted, the
# files byte-identical, np 1.
add_test(NAME restart_thermal_coupled_qs_kill_np1_np1
         COMMAND ${PY} ${REG}/restart/run_restart.py kill ${REG}/thermal/restart_coupled_qs.xml 1 1 ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(restart_thermal_coupled_qs_kill_np1_np1 PROPERTIES LABELS "regression" TIMEOUT 600)
# Temperature advanced beside a quasi-static mechanics (NOXQuasiStatic with Solve For Temperature: a Backward Euler
# heat step after each converged load step): a free 3D block heated uniformly (the expansion of each step's start
# temperature), and a clamped plane-stress J2 block heated by a flux and by its own plastic work, adiabatic, against
# a classical integration of the staggered scheme (check_coupled_qs.py); np 1 and 2.
foreach(np 1 2)
  foreach(case free_3d heating_plane_stress)
    string(REGEX REPLACE "_.*" "" mode ${case})
    set(name thermal_coupled_qs_${case}_np${np})
    periforge_run(${name} ${REG}/thermal/coupled_qs_${case}.xml ${np})
    periforge_check(${name}_check ${name} ${PY} ${REG}/thermal/check_coupled_qs.py ${mode}
      ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/coupled_qs_${case}.e)
  endforeach()
endforeach()

# The Temperature field (issue 33): thermal expansion of the Elastic solid (3D, plane stress, plane strain) and of
# Elastic Correspondence (3D, plane strain) against the closed forms of linear thermoelasticity (free and clamped
# blocks) and steady conduction (ImplicitDiffusion)
# against Fourier's linear profile, np 1 and 2.
foreach(np 1 2)
  foreach(kind free clamped)
    foreach(dim 3d plane_stress plane_strain corr_3d corr_plane_strain)
      set(name thermal_${kind}_${dim}_np${np})
      periforge_run(${name} ${REG}/thermal/thermal_${kind}_${dim}.xml ${np})
      periforge_check(${name}_check ${name}
        ${PY} ${REG}/thermal/check_thermal.py ${kind} ${dim} ${CMAKE_CURRENT_BINARY_DIR}/regression/${name}/thermal_${kind}_${dim}.e)
    endforeach()
  endforeach()
  periforge_run(conduction_bar_np${np} ${REG}/thermal/conduction_bar.xml ${np})
  periforge_check(conduction_bar_np${np}_check conduction_bar_np${np}
    ${PY} ${REG}/thermal/check_conduction.py ${CMAKE_CURRENT_BINARY_DIR}/regression/conduction_bar_np${np}/conduction_bar.e)
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

# Microelastic (bond-based PMB) bar in uniaxial tension, 3D, ADR, np = 1 and 2: interior strain and the
# reaction against the affine field's (check_microelastic_bar.py says why not against E A eps).
foreach(np 1 2)
  periforge_run(bar_3d_microelastic_np${np} ${REG}/microelastic/bar_3d_microelastic.xml ${np})
  periforge_check(bar_3d_microelastic_np${np}_check bar_3d_microelastic_np${np}
    ${PY} ${REG}/microelastic/check_microelastic_bar.py
    ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_microelastic_np${np}/bar_3d_microelastic.csv)
endforeach()

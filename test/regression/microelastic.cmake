# Microelastic (bond-based PMB) bar in uniaxial tension, 3D, ADR, np = 1: interior strain and the reaction
# against the affine field's (check_microelastic_bar.py says why not against E A eps). np 2 until session 26: the
# bond-based pair force across ranks is checked by Peridigm's ElasticBondBased decks at np 2 (issue 37: a deck runs at one rank count unless np 1 and 2 test different code).
foreach(np 1)
  periforge_run(bar_3d_microelastic_np${np} ${REG}/microelastic/bar_3d_microelastic.xml ${np})
  periforge_check(bar_3d_microelastic_np${np}_check bar_3d_microelastic_np${np}
    ${PY} ${REG}/microelastic/check_microelastic_bar.py
    ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_microelastic_np${np}/bar_3d_microelastic.csv)
endforeach()

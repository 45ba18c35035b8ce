# YAML decks: the YAML form of a deck (converted at test time) gives the XML run's history bit for bit.
foreach(case bar_3d bar_verlet)
  periforge_check(yaml_${case}_equals_xml ${case}_np1
    ${PY} ${REG}/yaml/check_yaml_twin.py ${PERIFORGE_EXE} ${REG}/bar/${case}.xml
    ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}_np1/${case}.csv)
endforeach()

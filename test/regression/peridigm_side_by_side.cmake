# Periforge against Peridigm's own output of the same deck, stored in the repo (peridigm_side_by_side/README.md:
# which Peridigm and which build script made the gold files): Elastic Plastic Hardening with Peridigm's
# Hardening Modulus and shear correction factor, and Elastic Plastic, on a yielding 10^3 cube at np = 1 and 2;
# tolerances (1e-8 of each field's largest value) and their reason in the .comp files.
set(SBS ${REG}/peridigm_side_by_side)
foreach(deck sbs_hardening_scf_on sbs_elastic_plastic)
  foreach(np 1 2)
    periforge_run(peridigm_${deck}_np${np} ${SBS}/${deck}.xml ${np})
    periforge_check(peridigm_${deck}_np${np}_vs_peridigm peridigm_${deck}_np${np}
      ${PY} ${PROJECT_SOURCE_DIR}/scripts/exodiff.py ${CMAKE_CURRENT_BINARY_DIR}/regression/peridigm_${deck}_np${np}/${deck}.e
      ${SBS}/${deck}_gold.e ${SBS}/${deck}.comp)
  endforeach()
endforeach()

# The two examples of Asgari & Kouchakzadeh (2023, seed 002, Sec. 5) at the coarse resolution (dx = 0.5 mm,
# delta = 1.5 mm, 2 564 points, np = 2, 40 NOX load steps, about 20 s each), judged against the stored CalculiX
# references (examples/<case>/fe/, mesh-converged; no ccx needed) by scripts/validate_plane_j2. The issue's bounds
# (force 3 %, plastic zone 10 %) hold at the fine resolutions (delta = 0.5 / 0.25 mm, several minutes each:
# examples/*/README.md); the coarse horizon is 15 % of the 10 mm ligament, and the OSB free-surface effect at the
# notch (no surface correction) makes the coarse plates stiff. Measured (2026-12-06, np = 2):
#   grooved plate (plane strain): F error +2.19 % (step 1) .. +5.44 % (step 40); zone -21.4 / +24.3 / +20.7 % at
#     steps 20 / 30 / 40 (4.00 / 36.00 / 235.00 vs 5.09 / 28.97 / 194.72 mm^2);
#   perforated plate (plane stress): F error +4.97 % (step 1) .. +8.56 % (step 40); zone +17.8 / +32.9 / +35.5 %
#     (11 / 109 / 158 vs 9.34 / 82.04 / 116.59 mm^2).
# Bounds: the signed F error in a band 0.5 %-points wider than measured on each side (NOX stops at 1e-6 of the
# residual, np = 1 vs 2 differ far below 0.1 %; the rest is room for round-off carried along a plastic history);
# a 2 % error in E or sigma_y moves the band's ends by about 2 %-points and fails one side. Zone: measured + 2
# points' area (0.5 mm^2) at the tightest step, rounded up: 27 % (grooves), 38 % (hole); the zone counts whole
# points, so one point more or less moves it by 0.25 mm^2.
foreach(case grooved_plate perforated_plate)
  periforge_run(${case}_coarse_np2 ${REG}/../../examples/${case}/${case}_coarse.xml 2)
endforeach()
periforge_check(grooved_plate_coarse_np2_vs_fe grooved_plate_coarse_np2
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plane_j2 grooved_plate
  ${CMAKE_CURRENT_BINARY_DIR}/regression/grooved_plate_coarse_np2/grooved_plate_coarse.csv
  ${CMAKE_CURRENT_BINARY_DIR}/regression/grooved_plate_coarse_np2/grooved_plate_coarse.e
  --only force,zone --force-tol 0.060 --force-band 0.017,0.060 --zone-tol 0.27)
periforge_check(perforated_plate_coarse_np2_vs_fe perforated_plate_coarse_np2
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plane_j2 perforated_plate
  ${CMAKE_CURRENT_BINARY_DIR}/regression/perforated_plate_coarse_np2/perforated_plate_coarse.csv
  ${CMAKE_CURRENT_BINARY_DIR}/regression/perforated_plate_coarse_np2/perforated_plate_coarse.e
  --only force,zone --force-tol 0.091 --force-band 0.045,0.091 --zone-tol 0.38)

# The READMEs' resolution study (examples/<case>/runs/*.csv: step, force and plastic-zone area of each run, written by
# validate_plane_j2 --write-summary from runs of `scripts/plane_j2_decks --study CASE DX RATIO` or the decks; minutes
# to an hour each, not in ctest) against the same FE references: each row's bounds are the README's quoted largest
# force and zone errors rounded up at their last digit, so a changed summary or FE file fails here. The fine decks'
# rows (grooves delta 0.5 mm, hole delta 0.25 mm) are also the issue's bounds (3 %, 10 %) met; the influence rows
# (the fine grooved deck with Parabolic Decay and Gaussian omega) quote how far those depart from J2.
# case | summary | force tol | zone tol
set(plane_j2_study
  "grooved_plate delta1.5_dx0.5 0.0545 0.244"
  "grooved_plate delta1.0_dx0.2 0.0314 0.120"
  "grooved_plate delta0.8_dx0.2 0.0268 0.106"
  "grooved_plate delta0.5_dx0.125 0.0202 0.078"
  "grooved_plate influence_parabolic 0.0823 0.510"
  "grooved_plate influence_gaussian 0.1850 0.866"
  "perforated_plate delta1.5_dx0.5 0.0857 0.356"
  "perforated_plate delta1.0_dx0.2 0.0516 0.247"
  "perforated_plate delta0.5_dx0.125 0.0310 0.115"
  "perforated_plate delta0.25_dx0.0625 0.0198 0.041")
foreach(row ${plane_j2_study})
  separate_arguments(f UNIX_COMMAND "${row}")
  list(GET f 0 case)
  list(GET f 1 stem)
  list(GET f 2 ftol)
  list(GET f 3 ztol)
  periforge_check(${case}_${stem}_summary_vs_fe "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plane_j2 ${case}
    ${PROJECT_SOURCE_DIR}/examples/${case}/runs/${stem}.csv --force-tol ${ftol} --zone-tol ${ztol})
endforeach()

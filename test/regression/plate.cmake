# Coarse plate with a hole, isotropic hardening, full 120-step cycle at np = 2, against the gold history
# from np = 1 (scripts/regenerate_gold). Tolerances: ADR stops each step at 1e-5 of the load scale (the
# largest reaction norm so far: on unloading steps the peak's), so two partitions stop at different iterates,
# and the plastic history carries that difference along the cycle. Measured np = 2 vs the np = 1 gold (max
# over 120 steps, 2026-12-02, gold regenerated when the load scale became the peak's): reaction 0.55 N (of
# 4e4 N), stress at A 3.5e4 Pa (of 9e8), plastic strain 8.1e-8 (of 1e-2), u_y of the driven layer 6.1e-9 m
# (of 2.5e-4 x; 1.25e-9 m while unloading steps were judged against their own, smaller reaction). Bounds
# are about 4x those: 2 N, 6e4 Pa (1e-4 sigma_y), 4e-7, 2.5e-8 m (1e-4 of u_x). A change of the model or of
# the solver's answer moves them by orders of magnitude more.
periforge_run(plate_iso_coarse_np2 ${REG}/../../examples/plate_with_hole/plate_iso_coarse.xml 2)
periforge_check(plate_iso_coarse_np2_vs_gold plate_iso_coarse_np2
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/compare_csv
  ${CMAKE_CURRENT_BINARY_DIR}/regression/plate_iso_coarse_np2/plate_iso_coarse.csv
  ${REG}/plate/plate_iso_coarse_gold.csv
  ${plate_tols})

# The same plate solved by NOXQuasiStatic (np = 2) against ADR's history (np = 1), both at relative
# tolerance 1e-7 (issue 4: "same history as ADR within the regression tolerances"). At 1e-5 the two
# solvers' own stopping errors (up to 7e-7 in plastic strain at A) exceed the bounds above, so both are
# converged further; measured at 1e-7: reaction 0.04 N, stress at A 174 Pa, plastic strain 4.3e-9. The
# bounds are the ADR np = 1 vs np = 2 ones above, reasons there.
periforge_run(plate_iso_coarse_nox_np2 ${REG}/plate/plate_iso_coarse_nox.xml 2)
periforge_check(plate_iso_coarse_nox_vs_adr plate_iso_coarse_nox_np2
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/compare_csv
  ${CMAKE_CURRENT_BINARY_DIR}/regression/plate_iso_coarse_nox_np2/plate_iso_coarse_nox.csv
  ${REG}/plate/plate_iso_coarse_adr_tight_gold.csv
  ${plate_tols})

# The same np = 2 run against the independent FE solution (CalculiX, ${PERIFORGE_SHARED_DIR}/reference/calculix;
# scripts/validate_plate, which exits 1 on a missed bound and 2 when the FE file is missing -- then this test
# fails, see test/CMakeLists.txt). Measured (2026-12-02, the np = 2 run): F_x max 4.33 % off FE (step 37,
# -4 599 vs -4 408 N) over the 108 steps where |F_FE| > 10 % of its peak; residual F_x at steps 40 / 80 / 120
# -3.7 / +3.3 / -1.2 %; plastic strain at B (FE on the ligament at the node's y) -23.5 / -11.6 / -6.7 % at
# steps 20 / 60 / 100. Bounds: F_x 4.8 % (measured + 0.47 %-points: np = 1 vs np = 2 differ by <= 2 N, 0.05 %
# of the step-37 force; the rest is room for compiler/BLAS round-off carried along a 120-step plastic history;
# a 5 % error of sigma_y or a 5 % thickness error moves F_x by 4-5 % at the peaks and fails); residual 6 %
# (measured + 2.3 %-points, same reasons, on a force 20x smaller); plastic strain at B 25 % (issue 5's bound;
# the coarse grid's -23.5 % at step 20 is the 0.5 mm probe offset and delta = 3 mm smoothing, docs/validation.md).
# Not judged at this resolution (printed): signed von Mises at B and the plastic-zone area, which the coarse grid
# misses for the reasons docs/validation.md gives and the paper-resolution run meets.
periforge_check(plate_iso_coarse_np2_vs_fe plate_iso_coarse_np2
  ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plate
  ${CMAKE_CURRENT_BINARY_DIR}/regression/plate_iso_coarse_np2/plate_iso_coarse.csv
  ${CMAKE_CURRENT_BINARY_DIR}/regression/plate_iso_coarse_np2/plate_iso_coarse.e
  --ref-dir ${PERIFORGE_SHARED_DIR}/reference/calculix --only fx,residual,peeq
  --fx-tol 0.048 --residual-tol 0.06 --peeq-tol 0.25)

# README's and docs/validation.md's numbers for the paper-resolution plate (a 2.5-minute run at np 2, not in ctest),
# checked on its stored history docs/data/plate_iso_paper.csv (the deck with its Surface Correction) against the
# shared FE reference: F_x within 1.74 % at each of the 108 steps where |F_FE| > 10 % of its peak (measured 1.73 % at
# step 37), residuals within 5 % (measured -4.2 / +4.97 / -2.5 %). Bounds: the quoted numbers rounded up at their
# last digit.
periforge_check(plate_iso_paper_history_vs_fe "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plate
  ${PROJECT_SOURCE_DIR}/docs/data/plate_iso_paper.csv --ref-dir ${PERIFORGE_SHARED_DIR}/reference/calculix
  --only fx,residual --fx-tol 0.0174 --residual-tol 0.05)

# The same history without the Surface Correction (the deck until 2026-12-06, docs/data/plate_iso_paper_uncorrected.csv)
# against the shared reference: docs/validation.md's table of that run, F_x within 1.81 % (measured 1.80 %, step 37),
# residuals within 3 % (-1.2 / +2.4 / -0.2 %).
periforge_check(plate_iso_paper_uncorrected_history_vs_fe "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plate
  ${PROJECT_SOURCE_DIR}/docs/data/plate_iso_paper_uncorrected.csv --ref-dir ${PERIFORGE_SHARED_DIR}/reference/calculix
  --only fx,residual --fx-tol 0.0181 --residual-tol 0.03)

# docs/validation.md's before/after table ("Paper resolution against the CalculiX references", issue 38): the stored
# paper-resolution histories (docs/data/plate_<hardening>_paper.csv with the decks' Surface Correction,
# *_uncorrected.csv without it; each carries its probe lines, A and B are lattice points) against the repository's
# finite-strain CalculiX references (examples/plate_with_hole/fe/), judged by validate_plate with the table's numbers
# rounded up at their last digit: F_x where |F_FE| > 10 % of its peak, residuals at steps 40/80/120, signed von Mises
# at B (fraction of sigma_y, every step), PEEQ at B at steps 20/60/100. Needs neither ../shared nor ccx.
# The iso histories also against the small-strain reference (the same table's last rows; ccx's small-strain routine is
# right for isotropic hardening only).
foreach(row "iso_paper finite 0.0173 0.050 0.0267 0.0481" "iso_paper_uncorrected finite 0.0180 0.0248 0.0500 0.0762"
            "kin_paper finite 0.0167 0.0413 0.0381 0.0481" "kin_paper_uncorrected finite 0.0179 0.0191 0.0651 0.0756"
            "mixed_paper finite 0.0119 0.0468 0.0141 0.0246" "mixed_paper_uncorrected finite 0.0149 0.0207 0.0408 0.0619"
            "iso_paper small 0.0179 0.0449 0.0266 0.0380" "iso_paper_uncorrected small 0.0185 0.0157 0.0472 0.0664")
  separate_arguments(f UNIX_COMMAND "${row}")
  list(GET f 0 stem)
  list(GET f 1 kinematics)
  list(GET f 2 fx)
  list(GET f 3 res)
  list(GET f 4 svm)
  list(GET f 5 peeq)
  string(REGEX MATCH "^[a-z]+" hardening "${stem}")
  set(name plate_${stem}_vs_own_fe)
  if(kinematics STREQUAL "small")
    set(name plate_${stem}_vs_own_fe_small_strain)
  endif()
  periforge_check(${name} "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/validate_plate
    ${PROJECT_SOURCE_DIR}/docs/data/plate_${stem}.csv
    --ref ${PROJECT_SOURCE_DIR}/examples/plate_with_hole/fe/plate_${hardening}_${kinematics}.csv
    --only fx,residual,svm,peeq --fx-tol ${fx} --residual-tol ${res} --svm-tol ${svm} --peeq-tol ${peeq})
endforeach()

# The CalculiX references made in the repository (scripts/plate_fe_reference -> examples/plate_with_hole/fe/: iso in
# small and finite strain, kin and mixed in finite strain, which ccx 2.20 gets right): the stored iso finite-strain
# one against the shared reference it must reproduce (the same model): F_x within 2 N at every step (measured
# 0.48 N), von Mises at A and B within 2 MPa where both runs' PEEQ agree (1.45 MPa) and 8 MPa at the onset of
# reversed yield, where the state depends on ccx's increments (6.55 MPa at B, step 53). A reference written with
# another load, material or mesh moves F_x by hundreds of N.
periforge_check(plate_fe_reference_vs_shared "" ${PY} ${PROJECT_SOURCE_DIR}/scripts/plate_fe_reference
  --check-stored --shared ${PERIFORGE_SHARED_DIR}/reference/calculix/caseA_iso.csv)

# Bars in uniaxial stress loaded past yield and back (issue 16): J2 with isotropic or kinematic hardening
# (K or H = 20 GPa, sigma_y = 600 MPa, E = 200 GPa), 3D (np = 2) and plane stress (np = 1), partial
# volumes, delta = 3.015 dx, eps 0 -> 9e-3 (3 eps_y) -> 0 in 40 steps of 4.5e-4, against the 1D
# elastoplastic closed form written in check_plastic_bar.py. Measured (2026-12-02; 3D iso / 3D kin /
# plane-stress iso / plane-stress kin):
#   interior stress (probe Mid vs sigma_1D at the probes' strain): max 1.21 / 1.35 / 1.20 / 1.09 % of sigma_y.
#     Bound 2 %: the lattice point itself is 0.84 % (3D) / 1.20 % (plane stress) off classical J2 at this
#     ratio with partial volumes (J2Equivalence.PartialVolumeFamilies), plus the probe's neighbours near the
#     free faces; a 5 % error of sigma_y (30 MPa) or of the hardening (> 10 MPa by the peak) exceeds it.
#   interior elastic stiffness (svm_Mid / (E eps_interior), elastic steps): +0.20 % (3D), +0.52 % (plane
#     stress). Bound 1 %: a 2 % stiffness error fails.
#   interior plastic strain at the peak / end: +1.2 / +1.2 / +0.8 / +0.8 % and +1.5 / +1.8 / +1.2 / +0.9 %.
#     Bound 4 %: the same lattice error, amplified by E/(E + K + H) ~ 11 in the plastic strain.
#   reverse yield: the interior point yields again in the closed form's step (36 iso, 34 kin: the
#     Bauschinger effect, 2 steps earlier); the reaction's slope drops one step earlier in three of four
#     cases (the over-stiff surface band yields first). Bound: one load step (issue 16).
#   reaction / (A sigma_1D) where |sigma_1D| > sigma_y/2: 1.088-1.269 / 1.077-1.247 / 1.031-1.117 /
#     1.031-1.116; hardening slope of the reaction +28.4 % (3D), +10.6 % (plane stress). The free
#     lateral surfaces carry more than the interior (the OSB surface effect, not corrected, as in the
#     paper: +17 % (3D, 10 x 10 points) and +7 % (plane stress, 20 points) already in the elastic step), so
#     the reaction is held to measured bands (about 2 % beyond the extremes; slope 35 % / 15 %): a guard
#     against a changed structural response, not a closed-form check -- the interior checks are.
set(PB ${REG}/plastic_bar)
set(pb_common --E 200e9 --sy 600e6 --rate 4.5e-4 --peak 20 --gauge 0.03 --stress-tol 0.02 --alpha-tol 0.04
  --stiffness-tol 0.01 --yield-steps 1)
set(pb_3d --area 4e-4 --reaction-min 1.06 --reaction-max 1.29 --slope-tol 0.35)
set(pb_plane_stress --area 2e-5 --reaction-min 1.01 --reaction-max 1.14 --slope-tol 0.15)
set(pb_iso --K 20e9 --H 0)
set(pb_kin --K 0 --H 20e9)
foreach(dim_np 3d:2 plane_stress:1)
  string(REPLACE ":" ";" dn ${dim_np})
  list(GET dn 0 dim)
  list(GET dn 1 np)
  foreach(hard iso kin)
    set(case plastic_bar_${dim}_${hard})
    periforge_run(${case}_np${np} ${PB}/${case}.xml ${np})
    periforge_check(${case}_np${np}_vs_closed_form ${case}_np${np}
      ${PY} ${PB}/check_plastic_bar.py ${CMAKE_CURRENT_BINARY_DIR}/regression/${case}_np${np}/${case}.csv
      ${pb_common} ${pb_${dim}} ${pb_${hard}})
  endforeach()
endforeach()

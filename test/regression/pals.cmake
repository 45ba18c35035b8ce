# Peridigm's Pals solid on the 3D bar of bar_3d_nox.xml (uniaxial stress, eps = 1e-3, free lateral faces), np 2: the
# reaction against the classical E A eps and the strain between the probes against eps. Its position-aware influence
# functions give the surface points the classical moments: the bound is 0.75 % (measured: reaction -0.18 %, strain
# +0.65 %), which the plain OSB Elastic bar's reaction (+0.90 %, core.cmake) would fail.
periforge_run(bar_3d_pals_np2 ${REG}/pals/bar_3d_pals.xml 2)
periforge_check(bar_3d_pals_np2_check bar_3d_pals_np2
  ${PY} ${REG}/bar/check_bar.py ${CMAKE_CURRENT_BINARY_DIR}/regression/bar_3d_pals_np2/bar_3d_pals.csv
  --dim 3 --area 4e-4 --ratio 3.015 --reaction-against classical --tol 0.0075 --E 200e9 --nu 0.3 --strain 1e-3)

# Discretization "Exodus" (Peridigm's genesis meshes: one point per element). check_exodus.py writes its
# meshes with test/regression/exodus/write_genesis.py (netCDF4) and checks, at np 1 and 2:
#  - a 6x3x3 HEX8 box (blocks 1 and 7, named and unnamed face node sets) runs a 20-step Verlet problem like the
#    PdQuickGrid lattice of the same box: fields agree to 1e-10 of their scale (round-off measures 4e-12: the
#    24-tet centroids and volumes are a few ulp off the lattice's), coordinates are the cell centres, volumes h^3;
#  - a QUAD4 mesh with Thickness: centres and area * Thickness;
#  - bad meshes (missing, not Exodus, unknown element type, inverted element, node set beyond num_nodes, QUAD
#    without Thickness) stop with one input-error line naming the deck and the parameter, no crash, no hang.
# About 11 s (the failing mpirun jobs each wait 2-3 s in Open MPI's abort path; the script runs four at a time).
add_test(NAME exodus_discretization
  COMMAND ${PY} ${REG}/exodus/check_exodus.py ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(exodus_discretization PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 120)

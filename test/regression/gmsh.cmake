# Discretization "Gmsh" (MSH 4.1, ASCII and binary: one point per element by Peridigm's rule). check_gmsh.py reads
# the committed meshes of test/regression/gmsh (made from the .geo files there; gmsh is not needed) and checks at
# np 1 and 2:
#  - a 6x3x3 hex box (volumes 1 and 7 "top", face groups as node sets, the alias "top" in Block Names) runs
#    check_exodus.py's Verlet problem like the PdQuickGrid lattice: fields agree to 1e-10 of their scale, point by
#    point matched by coordinates (measured 6e-12), coordinates the cell centres, volumes h^3;
#  - quadrilaterals with Thickness and tetrahedra: centroids and measures by closed forms on the file's nodes;
#  - bad meshes (missing, MSH 2.2, unknown element type, inverted, a node set naming a node $Nodes lacks, 2D
#    without Thickness): one input-error line naming the deck, the parameter and the mesh.
# About 10 s.
add_test(NAME gmsh_discretization
  COMMAND ${PY} ${REG}/gmsh/check_gmsh.py ${PERIFORGE_EXE} ${MPIRUN})
set_tests_properties(gmsh_discretization PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 120)

# examples/gmsh from its .geo to a run: gmsh meshes the paper's plate with a hole (quadrilaterals, the lattice's
# 1 mm grid outside an O-grid around the hole), plate_gmsh.xml runs its 120-step cycle beside the lattice deck
# examples/plate_with_hole/plate_iso_coarse.xml, and the right reaction F_x must agree within 2 % of the
# lattice's peak at every step (measured 0.99 %, at the peaks). Skipped (77, one line) without gmsh. About 45 s.
add_test(NAME gmsh_plate_vs_lattice
  COMMAND ${PY} ${PROJECT_SOURCE_DIR}/examples/gmsh/compare_lattice.py ${PERIFORGE_EXE})
set_tests_properties(gmsh_plate_vs_lattice PROPERTIES LABELS "regression" PROCESSORS 2 TIMEOUT 600 SKIP_RETURN_CODE 77)

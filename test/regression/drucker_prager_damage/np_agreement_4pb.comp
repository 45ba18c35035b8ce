# four_point_bending_coarse_t7.xml, np = 2 against np = 1 (NOXQuasiStatic, relative tolerance 1e-6): the broken set
# must be the same, so Damage is compared exactly. Displacements reach 7e-6 m; the Newton-Krylov solves stop within
# 1e-6 of the load scale, at different iterates on 1 and 2 ranks (the Krylov dot products sum in another order), so
# bounds of 1e-3 of the largest displacement (7e-9 m) and 1e-3 of f_t in stress (1e3 Pa). Set after measuring:
# see four_point_bending.md.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 7.0E-9
	DisplacementY   absolute 7.0E-9
ELEMENT VARIABLES
	Damage absolute 0.0
	Unrotated_Cauchy_StressXX absolute 1.0E3
	Unrotated_Cauchy_StressYY absolute 1.0E3
	Unrotated_Cauchy_StressXY absolute 1.0E3

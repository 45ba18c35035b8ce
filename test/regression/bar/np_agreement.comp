# np = 1 vs np = 2 of the same ADR deck. ADR stops at a relative residual of 1e-7 of the reaction;
# the two runs stop at different iterates within that tolerance, so displacements (~1e-4 m) may differ
# by ~1e-7 relative: 1e-10 m absolute. A partition error (a missing ghost or bond) is orders larger.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-10
	DisplacementY   absolute 1.0E-10
	DisplacementZ   absolute 1.0E-10

# tension_bar.xml, np = 2 against np = 1: the broken set must be the same, so Damage (a ratio of bond counts) is
# compared exactly; the stress within what ADR's relative tolerance 1e-8 leaves (sigma_xx ~ 1e6 Pa: 1e-2 Pa, bound
# 1 Pa) and the lateral displacement likewise (u_y ~ 1e-9 m at most here: bound 1e-12 m).
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-12
	DisplacementY   absolute 1.0E-12
	DisplacementZ   absolute 1.0E-12
ELEMENT VARIABLES
	Damage absolute 0.0
	Unrotated_Cauchy_StressXX absolute 1.0

# Newton (relative residual 1e-10) vs ADR (relative residual 1e-7) on the same bar: they agree within
# ADR's tolerance; displacements (~1e-4 m) to ~1e-7 relative, i.e. 1e-10 m absolute.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-10
	DisplacementY   absolute 1.0E-10
	DisplacementZ   absolute 1.0E-10

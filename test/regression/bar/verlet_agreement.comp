# np = 1 vs np = 2 of the Verlet deck with a fixed dt: the same arithmetic but for the order of the
# ghost-force sums, so results agree to round-off: 1e-12 relative, where differences up to 1e-17 m
# (1e-12 of the largest displacement, 1e-5 m) pass so that u_y near the bar axis, which passes through
# zero, is judged against the field's scale rather than its own.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   relative 1.0E-12 floor 1.0E-17
	DisplacementY   relative 1.0E-12 floor 1.0E-17
	DisplacementZ   relative 1.0E-12 floor 1.0E-17

# np = 1 vs np = 2 of the same explicit coupled deck (Verlet with the Temperature field). An explicit run has no
# solver tolerance: the gather-form models and the conduction sum each point's own family in the same order at any
# np, so the two runs agree to round-off (measured: bit-identical). 1e-9 K and 1e-12 m leave room for a summation
# order change only; a missing ghost temperature or a source applied on the wrong rank is off by kelvins.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-12
	DisplacementY   absolute 1.0E-12
	DisplacementZ   absolute 1.0E-12
	Temperature     absolute 1.0E-9

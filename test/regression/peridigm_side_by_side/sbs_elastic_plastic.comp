# Periforge against Peridigm's own output of the same deck (README.md). Absolute tolerances of 1e-8 x the
# field's largest value over the run (max |Peridigm|: Displacement 4.8e-5, Velocity 98, Force_Density 1.4e12,
# Dilatation 1.25e-2, Weighted_Volume 7.1e-13, Lambda 1.2e-24), as for the hardening deck. Measured: at most
# 1.3e-13 of the largest value (round-off: Peridigm and Periforge sum the same bonds in different orders); the
# margin of 1e-8 is kept the same as for the hardening deck, whose factor carries 1e-10 rounding.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 5.0E-13
	DisplacementY   absolute 5.0E-13
	DisplacementZ   absolute 5.0E-13
	VelocityX       absolute 1.0E-6
	VelocityY       absolute 1.0E-6
	VelocityZ       absolute 1.0E-6
	Force_DensityX  absolute 1.4E4
	Force_DensityY  absolute 1.4E4
	Force_DensityZ  absolute 1.4E4
ELEMENT VARIABLES
	Dilatation      absolute 1.2E-10
	Weighted_Volume absolute 7.0E-21
	Lambda          absolute 1.0E-32

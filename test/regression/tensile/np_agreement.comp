# tensile_coarse at np 1 against np 2 (examples/tensile_8300). The runs do NOT agree bit for bit: each point's
# family lists its owned neighbours before its ghosts (local index order, DistributedLayout), so at np 2 the
# correspondence sums K = sum w xi(x)xi and F = (sum w Y(x)xi) K^-1 of the points next to the cut run in another
# order; F differs by one ulp already in the initial frame (u = 0: F_xx at 31, F_zz at 42 of 1024 points) and
# the 216 steps carry it. Measured over the run: displacement 9.4e-18 m, F 5.3e-15, unrotated stress 3.5e-4 Pa (1e-12 of 4e8 Pa),
# eps_p 3.9e-15, its rate 3.0e-8 1/s (of 1e4). Bounds about 100x those: round-off passes, a partition error
# (a missing ghost or bond: a strain error of order 1e-3) fails by orders of magnitude.
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES
	DisplacementX   absolute 1.0E-15
	DisplacementY   absolute 1.0E-15
	DisplacementZ   absolute 1.0E-15
ELEMENT VARIABLES
	Deformation_GradientXX   absolute 5.0E-13
	Deformation_GradientYY   absolute 5.0E-13
	Deformation_GradientZZ   absolute 5.0E-13
	Deformation_GradientXZ   absolute 5.0E-13
	Deformation_GradientYZ   absolute 5.0E-13
	Unrotated_Cauchy_StressXX   absolute 0.05
	Unrotated_Cauchy_StressYY   absolute 0.05
	Unrotated_Cauchy_StressZZ   absolute 0.05
	Equivalent_Plastic_Strain   absolute 5.0E-13
	Equivalent_Plastic_Strain_Rate   absolute 5.0E-6
	Von_Mises_Stress   absolute 0.05

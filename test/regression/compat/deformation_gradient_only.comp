# Peridigm's DeformationGradient.comp (suite cases DeformationGradient__PureShear, __SimpleShear, __SolidRotation)
# without its Velocity lines: at the held points Peridigm writes the prescribed rate plus dt/2 times the point's
# acceleration, Periforge the prescribed rate (docs/peridigm.md, "Differ"). Same tolerances otherwise.
DEFAULT TOLERANCE absolute 1.0E-9
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES absolute 1.0E-12
	DisplacementX   absolute 1.0E-16
	DisplacementY   absolute 1.0E-16
	DisplacementZ   absolute 1.0E-16
ELEMENT VARIABLES absolute 1.E-12
	Deformation_GradientXX absolute 1.0E-14
	Deformation_GradientYY absolute 1.0E-14
	Deformation_GradientZZ absolute 1.0E-14
	Deformation_GradientXY absolute 1.0E-14
	Deformation_GradientYZ absolute 1.0E-14
	Deformation_GradientZX absolute 1.0E-14
	Deformation_GradientYX absolute 1.0E-14
	Deformation_GradientZY absolute 1.0E-14
	Deformation_GradientXZ absolute 1.0E-14

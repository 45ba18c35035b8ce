# Peridigm's ThermalExpansionCubeElasticCorrespondence.comp (same tolerances) limited to the variables Periforge's
# kinematics share with Peridigm's: temperatures, forces, the hourglass force density, the rotation, the shape
# tensor's inverse and both stresses. Left out: displacements, Deformation_Gradient, Left_Stretch_Tensor and
# Unrotated_Rate_Of_Deformation, 5.5e-5 apart after the 1 % expansion because Peridigm takes each step's rate at
# its end (d = (F - F_n) F^-1 / dt, thermal strain alpha dT subtracted from d dt) where Periforge takes it at the
# midpoint, under which (1 + alpha dT) I is exactly stress-free (docs/peridigm.md).
DEFAULT TOLERANCE absolute 1.0E-9
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES absolute 1.0E-12
	Temperature_Change   absolute 1.0E-9
	Temperature          absolute 1.0E-9
	ForceX               absolute 1.0E-3
	ForceY               absolute 1.0E-3
	ForceZ               absolute 1.0E-3
	Hourglass_Force_DensityX  absolute 1.0E-3
	Hourglass_Force_DensityY  absolute 1.0E-3
	Hourglass_Force_DensityZ  absolute 1.0E-3
ELEMENT VARIABLES absolute 1.E-12
	Rotation_TensorXX absolute 1.0E-12
	Rotation_TensorXY absolute 1.0E-12
	Rotation_TensorXZ absolute 1.0E-12
	Rotation_TensorYX absolute 1.0E-12
	Rotation_TensorYY absolute 1.0E-12
	Rotation_TensorYZ absolute 1.0E-12
	Rotation_TensorZX absolute 1.0E-12
	Rotation_TensorZY absolute 1.0E-12
	Rotation_TensorZZ absolute 1.0E-12
	Shape_Tensor_InverseXX absolute 1.0E-12
	Shape_Tensor_InverseXY absolute 1.0E-12
	Shape_Tensor_InverseXZ absolute 1.0E-12
	Shape_Tensor_InverseYX absolute 1.0E-12
	Shape_Tensor_InverseYY absolute 1.0E-12
	Shape_Tensor_InverseYZ absolute 1.0E-12
	Shape_Tensor_InverseZX absolute 1.0E-12
	Shape_Tensor_InverseZY absolute 1.0E-12
	Shape_Tensor_InverseZZ absolute 1.0E-12
	Unrotated_Cauchy_StressXX absolute 1.0E-2
	Unrotated_Cauchy_StressXY absolute 1.0E-2
	Unrotated_Cauchy_StressXZ absolute 1.0E-2
	Unrotated_Cauchy_StressYX absolute 1.0E-2
	Unrotated_Cauchy_StressYY absolute 1.0E-2
	Unrotated_Cauchy_StressYZ absolute 1.0E-2
	Unrotated_Cauchy_StressZX absolute 1.0E-2
	Unrotated_Cauchy_StressZY absolute 1.0E-2
	Unrotated_Cauchy_StressZZ absolute 1.0E-2
	Cauchy_StressXX absolute 1.0E-2
	Cauchy_StressXY absolute 1.0E-2
	Cauchy_StressXZ absolute 1.0E-2
	Cauchy_StressYX absolute 1.0E-2
	Cauchy_StressYY absolute 1.0E-2
	Cauchy_StressYZ absolute 1.0E-2
	Cauchy_StressZX absolute 1.0E-2
	Cauchy_StressZY absolute 1.0E-2
	Cauchy_StressZZ absolute 1.0E-2

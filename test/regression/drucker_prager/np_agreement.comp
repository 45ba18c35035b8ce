# Biaxial Drucker-Prager coarse deck, np = 2 against np = 1. ADR stops each load step at a relative residual of
# 1e-6, so the two runs stop at different iterates: displacements (up to 6.3e-3 m at the top) differ by about
# 1e-6 of that, and plastic flow carries such differences from step to step. Measured (max over 200 steps):
# displacement 7.6e-9 m, von Mises 5.5 Pa (of 2.7e5 Pa), equivalent plastic strain 2.7e-7 (of 5e-2). Bounds
# about 5-10x: 5e-8 m, 50 Pa, 2e-6. A partition error (a missing ghost or bond) is orders larger.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 5.0E-8
	DisplacementY   absolute 5.0E-8
ELEMENT VARIABLES
	Von_Mises_Stress absolute 50.0
	Equivalent_Plastic_Strain absolute 2.0E-6

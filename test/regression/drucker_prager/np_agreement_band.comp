# Biaxial Drucker-Prager coarse deck with the NDO band, np = 2 against np = 1. The force is the same bits at both
# rank counts (gather form); ADR's global sums (damping, residual norm) are not, so the runs stop each load step at
# different iterates within the 1e-6 relative residual. With the band every point flows at once (a uniform,
# perfectly plastic state: no elastic core stiffens the soft mode), so the stopping points are further apart than
# without it (np_agreement.comp). Measured (max over 200 steps): displacement 1.9e-7 m (of 6.3e-3 m), von Mises
# 29 Pa (of 2.5e5 Pa), equivalent plastic strain 9.3e-6 (of 4.6e-2). Bounds about 5x: 1e-6 m, 150 Pa, 5e-5.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-6
	DisplacementY   absolute 1.0E-6
ELEMENT VARIABLES
	Von_Mises_Stress absolute 150.0
	Equivalent_Plastic_Strain absolute 5.0E-5

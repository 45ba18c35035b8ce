# restart_plate_nox.xml killed at np 2 after its first checkpoint (step 15) and restarted at np 1, against
# the uninterrupted np 1 run. Both rank counts converge each load step to the same relative tolerance 1e-7
# but from different Krylov round-off, so their iterates differ within it, and the restarted run carries
# np 2's state on at np 1. Measured, uninterrupted np 1 vs np 2 (max over the 31 steps and 9884 points):
# displacement 1.7e-12 m (of 2.5e-4), von Mises stress 13.5 Pa (of 7.0e8), plastic strain 2.5e-10 (of
# 5.1e-3). Bounds about 5x those; Proc_Num (the rank) differs by design and is left out.
COORDINATES absolute 0
TIME STEPS absolute 0
NODAL VARIABLES
	DisplacementX   absolute 1.0E-11
	DisplacementY   absolute 1.0E-11
	DisplacementZ   absolute 0
ELEMENT VARIABLES
	Von_Mises_Stress           absolute 70
	Signed_Von_Mises_Stress    absolute 70
	Equivalent_Plastic_Strain  absolute 1.3E-9

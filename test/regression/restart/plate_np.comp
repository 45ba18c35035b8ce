# restart_plate_nox.xml killed at np 2 after its first checkpoint (step 15) and restarted at np 1, against
# the uninterrupted np 1 run. Both rank counts converge each load step to the same relative tolerance 1e-7
# but from different Krylov round-off (and, since issue 20, MueLu aggregates differently on two ranks), so
# their iterates differ within it, and the restarted run carries np 2's state on at np 1. The bounds are
# that tolerance carried to each field: 1e-7 of its largest value (displacement 2.5e-4 m, von Mises stress
# 7e8 Pa; plastic strain 5.1e-3, kept at its earlier, looser 1.3e-9). Measured, uninterrupted np 1 vs np 2
# (max over the 31 steps and 9884 points), Epetra/ML then Tpetra/MueLu: displacement 4.6e-12 / 1.03e-11 m,
# stress 25.9 / 33.1 Pa, plastic strain 1.8e-10 / 1.2e-10. Proc_Num (the rank) differs by design, left out.
COORDINATES absolute 0
TIME STEPS absolute 0
NODAL VARIABLES
	DisplacementX   absolute 2.5E-11
	DisplacementY   absolute 2.5E-11
	DisplacementZ   absolute 0
ELEMENT VARIABLES
	Von_Mises_Stress           absolute 70
	Signed_Von_Mises_Stress    absolute 70
	Equivalent_Plastic_Strain  absolute 1.3E-9

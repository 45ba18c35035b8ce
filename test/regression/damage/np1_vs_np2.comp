# notched_plate_coarse at np 2 against np 1: the same crack, bond for bond. Damage (the share of broken bonds
# per point) must agree exactly at every output step; displacements within 1e-12 m (about 1e-8 of the 0.1 mm
# the loaded edges move: force sums in another order across ranks round differently, nothing more).
DEFAULT TOLERANCE absolute 1.0E-12
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
NODAL VARIABLES absolute 1.0E-12
	DisplacementX   absolute 1.0E-12
	DisplacementY   absolute 1.0E-12
	DisplacementZ   absolute 1.0E-12
ELEMENT VARIABLES absolute 0.0
	Damage              absolute 0.0
	Number_Of_Neighbors absolute 0.0
	Proc_Num            absolute 2.0

# restart_bar.xml killed at np 2 after its first checkpoint and restarted at np 1, against the uninterrupted
# np 1 run. Up to the checkpoint the steps are np 2's, after it they carry np 2's round-off on at np 1: both
# differ from np 1's by the summation order only. Measured, uninterrupted np 1 vs np 2 (max over the 21
# steps and 2160 nodes): displacement 1.4e-16 m (of 1e-4), force density 19 (of ~1e12), dilatation 1.9e-14
# (of 4e-4). Bounds about 5x those; Proc_Num (the rank) differs by design and is left out.
COORDINATES absolute 0
TIME STEPS absolute 0
NODAL VARIABLES
	DisplacementX   absolute 7.0E-16
	DisplacementY   absolute 7.0E-16
	DisplacementZ   absolute 0
	Force_DensityX  absolute 1.0E+2
	Force_DensityY  absolute 1.0E+2
	Force_DensityZ  absolute 0
ELEMENT VARIABLES
	Dilatation      absolute 1.0E-13

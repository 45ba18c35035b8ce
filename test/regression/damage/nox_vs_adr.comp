# bar_damage_nox (np 2) against bar_damage_adr (np 1): the same bonds broken at every step (Damage exactly
# equal) and the same equilibria within the solvers' tolerances. Measured: displacement 3.1e-11 m (of 4e-4 m at
# the ends; bound 1e-9, 30x), dilatation 9.7e-10 (bound 1e-8), force density 1.07e5 N/m^3 at a free node, i.e.
# 8.5e-4 N on its 8e-9 m^3: below the steps' residual tolerances (1e-3 to 5e-3 N), so any free node may keep
# up to about 5e5 N/m^3; bound 1e6 (the loaded layers carry about 1e11).
DEFAULT TOLERANCE absolute 1.0E-9
COORDINATES absolute 0.0
TIME STEPS absolute 1.0E-12
NODAL VARIABLES absolute 1.0E-9
	DisplacementX   absolute 1.0E-9
	DisplacementY   absolute 1.0E-9
	DisplacementZ   absolute 1.0E-9
	Force_DensityX  absolute 1.0E6
	Force_DensityY  absolute 1.0E6
	Force_DensityZ  absolute 1.0E6
ELEMENT VARIABLES absolute 0.0
	Damage          absolute 0.0
	Dilatation      absolute 1.0E-8
	Proc_Num        absolute 2.0

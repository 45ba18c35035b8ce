# two_cubes.xml at np 1 and np 2: a point's contact force is summed on its owner over its partners in gid order,
# its partners on the other rank arriving as moving ghosts, so the partition changes no sum (measured:
# bit-identical). 1e-12 m and 1e-9 m/s leave room for a summation order change only; a partner lost across the rank
# boundary changes the velocities by metres per second.
COORDINATES absolute 1.0E-12
TIME STEPS absolute 1.0E-14
NODAL VARIABLES
	DisplacementX   absolute 1.0E-12
	DisplacementY   absolute 1.0E-12
	DisplacementZ   absolute 1.0E-12
	VelocityX       absolute 1.0E-9
	VelocityY       absolute 1.0E-9
	VelocityZ       absolute 1.0E-9

# The same deck run by the dispatching build (target_clones: the AVX-512 clone on the CI machine) and by
# builds whose kernels were compiled for one instruction set only (baseline x86-64-v2, AVX2). The kernels
# promise the same bits on every instruction set (OsbBondLoops.hpp: fixed 8-lane partial sums, no FMA
# contraction), so every value must agree exactly: tolerance 0.
DEFAULT TOLERANCE absolute 0.0
COORDINATES absolute 0.0
TIME STEPS absolute 0.0
GLOBAL VARIABLES absolute 0.0
NODAL VARIABLES absolute 0.0
ELEMENT VARIABLES absolute 0.0

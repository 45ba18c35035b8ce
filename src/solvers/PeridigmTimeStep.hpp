#pragma once
// Peridigm's critical time step estimate for explicit dynamics (Peridigm_CriticalTimeStep.cpp), the default of a
// Verlet run without a Fixed dt, so that Peridigm's decks take Peridigm's steps: the bond-based bound
// min_i sqrt(2 rho_i / sum_j V_j c_i / |xi_ij|), c_i = 18 K / (pi delta^4) of i's block, over the points of blocks
// whose material has elastic constants (BlockModel::bulkModulus). Not a bound on every model's stiffness
// (VerletSolver::stableTimeStep is). Collective; 1e50 where no point has a bond.
namespace pf {

class Model;

double peridigmCriticalTimeStep(const Model& model);

}  // namespace pf

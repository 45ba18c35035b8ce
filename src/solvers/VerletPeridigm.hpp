#pragma once
// The two places where Peridigm's velocity-Verlet step (Peridigm.cpp, executeExplicit) and Periforge's differ
// without a different motion of the free points:
//  - positions: Peridigm forms the step's positions as y = (x + u_n) + dt v_{n+1/2} and only then u_{n+1} =
//    u_n + dt v_{n+1/2}; x + u_{n+1} differs from y in the last bit, and its regression decks' force tolerances
//    (1e-9 N/m^3 on 1e8) see that bit through the bond extension's cancellation (|y| - |x|).
//  - the velocity of a prescribed component: Peridigm sets it to the condition's rate, then its second half kick
//    adds dt/2 (f + b)/rho to every component, prescribed ones included, and that is what it writes (the next
//    step's condition overwrites it, so the motion is the same). Periforge's own choice is the rate alone
//    (Verlet's `Prescribed Velocity`).
#include <cstddef>
#include <vector>

namespace pf {

class Model;

// y[k] = (x[k] + uStart[k]) + dt v[k] for k < n: Peridigm's order of the sums.
void peridigmPositions(const double* x, const double* uStart, const double* v, double dt, std::size_t n, double* y);

// The step's positions (3 per owned node), u = uStart + dt v to rounding: Peridigm's (peridigmPositions), or
// x + u with rigid walls (their projection moves u without v) or for dt = 0 (the initial state).
void verletPositions(const Model& model, const std::vector<double>& uStart, const std::vector<double>& u,
                     const std::vector<double>& v, double dt, std::vector<double>& y);

// Peridigm's written velocity: v[k] += dt/2 (f[k] + b[k]) / rho[k/3] where fixed[k] (the free components had it).
void halfKickPrescribed(const std::vector<char>& fixed, const std::vector<double>& rho, const std::vector<double>& f,
                        const std::vector<double>& b, double dt, std::vector<double>& v);

}  // namespace pf

#pragma once
// The sparse pair-stiffness matrix that preconditions the matrix-free Newton-Krylov solve, as rows (no linear
// algebra library): each bond's extension stiffness c V_j n n^T between its two nodes (the reverse bond's c
// taken as c m_i/m_j), bonds longer than radiusFactor x the node's shortest left out and the rest stiffened to
// the family's second moment; the shift (a Newmark step's rho / (beta dt^2)) on the free diagonal; a
// prescribed row holds the mean free diagonal s alone. Global dof ids are 3 * point + component.
#include <cstddef>
#include <functional>
#include <vector>

namespace pf {

class Model;

// The preconditioner's bond radius (in shortest bonds) where the deck gives none. Collective. 3 (every bond of a
// delta = 3 dx family) when every block is 2D, 2 when any is 3D: there the sparser matrix cost more GMRES iterations
// but so much less per application that the run took less time (beam 2.4x, notched bar's first 12 steps 1.7x
// faster), while in 2D it took longer (the coarse plate +23 %): docs/benchmark-log.md, "Preconditioner bond radius".
double defaultPreconditionerRadius(const Model& model);

// Collective (two reductions). shift: 3 per owned node, or null. Streams the rows, so that no copy of the
// matrix is held beside the one the caller builds: sized(rows, counts) once with every owned row's global
// dof id (owned order) and entry count, then row(r, columns, values, n) for every owned row in that order
// (a column may repeat: sum). Returns s, the mean free diagonal over all ranks.
double pairStiffnessRows(
    const Model& model, double radiusFactor, const std::vector<double>* shift,
    const std::function<void(const std::vector<long long>& rows, const std::vector<std::size_t>& counts)>& sized,
    const std::function<void(std::size_t r, const long long* columns, const double* values, std::size_t n)>& row);

}  // namespace pf

#pragma once
// The sparse pair-stiffness matrix that preconditions the matrix-free Newton-Krylov solve, as rows (no linear
// algebra library): each bond's extension stiffness c V_j n n^T between its two nodes (the reverse bond's c
// taken as c m_i/m_j), bonds longer than radiusFactor x the node's shortest left out and the rest stiffened to
// the family's second moment; the shift (a Newmark step's rho / (beta dt^2)) on the free diagonal; a
// prescribed row holds the mean free diagonal s alone. Global dof ids are 3 * point + component.
#include <cstddef>
#include <vector>

namespace pf {

class Model;

struct PairRows {
  std::vector<long long> row;         // global dof id of each owned row, in owned order
  std::vector<std::size_t> offsets;   // row r's entries: [offsets[r], offsets[r + 1]); a column may repeat (sum)
  std::vector<long long> columns;
  std::vector<double> values;
  double scale = 1.0;                 // s: the mean free diagonal over all ranks
};

// Collective (two reductions). shift: 3 per owned node, or null.
PairRows pairStiffnessRows(const Model& model, double radiusFactor, const std::vector<double>* shift);

}  // namespace pf

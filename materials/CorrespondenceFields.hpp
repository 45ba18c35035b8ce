#pragma once
// How the correspondence models keep tensors in their StateStore: one node field per component (the output layer
// writes node scalars), 9 row-major components "XX", "XY", ..., "ZZ" or, for a symmetric tensor, the 6 "XX", "YY",
// "ZZ", "XY", "YZ", "XZ" (toSym6's order). Internal to materials/Correspondence*.
#include <string>
#include <vector>

#include "core/Material.hpp"
#include "core/StateStore.hpp"
#include "core/Tensor3.hpp"

namespace pf {

inline const char* kFull[9] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};  // row-major
inline const char* kSym[6] = {"XX", "YY", "ZZ", "XY", "YZ", "XZ"};                      // toSym6 order

// A tensor stored as one node field per component (the output layer writes node scalars).
struct TensorField {
  double* trial[9];
  const double* committed[9];
  int n = 0;
  TensorField(StateStore& s, const std::string& base, bool symmetric) : n(symmetric ? 6 : 9) {
    for (int c = 0; c < n; ++c) {
      const std::string name = base + (symmetric ? kSym[c] : kFull[c]);
      trial[c] = s.trial(name);
      committed[c] = s.committed(name);
    }
  }
  Mat3 committedAt(int i) const {
    double v[9];
    for (int c = 0; c < n; ++c) v[c] = committed[c][i];
    return n == 6 ? fromSym6(v) : Mat3{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]};
  }
  void set(int i, const Mat3& a) {
    double v[9];
    if (n == 6) toSym6(a, v);
    for (int c = 0; c < n; ++c) trial[c][i] = n == 6 ? v[c] : a[c];
  }
};

// history: a committed/trial pair (a field the update reads back, or one that must survive an evaluation without a
// step); otherwise one array, rewritten by every evaluation that wants it.
inline void addTensorSpecs(std::vector<StateSpec>& s, const std::string& base, bool symmetric, bool output, bool identity,
                           bool history = true) {
  for (int c = 0; c < (symmetric ? 6 : 9); ++c) {
    const bool diagonal = symmetric ? c < 3 : c % 4 == 0;
    s.push_back({base + (symmetric ? kSym[c] : kFull[c]), Location::Node, history, output, identity && diagonal ? 1.0 : 0.0});
  }
}

}  // namespace pf

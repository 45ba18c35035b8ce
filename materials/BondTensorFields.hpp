#pragma once
// Per-bond tensor history of the bond-associated correspondence models: one bond field per component (StateStore
// bond fields are scalars, as Peridigm's), named base + "XX".."ZZ" (or the 6 symmetric ones, CorrespondenceFields.hpp).
// Internal to materials/*BondAssociated* and *Hypoelastic*.
#include <limits>
#include <string>
#include <vector>

#include "CorrespondenceFields.hpp"
#include "UnrotatedHooke.hpp"

namespace pf {

struct BondTensor {
  double* trial[9];
  const double* committed[9];
  int n;
  BondTensor(StateStore& s, const std::string& base, bool symmetric) : n(symmetric ? 6 : 9) {
    for (int c = 0; c < n; ++c) {
      const std::string name = base + (symmetric ? kSym[c] : kFull[c]);
      trial[c] = s.trial(name), committed[c] = s.committed(name);
    }
  }
  Mat3 committedAt(int b) const {
    double v[9];
    for (int c = 0; c < n; ++c) v[c] = committed[c][b];
    return n == 6 ? fromSym6(v) : Mat3{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]};
  }
  void set(int b, const Mat3& a) {
    double v[9];
    if (n == 6) toSym6(a, v);
    for (int c = 0; c < n; ++c) trial[c][b] = n == 6 ? v[c] : a[c];
  }
  void keep(int b) { set(b, committedAt(b)); }
};

// History bond fields of one tensor; identity: the diagonal starts at 1 (a stretch or a rotation).
inline void addBondSpecs(std::vector<StateSpec>& s, const std::string& base, bool symmetric, bool identity) {
  for (int c = 0; c < (symmetric ? 6 : 9); ++c) {
    const bool diagonal = symmetric ? c < 3 : c % 4 == 0;
    s.push_back({base + (symmetric ? kSym[c] : kFull[c]), Location::Bond, true, false, identity && diagonal ? 1.0 : 0.0});
  }
}

// The state both bond-associated models keep: the node tensors Peridigm writes, the time of the last evaluation, and
// per bond the left stretch, rotation and unrotated Cauchy stress (history: 2 x 24 doubles per bond).
inline void addBondAssociatedSpecs(std::vector<StateSpec>& s) {
  addTensorSpecs(s, "Unrotated_Cauchy_Stress", true, true, false);
  addTensorSpecs(s, "Deformation_Gradient", false, true, true);
  addTensorSpecs(s, "Rotation_Tensor", false, true, true);
  addTensorSpecs(s, "Left_Stretch_Tensor", false, true, true);
  addTensorSpecs(s, "Cauchy_Stress", true, true, false, false);
  addTensorSpecs(s, "Unrotated_Rate_Of_Deformation", true, true, false);
  s.push_back({"Von_Mises_Stress", Location::Node, false, true});
  s.push_back({"Correspondence_Time", Location::Node, true, false, std::numeric_limits<double>::quiet_NaN()});
  addBondSpecs(s, "Bond_Left_Stretch_Tensor", false, true);
  addBondSpecs(s, "Bond_Rotation_Tensor", false, true);
  addBondSpecs(s, "Bond_Unrotated_Cauchy_Stress", true, false);
}

}  // namespace pf

#pragma once
// 3x3 tensors as row-major std::array<double, 9> (A[3*i+j] = A_ij) and the few operations the
// correspondence models need. Header-only, no allocation; inverse() reports a singular matrix by a zero
// determinant instead of throwing, so callers name what failed.
#include <array>
#include <cmath>

namespace pf {

using Mat3 = std::array<double, 9>;

inline Mat3 identity3() { return {1, 0, 0, 0, 1, 0, 0, 0, 1}; }

inline Mat3 operator+(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c[k] = a[k] + b[k];
  return c;
}
inline Mat3 operator-(const Mat3& a, const Mat3& b) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c[k] = a[k] - b[k];
  return c;
}
inline Mat3 operator*(double s, const Mat3& a) {
  Mat3 c;
  for (int k = 0; k < 9; ++k) c[k] = s * a[k];
  return c;
}

inline Mat3 mul(const Mat3& a, const Mat3& b) {  // a b
  Mat3 c{};
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      for (int j = 0; j < 3; ++j) c[3 * i + j] += a[3 * i + k] * b[3 * k + j];
  return c;
}
inline Mat3 transpose(const Mat3& a) { return {a[0], a[3], a[6], a[1], a[4], a[7], a[2], a[5], a[8]}; }
inline Mat3 mulTN(const Mat3& a, const Mat3& b) { return mul(transpose(a), b); }  // a^T b
inline Mat3 mulNT(const Mat3& a, const Mat3& b) { return mul(a, transpose(b)); }  // a b^T
inline Mat3 sym(const Mat3& a) { return 0.5 * (a + transpose(a)); }
inline Mat3 skew(const Mat3& a) { return 0.5 * (a - transpose(a)); }
inline double trace(const Mat3& a) { return a[0] + a[4] + a[8]; }
inline double ddot(const Mat3& a, const Mat3& b) {
  double s = 0;
  for (int k = 0; k < 9; ++k) s += a[k] * b[k];
  return s;
}
inline double det(const Mat3& a) {
  return a[0] * (a[4] * a[8] - a[5] * a[7]) - a[1] * (a[3] * a[8] - a[5] * a[6]) + a[2] * (a[3] * a[7] - a[4] * a[6]);
}
// cof(a) = det(a) a^-T, defined for a singular a too (row-major a of 9 values).
inline Mat3 cofactor(const double* a) {
  return {a[4] * a[8] - a[5] * a[7], a[5] * a[6] - a[3] * a[8], a[3] * a[7] - a[4] * a[6],
          a[2] * a[7] - a[1] * a[8], a[0] * a[8] - a[2] * a[6], a[1] * a[6] - a[0] * a[7],
          a[1] * a[5] - a[2] * a[4], a[2] * a[3] - a[0] * a[5], a[0] * a[4] - a[1] * a[3]};
}
// inv = a^-1 and returns det(a); leaves inv unset when det(a) == 0.
inline double inverse(const Mat3& a, Mat3& inv) {
  const double d = det(a);
  if (d == 0.0) return 0.0;
  const double r = 1.0 / d;
  inv = {r * (a[4] * a[8] - a[5] * a[7]), r * (a[2] * a[7] - a[1] * a[8]), r * (a[1] * a[5] - a[2] * a[4]),
         r * (a[5] * a[6] - a[3] * a[8]), r * (a[0] * a[8] - a[2] * a[6]), r * (a[2] * a[3] - a[0] * a[5]),
         r * (a[3] * a[7] - a[4] * a[6]), r * (a[1] * a[6] - a[0] * a[7]), r * (a[0] * a[4] - a[1] * a[3])};
  return d;
}
inline Mat3 deviator(const Mat3& a) {
  Mat3 s = a;
  const double p = trace(a) / 3.0;
  s[0] -= p, s[4] -= p, s[8] -= p;
  return s;
}
// sqrt(3/2 s:s), s the deviator of a symmetric a.
inline double vonMises(const Mat3& a) {
  const Mat3 s = deviator(a);
  return std::sqrt(1.5 * ddot(s, s));
}

// Symmetric tensors as 6 values in the order XX, YY, ZZ, XY, YZ, XZ (the output components).
inline Mat3 fromSym6(const double* v) { return {v[0], v[3], v[5], v[3], v[1], v[4], v[5], v[4], v[2]}; }
inline void toSym6(const Mat3& a, double* v) {
  v[0] = a[0], v[1] = a[4], v[2] = a[8];
  v[3] = 0.5 * (a[1] + a[3]), v[4] = 0.5 * (a[5] + a[7]), v[5] = 0.5 * (a[2] + a[6]);
}

}  // namespace pf

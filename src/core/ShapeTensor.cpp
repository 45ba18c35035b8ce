#include "ShapeTensor.hpp"

namespace pf {
namespace {

// K is singular for a family without three non-coplanar bonds; in floating point it is then merely
// ill-conditioned.
const double kMinShapeQuality = 1e-8;

}  // namespace

FamilySums familySums(const FamilyView& fam, int i, const double* y, bool planar) {
  FamilySums s;
  Mat3& K = s.K;
  Mat3& N = s.N;
  const double* xi0 = fam.x + 3 * i;
  const double* yi = y + 3 * i;
  for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b) {
    const int j = fam.neighbors[b];
    const double w = bondWeight(fam, b);
    if (w == 0.0) continue;
    ++s.bonds;
    const double xi[3] = {fam.x[3 * j] - xi0[0], fam.x[3 * j + 1] - xi0[1], fam.x[3 * j + 2] - xi0[2]};
    const double Y[3] = {y[3 * j] - yi[0], y[3 * j + 1] - yi[1], y[3 * j + 2] - yi[2]};
    for (int a = 0; a < 3; ++a)
      for (int c = 0; c < 3; ++c) {
        K[3 * a + c] += w * xi[a] * xi[c];
        N[3 * a + c] += w * Y[a] * xi[c];
      }
  }
  if (planar) {
    const double d2 = K[0] * K[4] - K[1] * K[3], t2 = 0.5 * (K[0] + K[4]);
    s.quality = t2 > 0 ? d2 / (t2 * t2) : 0.0;
  } else {
    const double t3 = trace(K) / 3.0;
    s.quality = t3 > 0 ? det(K) / (t3 * t3 * t3) : 0.0;
  }
  return s;
}

bool tryShapeAndGradient(const FamilyView& fam, int i, const double* y, bool planar, ShapeAndGradient& out) {
  const FamilySums s = familySums(fam, i, y, planar);
  if (!(s.quality > kMinShapeQuality)) return false;
  const Mat3& K = s.K;
  if (planar) {  // the 2x2 in-plane block; z stays the identity
    const double d2 = K[0] * K[4] - K[1] * K[3];
    out.Kinv = {K[4] / d2, -K[1] / d2, 0, -K[3] / d2, K[0] / d2, 0, 0, 0, 0};
  } else {
    inverse(K, out.Kinv);
  }
  out.F = mul(s.N, out.Kinv);
  if (planar) out.F[2] = out.F[5] = out.F[6] = out.F[7] = 0.0, out.F[8] = 1.0;
  return true;
}

}  // namespace pf

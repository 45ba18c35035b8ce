#include "SpaceFillingCurve.hpp"

#include <algorithm>

namespace pf {

// Skilling's construction ("Programming the Hilbert curve", AIP Conf. Proc. 707, 2004): undo the curve's
// rotations and reflections from the coarsest level down, Gray-code the result, then interleave the
// axes' bits. Unlike the Morton curve the Hilbert curve never jumps between distant cells, so the
// neighbours of consecutive families share more of the cache: the hardening kernel on the 40^3 cube ran
// 8-11 % faster in Hilbert order than in Morton order (docs/benchmark-log.md, session 5).
std::uint64_t hilbertKey(std::uint32_t x, std::uint32_t y, std::uint32_t z) {
  std::uint32_t X[3] = {x, y, z};
  const std::uint32_t top = 1u << (kHilbertBits - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {
    const std::uint32_t below = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= below;  // reflect
      } else {          // exchange the low bits of axes 0 and i
        const std::uint32_t t = (X[0] ^ X[i]) & below;
        X[0] ^= t;
        X[i] ^= t;
      }
    }
  }
  for (int i = 1; i < 3; ++i) X[i] ^= X[i - 1];
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (int i = 0; i < 3; ++i) X[i] ^= t;
  std::uint64_t key = 0;
  for (int bit = kHilbertBits - 1; bit >= 0; --bit)
    for (int i = 0; i < 3; ++i) key = (key << 1) | ((X[i] >> bit) & 1u);
  return key;
}

std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& coords) {
  const std::size_t n = coords.size() / 3;
  double lo[3] = {1e300, 1e300, 1e300}, hi[3] = {-1e300, -1e300, -1e300};
  for (std::size_t p = 0; p < n; ++p)
    for (int d = 0; d < 3; ++d) {
      lo[d] = std::min(lo[d], coords[3 * p + d]);
      hi[d] = std::max(hi[d], coords[3 * p + d]);
    }
  return hilbertKeys(coords, lo, hi);
}

std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& coords, const double* lo, const double* hi) {
  const std::size_t n = coords.size() / 3;
  double scale = 0;
  for (int d = 0; d < 3; ++d) scale = std::max(scale, hi[d] - lo[d]);
  scale = scale > 0 ? static_cast<double>((1u << kHilbertBits) - 1) / scale : 0.0;
  std::vector<std::uint64_t> key(n);
  for (std::size_t p = 0; p < n; ++p) {
    std::uint32_t c[3];
    for (int d = 0; d < 3; ++d) c[d] = static_cast<std::uint32_t>((coords[3 * p + d] - lo[d]) * scale);
    key[p] = hilbertKey(c[0], c[1], c[2]);
  }
  return key;
}

}  // namespace pf

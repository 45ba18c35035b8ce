#pragma once
// Keys along a 3D Hilbert curve, used to order points so that points close in space are close in
// memory. hilbertKey maps a cell (kHilbertBits per axis) to its position on the curve; consecutive
// positions are face-adjacent cells. hilbertKeys scales a point cloud's bounding box onto the cells.
#include <cstdint>
#include <vector>

namespace pf {

constexpr int kHilbertBits = 21;  // per axis: 63-bit keys

std::uint64_t hilbertKey(std::uint32_t x, std::uint32_t y, std::uint32_t z);

// One key per point of coords (3 per point); the longest side of the bounding box spans the cells.
std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& coords);
// The same with the box [lo, hi] (3 values each) given, e.g. the whole cloud's when coords are a share.
std::vector<std::uint64_t> hilbertKeys(const std::vector<double>& coords, const double* lo, const double* hi);

}  // namespace pf

#pragma once
// Two points at the same place have a zero-length bond, which no material can take: the run would end
// in an unexplained non-convergence. Duplicates are found in O(N log N) by sorting the points into cells.
#include <string>
#include <utility>
#include <vector>

namespace pf {

struct PointCloud;

// The length below which two points count as one: 1e-9 x the grid spacing when uniform, else 1e-9 x the
// smallest nonzero point size (cube root of the volume), the cloud's smallest distance scale.
double duplicateTolerance(const PointCloud& cloud);

// {i, j} (0-based, i < j, i the smallest id that has a duplicate) of two points within tol of each other
// in every coordinate; {-1, -1} if none. Deterministic: every rank finds the same pair.
std::pair<int, int> findDuplicatePoints(const std::vector<double>& x, double tol);

// InputError "inputFile: Discretization: points i and j have the same coordinates (x, y, z)" if any.
void requireDistinctPoints(const PointCloud& cloud, const std::string& inputFile);

}  // namespace pf

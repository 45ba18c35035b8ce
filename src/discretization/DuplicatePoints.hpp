#pragma once
// Two points at the same place have a zero-length bond, which no material can take: the run would end
// in an unexplained non-convergence. Duplicates are found in O(N log N) by sorting the points into cells.
#include <string>
#include <utility>
#include <vector>

namespace pf {

// The length below which two points count as one: 1e-9 x the grid spacing when uniform (spacing > 0), else
// 1e-9 x the smallest point size (cube root of the cloud's smallest volume), its smallest distance scale.
double duplicateTolerance(double spacing, double smallestVolume);

// {i, j} (0-based, i < j, i the smallest id that has a duplicate) of two points within tol of each other
// in every coordinate; {-1, -1} if none. Deterministic: every rank finds the same pair.
std::pair<int, int> findDuplicatePoints(const std::vector<double>& x, double tol);

// "inputFile: Discretization: points i+1 and j+1 have the same coordinates (x, y, z)" (i, j 0-based).
std::string duplicateMessage(const std::string& inputFile, int i, int j, const double* x);

}  // namespace pf

#pragma once
// Parameters every OSB solid accepts: density, elastic moduli (any two), planar options, and Peridigm
// options that Periforge accepts but does not need.
#include <vector>

#include "core/Parameters.hpp"

namespace pf {

std::vector<ParameterSpec> elasticSolidParameters();

}  // namespace pf

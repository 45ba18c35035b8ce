#pragma once
// The one exception type for user mistakes (bad input, unreadable files). main() prints what() as a
// single line and exits non-zero; messages name the parameter and the input file.
#include <stdexcept>
#include <string>

namespace pf {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace pf

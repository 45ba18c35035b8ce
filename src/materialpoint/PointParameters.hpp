#pragma once
// Model parameters given as text "Name=value" (periforge-point --param): the value is read by the kind
// of the model's ParameterSpec of that name (number, true/false, text); ranges, choices and defaults are
// then checked by makeMaterial, through the same specs as a deck's Materials list.
#include <map>
#include <string>

#include "core/MaterialEntry.hpp"

namespace pf {

// Adds one "Name=value" to values (numbers, bools as 0/1) or strings; InputError (one line, naming the
// parameter) if the model declares no such parameter or the value is not of its kind.
void addParameter(const MaterialEntry& entry, const std::string& assignment, std::map<std::string, double>& values,
                  std::map<std::string, std::string>& strings);

}  // namespace pf

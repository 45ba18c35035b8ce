#pragma once
// Reading one Teuchos parameter list against declared ParameterSpecs: unknown entries, wrong types,
// missing required ones, out-of-range values and unknown choices are InputErrors "file: path: message".
// Internal to src/input (the only layer that sees Teuchos).
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/Parameters.hpp"
#include "core/ParamTree.hpp"
#include "core/Words.hpp"

namespace pf {

using PL = Teuchos::ParameterList;

[[noreturn]] void fail(const std::string& file, const std::string& path, const std::string& msg);

// Checks l against specs (sub-lists: the names allowed, checked by the caller) and returns its values
// with the specs' defaults attached (ParameterValues::get falls back to them).
ParameterValues readList(const PL& l, const std::vector<ParameterSpec>& specs, const std::vector<std::string>& sublists,
                         const std::string& file, const std::string& path);

// The same checks without the values (for lists whose values the caller reads itself).
void checkList(const PL& l, const std::vector<ParameterSpec>& specs, const std::vector<std::string>& sublists,
               const std::string& file, const std::string& path);

const PL& requireSublist(const PL& l, const std::string& name, const std::string& file, const std::string& path);

// The top-level lists named stem ("Solver", "Output"): the plain one if present, then Peridigm's numbered
// stem1, stem2, ... in increasing number.
std::vector<std::string> numberedLists(const PL& deck, const std::string& stem);
// The output lists: numberedLists(deck, "Output"), then, in the deck's order, every other top-level list whose
// name contains "Output" ("Output Data", "Output History": Peridigm takes each such list, Peridigm.cpp
// initializeOutputManager). A numbered name with a leading zero ("Output01") is neither (the deck parser says so).
std::vector<std::string> outputLists(const PL& deck);

// A copy of a list as typed values, for a library that reads it itself (NOX).
ParamTree treeOf(const PL& l, const std::string& file, const std::string& path);

// Typed access after the checks. Numbers written as int where a double is expected (YAML) are accepted.
double getNumber(const PL& l, const std::string& name);
double getNumber(const PL& l, const std::string& name, double fallback);
std::string getText(const PL& l, const std::string& name, const std::string& fallback);
// A parameter as text whatever its scalar type (YAML turns "0.0" or "7" into numbers).
std::string scalarAsText(const Teuchos::ParameterEntry& e);

std::string joinNames(const std::vector<std::string>& names);  // 'a', 'b', 'c'
std::string numberText(double v);                               // as << prints it
// Splits on commas, trimming blanks; an empty entry or an empty list is an InputError.
std::vector<std::string> commaList(const std::string& text, const std::string& param, const std::string& file,
                                   const std::string& path);

}  // namespace pf

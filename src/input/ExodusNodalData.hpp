#pragma once
// The nodal results of an Exodus II file (what Peridigm's Data Loader reads): its output times, its nodal
// variables by name, its node or element id map, and one variable's values at one step for a range of nodes.
// Every failure is an InputError through ExodusFile::fail (deck, parameter, file).
#include <string>
#include <vector>

#include "ExodusFile.hpp"

namespace pf {

std::vector<double> exodusTimes(const ExodusFile& f);                    // one per stored step, in file order
std::vector<std::string> exodusNodalVariables(const ExodusFile& f);      // in file order
// The 1-based index of the nodal variable `name`; an InputError listing the file's variables if it has none.
int exodusNodalVariableIndex(const ExodusFile& f, const std::string& name);
// The ids of the nodes (nodes = true) or elements in file order: Peridigm's reading, its auxiliary map
// "original_global_id_map" (written by SEACAS decomp/loadbal) when the file has one, else the id map; another
// auxiliary map is an InputError.
std::vector<long long> exodusIdMap(const ExodusFile& f, bool nodes);
// Variable `variable` (1-based) at step `step` (1-based) for the nodes [first, first + count) (first 1-based).
void readNodalValues(const ExodusFile& f, int step, int variable, long long first, long long count, double* out);

}  // namespace pf

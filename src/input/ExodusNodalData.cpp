#include "ExodusNodalData.hpp"

#include <exodusII.h>

namespace pf {

std::vector<double> exodusTimes(const ExodusFile& f) {
  const int steps = ex_inquire_int(f.id(), EX_INQ_TIME);
  if (steps < 0) f.fail("ex_inquire(EX_INQ_TIME) failed");
  std::vector<double> times(static_cast<std::size_t>(steps));
  if (steps > 0) f.check(ex_get_all_times(f.id(), times.data()), "ex_get_all_times");
  return times;
}

std::vector<std::string> exodusNodalVariables(const ExodusFile& f) {
  int count = 0;
  f.check(ex_get_variable_param(f.id(), EX_NODAL, &count), "ex_get_variable_param(nodal)");
  std::vector<std::string> names;
  for (int k = 1; k <= count; ++k) {
    char name[MAX_STR_LENGTH + 1] = {0};
    f.check(ex_get_variable_name(f.id(), EX_NODAL, k, name), "ex_get_variable_name(nodal)");
    names.push_back(name);
  }
  return names;
}

int exodusNodalVariableIndex(const ExodusFile& f, const std::string& name) {
  const std::vector<std::string> names = exodusNodalVariables(f);
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<int>(k) + 1;
  std::string held;
  for (const std::string& n : names) held += (held.empty() ? "'" : ", '") + n + "'";
  f.fail("it has no nodal variable '" + name + "' (it has " + (held.empty() ? std::string("none") : held) + ")");
}

std::vector<long long> exodusIdMap(const ExodusFile& f, bool nodes) {
  const long long n = nodes ? f.summary().nodes : f.summary().elements;
  const ex_entity_type type = nodes ? EX_NODE_MAP : EX_ELEM_MAP;
  const std::string what = nodes ? "node" : "element";
  std::vector<int> ids(static_cast<std::size_t>(n));
  int nodeMaps = 0, elementMaps = 0;
  f.check(ex_get_map_param(f.id(), &nodeMaps, &elementMaps), "ex_get_map_param");
  const int maps = nodes ? nodeMaps : elementMaps;
  if (maps > 1) f.fail("it has " + std::to_string(maps) + " auxiliary " + what + " maps (at most one, "
                       "'original_global_id_map', is understood)");
  if (maps == 1) {
    char name[MAX_STR_LENGTH + 1] = {0};
    f.check(ex_get_name(f.id(), type, 1, name), "ex_get_name(map)");
    if (std::string(name) != "original_global_id_map")
      f.fail("its auxiliary " + what + " map is '" + name + "' (only 'original_global_id_map' is understood)");
    if (n > 0) f.check(ex_get_num_map(f.id(), type, 1, ids.data()), "ex_get_num_map");
  } else if (n > 0) {
    f.check(ex_get_id_map(f.id(), type, ids.data()), "ex_get_id_map");
  }
  return std::vector<long long>(ids.begin(), ids.end());
}

void readNodalValues(const ExodusFile& f, int step, int variable, long long first, long long count, double* out) {
  if (count <= 0) return;
  f.check(ex_get_partial_var(f.id(), step, EX_NODAL, variable, 1, first, count, out), "ex_get_partial_var(nodal)");
}

}  // namespace pf

// Peridigm's "Data Loader" list -> DataLoaderSpec: the file and its nodal variable, checked here once (the file
// opens, holds the variable, and its output times rise and cover the run's); the node count and ids are checked
// against the points when the model is built (model/LoadedField.cpp).
#include <algorithm>

#include "ExodusFile.hpp"
#include "ExodusNodalData.hpp"
#include "Input.hpp"
#include "Sections.hpp"

namespace pf {

std::vector<ParameterSpec> dataLoaderSpecs() {
  using S = ParameterSpec;
  return {S::text("File Name", "the Exodus II file holding the field as a nodal variable, one node per point in the "
                               "points' order (Peridigm's output of the same mesh); the one serial file at any number of ranks")
              .need(),
          S::text("Field Name", "the file's nodal variable; the run holds it as a field of that name, imposed at every "
                                "evaluated time by linear interpolation between the file's two output times around it, "
                                "and Output Variables may name it")
              .need()};
}

DataLoaderSpec parseDataLoader(const PL& d, const std::string& file, const std::string& dir,
                               const std::vector<SolverSpec>& solvers) {
  const std::string path = "Data Loader";
  const ParameterValues v = readList(d, dataLoaderSpecs(), {}, file, path);
  DataLoaderSpec s;
  s.given = true;
  s.field = v.text("Field Name");
  if (s.field.empty()) fail(file, path + "/Field Name", "is empty");
  const std::vector<std::string>& known = knownOutputVariables();
  if (std::find(known.begin(), known.end(), s.field) != known.end())
    fail(file, path + "/Field Name", "'" + s.field + "' is a variable Periforge computes; the Data Loader loads a "
                                     "field of its own (a name no material or solver writes)");
  if (v.text("File Name").empty()) fail(file, path + "/File Name", "is empty");
  s.file = resolvePath(v.text("File Name"), dir);
  const ExodusFile f(s.file, file, path + "/File Name", "data file");
  const std::vector<std::string> names = exodusNodalVariables(f);
  if (std::find(names.begin(), names.end(), s.field) == names.end()) {
    std::string held;
    for (const std::string& n : names) held += (held.empty() ? "'" : ", '") + n + "'";
    fail(file, path + "/Field Name", "'" + s.field + "' is not a nodal variable of the data file '" + s.file +
                                         "' (it has " + (held.empty() ? std::string("none") : held) + ")");
  }
  const std::vector<double> times = exodusTimes(f);
  if (times.size() < 2) f.fail("it has " + std::to_string(times.size()) + " output time(s); the field is interpolated "
                               "between two (Peridigm's rule), so it needs at least two");
  for (std::size_t k = 1; k < times.size(); ++k)
    if (!(times[k] > times[k - 1]))
      f.fail("its output times do not rise: step " + std::to_string(k + 1) + " is at " + numberText(times[k]) +
             ", step " + std::to_string(k) + " at " + numberText(times[k - 1]));
  const double t0 = solvers.front().times.front(), t1 = solvers.back().times.back();
  if (t0 < times.front() || t1 > times.back())
    f.fail("its output times [" + numberText(times.front()) + ", " + numberText(times.back()) +
           "] do not cover the run's [" + numberText(t0) + ", " + numberText(t1) + "]");
  return s;
}

}  // namespace pf

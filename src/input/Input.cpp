#include "Input.hpp"

#include <fstream>

#include <Teuchos_FileInputSource.hpp>
#include <Teuchos_XMLParameterListCoreHelpers.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include "StrictXml.hpp"
#include "core/InputError.hpp"

namespace pf {

namespace {

bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Teuchos messages span many lines with source locations; keep the first meaningful line so the
// user sees one line.
std::string firstLine(const std::string& what) {
  std::string out;
  std::size_t start = 0;
  while (start < what.size()) {
    std::size_t end = what.find('\n', start);
    if (end == std::string::npos) end = what.size();
    std::string line = what.substr(start, end - start);
    start = end + 1;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    if (line.find(".cpp:") != std::string::npos || line.find(".hpp:") != std::string::npos ||
        line.find("Throw number") != std::string::npos || line.find("Throw test") != std::string::npos)
      continue;
    out = line;
    break;
  }
  return out.empty() ? std::string("parse error") : out;
}

}  // namespace

std::string inputDirectory(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  if (slash == std::string::npos) return ".";
  if (slash == 0) return "/";
  return path.substr(0, slash);
}

std::string resolvePath(const std::string& name, const std::string& inputDir) {
  if (name.empty() || name[0] == '/' || inputDir.empty() || inputDir == ".") return name;
  return inputDir + "/" + name;
}

Teuchos::RCP<Teuchos::ParameterList> readInput(const std::string& path) {
  {
    std::ifstream probe(path);
    if (!probe) throw InputError(path + ": cannot open input file");
    // (Teuchos would say "An empty XML std::string or file was specified!", or read an empty YAML deck.)
    if ((probe >> std::ws).peek() == std::ifstream::traits_type::eof())
      throw InputError(path + ": the input file is empty");
  }
  const bool yaml = endsWith(path, ".yaml") || endsWith(path, ".yml");
  try {
    if (yaml) return Teuchos::getParametersFromYamlFile(path);
    const Teuchos::XMLObject xml = Teuchos::FileInputSource(path).getObject();
    checkStrictly(xml, path);
    return Teuchos::getParametersFromXmlFile(path);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    throw InputError(path + ": cannot parse " + (yaml ? "YAML" : "XML") + " input: " + firstLine(e.what()));
  }
}

}  // namespace pf

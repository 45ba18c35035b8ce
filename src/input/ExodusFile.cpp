#include "ExodusFile.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cctype>
#include <sys/stat.h>

#include "core/InputError.hpp"

namespace pf {

ExodusFile::ExodusFile(const std::string& path, const std::string& inputFile, const std::string& parameter,
                       const std::string& kind)
    : path_(path), inputFile_(inputFile), parameter_(parameter), kind_(kind) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) fail("cannot open the file");
  ex_opts(0);  // errors come back as return codes and become one InputError; the library prints nothing
  int cpuWordSize = sizeof(double), ioWordSize = 0;
  float version = 0.0f;
  exoid_ = ex_open(path.c_str(), EX_READ, &cpuWordSize, &ioWordSize, &version);
  if (exoid_ < 0) fail("not an Exodus II file (ex_open failed)");
  char title[MAX_LINE_LENGTH + 1] = {0};
  int dim = 0, nodes = 0, elements = 0, blocks = 0, nodeSets = 0, sideSets = 0;
  check(ex_get_init(exoid_, title, &dim, &nodes, &elements, &blocks, &nodeSets, &sideSets), "ex_get_init");
  summary_.dimension = dim;
  summary_.nodes = nodes;
  summary_.elements = elements;
  std::vector<int> ids(static_cast<std::size_t>(blocks));
  if (!ids.empty()) check(ex_get_ids(exoid_, EX_ELEM_BLOCK, ids.data()), "ex_get_ids(element blocks)");
  long long first = 0;
  for (int id : ids) {
    char type[MAX_STR_LENGTH + 1] = {0};
    int n = 0, perElement = 0, edges = 0, faces = 0, attributes = 0;
    check(ex_get_block(exoid_, EX_ELEM_BLOCK, id, type, &n, &perElement, &edges, &faces, &attributes), "ex_get_block");
    ExodusBlock b;
    b.id = id;
    b.type = type;
    std::transform(b.type.begin(), b.type.end(), b.type.begin(), [](unsigned char c) { return std::toupper(c); });
    b.elements = n, b.nodesPerElement = perElement, b.attributes = attributes, b.first = first;
    first += n;
    summary_.blocks.push_back(b);
  }
  if (first != summary_.elements) fail("its element blocks hold " + std::to_string(first) + " elements, its header " +
                                       std::to_string(summary_.elements));
  std::vector<int> setIds(static_cast<std::size_t>(nodeSets));
  if (!setIds.empty()) check(ex_get_ids(exoid_, EX_NODE_SET, setIds.data()), "ex_get_ids(node sets)");
  for (int id : setIds) {
    ExodusNodeSet s;
    s.id = id;
    char name[MAX_STR_LENGTH + 1] = {0};
    check(ex_get_name(exoid_, EX_NODE_SET, id, name), "ex_get_name(node set)");
    s.name = name[0] ? std::string(name) : "nodelist_" + std::to_string(id);  // Peridigm's name for an unnamed set
    int count = 0, factors = 0;
    check(ex_get_set_param(exoid_, EX_NODE_SET, id, &count, &factors), "ex_get_set_param(node set)");
    s.nodes = count;
    for (const ExodusNodeSet& o : summary_.nodeSets)
      if (o.name == s.name) fail("two node sets are named '" + s.name + "'");
    summary_.nodeSets.push_back(s);
  }
}

ExodusFile::~ExodusFile() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void ExodusFile::check(int status, const char* call) const {
  if (status < 0) fail(std::string(call) + " failed (status " + std::to_string(status) + ")");
}

void ExodusFile::fail(const std::string& msg) const {
  throw InputError(inputFile_ + ": " + parameter_ + ": " + kind_ + " '" + path_ + "': " + msg);
}

}  // namespace pf

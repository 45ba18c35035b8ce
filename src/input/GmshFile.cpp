#include "GmshFile.hpp"

#include <algorithm>
#include <map>
#include <sstream>
#include <sys/stat.h>

#include "core/InputError.hpp"

namespace pf {

namespace {

// Gmsh's element types (its manual, "MSH file format": node ordering), corners first as Exodus numbers them.
const GmshElementType kTypes[] = {
    {1, 1, 2, ""},          {2, 2, 3, "TRI3"},     {3, 2, 4, "QUAD4"},     {4, 3, 4, "TETRA4"},
    {5, 3, 8, "HEX8"},      {6, 3, 6, "WEDGE6"},   {7, 3, 5, "PYRAMID5"},  {8, 1, 3, ""},
    {9, 2, 6, "TRI6"},      {10, 2, 9, "QUAD9"},   {11, 3, 10, "TETRA10"}, {12, 3, 27, "HEX27"},
    {13, 3, 18, "WEDGE"},   {14, 3, 14, "PYRAMID"}, {15, 0, 1, ""},        {16, 2, 8, "QUAD8"},
    {17, 3, 20, "HEX20"},   {18, 3, 15, "WEDGE15"}, {19, 3, 13, "PYRAMID13"}, {20, 2, 9, "TRI"},
    {21, 2, 10, "TRI"},     {22, 2, 12, "TRI"},    {23, 2, 15, "TRI"},     {24, 2, 15, "TRI"},
    {25, 2, 21, "TRI"},     {26, 1, 4, ""},        {27, 1, 5, ""},         {28, 1, 6, ""},
    {29, 3, 20, "TETRA"},   {30, 3, 35, "TETRA"},  {31, 3, 56, "TETRA"},   {36, 2, 16, "QUAD"},
    {37, 2, 25, "QUAD"},    {92, 3, 64, "HEX"},    {93, 3, 125, "HEX"}};

constexpr long long kChunk = 1 << 16;  // nodes per read in forEachNode: bounds its buffers whatever the mesh
using Entity = std::pair<int, int>;    // (dimension, tag)

}  // namespace

const GmshElementType* gmshElementType(int type) {
  for (const GmshElementType& t : kTypes)
    if (t.type == type) return &t;
  return nullptr;
}

struct GmshFile::Scan {
  std::map<Entity, std::string> names;           // physical group -> name
  std::map<Entity, std::vector<int>> physicals;  // entity -> its physical groups' tags
  long long nodeBlocks = -1;                     // -1: no $Nodes yet
  bool format = false;
};

GmshFile::GmshFile(const std::string& path, const std::string& inputFile, const std::string& parameter)
    : path_(path), inputFile_(inputFile), parameter_(parameter), scan_(std::make_unique<Scan>()) {
  struct stat st;
  if (stat(path.c_str(), &st) != 0) fail("cannot open the file");
  in_ = std::make_unique<MshStream>(path, [this](const std::string& m) { fail(m); });
  if (!in_->opened()) fail("cannot open the file");
  for (std::string m = in_->nextMarker(); !m.empty(); m = in_->nextMarker()) {
    if (!scan_->format && m != "$MeshFormat") fail("not a Gmsh MSH file (it does not start with $MeshFormat)");
    if (m == "$MeshFormat") readFormat();
    else if (m == "$PhysicalNames") readPhysicalNames();
    else if (m == "$Entities") readEntities();
    else if (m == "$PartitionedEntities")
      fail("it is a partitioned mesh: save it whole (Mesh.PartitionSplitMeshFiles = 0, no partitioned entities)");
    else if (m == "$Nodes") scanNodes();
    else if (m == "$Elements") scanElements();
    else if (m.compare(0, 4, "$End") != 0)  // another section ($Periodic, $NodeData, ...): not needed
      for (std::string e = in_->nextMarker(); !e.empty() && e != "$End" + m.substr(1); e = in_->nextMarker()) {}
  }
  if (!scan_->format) fail("not a Gmsh MSH file (no $MeshFormat)");
  if (scan_->nodeBlocks < 0) fail("it has no $Nodes section");
  summarize();
}

GmshFile::~GmshFile() = default;

void GmshFile::fail(const std::string& msg) const {
  throw InputError(inputFile_ + ": " + parameter_ + ": mesh file '" + path_ + "': " + msg);
}

void GmshFile::readFormat() {
  std::istringstream header(in_->line());
  std::string version;
  int fileType = -1, dataSize = 0;
  header >> version >> fileType >> dataSize;
  if (version != "4.1")
    fail("MSH version " + (version.empty() ? std::string("?") : version) + ", Periforge reads MSH 4.1 (gmsh -format "
         "msh41, or Mesh.MshFileVersion = 4.1 in the .geo)");
  if (fileType != 0 && fileType != 1) fail("$MeshFormat file-type " + std::to_string(fileType) + " (0 ASCII, 1 binary)");
  if (dataSize != 8) fail("$MeshFormat data-size " + std::to_string(dataSize) + ", Periforge reads 8 (size_t, double)");
  in_->setBinary(fileType == 1);
  if (fileType == 1) {
    if (in_->integer() != 1) fail("binary mesh written with the other byte order (save it as ASCII: -format msh41 "
                                  "without -bin)");
    in_->line();
  }
  scan_->format = true;
}

// Always text, also in a binary file: "dim tag "name"" lines.
void GmshFile::readPhysicalNames() {
  const bool binary = in_->binary();
  in_->setBinary(false);
  const long long n = in_->size();
  in_->line();
  for (long long k = 0; k < n; ++k) {
    const std::string l = in_->line();
    std::istringstream s(l);
    int dim = 0, tag = 0;
    const std::size_t open = l.find('"'), close = l.rfind('"');
    if (!(s >> dim >> tag) || open == std::string::npos || close <= open)
      fail("$PhysicalNames: expected 'dimension tag \"name\"', got '" + l + "'");
    scan_->names[{dim, tag}] = l.substr(open + 1, close - open - 1);
  }
  in_->setBinary(binary);
}

void GmshFile::readEntities() {
  long long counts[4];
  for (long long& c : counts) c = in_->size();
  for (int dim = 0; dim < 4; ++dim)
    for (long long k = 0; k < counts[dim]; ++k) {
      const int tag = in_->integer();
      for (int c = 0; c < (dim == 0 ? 3 : 6); ++c) in_->real();  // a point's coordinates, else a bounding box
      std::vector<int>& physicals = scan_->physicals[{dim, tag}];
      for (long long p = in_->size(); p > 0; --p) physicals.push_back(std::abs(in_->integer()));
      if (dim > 0)
        for (long long b = in_->size(); b > 0; --b) in_->integer();  // bounding entities
    }
}

void GmshFile::scanNodes() {
  scan_->nodeBlocks = in_->size();
  summary_.nodes = in_->size();
  summary_.minNodeTag = in_->size();
  summary_.maxNodeTag = in_->size();
  summary_.nodesPosition = in_->tell();
  for (long long b = 0; b < scan_->nodeBlocks; ++b) {
    const int dim = in_->integer();
    in_->integer();
    const int parametric = in_->integer();
    const long long n = in_->size();
    in_->skip(2 * n, n * 8 * (4 + (parametric ? dim : 0)));
  }
}

void GmshFile::scanElements() {
  const long long blocks = in_->size();
  in_->size(), in_->size(), in_->size();  // element count, smallest and largest tag
  for (long long k = 0; k < blocks; ++k) {
    GmshElementBlock b;
    b.dim = in_->integer();
    b.entity = in_->integer();
    b.type = in_->integer();
    b.elements = in_->size();
    b.position = in_->tell();
    const GmshElementType* t = gmshElementType(b.type);
    if (!t)
      fail("element type " + std::to_string(b.type) + " (entity of dimension " + std::to_string(b.dim) + ", tag " +
           std::to_string(b.entity) + ") is not one Periforge reads (points, lines, triangles, quadrangles, "
           "tetrahedra, hexahedra, prisms, pyramids of Gmsh's types 1-31, 36, 37, 92, 93)");
    if (t->dim != b.dim)
      fail("element type " + std::to_string(b.type) + " is of dimension " + std::to_string(t->dim) +
           ", its entity of dimension " + std::to_string(b.dim));
    b.nodesPerElement = t->nodes;
    b.exodusType = t->exodus;
    in_->skip(b.elements, b.elements * 8 * (1 + t->nodes));
    summary_.blocks.push_back(b);
  }
}

}  // namespace pf

namespace pf {

namespace {

std::string entityText(int dim, int tag) {
  static const char* kinds[] = {"point", "curve", "surface", "volume"};
  return std::string(kinds[std::clamp(dim, 0, 3)]) + " " + std::to_string(tag);
}

}  // namespace

// Peridigm's element rule on Gmsh's physical groups (the header's comment): the blocks of the top dimension, the
// node sets of the lower ones.
void GmshFile::summarize() {
  GmshSummary& s = summary_;
  for (const GmshElementBlock& b : s.blocks)
    if (b.elements > 0) s.dimension = std::max(s.dimension, b.dim);
  if (s.dimension < 2) fail("it holds no 2D or 3D elements");
  bool grouped = false;
  for (const auto& [entity, physicals] : scan_->physicals) grouped |= entity.first == s.dimension && !physicals.empty();
  auto physicalsOf = [&](const GmshElementBlock& b) {
    const auto it = scan_->physicals.find({b.dim, b.entity});
    return it == scan_->physicals.end() ? std::vector<int>{} : it->second;
  };
  for (GmshElementBlock& b : s.blocks) {
    const std::vector<int> physicals = physicalsOf(b);
    if (b.dim == s.dimension) {
      if (grouped && physicals.size() != 1)
        fail("the elements of " + entityText(b.dim, b.entity) + " belong to " + std::to_string(physicals.size()) +
             " physical groups of dimension " + std::to_string(b.dim) + ": each element needs one block (put the "
             "entity in one Physical " + (b.dim == 3 ? "Volume" : "Surface") + ")");
      b.block = grouped ? physicals[0] : b.entity;
      if (b.block < 1 || b.block >= 1000000000)
        fail(entityText(b.dim, b.entity) + ": block id " + std::to_string(b.block) + " is not in 1..999999999");
      b.first = s.elements;
      s.elements += b.elements;
      continue;
    }
    for (int tag : physicals) {
      auto same = [&](const GmshNodeSet& n) { return n.dim == b.dim && n.tag == tag; };
      auto it = std::find_if(s.nodeSets.begin(), s.nodeSets.end(), same);
      if (it == s.nodeSets.end()) {
        const auto name = scan_->names.find({b.dim, tag});
        s.nodeSets.push_back({b.dim, tag, name != scan_->names.end() ? name->second : "nodelist_" + std::to_string(tag)});
        it = s.nodeSets.end() - 1;
      }
      b.nodeSets.push_back(static_cast<int>(it - s.nodeSets.begin()));
    }
  }
  for (std::size_t i = 0; i < s.nodeSets.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (s.nodeSets[i].name == s.nodeSets[j].name)
        fail("two physical groups give the node set name '" + s.nodeSets[i].name + "' (dimensions " +
             std::to_string(s.nodeSets[j].dim) + " and " + std::to_string(s.nodeSets[i].dim) + "): name them apart");
  for (const auto& [group, name] : scan_->names)
    if (group.first == s.dimension) s.blockNames.push_back({name, group.second});
}

void GmshFile::forEachNode(const std::function<void(long long tag, const double* xyz)>& use) const {
  in_->seek(summary_.nodesPosition);
  std::vector<long long> tags;
  std::vector<double> xyz;
  for (long long b = 0; b < scan_->nodeBlocks; ++b) {
    const int dim = in_->integer();
    in_->integer();
    const int extra = in_->integer() ? dim : 0;  // parametric coordinates after x, y, z
    const long long n = in_->size();
    long long tagAt = in_->tell();
    in_->skip(n, n * 8);                         // to the block's coordinates
    long long xyzAt = in_->tell();
    for (long long done = 0; done < n; done += kChunk) {
      const long long count = std::min(kChunk, n - done);
      in_->seek(tagAt);
      tags.resize(static_cast<std::size_t>(count));
      for (long long& t : tags) t = in_->size();
      tagAt = in_->tell();
      in_->seek(xyzAt);
      xyz.resize(3 * static_cast<std::size_t>(count));
      for (long long k = 0; k < count; ++k) {
        for (int a = 0; a < 3; ++a) xyz[3 * k + a] = in_->real();
        for (int a = 0; a < extra; ++a) in_->real();
      }
      xyzAt = in_->tell();
      for (long long k = 0; k < count; ++k) use(tags[k], &xyz[3 * k]);
    }
    in_->seek(xyzAt);
  }
}

void GmshFile::forEachElement(const GmshElementBlock& b, long long skip, long long count,
                              const std::function<void(long long tag, const long long* nodes)>& use) const {
  in_->seek(b.position);
  in_->skip(skip, skip * 8 * (1 + b.nodesPerElement));
  std::vector<long long> nodes(static_cast<std::size_t>(b.nodesPerElement));
  for (long long k = 0; k < count; ++k) {
    const long long tag = in_->size();
    for (long long& n : nodes) n = in_->size();
    use(tag, nodes.data());
  }
}

}  // namespace pf

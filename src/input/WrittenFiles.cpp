// The files a run writes, checked against each other and against the files it reads, once the deck is
// parsed: a checkpoint named like an output's part, lock or status file, or like the deck itself, would
// overwrite or delete it in the middle of the run (issue 40).
#include <filesystem>
#include <map>

#include "Sections.hpp"

namespace pf {
namespace {

namespace fs = std::filesystem;

// The path as the file system sees it (relative names against the working directory, "./a" = "a",
// symbolic links of existing parents resolved), so that two spellings of one file compare equal.
// An empty path stays "" (the readers name it later); nothing here throws.
std::string identity(const std::string& path) {
  if (path.empty()) return "";
  std::error_code ec;
  const fs::path absolute = fs::absolute(path, ec);
  if (ec) return fs::path(path).lexically_normal().string();
  const fs::path canonical = fs::weakly_canonical(absolute, ec);
  return ec ? absolute.lexically_normal().string() : canonical.string();
}

// A base name to which suffixes are appended must end in a file name: "", "/", "./", "dir/" or "." would
// write hidden files (".csv") or files into a directory the user did not name as a file.
void requireFileBase(const std::string& base, const std::string& file, const std::string& where,
                     const std::string& parameter) {
  const std::string name = fs::path(base).filename().string();
  if (name.empty() || name == "." || name == "..")
    fail(file, where, "'" + parameter + "' = '" + base + "' names a directory, not a file: give a base name such as 'out'");
  std::error_code ec;
  if (fs::is_directory(base, ec))
    fail(file, where, "'" + parameter + "' = '" + base + "' is an existing directory: give a file's base name");
}

}  // namespace

void checkWrittenFiles(const Deck& deck) {
  // identity -> what it is, for the message: "the deck", "Output/Output Filename's .e.part", ...
  std::map<std::string, std::string> taken;
  auto claim = [&](const std::string& path, const std::string& what, const std::string& where,
                   const std::string& parameter) {
    const auto [it, added] = taken.emplace(identity(path), what);
    if (!added)
      fail(deck.file, where, "'" + parameter + "' makes the run write '" + path + "', which is " + it->second +
                                 ": choose another name");
  };
  auto read = [&](const std::string& path, const std::string& what) {
    if (!path.empty()) taken.emplace(identity(path), what);
  };
  read(deck.file, "the input deck");
  read(deck.discretization.meshFile, "the mesh file");
  if (deck.dataLoader.given) read(deck.dataLoader.file, "the Data Loader's file");
  for (const NodeSetSpec& s : deck.nodeSets)
    if (s.kind == NodeSetSpec::Kind::File) read(s.text, "node set '" + s.name + "''s file");
  if (deck.discretization.constructInterfaces)  // Peridigm's fixed name, in the working directory
    claim("Interfaces.e", "Construct Interfaces' file", "Discretization", "Construct Interfaces");
  for (const OutputSpec& o : deck.outputs) {
    requireFileBase(o.filename, deck.file, o.listName, "Output Filename");
    std::vector<std::string> suffixes = {".csv", ".csv.part", ".lock", ".status"};
    if (o.exodus) suffixes.insert(suffixes.end(), {".e", ".e.part"});
    for (const std::string& s : suffixes)
      claim(o.filename + s, o.listName + "'s '" + o.filename + s + "'", o.listName, "Output Filename");
  }
  // A base name equal to another file of the run (Output2 = 'out.e' beside Output 'out', or the deck) gives
  // files that read as variants of that one's ('out.e.csv', 'deck.xml.e'): refused as well.
  for (const OutputSpec& o : deck.outputs) {
    const auto it = taken.find(identity(o.filename));
    if (it != taken.end())
      fail(deck.file, o.listName, "'Output Filename' = '" + o.filename + "' is the name of " + it->second +
                                      ": its files would read as variants of that one; choose another name");
  }
  if (deck.restart.given) {
    const std::string& c = deck.restart.checkpointFile;
    requireFileBase(c, deck.file, "Restart", "Checkpoint Filename");
    claim(c, "the checkpoint", "Restart", "Checkpoint Filename");
    claim(c + ".tmp", "the checkpoint's temporary file '" + c + ".tmp'", "Restart", "Checkpoint Filename");
  }
}

}  // namespace pf

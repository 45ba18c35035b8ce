#pragma once
// Reads the values of a Gmsh MSH 4.1 file, ASCII or binary alike: in ASCII each value is a whitespace-separated
// token, in binary an int is 4 bytes, a size_t 8 and a double 8, in the machine's byte order (the file's header
// says which it was written in; GmshFile refuses the other). Section markers ("$Nodes") are lines in both.
// A read past the end or of a malformed token calls fail(message).
#include <fstream>
#include <functional>
#include <string>

namespace pf {

class MshStream {
 public:
  MshStream(const std::string& path, std::function<void(const std::string&)> fail);
  bool opened() const { return static_cast<bool>(in_); }
  void setBinary(bool binary) { binary_ = binary; }
  bool binary() const { return binary_; }

  int integer();        // an int (entity tags, dimensions, element types, physical tags)
  long long size();     // a size_t (counts, node and element tags)
  double real();        // a double
  std::string line();   // the rest of the current line (a text line: a section marker, a physical name)
  // The next line that starts with '$' (a section marker), or "" at the end of the file.
  std::string nextMarker();
  // Skips what an ASCII section holds in `lines` lines (node and element records), or `bytes` in binary.
  void skip(long long lines, long long bytes);

  long long tell();
  void seek(long long position);

 private:
  template <class T>
  T text(const char* what);
  template <class T>
  T raw();
  std::ifstream in_;
  std::function<void(const std::string&)> fail_;
  bool binary_ = false;
};

}  // namespace pf

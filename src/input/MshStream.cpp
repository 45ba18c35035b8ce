#include "MshStream.hpp"

#include <cstdint>
#include <limits>

namespace pf {

MshStream::MshStream(const std::string& path, std::function<void(const std::string&)> fail)
    : in_(path, std::ios::binary), fail_(std::move(fail)) {}

template <class T>
T MshStream::text(const char* what) {
  T v{};
  if (in_ >> v) return v;
  if (in_.eof()) fail_(std::string("the file ends where ") + what + " was expected");
  in_.clear();
  fail_(std::string("expected ") + what + " at byte " + std::to_string(tell()));
  return v;
}

template <class T>
T MshStream::raw() {
  T v{};
  if (!in_.read(reinterpret_cast<char*>(&v), sizeof v)) fail_("the binary data ends early");
  return v;
}

int MshStream::integer() { return binary_ ? raw<std::int32_t>() : text<int>("an integer"); }

long long MshStream::size() {
  const long long v = binary_ ? static_cast<long long>(raw<std::uint64_t>()) : text<long long>("a count or tag");
  if (v < 0) fail_("a count or tag is negative (" + std::to_string(v) + ")");
  return v;
}

double MshStream::real() { return binary_ ? raw<double>() : text<double>("a number"); }

std::string MshStream::line() {
  std::string s;
  std::getline(in_, s);
  if (!s.empty() && s.back() == '\r') s.pop_back();
  return s;
}

std::string MshStream::nextMarker() {
  std::string s;
  while (std::getline(in_, s)) {
    if (!s.empty() && s.back() == '\r') s.pop_back();
    if (!s.empty() && s[0] == '$') return s;
  }
  return "";
}

void MshStream::skip(long long lines, long long bytes) {
  if (binary_) {
    in_.seekg(bytes, std::ios::cur);
    return;
  }
  in_.ignore(std::numeric_limits<std::streamsize>::max(), '\n');  // the end of the header line before the records
  for (long long k = 0; k < lines; ++k) in_.ignore(std::numeric_limits<std::streamsize>::max(), '\n');
}

long long MshStream::tell() { return static_cast<long long>(in_.tellg()); }

void MshStream::seek(long long position) {
  in_.clear();
  in_.seekg(position);
}

}  // namespace pf

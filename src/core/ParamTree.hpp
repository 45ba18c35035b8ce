#pragma once
// A nested list of typed values kept as the deck gave them, for options a third-party library reads
// itself (NOX's "Direction", "Line Search", ...): the input layer copies them, an adapter hands them on.
#include <memory>
#include <string>
#include <vector>

namespace pf {

struct ParamTree {
  struct Entry {
    enum class Kind { Double, Int, Bool, String, List };
    std::string name;
    Kind kind = Kind::String;
    double number = 0.0;
    int integer = 0;
    bool flag = false;
    std::string text;
    std::shared_ptr<ParamTree> list;  // Kind::List
  };
  std::vector<Entry> entries;  // in deck order

  bool empty() const { return entries.empty(); }
  const Entry* find(const std::string& name) const {
    for (const Entry& e : entries)
      if (e.name == name) return &e;
    return nullptr;
  }
};

}  // namespace pf

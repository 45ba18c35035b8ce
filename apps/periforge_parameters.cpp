// periforge-parameters [KEY] — prints the parameter tables of the input deck (docs/input.md's tables are
// generated from it by scripts/generate_input_docs). Without KEY: every table, each after a line
// "## KEY: title"; --keys: the keys only.
#include <cstdio>
#include <cstring>
#include <string>

#include "input/ParameterTables.hpp"

int main(int argc, char** argv) {
  const bool keysOnly = argc == 2 && std::strcmp(argv[1], "--keys") == 0;
  if (argc > 2 || (argc == 2 && (std::strcmp(argv[1], "--help") == 0 || std::strcmp(argv[1], "-h") == 0))) {
    std::fprintf(argc > 2 ? stderr : stdout, "usage: periforge-parameters [--keys | KEY]\n");
    return argc > 2 ? 2 : 0;
  }
  bool found = false;
  for (const pf::ParameterTable& t : pf::parameterTables()) {
    if (keysOnly) {
      std::printf("%s\n", t.key.c_str());
      continue;
    }
    if (argc == 2 && t.key != argv[1]) continue;
    found = true;
    if (argc == 1) std::printf("## %s: %s\n\n", t.key.c_str(), t.title.c_str());
    std::printf("%s%s", pf::markdownTable(t.parameters).c_str(), argc == 1 ? "\n" : "");
  }
  if (argc == 2 && !keysOnly && !found) {
    std::fprintf(stderr, "periforge-parameters: no table '%s' (see --keys)\n", argv[1]);
    return 2;
  }
  return 0;
}

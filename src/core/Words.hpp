#pragma once
// Splitting the deck's word lists ("block_1 block_2", "Left, Right", node ids) the one way every layer
// reads them: on blanks and commas, empty words dropped.
#include <string>
#include <vector>

namespace pf {

std::vector<std::string> splitWords(const std::string& s);

}  // namespace pf

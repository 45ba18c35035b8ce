#pragma once
// Splitting the deck's word lists ("block_1 block_2", "Left, Right", node ids) the one way every layer
// reads them: on blanks and commas, empty words dropped.
#include <string>
#include <vector>

namespace pf {

std::vector<std::string> splitWords(const std::string& s);

// Text from a deck or a file as it can be printed in one line: bytes that are not printable text (control
// characters, a NUL from "&#0;", bytes that are not UTF-8) shown as \xNN, so that an error message is neither
// cut short at a NUL nor garbled on the terminal. Tabs and line breaks are kept (an expression may span lines).
std::string printable(const std::string& s);

// Text for a one-line message: line breaks as blanks, trailing blanks dropped.
std::string oneLine(std::string s);

}  // namespace pf

#pragma once
// What Teuchos' XML reader lets through: "0.003abc" read as 0.003, an int "2.5" read as 2, "inf" as a
// number, a sub-list given twice (merged). checkStrictly() rejects each of these with one line naming the
// file, the parameter path and the text, before the deck is converted. A parameter given twice is read as
// Teuchos reads it (the last wins), with a warning naming it.
#include <string>

#include <Teuchos_XMLObject.hpp>

namespace pf {

void checkStrictly(const Teuchos::XMLObject& deck, const std::string& file);

}  // namespace pf

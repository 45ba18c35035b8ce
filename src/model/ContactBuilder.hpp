#pragma once
// Builds the deck's contact (input/Deck.hpp ContactSpec) as a force term of the model (model/ContactForce.hpp):
// resolves the interactions' block names against the cloud's blocks. InputError naming the interaction for a
// block the discretization does not have, or two interactions giving one block pair different models.
#include <map>
#include <string>

#include "input/Deck.hpp"
#include "model/Model.hpp"

namespace pf {

// horizonOf: every block id of the cloud (on every rank) -> its horizon. No-op without a Contact list.
void addContact(const Deck& deck, const std::map<int, double>& horizonOf, Model& model);

}  // namespace pf

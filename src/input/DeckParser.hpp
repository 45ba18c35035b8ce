#pragma once
// Parses and validates a deck already read into a Teuchos list (readDeck() reads the file first). Tests
// use it with decks written as strings; file names the deck in messages, directory resolves its files.
#include <string>

#include <Teuchos_ParameterList.hpp>

#include "Deck.hpp"

namespace pf {

Deck parseDeck(const Teuchos::ParameterList& deck, const std::string& file, const std::string& directory = ".");

}  // namespace pf

#include "ContactBuilder.hpp"

#include <algorithm>
#include <cstdlib>
#include <memory>

#include "core/InputError.hpp"
#include "model/ContactForce.hpp"

namespace pf {

namespace {

int blockIdOf(const std::string& name) {
  const std::size_t at = name.find_last_of('_');
  return at == std::string::npos ? 0 : std::atoi(name.c_str() + at + 1);
}

// (block, block) -> law. Only Listed Interactions: General Contact every pair of two blocks, Self Contact every block
// with itself, a named pair its two blocks (overriding General or Self for them). Otherwise Peridigm's: every pair,
// itself included, by the first model (the interactions are resolved all the same, so a bad one is still an error).
std::map<std::pair<int, int>, int> interactingPairs(const Deck& deck, const std::map<int, double>& horizonOf) {
  std::map<std::pair<int, int>, int> every, named;
  std::map<std::pair<int, int>, std::string> namedBy;
  for (const ContactInteractionSpec& c : deck.contact.interactions) {
    const std::string where = deck.file + ": Contact/Interactions/" + c.name;
    if (c.kind != ContactInteractionSpec::Kind::Pair) {
      for (const auto& a : horizonOf)
        for (const auto& b : horizonOf)
          if (a.first <= b.first && (a.first == b.first) == (c.kind == ContactInteractionSpec::Kind::Self))
            every[{a.first, b.first}] = c.model;
      continue;
    }
    int ids[2];
    for (int k = 0; k < 2; ++k) {
      const std::string& name = k == 0 ? c.firstBlock : c.secondBlock;
      ids[k] = blockIdOf(name);
      if (!horizonOf.count(ids[k])) throw InputError(where + ": '" + name + "' is not a block of the discretization");
    }
    const std::pair<int, int> key{std::min(ids[0], ids[1]), std::max(ids[0], ids[1])};
    if (named.count(key) && named[key] != c.model)
      throw InputError(where + ": its blocks also interact by '" + namedBy[key] + "' with another contact model");
    named[key] = c.model;
    namedBy[key] = c.name;
  }
  for (const auto& kv : named) every[kv.first] = kv.second;
  if (deck.contact.onlyListedInteractions) return every;
  std::map<std::pair<int, int>, int> all;  // Peridigm's: every pair, itself included, by the first model
  for (const auto& a : horizonOf)
    for (const auto& b : horizonOf)
      if (a.first <= b.first) all[{a.first, b.first}] = 0;
  return all;
}

}  // namespace

void addContact(const Deck& deck, const std::map<int, double>& horizonOf, Model& model) {
  if (!deck.contact.given) return;
  ContactSetup setup;
  setup.searchRadius = deck.contact.searchRadius;
  setup.searchFrequency = deck.contact.searchFrequency;
  for (const ContactModelSpec& m : deck.contact.models)
    setup.laws.push_back(ContactLaw{{m.contactRadius, m.springConstant}, m.friction, m.frictionOfTime});
  setup.lawOf = interactingPairs(deck, horizonOf);
  setup.horizonOf = horizonOf;
  std::vector<int> block(model.numOwned());
  for (const BlockModel& b : model.blocks())
    for (int i = b.begin; i < b.end; ++i) block[i] = b.blockId;
  model.addForceTerm(std::make_unique<ContactForce>(model.layout(), model.volume(), std::move(block), std::move(setup)));
}

}  // namespace pf

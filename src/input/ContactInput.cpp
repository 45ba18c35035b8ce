// The "Contact" list -> ContactSpec, with Peridigm's names: Search Radius, Search Frequency, Models (Short Range
// Force, Time Dependent Short Range Force) and Interactions (block pairs, General Contact, Self Contact).
#include <algorithm>
#include <cstdlib>

#include "Sections.hpp"

namespace pf {

namespace {

using S = ParameterSpec;

const std::vector<std::string> kModels = {"Short Range Force", "Time Dependent Short Range Force"};

ContactModelSpec parseContactModel(const PL& m, const std::string& name, const std::string& file, const std::string& path) {
  if (m.isParameter("Horizon"))  // Peridigm refuses it too: each end of a pair takes its own block's horizon
    fail(file, path, "'Horizon' is not a contact model parameter: each point's block horizon is used");
  const ParameterValues v = readList(m, contactModelSpecs(), {}, file, path);
  ContactModelSpec c;
  c.name = name;
  c.contactRadius = v.get("Contact Radius");
  c.springConstant = v.get("Spring Constant");
  const std::string law = v.text("Contact Model");
  if (law == "Short Range Force") {
    const std::string mu = v.has("Friction Coefficient") ? v.text("Friction Coefficient") : "0";
    char* end = nullptr;
    c.friction = std::strtod(mu.c_str(), &end);
    if (end == mu.c_str() || *end != '\0' || !(c.friction >= 0.0))
      fail(file, path, "'Friction Coefficient' = '" + mu + "' must be a number >= 0 (a function of t needs 'Contact "
                       "Model' = 'Time Dependent Short Range Force')");
  } else {
    if (!v.has("Friction Coefficient"))
      fail(file, path, "missing required parameter 'Friction Coefficient' (a function of t) for '" + law + "'");
    c.frictionOfTime = std::make_shared<const Expression>(v.text("Friction Coefficient"),
                                                          file + ": " + path + "/Friction Coefficient");
  }
  return c;
}

int modelIndex(const ContactSpec& spec, const ParameterValues& v, const std::string& file, const std::string& path) {
  const std::string name = v.text("Contact Model");
  for (std::size_t k = 0; k < spec.models.size(); ++k)
    if (spec.models[k].name == name) return static_cast<int>(k);
  std::vector<std::string> known;
  for (const ContactModelSpec& m : spec.models) known.push_back(m.name);
  fail(file, path, "'Contact Model' = '" + name + "' is not a list of Contact/Models (known: " + joinNames(known) + ")");
}

// A named block must belong to a group of Blocks (unless a default group takes the blocks no group names: then the
// discretization decides, model/ContactBuilder.cpp).
void requireBlock(const std::string& b, const std::vector<BlockGroupSpec>& blocks, const std::string& file,
                  const std::string& path) {
  const int id = blockNumber(b);
  if (id <= 0) fail(file, path, "'" + b + "' is not a block name (block_<n>)");
  for (const BlockGroupSpec& g : blocks)
    if (g.isDefault || std::find(g.blockIds.begin(), g.blockIds.end(), id) != g.blockIds.end()) return;
  fail(file, path, "'" + b + "' is not a block of any Blocks group");
}

void parseInteractions(const PL& list, ContactSpec& spec, const std::vector<BlockGroupSpec>& blocks,
                       const std::string& file) {
  for (auto it = list.begin(); it != list.end(); ++it) {
    const std::string& n = list.name(it);
    const std::string path = "Contact/Interactions/" + n;
    if (!list.entry(it).isList()) fail(file, "Contact/Interactions", "'" + n + "' must be a sub-list (an interaction)");
    ContactInteractionSpec c;
    c.name = n;
    const bool every = n == "General Contact" || n == "Self Contact";
    const ParameterValues v = readList(list.sublist(n), every ? contactEverySpecs() : contactPairSpecs(), {}, file, path);
    c.model = modelIndex(spec, v, file, path);
    if (every) {
      c.kind = n == "General Contact" ? ContactInteractionSpec::Kind::General : ContactInteractionSpec::Kind::Self;
    } else {
      c.firstBlock = v.text("First Block");
      c.secondBlock = v.text("Second Block");
      for (const std::string& b : {c.firstBlock, c.secondBlock}) requireBlock(b, blocks, file, path);
    }
    spec.interactions.push_back(c);
  }
  if (spec.interactions.empty()) fail(file, "Contact/Interactions", "no interaction: name the blocks that contact");
}

}  // namespace

std::vector<ParameterSpec> contactSpecs() {
  return {S::real("Search Radius", "partners are looked for within this distance in the deformed configuration; "
                                   "at least the largest Contact Radius").need().positive(),
          S::integer("Search Frequency", "look for partners at the start and every n-th step (a point's partners stay "
                                         "fixed in between)").need().atLeast(1),
          S::flag("Verbose", "accepted (Peridigm prints its interactions)").byDefault("false"),
          S::flag("Only Listed Interactions",
                  "false (Peridigm's): every block touches every block, itself included, by the first of Models, "
                  "as Peridigm's contact does whatever Interactions say (they are still checked); true: only the "
                  "pairs Interactions name, each by its own model").byDefault("false")};
}

std::vector<ParameterSpec> contactModelSpecs() {
  return {S::text("Contact Model", "the force law").need().oneOf(kModels),
          S::real("Contact Radius", "points closer than this push each other apart").need().positive(),
          S::real("Spring Constant", "k of the force law (a modulus)").need().positive(),
          S::scalar("Friction Coefficient", "Coulomb friction mu (a number; Time Dependent Short Range Force: a "
                                            "function of t, required there)").byDefault("0")};
}

std::vector<ParameterSpec> contactPairSpecs() {
  return {S::text("First Block", "a block name").need(), S::text("Second Block", "a block name (the same: "
                                                                                  "self-contact)").need(),
          S::text("Contact Model", "a sub-list of Contact/Models").need()};
}

std::vector<ParameterSpec> contactEverySpecs() {
  return {S::text("Contact Model", "a sub-list of Contact/Models").need()};
}

ContactSpec parseContact(const PL& deck, const std::vector<SolverSpec>& solvers,
                         const std::vector<BlockGroupSpec>& blocks, const std::string& file) {
  ContactSpec spec;
  if (!deck.isSublist("Contact")) return spec;
  const PL& c = deck.sublist("Contact");
  const ParameterValues v = readList(c, contactSpecs(), {"Models", "Interactions"}, file, "Contact");
  spec.given = true;
  spec.searchRadius = v.get("Search Radius");
  spec.searchFrequency = static_cast<int>(v.get("Search Frequency"));
  spec.onlyListedInteractions = v.flag("Only Listed Interactions");
  const PL& models = requireSublist(c, "Models", file, "Contact");
  for (auto it = models.begin(); it != models.end(); ++it) {
    const std::string& n = models.name(it);
    if (!models.entry(it).isList()) fail(file, "Contact/Models", "'" + n + "' must be a sub-list (a contact model)");
    spec.models.push_back(parseContactModel(models.sublist(n), n, file, "Contact/Models/" + n));
    if (spec.models.back().contactRadius > spec.searchRadius)
      fail(file, "Contact/Models/" + n, "'Contact Radius' = " + numberText(spec.models.back().contactRadius) +
                                            " exceeds the 'Search Radius' " + numberText(spec.searchRadius) +
                                            ": pairs in contact would not be found");
  }
  if (spec.models.empty()) fail(file, "Contact/Models", "no contact model");
  parseInteractions(requireSublist(c, "Interactions", file, "Contact"), spec, blocks, file);
  for (const SolverSpec& s : solvers)
    if (s.type != "Verlet")
      fail(file, "Contact", "contact forces are applied by the Verlet solver only; '" + s.listName + "' is '" + s.type + "'");
  return spec;
}

}  // namespace pf

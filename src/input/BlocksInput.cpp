// The "Materials" and "Blocks" lists -> MaterialSpecs (checked against the model registry) and BlockGroupSpecs.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "Sections.hpp"

namespace pf {

// "block_<positive integer>" -> the integer, else 0.
int blockNumber(const std::string& n) {
  if (n.size() <= 6 || n.compare(0, 6, "block_") != 0 || n.find_first_not_of("0123456789", 6) != std::string::npos)
    return 0;
  try {
    const long id = std::stol(n.substr(6));
    return id >= 1 && id < 1000000000L ? static_cast<int>(id) : 0;
  } catch (const std::exception&) {
    return 0;
  }
}

namespace {

using S = ParameterSpec;

// Peridigm's Horizon is a double, or a string: an expression in x, y, z (Peridigm_HorizonManager.cpp). A string
// that is a plain number is the same constant (Peridigm evaluates it at every point to that value).
void readHorizon(const PL& list, const std::string& file, const std::string& path, BlockGroupSpec& g) {
  const Teuchos::ParameterEntry& e = list.getEntry("Horizon");
  std::string text = scalarAsText(e);
  double value = 0.0;
  bool number = !e.isType<std::string>();
  if (number) {
    value = getNumber(list, "Horizon");
  } else {
    const char* begin = text.c_str();
    char* end = nullptr;
    value = std::strtod(begin, &end);
    while (end && end != begin && std::isspace(static_cast<unsigned char>(*end))) ++end;
    number = end != begin && end && *end == '\0';
  }
  if (!number) {
    g.horizonExpression = std::make_shared<const Expression>(text, file + ": " + path + "/Horizon");
    return;
  }
  if (!(value > 0.0) || !std::isfinite(value)) {
    std::ostringstream got;
    got << value;
    fail(file, path, "'Horizon' must be positive (got " + got.str() + ")");
  }
  g.horizon = value;
}


}  // namespace

std::vector<ParameterSpec> blockSpecs() {
  return {S::text("Block Names",
                  "space-separated `block_N` (N ≥ 1; a Gmsh mesh's block also by its physical name); a block "
                  "belongs to one group only. Peridigm's `default` "
                  "(alone, in one group at most): every block of the discretization that no other group names")
              .need(),
          S::text("Material", "a sub-list name of `Materials`").need(), S::scalar("Horizon",
                    "horizon δ > 0: a number, or (Peridigm's string form) an expression in `x`, `y`, `z` evaluated at each "
                    "point's reference coordinates (a horizon that varies by point; correspondence models only)")
              .need(),
          S::text("Damage Model", "a sub-list name of `Damage Models`; none: the block's bonds never break"),
          S::text("Surface Correction",
                  "`NDO Band`: Li & Geng's surface-effect removal for correspondence models (the divergence form "
                  "within 2δ of the outer layer, traction term on it; docs/materials.md); every block group "
                  "must give the same")
              .oneOf({"None", "NDO Band"})
              .byDefault("None")};
}

MaterialSpec parseMaterial(const PL& m, const std::string& name, const std::string& file) {
  const std::string path = "Materials/" + name;
  if (!m.isParameter("Material Model")) fail(file, path, "missing required parameter 'Material Model'");
  if (!m.getEntry("Material Model").isType<std::string>()) fail(file, path, "'Material Model' must be a string");
  const std::string model = m.get<std::string>("Material Model");
  MaterialSpec spec;
  spec.name = name;
  spec.entry = findMaterial(model);
  if (!spec.entry) {
    std::vector<std::string> known;
    for (const MaterialEntry& e : materialRegistry()) known.push_back(e.model);
    fail(file, path, "unknown 'Material Model' = '" + model + "' (known: " + joinNames(known) + ")");
  }
  std::vector<ParameterSpec> specs = spec.entry->parameters;
  specs.push_back(S::text("Material Model", "model name").need());
  spec.values = readList(m, specs, {}, file, path);
  spec.values.name = name;
  return spec;
}

std::vector<MaterialSpec> parseMaterials(const PL& deck, const std::string& file) {
  const PL& mats = requireSublist(deck, "Materials", file, "top level");
  std::vector<MaterialSpec> out;
  for (auto it = mats.begin(); it != mats.end(); ++it) {
    if (!mats.entry(it).isList())
      fail(file, "Materials", "unknown parameter '" + mats.name(it) + "' (each material is a sub-list)");
    out.push_back(parseMaterial(mats.sublist(mats.name(it)), mats.name(it), file));
  }
  if (out.empty()) fail(file, "Materials", "no material defined");
  return out;
}

std::vector<BlockGroupSpec> parseBlocks(const PL& deck, const std::vector<MaterialSpec>& materials,
                                        const std::vector<DamageModelSpec>& damageModels, const std::string& file,
                                        const std::vector<std::pair<std::string, int>>& aliases) {
  const PL& blocks = requireSublist(deck, "Blocks", file, "top level");
  std::vector<std::string> matNames;
  for (const MaterialSpec& m : materials) matNames.push_back(m.name);
  std::vector<BlockGroupSpec> out;
  std::set<std::string> seen;
  for (auto it = blocks.begin(); it != blocks.end(); ++it) {
    const std::string bpath = "Blocks/" + blocks.name(it);
    if (!blocks.entry(it).isList())
      fail(file, "Blocks", "unknown parameter '" + blocks.name(it) + "' (each block group is a sub-list)");
    const ParameterValues b = readList(blocks.sublist(blocks.name(it)), blockSpecs(), {}, file, bpath);
    BlockGroupSpec g;
    g.name = blocks.name(it);
    g.material = b.text("Material");
    readHorizon(blocks.sublist(blocks.name(it)), file, bpath, g);
    g.ndoBand = b.text("Surface Correction") == "NDO Band";
    if (!out.empty() && out.front().ndoBand != g.ndoBand)
      fail(file, bpath, "'Surface Correction' differs from block group '" + out.front().name +
                            "' (the band's divergence reads every neighbour's stress: give it to all or none)");
    if (std::find(matNames.begin(), matNames.end(), g.material) == matNames.end())
      fail(file, bpath, "'Material' = '" + g.material + "' is not defined in Materials (defined: " +
                            joinNames(matNames) + ")");
    if (b.has("Damage Model")) {
      g.damageModel = b.text("Damage Model");
      std::vector<std::string> defined;
      for (const DamageModelSpec& d : damageModels) defined.push_back(d.name);
      if (std::find(defined.begin(), defined.end(), g.damageModel) == defined.end())
        fail(file, bpath, "'Damage Model' = '" + g.damageModel + "' is not defined in Damage Models (defined: " +
                              (defined.empty() ? std::string("none") : joinNames(defined)) + ")");
    }
    const std::vector<std::string> names = splitWords(b.text("Block Names"));
    if (names.empty()) fail(file, bpath, "'Block Names' is empty");
    for (const std::string& n : names) {
      if (n == "default") {
        if (names.size() != 1) fail(file, bpath, "'Block Names' = 'default' stands alone (no other names with it)");
        if (!seen.insert(n).second) fail(file, bpath, "'Block Names': 'default' is given by two block groups");
        g.isDefault = true;
        continue;
      }
      int id = blockNumber(n);
      for (const auto& [alias, tag] : aliases)
        if (id == 0 && alias == n) id = tag;
      if (id == 0)
        fail(file, bpath, "'Block Names' entry '" + n + "' is not of the form block_<positive integer>" +
                              (aliases.empty() ? std::string() : " nor a physical name of the mesh's blocks"));
      if (!seen.insert("block_" + std::to_string(id)).second)
        fail(file, bpath, "'Block Names': '" + n + "' is assigned to two block groups");
      g.blockIds.push_back(id);
    }
    out.push_back(g);
  }
  if (out.empty()) fail(file, "Blocks", "no block defined");
  return out;
}

}  // namespace pf

#include "InputSchema.hpp"

namespace pf {

MaterialInput materialInputFor(const PL& m, const std::string& name, const std::string& file) {
  return parseMaterial(m, name, file).values;
}

}  // namespace pf

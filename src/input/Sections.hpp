#pragma once
// The parsers of the deck's sections and the parameters each declares (also the source of the tables
// in docs/input.md, see ParameterTables.hpp). Internal to src/input; a Deck is built from them in order.
#include <set>
#include <string>
#include <vector>

#include "Deck.hpp"
#include "ListReader.hpp"

namespace pf {

// Discretization. defaultLayerWidth is applied by readDeck once the blocks are known.
std::vector<ParameterSpec> discretizationSpecs(const std::string& type);  // type "": the common ones
std::vector<ParameterSpec> quickGridSpecs();
std::vector<ParameterSpec> holeSpecs(bool box);
DiscretizationSpec parseDiscretization(const PL& d, const std::string& file, const std::string& dir);
// Layers without a "Layer Width" take the largest block horizon (maxHorizon); none: an InputError.
void applyDefaultLayerWidth(DiscretizationSpec& d, double maxHorizon, const std::string& file);
// "Bond Filters" (in Discretization or an Initial Damage model; path: the list's path). initialDamage: Peridigm's
// Initial Damage reading of an Exodus Mesh filter, a triangle of each element's first three nodes.
std::vector<ParameterSpec> bondFilterSpecs(const std::string& type);  // type "": Type only
BondFilters parseBondFilters(const PL& list, const std::string& file, const std::string& path, const std::string& dir,
                             bool initialDamage);
// Generated node-set names ("Left Layer", ...) of a discretization.
std::vector<std::string> generatedNodeSetNames(const DiscretizationSpec& d);

// Materials and Blocks.
std::vector<ParameterSpec> blockSpecs();
int blockNumber(const std::string& name);  // "block_<positive integer>" -> the integer, else 0
MaterialSpec parseMaterial(const PL& m, const std::string& name, const std::string& file);
std::vector<MaterialSpec> parseMaterials(const PL& deck, const std::string& file);
// aliases: other names of blocks (a Gmsh mesh's physical names) -> block id.
std::vector<BlockGroupSpec> parseBlocks(const PL& deck, const std::vector<MaterialSpec>& materials,
                                        const std::vector<DamageModelSpec>& damageModels, const std::string& file,
                                        const std::vector<std::pair<std::string, int>>& aliases = {});

// Damage Models (optional; before Blocks, which name them).
std::vector<ParameterSpec> criticalStretchSpecs();
std::vector<ParameterSpec> maximumPrincipalStressSpecs();
std::vector<ParameterSpec> timeDependentCriticalStretchSpecs();
std::vector<ParameterSpec> interfaceAwareSpecs();
std::vector<ParameterSpec> initialDamageSpecs();
std::vector<DamageModelSpec> parseDamageModels(const PL& deck, const std::string& file, const std::string& dir);

// Boundary Conditions: node sets first (a condition may name a set defined after it), then conditions.
std::vector<ParameterSpec> regionSpecs();
std::vector<ParameterSpec> conditionSpecs();
std::vector<NodeSetSpec> parseNodeSets(const PL& bcs, const std::set<std::string>& generated, const std::string& file,
                                       const std::string& dir);
std::vector<ConditionSpec> parseConditions(const PL& bcs, const std::set<std::string>& nodeSets,
                                           const std::string& file);
// Rigid walls: the conditions with Type = Rigid Wall (parseConditions skips them). solvers: every one must
// be Verlet (the only integrator that enforces them).
std::vector<ParameterSpec> rigidWallSpecs();
std::vector<RigidWallSpec> parseRigidWalls(const PL& bcs, const std::set<std::string>& nodeSets,
                                           const std::vector<SolverSpec>& solvers, const std::string& file);

// Contact (optional): the list's own parameters, a model's, an interaction's (a block pair, or General / Self
// Contact). solvers: every one must be Verlet (the only integrator that applies contact forces); blocks: the groups
// an interaction's blocks must belong to.
std::vector<ParameterSpec> contactSpecs();
std::vector<ParameterSpec> contactModelSpecs();
std::vector<ParameterSpec> contactPairSpecs();
std::vector<ParameterSpec> contactEverySpecs();
ContactSpec parseContact(const PL& deck, const std::vector<SolverSpec>& solvers,
                         const std::vector<BlockGroupSpec>& blocks, const std::string& file);

// Solver lists.
std::vector<ParameterSpec> solverListSpecs();
SolverSpec parseSolver(const PL& s, const std::string& file, const std::string& listName);

// Output lists. conditions: for "Applied Displacement"; dynamic: a dynamic solver runs (Acceleration).
std::vector<ParameterSpec> outputSpecs();
std::vector<ParameterSpec> probeSpecs();
// computeLabels: names besides the known variables that Output Variables may name: the Output Labels of the deck's
// compute classes and the Data Loader's field.
OutputSpec parseOutput(const PL& o, const std::string& file, const std::string& listName,
                       const std::set<std::string>& nodeSets, const std::vector<ConditionSpec>& conditions,
                       bool dynamic, const std::set<std::string>& computeLabels = {});

// The core's output fields and every registered model's declared outputs.
const std::vector<std::string>& knownOutputVariables();

// Peridigm's "Compute Class Parameters" (before the output lists, which may name their Output Labels).
std::vector<ParameterSpec> computeSpecs();
std::vector<ComputeSpec> parseComputes(const PL& list, const std::set<std::string>& nodeSets, const std::string& file);

// Data Loader (after the solvers, whose times its file must cover; before the output lists, which may name its field).
std::vector<ParameterSpec> dataLoaderSpecs();
DataLoaderSpec parseDataLoader(const PL& d, const std::string& file, const std::string& dir,
                               const std::vector<SolverSpec>& solvers);

// Restart (after the output lists: its default file name is the first one's).
std::vector<ParameterSpec> restartSpecs();
RestartSpec parseRestart(const PL& r, const std::string& file, const std::vector<OutputSpec>& outputs);

// The files the run writes (outputs, their part/lock/status files, the checkpoint): distinct from each other
// and from the files it reads, each with a file name after its directory. Throws InputError.
void checkWrittenFiles(const Deck& deck);

}  // namespace pf

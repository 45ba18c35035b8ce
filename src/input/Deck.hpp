#pragma once
// A validated input deck as plain structs: what every component reads instead of the raw parameter list.
// readDeck() parses and validates the file once (src/input is the only place that sees Teuchos); every
// value here has passed its type, range and cross-reference checks and file names are resolved.
#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "core/BondFilter.hpp"
#include "core/Expression.hpp"
#include "core/InfluenceFunction.hpp"
#include "core/MaterialEntry.hpp"
#include "core/ParamTree.hpp"
#include "core/Parameters.hpp"

namespace pf {

struct HoleSpec {
  std::array<double, 3> centre{};
  std::array<double, 3> axis{0.0, 0.0, 1.0};  // unit vector
  double radius = 0.0;
};

struct DiscretizationSpec {
  enum class Type { QuickGrid, TextFile, RectangleWithHoles, BoxWithHoles, Cylinder, Exodus, Gmsh };
  Type type = Type::QuickGrid;
  bool isElementMesh() const { return type == Type::Exodus || type == Type::Gmsh; }  // one point per element
  Influence influence = Influence::One;
  bool partialVolume = false;
  bool omitBondsBetweenBlocks = false;  // Peridigm's "Omit Bonds Between Blocks" = "All"
  BondFilters bondFilters;              // Peridigm's "Bond Filters": no bond crosses one (empty: none)
  // PdQuickGrid without "NeighborhoodType" (and without Partial Volume): Peridigm's default neighbourhood,
  // a box of round(δ/dx) cells per direction (its NoOp norm, QuickGrid.cxx); else the ball |ξ| <= δ.
  bool boxNeighbourhood = false;
  // PdQuickGrid: box corner, sizes and cells per direction.
  std::array<double, 3> origin{};
  std::array<double, 3> length{};
  std::array<int, 3> count{};
  // Text File, Exodus, Gmsh: the mesh file, resolved against the deck's directory.
  std::string meshFile;
  // Exodus, Gmsh: the mesh's node-set names (read from the file when the deck is parsed), its element count, and
  // (Gmsh) the physical names of its blocks, aliases of block_<tag> in Block Names.
  std::vector<std::string> meshNodeSets;
  long long meshElements = 0;
  std::vector<std::pair<std::string, int>> meshBlockNames;
  bool constructInterfaces = false;  // Exodus: Peridigm's "Construct Interfaces" (output/InterfaceOutput.hpp)
  // Rectangle / Box With Holes (origin and length above; z unused for the rectangle).
  double spacing = 0.0;
  bool gridNodes = false;           // "Grid" = "Nodes" (else cell centres)
  double thickness = 0.0;           // rectangle; Exodus and Gmsh meshes of 2D elements
  std::vector<HoleSpec> holes;
  std::vector<std::string> layers;  // faces with a fictitious layer: "Left", "Right", ...
  double layerWidth = 0.0;          // "Layer Width", or the largest block horizon
  // Cylinder (spacing above; origin = the centre of the base face).
  int cylinderAxis = 2;             // 0, 1, 2: x, y, z
  double radius = 0.0, cylinderLength = 0.0;
};

struct MaterialSpec {
  std::string name;                   // the sub-list name in Materials
  const MaterialEntry* entry = nullptr;
  MaterialInput values;               // checked against entry->parameters
};

// A "Damage Models" entry. Peridigm's "Critical Stretch": a bond breaks, for good, once its stretch
// (|y_j - y_i| - |xi|) / |xi| exceeds criticalStretch (core/BondDamage.hpp); its "Time Dependent Critical
// Stretch": the same with s_c = stretchOfTime(t) at the evaluated time; its "Initial Damage": the bonds that
// cross initialBreaks start broken and no other bond breaks (criticalStretch = infinity); Li & Geng's "Maximum
// Principal Stress": once the mean of its ends' largest principal Cauchy stress exceeds tensileStrength
// (core/StressDamage.hpp).
struct DamageModelSpec {
  std::string name;                   // the sub-list name in Damage Models
  std::string model;                  // one of the four names above
  double criticalStretch = 0.0;       // > 0 for Critical Stretch (infinity for Initial Damage), else 0
  double tensileStrength = 0.0;       // > 0 for Maximum Principal Stress, else 0
  double thermalExpansion = -1.0;     // (Time Dependent) Critical Stretch's Thermal Expansion Coefficient; < 0: not given
  std::shared_ptr<const Expression> stretchOfTime;  // Time Dependent Critical Stretch: s_c(t), else null
  BondFilters initialBreaks;          // Initial Damage's Bond Filters (triangles of an Exodus Mesh's elements)
};

struct BlockGroupSpec {
  std::string name;                   // the sub-list name in Blocks
  std::vector<int> blockIds;          // block_<n> -> n; empty for Peridigm's "default"
  bool isDefault = false;             // "Block Names" = "default": every block no other group names
  std::string material;               // a MaterialSpec name
  std::string damageModel;            // a DamageModelSpec name; empty: bonds never break
  // Horizon: a number (constant, horizonExpression null), or Peridigm's string form, an expression in x, y, z
  // evaluated at each point's reference coordinates (model/PointHorizons.hpp); then horizon is 0.
  double horizon = 0.0;
  std::shared_ptr<const Expression> horizonExpression;
  bool ndoBand = false;               // Surface Correction = NDO Band (model/SurfaceBand.hpp)
};

struct NodeSetSpec {
  enum class Kind { Ids, File, Region };
  std::string name;
  Kind kind = Kind::Ids;
  std::string text;                   // Ids: the ids as written; File: the resolved file name
  // Region: a face of the cloud ("Min X" ...) with a tolerance (0: default), or inclusive box bounds.
  std::string face;
  double tolerance = 0.0;
  std::array<double, 3> lo{}, hi{};
};

struct ConditionSpec {
  enum class Kind {
    PrescribedDisplacement,
    InitialDisplacement,
    InitialVelocity,
    BodyForce,
    Pressure,
    PrescribedTemperature,  // the Temperature field (model/FieldSet.hpp): imposed at every evaluated time
    InitialTemperature,     // its value at the start time
    HeatFlux,               // q [W/m^2] into the surface layer (model/FieldSurface.hpp)
    Convection              // h (T_amb - T) into the surface layer; value: T_amb
  };
  std::string name;                   // the sub-list name
  Kind kind = Kind::PrescribedDisplacement;
  std::string nodeSet;                // a NodeSetSpec, a generated set or "All"
  int coordinate = 0;                 // 0, 1, 2 (not for Pressure or the temperature conditions)
  std::shared_ptr<const Expression> value;
  double layerThickness = 0.0;        // Pressure, Heat Flux, Convection: the surface layer's thickness; 0 = the spacing
  double transferCoefficient = 0.0;   // Convection: h
  bool follower = false;              // Pressure: acts on the deformed surface (needs the NDO band)
  bool atInitialTime = false;         // Prescribed Displacement: also set in the initial state (not Peridigm's)
};

// A frictionless rigid plane the points of a node set may not cross (Verlet only; model/RigidWall.hpp).
struct RigidWallSpec {
  std::string name;                   // the sub-list name; the CSV's Reaction_<name>_X/Y/Z
  std::string nodeSet = "All";        // the points it stops
  std::array<double, 3> point{};      // a point of the plane
  std::array<double, 3> normal{};     // unit normal pointing to the side the body stays on
};

// Peridigm's "Contact" list (model/ContactForce.hpp): short-range forces between points that share no bond,
// found in the deformed configuration.
struct ContactModelSpec {
  std::string name;                              // the sub-list of Contact/Models
  double contactRadius = 0.0, springConstant = 0.0;
  double friction = 0.0;                         // Short Range Force: the friction coefficient
  std::shared_ptr<const Expression> frictionOfTime;  // Time Dependent Short Range Force: mu(t); null otherwise
};
struct ContactInteractionSpec {
  std::string name;                              // the sub-list of Contact/Interactions
  enum class Kind { Pair, General, Self } kind = Kind::Pair;
  std::string firstBlock, secondBlock;           // Pair: the two block names (may be equal)
  int model = 0;                                 // index into ContactSpec::models
};
struct ContactSpec {
  bool given = false;
  // false (Peridigm's): every block touches every block, itself included, by the first of `models` (its
  // ContactManager reads the interactions but applies none); true: only the interactions' pairs, each by its model.
  bool onlyListedInteractions = false;
  double searchRadius = 0.0;
  int searchFrequency = 1;
  std::vector<ContactModelSpec> models;
  std::vector<ContactInteractionSpec> interactions;
};

struct SolverSpec {
  std::string listName;               // "Solver", "Solver1", ...
  std::string type;                   // the solver sub-list: "Verlet", "NOXQuasiStatic", ...
  ParameterValues options;            // the solver sub-list, checked against the solver's specs
  ParamTree passThrough;              // sub-lists handed over unread (NOX's own options)
  std::vector<double> times;          // start time, then the end of every load step (Verlet: start, end)
  bool verbose = false;
  std::vector<std::string> fields;    // the fields it advances ("Displacement", "Temperature")
};

struct ProbeSpec {
  std::string name;
  std::array<double, 3> at{};
  std::vector<std::string> variables;
};

struct OutputSpec {
  std::string listName;               // "Output", "Output1", ...
  std::string filename;               // base name: <filename>.e and <filename>.csv
  bool exodus = true;
  int frequency = 1;
  long firstStep = 1, lastStep = 0;   // Initial / Final Output Step (0: no limit)
  std::vector<std::string> variables; // "Output Variables" set to true, in deck order
  std::vector<ProbeSpec> probes;
  bool reactionsGiven = false;        // "Reactions" given (else: every prescribed node set)
  std::vector<std::string> reactions, reactionNames;
  std::shared_ptr<const Expression> appliedDisplacement;  // "Applied Displacement" condition's value
};

// An entry of Peridigm's "Compute Class Parameters": a global output named `label` (a vector variable gives
// label X/Y/Z) reducing `variable` over a block or a node set (Sum, Minimum, Maximum), or taking it at the point
// nearest to `at` (Nearest_Point_Data). Output lists write it when their Output Variables name the label.
struct ComputeSpec {
  enum class Kind { BlockData, NodeSetData, NearestPointData };
  enum class Calculation { Sum, Minimum, Maximum };
  std::string name;                   // the sub-list name
  Kind kind = Kind::BlockData;
  Calculation calculation = Calculation::Sum;
  int block = 0;                      // BlockData: block_<block>
  std::string nodeSet;                // NodeSetData
  std::array<double, 3> at{};         // NearestPointData
  std::string variable, label;
};

// The "Restart" list: write a checkpoint every `frequency` steps (docs/output.md, "Restart").
struct RestartSpec {
  bool given = false;                 // the deck has a Restart list
  std::string checkpointFile;         // "Checkpoint Filename", default <first Output Filename>.restart
  int frequency = 0;                  // after every step whose CSV step number is a multiple of it
};

// Peridigm's "Data Loader" list: a nodal scalar field read from an Exodus results file and imposed on every point at
// every evaluated time, by linear interpolation between the file's output times (model/LoadedField.hpp).
struct DataLoaderSpec {
  bool given = false;                 // the deck has a Data Loader list
  std::string file;                   // "File Name", resolved against the deck's directory
  std::string field;                  // "Field Name": the file's nodal variable, also the run's field and output name
};

struct Deck {
  std::string file;                   // as given on the command line (error messages name it)
  std::string directory;              // relative file names in the deck resolve against it
  bool verbose = false;
  double maxMemory = 0.0;             // "Maximum Memory" in bytes for the whole run (0: MemAvailable only)
  DiscretizationSpec discretization;
  std::vector<MaterialSpec> materials;
  std::vector<DamageModelSpec> damageModels;
  std::vector<BlockGroupSpec> blocks;
  std::vector<NodeSetSpec> nodeSets;  // user-defined, in deck order
  std::vector<ComputeSpec> computes;  // "Compute Class Parameters", in deck order
  std::vector<ConditionSpec> conditions;
  std::vector<RigidWallSpec> walls;
  ContactSpec contact;
  std::vector<SolverSpec> solvers;    // run in sequence
  std::vector<OutputSpec> outputs;
  RestartSpec restart;
  DataLoaderSpec dataLoader;

  const MaterialSpec& material(const std::string& name) const;
  const DamageModelSpec* damageModel(const std::string& name) const;  // null for "" (no damage model)
  double maxHorizon() const;  // the largest constant Horizon (expression ones are known per point only)
  bool hasDynamicSolver() const;  // a solver whose entry is dynamic (Verlet, Implicit)
};

// Reads (XML, or YAML for .yaml/.yml) and validates a deck; InputError naming the file and parameter.
Deck readDeck(const std::string& path);

}  // namespace pf

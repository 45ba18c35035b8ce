#pragma once
// Bonds of the owned nodes in compressed-row form. Row i (an owned node, local index) holds its
// neighbours as local indices into the overlap arrays (owned nodes first, then ghosts). Built once on
// the reference configuration; kernels only read it.
#include <cstddef>
#include <functional>
#include <vector>

#include "FieldValues.hpp"

namespace pf {

struct BondFamily {
  std::vector<int> offsets;        // size numOwned + 1
  std::vector<int> neighbors;      // overlap-local index of the far end of each bond
  std::vector<double> refLength;   // |xi| of each bond
  std::vector<double> influence;   // omega(|xi|) of each bond
  std::vector<double> fraction;    // partial volume: share of V_j inside the horizon (empty = all 1)
  bool unitInfluence = false;      // every omega is exactly 1 (the kernels then skip the array)
  int numNodes = 0;                // overlap nodes (owned + ghosts) the neighbour indices refer to

  int numOwned() const { return offsets.empty() ? 0 : static_cast<int>(offsets.size()) - 1; }
  std::size_t numBonds() const { return neighbors.size(); }
};

// What a bond kernel sees: plain pointers into contiguous arrays, for owned nodes [begin, end).
// Per-node arrays are indexed by overlap-local node index, per-bond arrays by bond index.
struct FamilyView {
  int begin = 0, end = 0;           // owned nodes this call works on (one material block)
  const int* offsets = nullptr;
  const int* neighbors = nullptr;
  const double* refLength = nullptr;
  const double* influence = nullptr;
  const double* x = nullptr;        // reference coordinates, 3 per overlap node
  const double* volume = nullptr;   // overlap nodes
  const double* weightedVolume = nullptr;  // m = sum omega |xi|^2 V' per overlap node (ghosts too)
  // Per bond: the share of V_j that lies inside the horizon (partial-volume quadrature), or null when
  // every neighbour counts whole. Every family sum weights V_j by it, and the reaction f_j -= T V_i too.
  const double* fraction = nullptr;
  bool unitInfluence = false;       // influence[b] == 1 for every bond: kernels may skip reading it
  double horizon = 0.0;
  // Per overlap node, its own horizon when the horizons of the body are not all one value (a Horizon expression
  // in x, y, z, or blocks of different horizons; model/PointHorizons.hpp), else null. Peridigm's correspondence
  // models read a point's own horizon (Material::takesPointHorizon); bond families are always built from it.
  const double* pointHorizon = nullptr;
  // Bond damage (core/BondDamage.hpp); brokenN null: the block has no damage model and nothing breaks.
  const double* brokenN = nullptr;  // per bond, committed (or a quasi-static step's base set): 1 broken, 0 intact
  double* broken = nullptr;         // per bond, trial: written for every bond of [begin, end) on each evaluation
  double* damage = nullptr;         // per owned node: share of its bonds that are broken (Peridigm's Damage)
  // Per owned node: its number of broken bonds, committed and trial. A node with none committed has all its
  // flags 0 in both copies, so a kernel need not read or write them while it breaks nothing (BondDamage.hpp).
  const double* brokenCountN = nullptr;
  double* brokenCount = nullptr;
  double criticalStretch = 0.0;     // a bond breaks once (|y_j - y_i| - |xi|) / |xi| exceeds it
  // Maximum Principal Stress damage (core/StressDamage.hpp): > 0 is f_t, a bond breaks once the mean of its ends'
  // sigma1 exceeds it (then criticalStretch is 0 and unused); HUGE_VAL: the base set is kept, nothing new breaks.
  double tensileStrength = 0.0;
  int numNodes = 0;                 // size of the overlap node arrays (x, volume, y, force: per node)
  // Time of the state being evaluated (the time the solver last imposed boundary conditions for) and of
  // the reference state (the run's first such time). Rate-independent models ignore both; a rate-dependent
  // one keeps its own committed time as node history (docs/extending.md, "Time").
  double time = 0.0, startTime = 0.0;
  // Deformed positions of the last committed state, 3 per overlap node, for a model that integrates a work
  // over the step (an energy output); null unless the model asks (Material::wantsCommittedPositions) and
  // a state has been committed. Never needed for a force.
  const double* yN = nullptr;
  // Velocities of the state evaluated, 3 per overlap node (Peridigm's velocity at NP1: Verlet's half-step one, the
  // conditions' rate at prescribed components), for a model whose rate is the velocity gradient (Peridigm's
  // correspondence rate); null unless the model asks (Material::wantsVelocity) and the solver gives them
  // (Model::setVelocity: Verlet). Kinematics like y and yN, not a field.
  const double* velocity = nullptr;
  // Loading-balance correction (solvers/YieldRounds.hpp): per owned node, 1 if the point may return-map in this
  // evaluation, 0 if it must respond elastically even past its yield surface; null: every point may (normal
  // runs). Only models with Material::supportsYieldRounds() read it.
  const char* admitted = nullptr;
  // Li & Geng's NDO surface band (Surface Correction = NDO Band; model/SurfaceBand.hpp), null without it.
  // band: per overlap node, 1 within 2 delta of the body's outer layer, else 0. outerNormal: 3 per owned
  // node, the sum of the outward axis directions the point lacks a lattice neighbour in (0 off the outer
  // layer); layerThickness: per owned node, that lattice spacing.
  const double* band = nullptr;
  const double* outerNormal = nullptr;
  const double* layerThickness = nullptr;
  // A follower Pressure on the band's outer layer (Model::addFollowerPressure), null without one: per owned node,
  // q = p d / h (3 values; 0 off the loaded set), the reference traction over the layer thickness. The band adds
  // cof(F_i) q = J F^-T q (Li & Geng Eq. 31's T_ext / dx on the deformed surface).
  const double* followerLoad = nullptr;
  // The two-phase evaluation's buffer (Material::exchangeWidth), exchangeStride values per overlap node:
  // computeForce writes its owned nodes' rows, the core imports them to the ghosts before completeForce
  // reads any row. Null: one-pass evaluation.
  double* exchange = nullptr;
  int exchangeStride = 0;
  // Which completeForce call this is, 0 .. Material::exchangeRounds() - 1: before round r > 0 the core imports again
  // the owned rows round r - 1 rewrote (a model whose neighbours' values depend on their own neighbours').
  int exchangeRound = 0;
  // The model's nodal fields beside the displacement (core/FieldValues.hpp), for a material that reads one
  // (Material::fieldsRead); null when the model holds none. Every further field a material couples to comes
  // through here, not as one more member of this view.
  const FieldValues* fields = nullptr;
};

inline FamilyView makeView(const BondFamily& f, int begin, int end, const double* x, const double* volume,
                           const double* m, double horizon) {
  FamilyView v;
  v.begin = begin;
  v.end = end;
  v.offsets = f.offsets.data();
  v.neighbors = f.neighbors.data();
  v.refLength = f.refLength.data();
  v.influence = f.influence.data();
  v.fraction = f.fraction.empty() ? nullptr : f.fraction.data();
  v.unitInfluence = f.unitInfluence;
  v.x = x;
  v.volume = volume;
  v.weightedVolume = m;
  v.horizon = horizon;
  v.numNodes = f.numNodes;
  return v;
}

// The horizon of overlap node i: its own, or the block's when every point has that one.
inline double horizonAt(const FamilyView& fam, int i) { return fam.pointHorizon ? fam.pointHorizon[i] : fam.horizon; }

// m_i = sum_j omega_ij |xi_ij|^2 V_j (V_j times the bond's fraction, if any) for owned nodes [begin, end)
// (Pirzadeh 2024 Eq. 5 context).
void computeWeightedVolume(const FamilyView& fam, double* m);

// Keeps only the bonds keep(i, j) accepts (i: owned row, j: overlap index of the far end), compacting the
// rows; for a family whose influence is not set yet (a bond filter of the neighbour search).
void keepBonds(BondFamily& family, const std::function<bool(int, int)>& keep);

}  // namespace pf

#include "InterfaceOutput.hpp"

#include <exodusII.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>

#include "InterfaceMesh.hpp"
#include "core/InputError.hpp"
#include "input/ExodusFile.hpp"
#include "input/ExodusNodalData.hpp"

namespace pf {

namespace {
constexpr int kRecord = 7;  // per gathered interface: left, right (file positions), node count, 4 node ids (-1: none)
}  // namespace

InterfaceOutput::InterfaceOutput(const Deck& deck, const Model& model, const std::string& inputFile)
    : model_(model), inputFile_(inputFile) {
  const MeshConnectivity mesh = readConnectivity(deck.discretization.meshFile, inputFile);
  const DistributedLayout& layout = model.layout();
  const BondFamily& fam = layout.family();
  const std::vector<int>& gids = layout.gids();
  std::vector<double> mine;  // kRecord per interface
  std::vector<long long> nodes;
  for (int i = 0; i < layout.numOwned(); ++i) {
    // Peridigm's neighbour list is in file order: so is the search here, whatever the bonds' order.
    std::vector<std::pair<int, int>> neighbours;
    for (int b = fam.offsets[i]; b < fam.offsets[i + 1]; ++b)
      if (gids[fam.neighbors[b]] > gids[i]) neighbours.emplace_back(gids[fam.neighbors[b]], fam.neighbors[b]);
    std::sort(neighbours.begin(), neighbours.end());
    for (const auto& [gid, local] : neighbours) {
      if (!sharedFace(mesh, gids[i], gid, nodes)) continue;
      left_.push_back(i), right_.push_back(local);
      keys_.push_back(gids[i]), keys_.push_back(gid);
      mine.insert(mine.end(), {static_cast<double>(gids[i]), static_cast<double>(gid), static_cast<double>(nodes.size())});
      for (std::size_t k = 0; k < 4; ++k) mine.push_back(k < nodes.size() ? static_cast<double>(nodes[k]) : -1.0);
    }
  }
  const std::vector<double> all = layout.comm().gatherToRoot(mine);
  bool failed = false;
  std::string why;
  if (layout.comm().rank() == 0) {
    const std::size_t n = all.size() / kRecord;
    order_.resize(n);
    std::iota(order_.begin(), order_.end(), 0);
    auto key = [&](int k) { return std::make_pair(all[kRecord * k], all[kRecord * k + 1]); };
    std::sort(order_.begin(), order_.end(), [&](int a, int b) { return key(a) < key(b); });
    std::vector<std::vector<long long>> faces(n);
    for (std::size_t f = 0; f < n; ++f) {
      const double* r = &all[kRecord * static_cast<std::size_t>(order_[f])];
      for (int k = 0; k < static_cast<int>(r[2]); ++k) faces[f].push_back(static_cast<long long>(r[3 + k]));
      sizes_.push_back(static_cast<int>(r[2]));
    }
    pending_.assign(n, 0.0);
    try {
      writeMesh(faces, mesh, deck.discretization.meshFile);
    } catch (const InputError& e) {
      failed = true, why = e.what();
    }
  }
  if (layout.comm().anyFailed(failed)) throw InputError(layout.comm().broadcast(why, 0));
}

InterfaceOutput::~InterfaceOutput() {
  if (exoid_ >= 0) ex_close(exoid_);
}

void InterfaceOutput::fail(const std::string& msg) const {
  throw InputError(inputFile_ + ": Discretization/Construct Interfaces: '" + fileName() + "': " + msg);
}

// Rank 0: the mesh's nodes by id (those of some element), the interfaces as QUAD4 then TRI3, the variable.
void InterfaceOutput::writeMesh(const std::vector<std::vector<long long>>& faces, const MeshConnectivity& conn,
                                const std::string& meshFile) {
  const ExodusFile mesh(meshFile, inputFile_, "Discretization/Construct Interfaces");
  const long long numNodes = mesh.summary().nodes;
  std::vector<double> x(static_cast<std::size_t>(numNodes)), y(x.size()), z(x.size());
  if (numNodes > 0) mesh.check(ex_get_coord(mesh.id(), x.data(), y.data(), z.data()), "ex_get_coord");
  const std::vector<long long> ids = exodusIdMap(mesh, true);
  std::map<long long, std::size_t> used;  // node id -> its file position, for the nodes of some element
  std::map<long long, std::size_t> position;
  for (std::size_t k = 0; k < ids.size(); ++k) position[ids[k]] = k;
  for (long long id : conn.nodes) used[id] = position.at(id);
  std::vector<double> ux, uy, uz;
  std::vector<int> nodeIds;
  std::map<long long, int> local;  // node id -> 1-based index in the written file
  for (const auto& [id, k] : used) {
    ux.push_back(x[k]), uy.push_back(y[k]), uz.push_back(z[k]);
    nodeIds.push_back(static_cast<int>(id));
    local[id] = static_cast<int>(nodeIds.size());
  }
  int cpu = sizeof(double), io = sizeof(float);  // Peridigm writes single precision
  exoid_ = ex_create(fileName(), EX_CLOBBER, &cpu, &io);
  if (exoid_ < 0) fail("cannot create the file");
  auto check = [&](int status, const char* call) {
    if (status < 0) fail(std::string(call) + " failed (status " + std::to_string(status) + ")");
  };
  std::vector<int> quads, tris;
  for (const auto& f : faces)
    for (long long id : f) (f.size() == 4 ? quads : tris).push_back(local.at(id));
  const int numQuads = static_cast<int>(quads.size() / 4), numTris = static_cast<int>(tris.size() / 3);
  check(ex_put_init(exoid_, "Interfaces.e", 3, static_cast<int64_t>(nodeIds.size()), numQuads + numTris, 2, 0, 0),
        "ex_put_init");
  check(ex_put_coord(exoid_, ux.data(), uy.data(), uz.data()), "ex_put_coord");
  const char* coordNames[] = {"coordinates_x", "coordinates_y", "coordinates_x"};  // Peridigm's names, x twice
  check(ex_put_coord_names(exoid_, const_cast<char**>(coordNames)), "ex_put_coord_names");
  std::vector<int> elementIds(static_cast<std::size_t>(numQuads + numTris));
  std::iota(elementIds.begin(), elementIds.end(), 1);
  check(ex_put_id_map(exoid_, EX_ELEM_MAP, elementIds.data()), "ex_put_id_map(elements)");
  check(ex_put_id_map(exoid_, EX_NODE_MAP, nodeIds.data()), "ex_put_id_map(nodes)");
  check(ex_put_block(exoid_, EX_ELEM_BLOCK, 1, numQuads > 0 ? "QUAD4" : "NULL", numQuads, 4, 0, 0, 0), "ex_put_block");
  check(ex_put_block(exoid_, EX_ELEM_BLOCK, 2, numTris > 0 ? "TRI3" : "NULL", numTris, 3, 0, 0, 0), "ex_put_block");
  if (numQuads > 0) check(ex_put_conn(exoid_, EX_ELEM_BLOCK, 1, quads.data(), nullptr, nullptr), "ex_put_conn");
  if (numTris > 0) check(ex_put_conn(exoid_, EX_ELEM_BLOCK, 2, tris.data(), nullptr, nullptr), "ex_put_conn");
  check(ex_put_variable_param(exoid_, EX_ELEM_BLOCK, 1), "ex_put_variable_param");
  const char* names[] = {"interface_aperture"};
  check(ex_put_variable_names(exoid_, EX_ELEM_BLOCK, 1, const_cast<char**>(names)), "ex_put_variable_names");
  int truth[2] = {1, 1};
  check(ex_put_truth_table(exoid_, EX_ELEM_BLOCK, 2, 1, truth), "ex_put_truth_table");
  check(ex_update(exoid_), "ex_update");
}

void InterfaceOutput::write(double time, const std::vector<double>& u) {
  const DistributedLayout& layout = model_.layout();
  std::vector<double> uo(3 * static_cast<std::size_t>(layout.numOverlap()));
  layout.importToOverlap(u.data(), uo.data(), 3);
  const std::vector<double>& x = model_.coordinates();
  std::vector<double> mine;
  for (std::size_t k = 0; k < left_.size(); ++k) {
    double X = 0.0, Y = 0.0;
    for (int c = 0; c < 3; ++c) {
      const double dx = x[3 * right_[k] + c] - x[3 * left_[k] + c];
      const double dy = dx + uo[3 * right_[k] + c] - uo[3 * left_[k] + c];
      X += dx * dx, Y += dy * dy;
    }
    mine.push_back(std::sqrt(Y) - std::sqrt(X));
  }
  const std::vector<double> all = layout.comm().gatherToRoot(mine);
  bool failed = false;
  if (layout.comm().rank() == 0) {
    ++step_;
    std::vector<double> quads, tris;  // the file stores them as floats
    for (std::size_t f = 0; f < pending_.size(); ++f) (sizes_[f] == 4 ? quads : tris).push_back(pending_[f]);
    failed = ex_put_time(exoid_, step_, &time) < 0 ||
             (!quads.empty() && ex_put_var(exoid_, step_, EX_ELEM_BLOCK, 1, 1, static_cast<int64_t>(quads.size()), quads.data()) < 0) ||
             (!tris.empty() && ex_put_var(exoid_, step_, EX_ELEM_BLOCK, 1, 2, static_cast<int64_t>(tris.size()), tris.data()) < 0) ||
             ex_update(exoid_) < 0;
    for (std::size_t f = 0; f < pending_.size(); ++f) pending_[f] = all[static_cast<std::size_t>(order_[f])];
  }
  if (layout.comm().anyFailed(failed)) fail("writing output " + std::to_string(step_) + " failed");
}

}  // namespace pf

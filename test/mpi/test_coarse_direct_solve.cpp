// MueLu's coarsest level is solved directly; with a hierarchy of that one level (`coarse: max size` above the
// matrix size) the preconditioner is the exact inverse of the pair stiffness, so M^-1 (A z) must give z back at
// any rank count. At np 2 it did not (relative error 1.5 on the beam; Amesos2 13.2's KLU2 on a matrix spread over
// ranks, MueLuPreconditioner.cpp), which cost the np 2 Krylov solves 2.8x the iterations of np 1.
#include <gtest/gtest.h>

#include <Teuchos_ParameterList.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "core/Expression.hpp"
#include "core/Material.hpp"
#include "model/Model.hpp"
#include "model/NodalLoad.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedLayout.hpp"
#include "solvers/KrylovSolver.hpp"
#include "solvers/PairStiffness.hpp"

namespace {

// Only the pair stiffness matters here: one constant per bond.
class PairOnlyMaterial : public pf::Material {
 public:
  void computeForce(const pf::FamilyView&, const double*, pf::StateStore&, double*) const override {}
  void stiffnessBound(const pf::FamilyView& fam, double* bound) const override {
    for (int i = fam.begin; i < fam.end; ++i) bound[i] = 1.0;
  }
  void pairStiffness(const pf::FamilyView& fam, double* c) const override {
    for (int b = fam.offsets[fam.begin]; b < fam.offsets[fam.end]; ++b) c[b] = 2.0e3;
  }
  double density() const override { return 1.0; }
  pf::Dimension dimension() const override { return pf::Dimension::ThreeD; }
};

constexpr int kSide = 7;  // points per edge of the cube, 1 apart, horizon 1.8

// The cube split into slabs along x between the ranks, its x = 0 face held in x, y and z.
std::unique_ptr<pf::Model> cubeModel(const pf::Communicator& comm) {
  const int n = kSide * kSide * kSide;
  pf::PointCloud mine;
  mine.numGlobal = n;
  for (int p = 0; p < n; ++p) {
    const int ix = p % kSide, iy = (p / kSide) % kSide, iz = p / (kSide * kSide);
    if (ix * comm.size() / kSide != comm.rank()) continue;
    mine.gid.push_back(p);
    mine.x.insert(mine.x.end(), {double(ix), double(iy), double(iz)});
    mine.volume.push_back(1.0);
    mine.block.push_back(1);
  }
  auto layout = std::make_unique<pf::DistributedLayout>(comm, mine, std::vector<double>(mine.size(), 1.8),
                                                        pf::Influence(pf::Influence::One));
  std::vector<double> xo = layout->releaseCoordinates(), vo = layout->releaseVolumes();
  const int owned = layout->numOwned();
  std::vector<pf::BlockModel> blocks = {{1, "block_1", "m", 1.8, 0, owned, std::make_shared<PairOnlyMaterial>()}};
  auto model = std::make_unique<pf::Model>(std::move(layout), std::move(xo), std::move(vo), std::move(blocks));
  std::vector<int> face;
  for (int i = 0; i < owned; ++i)
    if (model->coordinates()[3 * i] == 0.0) face.push_back(i);
  for (int a = 0; a < 3; ++a)
    model->addPrescribedDisplacement({face, a, std::make_shared<pf::Expression>("0", "test"), {}});
  return model;
}

double z(long long dof) { return std::sin(0.37 * double(dof)) + 1.0; }  // known on every rank, by global dof id

TEST(CoarseDirectSolve, OneLevelMueLuIsTheInverseOfThePairStiffness) {
  const pf::Communicator world = pf::Communicator::world();
  auto model = cubeModel(world);
  const double radius = 1.0e9;  // every bond kept
  // b = A z, row by row from the same rows the solver assembles (z is a function of the global dof id).
  std::vector<long long> ids;
  std::vector<double> b;
  pf::pairStiffnessRows(
      *model, radius, nullptr,
      [&](const std::vector<long long>& rows, const std::vector<std::size_t>&) {
        ids = rows;
        b.assign(rows.size(), 0.0);
      },
      [&](std::size_t r, const long long* columns, const double* values, std::size_t n) {
        for (std::size_t k = 0; k < n; ++k) b[r] += values[k] * z(columns[k]);
      });
  pf::KrylovSolver krylov(*model, radius, nullptr, "test: Linear Solver");
  Teuchos::ParameterList ls;
  ls.set("Preconditioner", "ML");
  ls.sublist("MueLu").set("coarse: max size", 100000);
  std::vector<double> out(b.size(), 0.0);
  krylov.applyPreconditioner(b.data(), out.data(), ls);
  double local[2] = {0.0, 0.0}, total[2];
  for (std::size_t r = 0; r < ids.size(); ++r) {
    local[0] += (out[r] - z(ids[r])) * (out[r] - z(ids[r]));
    local[1] += z(ids[r]) * z(ids[r]);
  }
  world.sum(local, total, 2);
  // A direct solve of ~1 000 rows with entries of one scale: round-off ~1e-13 (3e-11 on the beam's 16 000 rows).
  EXPECT_LT(std::sqrt(total[0] / total[1]), 1e-10) << "np " << world.size();
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

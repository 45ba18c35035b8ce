// A material that fails on one rank only must make Model::internalForce fail on every rank with the same
// error, instead of leaving the other ranks waiting in the force export (np = 2 under ctest, which times a
// hang out).
#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "core/Material.hpp"
#include "model/Model.hpp"
#include "parallel/Communicator.hpp"
#include "parallel/DistributedLayout.hpp"

namespace {

// Adds nothing; throws when told to, on the rank it is told on.
class FailingMaterial : public pf::Material {
 public:
  explicit FailingMaterial(int failingRank, int myRank) : fail_(failingRank == myRank) {}
  void computeForce(const pf::FamilyView&, const double*, pf::StateStore&, double*) const override {
    if (fail_) throw pf::ConstitutiveFailure("return mapping did not converge on the failing rank");
  }
  void stiffnessBound(const pf::FamilyView& fam, double* bound) const override {
    for (int i = fam.begin; i < fam.end; ++i) bound[i] = 1.0;
  }
  void pairStiffness(const pf::FamilyView&, double*) const override {}
  double density() const override { return 1.0; }
  pf::Dimension dimension() const override { return pf::Dimension::ThreeD; }

 private:
  bool fail_;
};

// A row of 8 points, 1 apart, horizon 1.5, split in halves between the ranks.
std::unique_ptr<pf::Model> rowModel(const pf::Communicator& comm, int failingRank) {
  const int n = 8;
  pf::PointCloud mine;
  mine.numGlobal = n;
  for (int p = 0; p < n; ++p)
    if (p * comm.size() / n == comm.rank()) {
      mine.gid.push_back(p);
      mine.x.insert(mine.x.end(), {static_cast<double>(p), 0.0, 0.0});
      mine.volume.push_back(1.0);
      mine.block.push_back(1);
    }
  auto layout = std::make_unique<pf::DistributedLayout>(comm, mine, std::vector<double>(mine.size(), 1.5),
                                                        pf::Influence(pf::Influence::One));
  std::vector<double> xo = layout->releaseCoordinates(), vo = layout->releaseVolumes();
  const int owned = layout->numOwned();
  std::vector<pf::BlockModel> blocks = {
      {1, "block_1", "m", 1.5, 0, owned, std::make_shared<FailingMaterial>(failingRank, comm.rank())}};
  return std::make_unique<pf::Model>(std::move(layout), std::move(xo), std::move(vo), std::move(blocks));
}

TEST(ModelFailure, OneRanksMaterialFailureFailsEveryRank) {
  const pf::Communicator world = pf::Communicator::world();
  for (int failing = 0; failing < world.size(); ++failing) {
    auto model = rowModel(world, failing);
    std::vector<double> u(model->numDofs(), 0.0), f(model->numDofs(), 0.0);
    try {
      model->internalForce(u.data(), f.data());
      ADD_FAILURE() << "rank " << world.rank() << ": no error when rank " << failing << " failed";
    } catch (const pf::ConstitutiveFailure& e) {
      EXPECT_EQ(std::string(e.what()), "return mapping did not converge on the failing rank");
    }
  }
}

TEST(ModelFailure, NoFailureNoError) {
  const pf::Communicator world = pf::Communicator::world();
  auto model = rowModel(world, -1);
  std::vector<double> u(model->numDofs(), 0.0), f(model->numDofs(), 0.0);
  EXPECT_NO_THROW(model->internalForce(u.data(), f.data()));
}

}  // namespace

int main(int argc, char** argv) {
  pf::MpiSession mpi(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}

#include <gtest/gtest.h>
#include <cstdio>
#include "J2PathRunner.hpp"
using namespace pftest;
TEST(TmpSweep, Scale) {
  for (auto dim : {pf::Dimension::ThreeD, pf::Dimension::PlaneStress, pf::Dimension::PlaneStrain})
  for (double sc : {1.0, 0.1, 0.01}) {
  auto v = j2Values(dim, 20e9/sc, 0); v["Young's Modulus"] = kE/sc;
  auto mat = pf::makeMaterial("Elastic Plastic Hardening", v);
  pf::MaterialPoint mp(*mat, kDx, 10, kDx);
  ClassicalJ2 cl(kE, kNu, kSy, 20e9, 0, dim == pf::Dimension::PlaneStress ? ClassicalJ2::Mode::PlaneStress : dim == pf::Dimension::ThreeD ? ClassicalJ2::Mode::ThreeD : ClassicalJ2::Mode::PlaneStrain);
  double err = 0;
  for (int k = 1; k <= 120; ++k) {
    double s = pathStrain(Path::Cyclic, k, 120, 0.012);
    Sym e = pathTensor(Path::Cyclic, s);
    std::array<double,9> F{1+e[0]*sc,0,0,0,1,0,0,0,1};
    mp.deform(F); mp.evaluate(); cl.update(e);
    err = std::max(err, std::fabs(mp.value("Von_Mises_Stress") - cl.vonMises())/kSy);
    if (sc < 0.5 && k % 10 == 0 && dim == pf::Dimension::ThreeD) std::printf("k %d pd %g cl %g a %g %g\n", k, mp.value("Von_Mises_Stress"), cl.vonMises(), mp.value("Equivalent_Plastic_Strain"), cl.alphaT);
    mp.commit(); cl.commit();
  }
  std::printf("%s scale %g err %.3f%%\n", dimName(dim), sc, 100*err);
  }
}

#include "BondStressLaw.hpp"

#include "UnrotatedHooke.hpp"
#include "PeridigmJ2Update.hpp"

namespace pf {
namespace {

class HookeLaw : public BondStressLaw {
 public:
  HookeLaw(double K, double G) : K_(K), G_(G) {}
  bool hasHistory() const override { return false; }
  Mat3 update(const Mat3& tauN, double hN, const Mat3& de, double, double& h) const override {
    h = hN;
    return tauN + hookeIncrement(K_, G_, de);
  }

 private:
  double K_, G_;
};

class PeridigmJ2Law : public BondStressLaw {
 public:
  PeridigmJ2Law(double K, double G, double Y, double H, bool hardening) : K_(K), G_(G), Y_(Y), H_(H), hardening_(hardening) {}
  bool hasHistory() const override { return true; }
  Mat3 update(const Mat3& tauN, double hN, const Mat3& de, double, double& h) const override {
    const PeridigmJ2Step s = hardening_ ? peridigmIsotropicHardening(tauN, de, hN, K_, G_, Y_, H_)
                                        : peridigmPerfectPlastic(tauN, de, hN, K_, G_, Y_);
    h = s.eqps;
    return s.tau;
  }

 private:
  double K_, G_, Y_, H_;
  bool hardening_;
};

class FosterBondLaw : public BondStressLaw {
 public:
  FosterBondLaw(double K, double G, const FosterLaw& law) : K_(K), G_(G), law_(law) {}
  bool hasHistory() const override { return true; }
  Mat3 update(const Mat3& tauN, double hN, const Mat3& de, double dt, double& h) const override {
    const FosterStep s = fosterUpdate(law_, K_, G_, tauN, hN, de, dt);
    h = s.epsP;
    return s.tau;
  }

 private:
  double K_, G_;
  FosterLaw law_;
};

class DruckerPragerBondLaw : public BondStressLaw {
 public:
  DruckerPragerBondLaw(double K, double G, const DruckerPragerLaw& law) : K_(K), G_(G), law_(law) {}
  bool hasHistory() const override { return true; }
  Mat3 update(const Mat3& tauN, double hN, const Mat3& de, double, double& h) const override {
    const DruckerPragerStep s = druckerPragerUpdate(law_, K_, G_, tauN, hN, de);
    h = s.xi;
    return s.tau;
  }

 private:
  double K_, G_;
  DruckerPragerLaw law_;
};

}  // namespace

std::unique_ptr<BondStressLaw> hookeBondLaw(double bulk, double shear) {
  return std::unique_ptr<BondStressLaw>(new HookeLaw(bulk, shear));
}
std::unique_ptr<BondStressLaw> perfectPlasticBondLaw(double bulk, double shear, double yield) {
  return std::unique_ptr<BondStressLaw>(new PeridigmJ2Law(bulk, shear, yield, 0.0, false));
}
std::unique_ptr<BondStressLaw> isotropicHardeningBondLaw(double bulk, double shear, double yield, double hardening) {
  return std::unique_ptr<BondStressLaw>(new PeridigmJ2Law(bulk, shear, yield, hardening, true));
}
std::unique_ptr<BondStressLaw> fosterBondLaw(double bulk, double shear, const FosterLaw& law) {
  return std::unique_ptr<BondStressLaw>(new FosterBondLaw(bulk, shear, law));
}
std::unique_ptr<BondStressLaw> druckerPragerBondLaw(double bulk, double shear, const DruckerPragerLaw& law) {
  return std::unique_ptr<BondStressLaw>(new DruckerPragerBondLaw(bulk, shear, law));
}

}  // namespace pf

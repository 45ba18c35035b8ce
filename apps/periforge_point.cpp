// periforge-point: one interior peridynamic material point (complete family on a regular lattice) driven
// along a homogeneous small-strain path; prints CSV per step. For checking a material model by hand,
// e.g. periforge-point --model "Elastic Plastic Hardening" --dim 3D --ratio 10 --path cyclic --K 20e9
#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>

#include "core/InputError.hpp"
#include "core/Material.hpp"
#include "materialpoint/MaterialPoint.hpp"

namespace {

const char* kUsage =
    "usage: periforge-point [--model NAME] [--dim 3D|PlaneStress|PlaneStrain] [--ratio R] "
    "[--path uniaxial|shear|cyclic]\n"
    "                       [--E Pa] [--nu v] [--sy Pa] [--K Pa] [--H Pa] [--strain s] [--steps n]\n"
    "                       [--partial-volume 0|1]\n"
    "  Homogeneous deformation y = (I + eps) X of one lattice point's family (spacing 1 mm, horizon R mm):\n"
    "  uniaxial: eps_xx = s; shear: eps_xy = eps_yx = s/2; cyclic: eps_xx 0 -> s -> -s -> s.\n"
    "  Defaults: Elastic Plastic Hardening, 3D, 10, uniaxial, 200e9, 0.3, 600e6, 20e9, 0, 0.012, 120, 0.\n"
    "  --partial-volume 1 weights each bond by the share of its cell inside the horizon.\n"
    "  CSV: step,strain,von_mises,signed_von_mises,eq_plastic_strain,lambda,back_stress\n";

double number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try { v = std::stod(text, &used); } catch (const std::exception&) { used = 0; }
  if (used != text.size() || text.empty()) throw pf::InputError("periforge-point: " + flag + " needs a number, got '" + text + "'");
  return v;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::map<std::string, std::string> opt = {{"--model", "Elastic Plastic Hardening"}, {"--dim", "3D"},
                                              {"--ratio", "10"}, {"--path", "uniaxial"}, {"--E", "200e9"},
                                              {"--nu", "0.3"}, {"--sy", "600e6"}, {"--K", "20e9"}, {"--H", "0"},
                                              {"--strain", "0.012"}, {"--steps", "120"},
                                              {"--partial-volume", "0"}};
    for (int a = 1; a < argc; ++a) {
      const std::string flag = argv[a];
      if (flag == "--help" || flag == "-h") { std::cout << kUsage; return 0; }
      if (!opt.count(flag)) throw pf::InputError("periforge-point: unknown option '" + flag + "'\n" + kUsage);
      if (a + 1 >= argc) throw pf::InputError("periforge-point: " + flag + " needs a value");
      opt[flag] = argv[++a];
    }
    const std::string model = opt["--model"], dim = opt["--dim"], path = opt["--path"];
    const double ratio = number("--ratio", opt["--ratio"]), amp = number("--strain", opt["--strain"]);
    const double stepsD = number("--steps", opt["--steps"]);
    const int steps = static_cast<int>(stepsD);
    if (!(ratio >= 1.0)) throw pf::InputError("periforge-point: --ratio must be >= 1");
    if (steps < 1 || steps != stepsD) throw pf::InputError("periforge-point: --steps must be a positive integer");
    if (path != "uniaxial" && path != "shear" && path != "cyclic")
      throw pf::InputError("periforge-point: --path must be uniaxial, shear or cyclic, got '" + path + "'");
    const double dx = 1e-3;
    std::map<std::string, double> v = {{"Density", 8000.0}, {"Young's Modulus", number("--E", opt["--E"])},
                                       {"Poisson's Ratio", number("--nu", opt["--nu"])}};
    if (model != "Elastic") v["Yield Stress"] = number("--sy", opt["--sy"]);
    if (model == "Elastic Plastic Hardening") {
      v["Isotropic Hardening Modulus"] = number("--K", opt["--K"]);
      v["Kinematic Hardening Modulus"] = number("--H", opt["--H"]);
    }
    if (dim == "PlaneStress") { v["Plane Stress"] = 1; v["Thickness"] = dx; }
    else if (dim == "PlaneStrain") { v["Plane Strain"] = 1; v["Thickness"] = dx; }
    else if (dim != "3D") throw pf::InputError("periforge-point: --dim must be 3D, PlaneStress or PlaneStrain, got '" + dim + "'");

    auto mat = pf::makeMaterial(model, v);
    const std::string pv = opt["--partial-volume"];
    if (pv != "0" && pv != "1") throw pf::InputError("periforge-point: --partial-volume must be 0 or 1, got '" + pv + "'");
    pf::MaterialPoint mp(*mat, dx, ratio, dx, pv == "1");
    auto field = [&](const char* name) { return mp.state().has(name) ? mp.value(name) : 0.0; };
    std::printf("step,strain,von_mises,signed_von_mises,eq_plastic_strain,lambda,back_stress\n");
    for (int k = 1; k <= steps; ++k) {
      const double t = double(k) / steps;
      double s = amp * t;
      if (path == "cyclic") s = t <= 0.25 ? 4 * t * amp : t <= 0.75 ? amp * (1 - 4 * (t - 0.25)) : amp * (-1 + 8 * (t - 0.75));
      std::array<double, 9> F{1, 0, 0, 0, 1, 0, 0, 0, 1};
      if (path == "shear") { F[1] = F[3] = 0.5 * s; } else { F[0] += s; }
      mp.deform(F);
      mp.evaluate();
      std::printf("%d,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g\n", k, s, field("Von_Mises_Stress"),
                  field("Signed_Von_Mises_Stress"), field("Equivalent_Plastic_Strain"), field("Lambda"),
                  field("Back_Stress"));
      mp.commit();
    }
    return 0;
  } catch (const pf::InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  } catch (const pf::ConstitutiveFailure& e) {
    std::fprintf(stderr, "periforge-point: constitutive failure: %s\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "periforge-point: %s\n", e.what());
    return 1;
  }
}

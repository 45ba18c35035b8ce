// periforge-point: one interior peridynamic material point (complete family on a regular lattice) driven
// along a homogeneous small-strain path; prints CSV per step with every output field the model declares.
// For checking a material model by hand, e.g.
//   periforge-point --model "Elastic Plastic Hardening" --dim 3D --ratio 10 --path cyclic --K 20e9
//   periforge-point --model Microelastic --param "Bulk Modulus=100e9" --path shear
#include <array>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/InputError.hpp"
#include "core/Material.hpp"
#include "core/MaterialEntry.hpp"
#include "materialpoint/MaterialPoint.hpp"
#include "materialpoint/PointParameters.hpp"

namespace {

const char* kUsage =
    "usage: periforge-point [--model NAME] [--dim 3D|PlaneStress|PlaneStrain] [--ratio R] "
    "[--path uniaxial|shear|cyclic]\n"
    "                       [--param \"Name=value\"]... [--E Pa] [--nu v] [--sy Pa] [--K Pa] [--H Pa]\n"
    "                       [--strain s] [--steps n] [--time T] [--partial-volume 0|1]\n"
    "  Homogeneous deformation y = (I + eps) X of one lattice point's family (spacing 1 mm, horizon R mm):\n"
    "  uniaxial: eps_xx = s; shear: eps_xy = eps_yx = s/2; cyclic: eps_xx 0 -> s -> -s -> s.\n"
    "  Defaults: Elastic Plastic Hardening, 3D, 10, uniaxial, 0.012, 120, 0.\n"
    "  --param sets any parameter of the model by its input name (repeatable), checked against the model's\n"
    "  specs like a deck's Materials list (ranges, choices, defaults). Density is 8000 unless given.\n"
    "  --E, --nu, --sy, --K, --H set Young's Modulus, Poisson's Ratio, Yield Stress, Isotropic and Kinematic\n"
    "  Hardening Modulus. For the OSB models (Elastic, Elastic Plastic, Elastic Plastic Hardening) those the\n"
    "  model takes default to 200e9, 0.3, 600e6, 20e9, 0 unless a --param names them; other models get only\n"
    "  what is given (e.g. Microelastic: --param \"Bulk Modulus=1e11\" or --E). Every other parameter keeps the\n"
    "  model's default, Peridigm's (Yield Normalization = Continuum; Elastic Plastic Hardening in 3D: Apply Shear\n"
    "  Correction Factor = true): --param \"Yield Normalization=Discrete\" for the lattice-consistent constants.\n"
    "  --dim PlaneStress|PlaneStrain sets Plane Stress|Strain and Thickness = 1 mm.\n"
    "  --partial-volume 1 weights each bond by the share of its cell inside the horizon.\n"
    "  --time T: the path takes T seconds (default 1), step k at T k / steps: the time rate-dependent models see.\n"
    "  CSV: step,strain, then every output field the model declares (its registry outputs) that it writes\n"
    "  in this setting, by name (e.g. Von_Mises_Stress, Equivalent_Plastic_Strain, Stored_Elastic_Energy).\n";

double number(const std::string& flag, const std::string& text) {
  std::size_t used = 0;
  double v = 0;
  try { v = std::stod(text, &used); } catch (const std::exception&) { used = 0; }
  if (used != text.size() || text.empty()) throw pf::InputError("periforge-point: " + flag + " needs a number, got '" + text + "'");
  return v;
}

struct Options {
  std::map<std::string, std::string> opt = {{"--model", "Elastic Plastic Hardening"}, {"--dim", "3D"}, {"--ratio", "10"},
                                            {"--path", "uniaxial"}, {"--strain", "0.012"}, {"--steps", "120"},
                                            {"--time", "1"}, {"--partial-volume", "0"}};
  std::map<std::string, std::string> shortcuts;  // --E, --nu, ... as given
  std::vector<std::string> params;               // --param, in order
};

const std::map<std::string, std::string>& shortcutNames() {
  static const std::map<std::string, std::string> m = {
      {"--E", "Young's Modulus"}, {"--nu", "Poisson's Ratio"}, {"--sy", "Yield Stress"},
      {"--K", "Isotropic Hardening Modulus"}, {"--H", "Kinematic Hardening Modulus"}};
  return m;
}

// Returns false after printing --help.
bool parse(int argc, char** argv, Options& o) {
  for (int a = 1; a < argc; ++a) {
    const std::string flag = argv[a];
    if (flag == "--help" || flag == "-h") { std::cout << kUsage; return false; }
    const bool known = o.opt.count(flag) || shortcutNames().count(flag) || flag == "--param";
    if (!known) throw pf::InputError("periforge-point: unknown option '" + flag + "' (see --help)");
    if (a + 1 >= argc) throw pf::InputError("periforge-point: " + flag + " needs a value");
    const std::string value = argv[++a];
    if (flag == "--param") o.params.push_back(value);
    else if (shortcutNames().count(flag)) o.shortcuts[flag] = value;
    else o.opt[flag] = value;
  }
  return true;
}

// The model's parameters from --param, the shortcuts, the legacy defaults and --dim.
void materialValues(const Options& o, const pf::MaterialEntry& e, double dx, std::map<std::string, double>& v,
                    std::map<std::string, std::string>& s) {
  for (const std::string& p : o.params) pf::addParameter(e, p, v, s);
  auto takes = [&](const std::string& n) {
    for (const pf::ParameterSpec& p : e.parameters)
      if (p.name == n) return true;
    return false;
  };
  const bool osb = e.model == "Elastic" || e.model == "Elastic Plastic" || e.model == "Elastic Plastic Hardening";
  const std::map<std::string, std::string> legacy = {{"--E", "200e9"}, {"--nu", "0.3"}, {"--sy", "600e6"},
                                                     {"--K", "20e9"}, {"--H", "0"}};
  const bool peridigmLaw = v.count("Hardening Modulus") != 0;
  for (const auto& sc : shortcutNames()) {
    const std::string& name = sc.second;
    auto given = o.shortcuts.find(sc.first);
    if (given != o.shortcuts.end()) v[name] = number(sc.first, given->second);  // unknown to the model: refused
    // Peridigm's "Hardening Modulus" is the other hardening law: no legacy K, H beside it.
    else if (osb && takes(name) && !v.count(name) && !(peridigmLaw && name.find("Hardening") != std::string::npos))
      v[name] = number(sc.first, legacy.at(sc.first));
  }
  if (takes("Density") && !v.count("Density")) v["Density"] = 8000.0;
  const std::string dim = o.opt.at("--dim");
  if (dim == "PlaneStress" || dim == "PlaneStrain") {
    v[dim == "PlaneStress" ? "Plane Stress" : "Plane Strain"] = 1;
    if (!v.count("Thickness")) v["Thickness"] = dx;
  } else if (dim != "3D") {
    throw pf::InputError("periforge-point: --dim must be 3D, PlaneStress or PlaneStrain, got '" + dim + "'");
  }
}

double pathStrain(const std::string& path, double amp, int k, int steps) {
  const double t = double(k) / steps;
  if (path != "cyclic") return amp * t;
  return t <= 0.25 ? 4 * t * amp : t <= 0.75 ? amp * (1 - 4 * (t - 0.25)) : amp * (-1 + 8 * (t - 0.75));
}

int run(const Options& o) {
  const std::string model = o.opt.at("--model"), path = o.opt.at("--path"), pv = o.opt.at("--partial-volume");
  const double ratio = number("--ratio", o.opt.at("--ratio")), amp = number("--strain", o.opt.at("--strain"));
  const double stepsD = number("--steps", o.opt.at("--steps"));
  const int steps = static_cast<int>(stepsD);
  const double duration = number("--time", o.opt.at("--time"));
  if (!(duration > 0.0)) throw pf::InputError("periforge-point: --time must be > 0");
  if (!(ratio >= 1.0)) throw pf::InputError("periforge-point: --ratio must be >= 1");
  if (steps < 1 || steps != stepsD) throw pf::InputError("periforge-point: --steps must be a positive integer");
  if (path != "uniaxial" && path != "shear" && path != "cyclic")
    throw pf::InputError("periforge-point: --path must be uniaxial, shear or cyclic, got '" + path + "'");
  if (pv != "0" && pv != "1") throw pf::InputError("periforge-point: --partial-volume must be 0 or 1, got '" + pv + "'");
  const pf::MaterialEntry* entry = pf::findMaterial(model);
  if (!entry) throw pf::InputError("periforge-point: unknown model '" + model + "'");
  const double dx = 1e-3;
  std::map<std::string, double> v;
  std::map<std::string, std::string> s;
  materialValues(o, *entry, dx, v, s);
  auto mat = pf::makeMaterial(model, v, s);
  // Columns: the declared outputs this setting writes (e.g. Elastic's energy exists in 3D only).
  std::vector<std::string> columns;
  for (const pf::StateSpec& spec : mat->stateSpecs())
    for (const std::string& name : entry->outputs)
      if (spec.output && spec.name == name) columns.push_back(name);
  for (const std::string& c : columns) mat->enableOutput(c);
  pf::MaterialPoint mp(*mat, dx, ratio, dx, pv == "1");
  std::printf("step,strain");
  for (const std::string& c : columns) std::printf(",%s", c.c_str());
  std::printf("\n");
  for (int k = 1; k <= steps; ++k) {
    const double e = pathStrain(path, amp, k, steps);
    std::array<double, 9> F{1, 0, 0, 0, 1, 0, 0, 0, 1};
    if (path == "shear") { F[1] = F[3] = 0.5 * e; } else { F[0] += e; }
    mp.deform(F);
    mp.setTime(duration * k / steps);
    mp.evaluate();
    std::printf("%d,%.10g", k, e);
    for (const std::string& c : columns) std::printf(",%.10g", mp.value(c));
    std::printf("\n");
    mp.commit();
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    Options o;
    if (!parse(argc, argv, o)) return 0;
    return run(o);
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

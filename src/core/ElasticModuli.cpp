#include "ElasticModuli.hpp"

#include <cmath>

#include "InputError.hpp"
#include "MaterialEntry.hpp"

namespace pf {

ElasticModuli elasticModuliFrom(const MaterialInput& in) {
  const char* names[4] = {"Bulk Modulus", "Shear Modulus", "Young's Modulus", "Poisson's Ratio"};
  int given = 0;
  for (const char* n : names) given += in.has(n) ? 1 : 0;
  const std::string where = in.inputFile + ": material '" + in.name + "'";
  if (given != 2)
    throw InputError(where + " needs exactly two of 'Bulk Modulus', 'Shear Modulus', 'Young's Modulus', "
                     "'Poisson's Ratio' (" + std::to_string(given) + " given)");
  ElasticModuli m;
  const bool K = in.has("Bulk Modulus"), G = in.has("Shear Modulus"), E = in.has("Young's Modulus");
  const bool nu = in.has("Poisson's Ratio");
  if (K && G) {
    m.bulk = in.get("Bulk Modulus"); m.shear = in.get("Shear Modulus");
  } else if (E && nu) {
    const double e = in.get("Young's Modulus"), v = in.get("Poisson's Ratio");
    m.bulk = e / (3 * (1 - 2 * v)); m.shear = e / (2 * (1 + v));
  } else if (K && E) {
    const double k = in.get("Bulk Modulus"), e = in.get("Young's Modulus");
    m.bulk = k; m.shear = 3 * k * e / (9 * k - e);
  } else if (K && nu) {
    const double k = in.get("Bulk Modulus"), v = in.get("Poisson's Ratio");
    m.bulk = k; m.shear = 3 * k * (1 - 2 * v) / (2 * (1 + v));
  } else if (G && E) {
    const double g = in.get("Shear Modulus"), e = in.get("Young's Modulus");
    m.shear = g; m.bulk = e * g / (3 * (3 * g - e));
  } else {  // G && nu
    const double g = in.get("Shear Modulus"), v = in.get("Poisson's Ratio");
    m.shear = g; m.bulk = 2 * g * (1 + v) / (3 * (1 - 2 * v));
  }
  m.young = 9 * m.bulk * m.shear / (3 * m.bulk + m.shear);
  m.poisson = (3 * m.bulk - 2 * m.shear) / (2 * (3 * m.bulk + m.shear));
  if (!(m.bulk > 0) || !(m.shear > 0) || !std::isfinite(m.bulk) || !std::isfinite(m.shear))
    throw InputError(where + ": elastic constants give a non-positive bulk or shear modulus");
  return m;
}

Dimension dimensionFrom(const MaterialInput& in, double* thickness, const char* thicknessName) {
  const std::string h = thicknessName;
  const bool ps = in.flag("Plane Stress"), pe = in.flag("Plane Strain");
  const std::string where = in.inputFile + ": material '" + in.name + "'";
  if (ps && pe) throw InputError(where + ": 'Plane Stress' and 'Plane Strain' are both true");
  if (!ps && !pe) {
    if (in.has(h)) throw InputError(where + ": '" + h + "' is only for Plane Stress / Plane Strain");
    *thickness = 0.0;
    return Dimension::ThreeD;
  }
  if (!in.has(h)) throw InputError(where + ": '" + h + "' is needed by Plane Stress / Plane Strain");
  *thickness = in.get(h);  // > 0: its spec's range
  return ps ? Dimension::PlaneStress : Dimension::PlaneStrain;
}

}  // namespace pf

// Every registry entry tells the truth about itself (materials/MaterialRegistry.cpp, core/MaterialEntry.hpp):
//  - built from a minimal valid deck list (3D, and 2D where it takes Plane Stress / Plane Strain), the
//    output fields of its stateSpecs() are its declared MaterialEntry::outputs (their union over the
//    settings: Elastic has its energy in 3D only);
//  - no parameter with a default is also required, and every default lies in its range and choices;
//  - the input layer (pf::materialInputFor) refuses a value outside each declared range or choices, with
//    one line naming the file and the parameter, and hands the default of what the list leaves out.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include <Teuchos_ParameterList.hpp>

#include "core/InputError.hpp"
#include "core/MaterialEntry.hpp"
#include "input/InputSchema.hpp"
#include "test_input_helpers.hpp"

namespace {

const char* kFile = "registry_test.xml";

// A value inside a spec's range (for required parameters).
double inside(const pf::ParameterSpec& s) {
  if (s.min > -1e300) return s.min + 1.0;
  if (s.max < 1e300) return s.max - 1.0;
  return 1.0;
}

// A value just outside the range.
double outside(const pf::ParameterSpec& s) {
  if (s.min > -1e300) return s.minExclusive ? s.min : s.min - 1.0;
  return s.maxExclusive ? s.max : s.max + 1.0;
}

void setValue(Teuchos::ParameterList& l, const pf::ParameterSpec& s, double v) {
  if (s.kind == pf::ParameterSpec::Kind::Int) l.set(s.name, static_cast<int>(v));
  else l.set(s.name, v);
}

// The required parameters of the entry at a value inside their range, plus the first of a few sets of
// elastic constants the model accepts (the models need one or two of them: a cross-parameter rule no
// spec can state). planar: Plane Stress with a Thickness (Height). Empty list if none is accepted.
Teuchos::ParameterList minimalList(const pf::MaterialEntry& e, bool planar) {
  const std::vector<std::vector<std::pair<std::string, double>>> constants = {
      {}, {{"Young's Modulus", 200e9}}, {{"Young's Modulus", 200e9}, {"Poisson's Ratio", 0.3}}};
  for (const auto& extra : constants) {
    Teuchos::ParameterList l;
    l.set("Material Model", e.model);
    for (const pf::ParameterSpec& s : e.parameters) {
      if (!s.required) continue;
      if (s.kind == pf::ParameterSpec::Kind::String) l.set(s.name, s.choices.empty() ? std::string("x") : s.choices[0]);
      else if (s.kind == pf::ParameterSpec::Kind::Bool) l.set(s.name, false);
      else setValue(l, s, s.name == "Density" ? 8000.0 : inside(s));
    }
    for (const auto& kv : extra) l.set(kv.first, kv.second);
    if (planar) {
      l.set("Plane Stress", true);
      bool height = false;  // Elastic Bond Based's thickness is Peridigm's "Height"
      for (const pf::ParameterSpec& s : e.parameters) height = height || s.name == "Height";
      l.set(height ? "Height" : "Thickness", 1e-3);
    }
    try {
      e.create(pf::materialInputFor(l, "M", kFile));
      return l;
    } catch (const pf::InputError&) {
    }
  }
  return Teuchos::ParameterList();
}

bool takes(const pf::MaterialEntry& e, const std::string& name) {
  for (const pf::ParameterSpec& s : e.parameters)
    if (s.name == name) return true;
  return false;
}

}  // namespace

TEST(MaterialRegistry, OutputsAreTheOutputFieldsOfStateSpecs) {
  ASSERT_FALSE(pf::materialRegistry().empty());
  for (const pf::MaterialEntry& e : pf::materialRegistry()) {
    SCOPED_TRACE(e.model);
    const std::set<std::string> declared(e.outputs.begin(), e.outputs.end());
    EXPECT_EQ(declared.size(), e.outputs.size()) << "an output is declared twice";
    std::set<std::string> written;
    for (bool planar : {false, true}) {
      if (planar && !takes(e, "Plane Stress")) continue;
      const Teuchos::ParameterList l = minimalList(e, planar);
      ASSERT_TRUE(l.isParameter("Material Model")) << "no minimal input accepted" << (planar ? " (2D)" : " (3D)");
      const auto mat = e.create(pf::materialInputFor(l, "M", kFile));
      EXPECT_EQ(mat->dimension() != pf::Dimension::ThreeD, planar);
      for (const pf::StateSpec& s : mat->stateSpecs()) {
        if (!s.output) continue;
        EXPECT_TRUE(declared.count(s.name)) << "'" << s.name << "' is written but not in outputs";
        written.insert(s.name);
      }
    }
    EXPECT_EQ(written, declared) << "a declared output no setting writes";
  }
}

TEST(MaterialRegistry, DefaultsAreOptionalAndAdmissible) {
  for (const pf::MaterialEntry& e : pf::materialRegistry())
    for (const pf::ParameterSpec& s : e.parameters) {
      SCOPED_TRACE(e.model + ": " + s.name);
      if (s.defaultValue.empty()) continue;
      EXPECT_FALSE(s.required) << "a parameter with a default is never missing";
      if (!s.choices.empty()) {
        EXPECT_NE(std::find(s.choices.begin(), s.choices.end(), s.defaultValue), s.choices.end());
      }
      if (s.kind == pf::ParameterSpec::Kind::Bool) {
        EXPECT_TRUE(s.defaultValue == "true" || s.defaultValue == "false");
      }
      if (s.kind == pf::ParameterSpec::Kind::Double || s.kind == pf::ParameterSpec::Kind::Int) {
        EXPECT_EQ(s.rangeError(std::stod(s.defaultValue)), "");
      }
    }
}

TEST(MaterialRegistry, InputLayerRefusesValuesOutsideTheSpecs) {
  for (const pf::MaterialEntry& e : pf::materialRegistry()) {
    const Teuchos::ParameterList base = minimalList(e, false);
    ASSERT_TRUE(base.isParameter("Material Model")) << e.model;
    // What the list leaves out comes back as the spec's default, and has() stays false.
    const pf::MaterialInput in = pf::materialInputFor(base, "M", kFile);
    int tried = 0;
    for (const pf::ParameterSpec& s : e.parameters) {
      SCOPED_TRACE(e.model + ": " + s.name);
      if (!s.defaultValue.empty() && !base.isParameter(s.name)) {
        EXPECT_FALSE(in.has(s.name));
        if (s.kind == pf::ParameterSpec::Kind::String) EXPECT_EQ(in.text(s.name), s.defaultValue);
        else EXPECT_NO_THROW(in.get(s.name));
      }
      Teuchos::ParameterList bad = base;
      if (s.hasRange() && s.kind != pf::ParameterSpec::Kind::Bool) setValue(bad, s, outside(s));
      else if (!s.choices.empty()) bad.set(s.name, std::string("Not A Choice"));
      else continue;
      EXPECT_INPUT_ERROR(pf::materialInputFor(bad, "M", kFile), kFile, "'" + s.name + "'");
      ++tried;
    }
    EXPECT_GE(tried, 3) << e.model << ": Density, a modulus and Thickness at least declare a range";
  }
}

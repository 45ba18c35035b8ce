#pragma once
// Peridigm's compute classes (deck list "Compute Class Parameters", input/Deck.hpp ComputeSpec) as global outputs:
// each reduces one output variable over its points (a block's, a node set's, or the one point nearest a
// position) by Sum, Minimum or Maximum, component by component. The caller says which owned points each compute
// covers and how to read a variable at a point; evaluate() is collective and returns the values in names() order.
#include <functional>
#include <string>
#include <vector>

#include "input/Deck.hpp"

namespace pf {

class Communicator;

class ComputeClasses {
 public:
  // points: owned-local indices of the points this rank contributes; vector: the variable has 3 components.
  void add(const ComputeSpec& spec, std::vector<int> points, bool vector);
  bool empty() const { return computes_.empty(); }
  // Exodus global / history names: the Output Label, or Label X, Y, Z for a vector variable (Peridigm's).
  std::vector<std::string> names() const;
  // value(variable, component, owned-local point). Collective.
  std::vector<double> evaluate(const Communicator& comm,
                               const std::function<double(const std::string&, int, int)>& value) const;

 private:
  struct Compute {
    ComputeSpec spec;
    std::vector<int> points;
    bool vector = false;
    ComputeSpec::Calculation calculation = ComputeSpec::Calculation::Sum;  // Sum for Nearest_Point_Data
  };
  std::vector<Compute> computes_;
};

}  // namespace pf

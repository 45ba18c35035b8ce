#pragma once
// Peridigm's interface file for Discretization/Construct Interfaces (Peridigm_InterfaceData.cpp): `Interfaces.e` in
// the working directory, the mesh's nodes (by id) and one QUAD4 (block 1) or TRI3 (block 2) element per interface
// (output/InterfaceMesh.hpp), with the element variable interface_aperture, |y_R - y_L| - |x_R - x_L| of the two
// elements' points. Peridigm writes each output's values before it updates them: the file holds at each output the
// apertures of the one before (0 at the first), and so does this one. One merged file at every number of ranks.
#include <string>
#include <vector>

#include "input/Deck.hpp"
#include "model/Model.hpp"
#include "output/InterfaceMesh.hpp"

namespace pf {

class InterfaceOutput {
 public:
  // Collective: builds the owned points' interfaces, gathers them on rank 0 in Peridigm's order (by self's file
  // position, then the neighbour's) and writes the file's mesh there. InputError for a mesh Peridigm's rule does
  // not read (InterfaceMesh.hpp) or a file that cannot be written.
  InterfaceOutput(const Deck& deck, const Model& model, const std::string& inputFile);
  ~InterfaceOutput();
  InterfaceOutput(const InterfaceOutput&) = delete;
  InterfaceOutput& operator=(const InterfaceOutput&) = delete;
  // Collective: one output at `time` of displacements u (3 per owned node).
  void write(double time, const std::vector<double>& u);
  static const char* fileName() { return "Interfaces.e"; }

 private:
  const Model& model_;
  std::string inputFile_;
  std::vector<int> left_, right_;  // this rank's interfaces: owned index and overlap index of the two points
  std::vector<double> keys_;       // their (left, right) file positions, for rank 0's order
  std::vector<int> order_;         // rank 0: gathered position -> file position of each interface
  std::vector<int> sizes_;         // rank 0: nodes of each interface, in file order
  std::vector<double> pending_;    // rank 0: the values the next output writes, in file order
  int exoid_ = -1, step_ = 0;
  void fail(const std::string& msg) const;
  void writeMesh(const std::vector<std::vector<long long>>& faces, const MeshConnectivity& conn,
                 const std::string& meshFile);
};

}  // namespace pf

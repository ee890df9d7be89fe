#pragma once
// The data of a `char_meca` concept (AFFE_CHAR_MECA): dualised kinematic conditions (DDL_IMPO,
// FACE_IMPO, LIAISON_DDL, LIAISON_UNIF, LIAISON_SOLIDE) as linear relations sum(c_i u_i) = value
// that the assembly enforces with one Lagrange multiplier each (so their reactions exist), and
// loads: nodal forces, pressures and forces on skin cells, forces per unit volume, gravity.
// Values are those at load multiplier 1 (EXCIT FONC_MULT scales the whole load).

#include "interpreter/Value.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace stella {

class Model;

struct RelationTerm {
  NodeId node = 0;
  int component = 0; // 0 = DX, 1 = DY, 2 = DZ
  double coefficient = 1.0;
};

struct LinearRelation {
  std::vector<RelationTerm> terms;
  double value = 0.0;
  std::string origin; // the keyword, e.g. "DDL_IMPO"
};

struct NodalForce {
  NodeId node = 0;
  int component = 0;
  double value = 0.0;
};

struct CellPressure {
  CellId cell = 0;
  double pressure = 0.0;
};

struct CellForce {
  CellId cell = 0;
  std::array<double, 3> force{}; // per unit area (skin cells) or volume (volume cells)
};

struct Gravity {
  std::vector<CellId> cells;            // volume cells
  std::array<double, 3> acceleration{}; // GRAVITE * DIRECTION (normalised)
};

class MechanicalLoad : public ConceptData {
public:
  std::shared_ptr<const Model> model;
  std::vector<LinearRelation> relations;
  std::vector<NodalForce> nodalForces;
  std::vector<CellPressure> pressures;  // skin cells
  std::vector<CellForce> surfaceForces; // skin cells (FORCE_CONTOUR, FORCE_FACE)
  std::vector<CellForce> volumeForces;  // volume cells (FORCE_INTERNE)
  std::vector<Gravity> gravity;         // PESANTEUR (needs RHO)

  bool hasForces() const {
    return !nodalForces.empty() || !pressures.empty() || !surfaceForces.empty() || !volumeForces.empty() ||
           !gravity.empty();
  }
};

} // namespace stella

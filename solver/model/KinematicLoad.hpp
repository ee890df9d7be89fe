#pragma once
// The data of a `char_cine_meca` concept (AFFE_CHAR_CINE MECA_IMPO): displacement components
// imposed by elimination of the equations (no multiplier, no reaction unknown).

#include "interpreter/Value.hpp"
#include "solver/mesh/Mesh.hpp"

#include <memory>
#include <vector>

namespace stella {

class Model;

struct ImposedDof {
  NodeId node = 0;
  int component = 0;
  double value = 0.0;
};

class KinematicLoad : public ConceptData {
public:
  std::shared_ptr<const Model> model;
  std::vector<ImposedDof> imposed;
};

} // namespace stella

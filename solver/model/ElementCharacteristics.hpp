#pragma once
// The data of a `cara_elem` concept (AFFE_CARA_ELEM): characteristics of the elements that the
// mesh does not carry. Implemented: translational stiffness of discrete springs (DISCRET /
// DISCRET_2D, CARA='K_T_D_N', diagonal in the global frame) on the POI1 cells that carry
// 'DIS_T' / '2D_DIS_T' elements. The spring of a POI1 cell on node n adds k_c to the stiffness
// of (n, component c) and k_c u_c to its internal forces (notice section 4.4.2: springs hold the
// rigid-body motions of a body that nothing else holds). The keywords are read by
// solver/inputs/ElementCharacteristicsReader.

#include "interpreter/Value.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <memory>
#include <vector>

namespace stella {

class Model;

struct DiscreteSpring {
  CellId cell = 0;
  NodeId node = 0;
  std::array<double, 3> stiffness{}; // KX, KY (, KZ) in the global frame
};

class ElementCharacteristics : public ConceptData {
public:
  std::shared_ptr<const Model> model;
  std::vector<DiscreteSpring> springs; // one per discrete cell given a stiffness, in cell order
};

// Checks that every discrete element of the model has a stiffness: CARA_5 naming the first one
// without, and saying to give CARA_ELEM (null `cara` when the command has none).
void checkDiscreteElementsCovered(const Model& model, const ElementCharacteristics* cara,
                                  const SourceLocation& at);

} // namespace stella

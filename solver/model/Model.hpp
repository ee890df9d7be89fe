#pragma once
// The data of a `modele` concept (AFFE_MODELE): which cells of the mesh carry a finite element
// and of which kind. Volume elements of a modelling ('3D', 'D_PLAN', 'C_PLAN', 'AXIS', and the
// mean-dilatation '3D_SI', 'D_PLAN_SI', 'AXIS_SI') on the
// cells of the modelling's dimension; skin elements (for pressures, surface forces and contact)
// on the cells one dimension lower; discrete springs ('DIS_T', '2D_DIS_T') on POI1 cells.
// Every node touched by an element carries the displacement components DX, DY (, DZ).

#include "interpreter/Value.hpp"
#include "solver/fem/Modelling.hpp"
#include "solver/mesh/Mesh.hpp"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {

enum class ElementKind : std::uint8_t { None, Volume, Skin, Discrete };

struct ModelCell {
  ElementKind kind = ElementKind::None;
  fem::Modelling modelling = fem::Modelling::ThreeD;             // for Volume and Skin cells
  fem::VolumeStrain volumeStrain = fem::VolumeStrain::Pointwise; // Volume cells of the '_SI' modelisations
};

class Model : public ConceptData {
public:
  explicit Model(std::shared_ptr<const Mesh> m);

  std::shared_ptr<const Mesh> mesh;
  std::vector<ModelCell> cells;  // one per mesh cell
  std::vector<bool> activeNodes; // nodes carrying displacement DOFs
  int components = 3;            // DX, DY (2D models) or DX, DY, DZ
  // The volume modelling of the model (a model mixes no two volume modellings).
  fem::Modelling modelling = fem::Modelling::ThreeD;
  bool hasVolume = false;

  const ModelCell& cell(CellId c) const { return cells[static_cast<std::size_t>(c)]; }
  bool nodeActive(NodeId n) const { return activeNodes[static_cast<std::size_t>(n)]; }
  // Cells of the given kind, in mesh order.
  std::vector<CellId> cellsOfKind(ElementKind k) const;
  // "DX", "DY", "DZ" for 0, 1, 2; the index of a component name or nullopt.
  static std::string componentName(int c);
  std::optional<int> componentIndex(const std::string& name) const;
  std::vector<std::string> componentNames() const;
};

} // namespace stella

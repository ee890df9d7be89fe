#pragma once
// The data of a `cham_mater` concept (AFFE_MATERIAU): the material of each cell (later
// occurrences of AFFE override earlier ones, as in code_aster).

#include "solver/mesh/Mesh.hpp"
#include "solver/model/Material.hpp"

#include <memory>
#include <vector>

namespace stella {

class MaterialField : public ConceptData {
public:
  std::shared_ptr<const Mesh> mesh;
  std::vector<std::shared_ptr<const Material>> materials; // distinct materials
  std::vector<int> cellMaterial;                          // per cell: index into materials, or -1

  const Material* material(CellId c) const {
    const int i = cellMaterial[static_cast<std::size_t>(c)];
    return i < 0 ? nullptr : materials[static_cast<std::size_t>(i)].get();
  }
};

} // namespace stella

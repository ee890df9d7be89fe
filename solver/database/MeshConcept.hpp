#pragma once
// The data of a `maillage` concept: a shared mesh (results and models keep it alive).
// Shared contract (written first by the lead): extend it, do not replace it.

#include "interpreter/Value.hpp"
#include "solver/mesh/Mesh.hpp"

#include <memory>

namespace stella {

class MeshConcept : public ConceptData {
public:
  explicit MeshConcept(std::shared_ptr<Mesh> m) : mesh(std::move(m)) {}
  std::shared_ptr<Mesh> mesh;
};

} // namespace stella

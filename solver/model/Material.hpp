#pragma once
// The data of a `mater` concept (DEFI_MATERIAU): linear elasticity (ELAS: E, NU, RHO, ALPHA)
// and linear isotropic hardening (ECRO_LINE: D_SIGM_EPSI, SY).

#include "interpreter/Value.hpp"

#include <optional>
#include <string>

namespace stella {

struct ElasticMaterial {
  double youngModulus = 0.0;       // E
  double poissonRatio = 0.0;       // NU
  std::optional<double> density;   // RHO
  std::optional<double> expansion; // ALPHA
};

struct LinearHardeningMaterial {
  double tangentModulus = 0.0; // D_SIGM_EPSI
  double yieldStress = 0.0;    // SY
};

class Material : public ConceptData {
public:
  std::string name;
  std::optional<ElasticMaterial> elastic;
  std::optional<LinearHardeningMaterial> hardening;
};

} // namespace stella

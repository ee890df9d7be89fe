#pragma once
// The mechanical modellings of AFFE_MODELE (MODELISATION='3D', 'D_PLAN', 'C_PLAN', 'AXIS') and
// the strain/stress layout each one uses.
//
// Strains and stresses are vectors in code_aster's component order: 3D (XX, YY, ZZ, XY, XZ, YZ),
// 2D (XX, YY, ZZ, XY). Stresses carry tensor components (SIXY = sigma_xy); strain vectors used
// with B matrices carry engineering shears (2 eps_xy), so that sigma . eps is the energy density
// and B^T D B the stiffness. In AXIS, X is the radius r, Y the axial coordinate and ZZ the hoop
// component (eps_zz = u_r / r); integrals are per radian (weight r, no 2 pi), as in code_aster.

#include <optional>
#include <string_view>

namespace stella::fem {

enum class Modelling { ThreeD, PlaneStrain, PlaneStress, Axisymmetric };

// How the volumetric part of the strain is taken at the Gauss points.
// - Pointwise: the strain of the displacement at the point (fully integrated cells).
// - CellMean: the mean-dilatation ("B-bar") treatment of the '_SI' modelisations (3D_SI,
//   D_PLAN_SI, AXIS_SI): the volumetric strain tr(eps) at every point is replaced by its mean
//   over the cell (weighted like the stiffness integral: by r in AXIS), the deviatoric part is
//   kept. Equivalent to integrating the volumetric term with one point; the cell can then flow
//   isochorically (plastic flow, nearly incompressible elasticity) without volumetric locking.
//   In D_PLAN_SI eps_zz is zero on average over a cell, not at each point.
enum class VolumeStrain { Pointwise, CellMean };

// A MODELISATION name of AFFE_MODELE read into a modelling and its volumetric treatment.
struct ModellingVariant {
  Modelling modelling = Modelling::ThreeD;
  VolumeStrain volumeStrain = VolumeStrain::Pointwise;
};

constexpr int spaceDimension(Modelling m) {
  return m == Modelling::ThreeD ? 3 : 2;
}
constexpr int strainSize(Modelling m) {
  return m == Modelling::ThreeD ? 6 : 4;
}

constexpr std::string_view modellingName(Modelling m) {
  switch (m) {
  case Modelling::ThreeD:
    return "3D";
  case Modelling::PlaneStrain:
    return "D_PLAN";
  case Modelling::PlaneStress:
    return "C_PLAN";
  case Modelling::Axisymmetric:
    return "AXIS";
  }
  return "?";
}

inline std::optional<Modelling> modellingFromName(std::string_view n) {
  for (Modelling m :
       {Modelling::ThreeD, Modelling::PlaneStrain, Modelling::PlaneStress, Modelling::Axisymmetric}) {
    if (modellingName(m) == n) {
      return m;
    }
  }
  return std::nullopt;
}

// '3D', 'D_PLAN', 'C_PLAN', 'AXIS' and the mean-dilatation '3D_SI', 'D_PLAN_SI', 'AXIS_SI'.
inline std::optional<ModellingVariant> modellingVariantFromName(std::string_view n) {
  constexpr std::string_view suffix = "_SI";
  if (n.size() > suffix.size() && n.substr(n.size() - suffix.size()) == suffix) {
    const auto base = modellingFromName(n.substr(0, n.size() - suffix.size()));
    if (base && *base != Modelling::PlaneStress) {
      return ModellingVariant{*base, VolumeStrain::CellMean};
    }
    return std::nullopt;
  }
  if (const auto base = modellingFromName(n)) {
    return ModellingVariant{*base, VolumeStrain::Pointwise};
  }
  return std::nullopt;
}

} // namespace stella::fem

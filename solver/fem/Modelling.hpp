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

} // namespace stella::fem

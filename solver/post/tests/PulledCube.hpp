#pragma once
// The unit cube of testcases/plate_plasticity (HEXA8, face groups X0, Y0, Z0, X1), elastic
// (E = 200000, NU = 0.3) in 3D, as the start of the command files of the post-processing tests.

#include <string>

namespace stella::testing {

inline const char* const kCubeMesh = "testcases/plate_plasticity/hexa8.msh";

// From DEBUT() to the material field CM: the mesh on unit 20, the node group X1, the model MO.
inline const std::string kCubeModel = R"(
DEBUT()
M = LIRE_MAILLAGE(FORMAT='GMSH', UNITE=20)
M = DEFI_GROUP(reuse=M, MAILLAGE=M, CREA_GROUP_NO=_F(GROUP_MA='X1'))
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=MAT))
)";

// kCubeModel, then the cube pulled by DX = 1e-3 imposed on X1 with the symmetry planes X0, Y0,
// Z0 (load BC), solved by MECA_STATIQUE into R: uniform SIXX = 200, DY = -0.3e-3 y.
inline const std::string kPulledCube =
    kCubeModel +
    R"(BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_MA='X0', DX=0.0), _F(GROUP_MA='Y0', DY=0.0),
                                          _F(GROUP_MA='Z0', DZ=0.0), _F(GROUP_MA='X1', DX=1.0e-3)))
R = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=BC))
)";

} // namespace stella::testing

// IMPR_RESU FORMAT='MED' writes the MED format that VERSION_MED asks (3.3.1, 4.0.0 or 4.1.0, the
// catalogue's values; 3.3.1 by default, as code_aster): h5py reads the version from the file's
// INFOS_GENERALES, and meshio (the common Python reader) reads each file's DEPL, compared with the closed
// form. Before, every file was MED 4.1 whatever VERSION_MED said. Appending to a unit that holds another
// version is refused (one file holds one version).
//
// Problem: a 2 x 1 x 1 bar of two HEXA8, E = 200000, NU = 0.3, symmetry planes x = 0, y = 0,
// z = 0 and DX = 2e-3 on x = 2: a uniform state, DX = 1e-3 x, DY = -0.3e-3 y, DZ = -0.3e-3 z,
// which the element reproduces exactly (tolerance 1e-12 relative, the solver's rounding).

#include "solver/io/MeshIO.hpp"
#include "solver/io/tests/CommRun.hpp"
#include "solver/io/tests/MeshTestUtil.hpp"
#include "solver/mesh/StructuredMesher.hpp"

#include <gtest/gtest.h>

namespace stella {
namespace {

const std::string barStudy = R"(DEBUT()
M = LIRE_MAILLAGE(UNITE=20, FORMAT='MED')
MO = AFFE_MODELE(MAILLAGE=M, AFFE=_F(TOUT='OUI', PHENOMENE='MECANIQUE', MODELISATION='3D'))
MAT = DEFI_MATERIAU(ELAS=_F(E=200000.0, NU=0.3))
CM = AFFE_MATERIAU(MAILLAGE=M, AFFE=_F(TOUT='OUI', MATER=MAT))
BC = AFFE_CHAR_MECA(MODELE=MO, DDL_IMPO=(_F(GROUP_NO='XMIN', DX=0.0), _F(GROUP_NO='YMIN', DY=0.0),
                                          _F(GROUP_NO='ZMIN', DZ=0.0), _F(GROUP_NO='XMAX', DX=2.0e-3)))
RESU = MECA_STATIQUE(MODELE=MO, CHAM_MATER=CM, EXCIT=_F(CHARGE=BC))
)";

const char* const versionCheck = R"py(
import sys, numpy as np, meshio, h5py
for path, want in zip(sys.argv[1::2], sys.argv[2::2]):
    f = h5py.File(path, "r")
    info = f["INFOS_GENERALES"].attrs
    got = (int(info["MAJ"]), int(info["MIN"]))
    assert got == tuple(int(v) for v in want.split(".")[:2]), (path, got, want)
    f.close()
    m = meshio.read(path, file_format="med")
    p = m.points
    d = [v for k, v in m.point_data.items() if k.startswith("RESU____DEPL")]
    assert len(d) == 1, m.point_data.keys()
    ref = np.column_stack([1e-3 * p[:, 0], -0.3e-3 * p[:, 1], -0.3e-3 * p[:, 2]])
    err = abs(d[0] - ref).max() / 2e-3
    print(path, want, "MED %d.%d" % got, "error %.1e" % err)
    assert err < 1e-12, err
print("OK")
)py";

TEST(MedVersion, VersionMedIsTheFormatWrittenAndMeshioReadsEach) {
  const auto dir = testing::tempDir("med_version");
  writeMedMesh(dir / "bar.med", testing::structuredVolume({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}}),
               "BAR");
  const std::string comm =
      barStudy +
      "IMPR_RESU(FORMAT='MED', UNITE=80, RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
      "IMPR_RESU(FORMAT='MED', UNITE=82, VERSION_MED='4.0.0', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
      "IMPR_RESU(FORMAT='MED', UNITE=83, VERSION_MED='4.1.0', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
      "FIN()\n";
  const auto r = testing::runComm(dir, "bar", comm,
                                  {{20, dir / "bar.med"}, {82, dir / "v40.med"}, {83, dir / "v41.med"}});
  ASSERT_EQ(r.diagnostic, JobDiagnostic::Ok) << r.message;
  const auto work = dir / "bar.work";
  EXPECT_EQ(testing::runPython(dir, versionCheck,
                               (dir / "bar.rmed").string() + " 3.3.1 " + (work / "fort.82").string() +
                                   " 4.0.0 " + (work / "fort.83").string() + " 4.1.0"),
            0);
}

TEST(MedVersion, AppendingAnotherVersionIsRefused) {
  const auto dir = testing::tempDir("med_version_mix");
  writeMedMesh(dir / "bar.med", testing::structuredVolume({CellType::HEXA8, {2, 1, 1}, {2, 1, 1}, {0, 0, 0}}),
               "BAR");
  const std::string comm =
      barStudy +
      "IMPR_RESU(FORMAT='MED', UNITE=82, VERSION_MED='3.3.1', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
      "IMPR_RESU(FORMAT='MED', UNITE=82, VERSION_MED='4.1.0', RESU=_F(RESULTAT=RESU, NOM_CHAM='DEPL'))\n"
      "FIN()\n";
  const auto r = testing::runComm(dir, "mix", comm, {{20, dir / "bar.med"}, {82, dir / "mix.med"}});
  EXPECT_NE(r.diagnostic, JobDiagnostic::Ok) << r.message;
  EXPECT_NE(r.message.find("the file is in MED 3.3, VERSION_MED asks 4.1.0"), std::string::npos) << r.message;
}

} // namespace
} // namespace stella

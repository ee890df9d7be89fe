// IMPR_RESU honours FORMAT_R (FORMAT='RESULTAT': the Fortran edit descriptor of the printed values)
// and GMSH VERSION (2.2 written; code_aster's 1.0 / 1.2 $PostFormat views refused by name).
// Before, both were accepted and ignored: every value printed as 1PE13.6.

#include "solver/io/RealEditDescriptor.hpp"
#include "solver/nonlinear/tests/StudyRun.hpp"
#include "solver/post/tests/PulledCube.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace stella {
namespace {

using testing::kCubeMesh;
using testing::kPulledCube;
using testing::runStudy;

std::string formatted(const std::string& descriptor, double value) {
  const auto d = parseRealEditDescriptor(descriptor);
  EXPECT_TRUE(d.has_value()) << descriptor;
  return d ? formatReal(*d, value) : std::string();
}

// Fortran's output for these descriptors, written out by hand from the standard's rules: Ew.d
// without scale factor is 0.<d digits>E+xx, kPEw.d has k digits before the point and d - k + 1
// after, Fw.d is fixed with d decimals, all right-aligned in w characters.
TEST(RealEditDescriptor, WritesAsFortranDoes) {
  EXPECT_EQ(formatted("E12.5", 123.456), " 0.12346E+03");
  EXPECT_EQ(formatted("1PE12.5", 123.456), " 1.23456E+02");
  EXPECT_EQ(formatted("1PE13.5", -123.456), " -1.23456E+02");
  EXPECT_EQ(formatted("1PE21.14", 1.0e-3), " 1.00000000000000E-03");
  EXPECT_EQ(formatted("E12.5", -4.5e-7), "-0.45000E-06");
  EXPECT_EQ(formatted("1PD12.4", 2.0), "  2.0000D+00");
  EXPECT_EQ(formatted("ES12.4", 0.0), "  0.0000E+00");
  EXPECT_EQ(formatted("E12.5", 0.0), " 0.00000E+00");
  EXPECT_EQ(formatted("F10.3", 123.4567), "   123.457");
  EXPECT_EQ(formatted("f8.2", -1.005e1), "  -10.05");
  EXPECT_EQ(formatted("2PE12.4", 123.456), "  12.346E+01");
  for (const char* bad : {"G12.5", "E12", "12.5", "1PF10.3", "E.5", "I8", ""}) {
    EXPECT_FALSE(parseRealEditDescriptor(bad).has_value()) << bad;
  }
}

// The first row of the DEPL table after `from` in `resu`.
std::string firstDeplRow(const std::string& resu, std::size_t from) {
  const auto start = resu.find(" CHAMP DEPL ", from);
  if (start == std::string::npos) {
    return {};
  }
  std::istringstream in(resu.substr(start));
  std::string line;
  std::getline(in, line); // title
  std::getline(in, line); // header
  std::getline(in, line);
  return line;
}

TEST(ImprResuFormat, FormatRSetsThePrintedValues) {
  // DX = 1e-3 on every node of X1 (imposed), so its rows' first value is known exactly.
  const std::string comm =
      kPulledCube +
      "IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='DEPL', GROUP_NO='X1', NOM_CMP='DX'))\n"
      "IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='DEPL', GROUP_NO='X1', NOM_CMP='DX',\n"
      "                                     FORMAT_R='F12.6'))\n"
      "IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='DEPL', GROUP_NO='X1', NOM_CMP='DX',\n"
      "                                     FORMAT_R='E12.5'))\n"
      "FIN()\n";
  auto run = runStudy("impr_format_r", comm, kCubeMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  const std::string resu = run->resu.str();
  const std::string byDefault = firstDeplRow(resu, 0);
  const std::string fixed = firstDeplRow(resu, resu.find(" CHAMP DEPL ") + 1);
  const std::string exponent = firstDeplRow(resu, resu.rfind(" CHAMP DEPL "));
  // Default 1PE21.14: one digit before the point, 14 after, in 21 characters.
  EXPECT_NE(byDefault.find("  1.00000000000000E-03"), std::string::npos) << resu;
  EXPECT_EQ(fixed.substr(fixed.size() - 13), "     0.001000") << resu;
  EXPECT_EQ(exponent.substr(exponent.size() - 13), "  0.10000E-02") << resu;
}

TEST(ImprResuFormat, UnknownFormatRIsRefusedAtItsLine) {
  const std::string comm = kPulledCube + "IMPR_RESU(FORMAT='RESULTAT', RESU=_F(RESULTAT=R, NOM_CHAM='DEPL',\n"
                                         "          FORMAT_R='G12.5'))\nFIN()\n";
  auto run = runStudy("impr_format_bad", comm, kCubeMesh);
  EXPECT_NE(run->failure(), FailureKind::None);
  EXPECT_NE(run->mess().find("impr_format_bad.comm:12:"), std::string::npos) << run->mess();
  EXPECT_NE(run->mess().find("FORMAT_R='G12.5' is not an edit descriptor stella writes"), std::string::npos)
      << run->mess();
}

TEST(ImprResuFormat, GmshVersionWrittenOrRefused) {
  const std::string written = kPulledCube +
                              "IMPR_RESU(FORMAT='GMSH', UNITE=37, VERSION=2.2, RESU=_F(RESULTAT=R, "
                              "NOM_CHAM='DEPL'))\nFIN()\n";
  auto run = runStudy("impr_gmsh_22", written, kCubeMesh);
  ASSERT_EQ(run->failure(), FailureKind::None) << run->mess();
  std::ifstream msh(std::filesystem::temp_directory_path() / "stella_impr_gmsh_22" / "fort.37");
  std::string first;
  std::string version;
  msh >> first >> version;
  EXPECT_EQ(first, "$MeshFormat");
  EXPECT_EQ(version, "2.2");
  const std::string refused = kPulledCube +
                              "IMPR_RESU(FORMAT='GMSH', UNITE=37, VERSION=1.2, RESU=_F(RESULTAT=R, "
                              "NOM_CHAM='DEPL'))\nFIN()\n";
  auto bad = runStudy("impr_gmsh_12", refused, kCubeMesh);
  EXPECT_NE(bad->failure(), FailureKind::None);
  EXPECT_NE(bad->mess().find("VERSION = 1.2"), std::string::npos) << bad->mess();
}

} // namespace
} // namespace stella

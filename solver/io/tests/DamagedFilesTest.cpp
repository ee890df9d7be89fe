// Every file of the damaged corpus (solver/io/tests/damaged/, built by
// tools/mesh/make_damaged_corpus.py) makes its reader raise a UserError whose message names the
// file, with a MESHFILE_* id; never a crash, an HDF5 stack trace or another exception. The good
// files the corpus comes from must load.

#include "interpreter/Diagnostics.hpp"
#include "solver/io/MeshIO.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace stella {
namespace {

const std::filesystem::path corpus = std::filesystem::path(STELLA_SOURCE_DIR) / "solver/io/tests/damaged";

std::vector<std::filesystem::path> filesIn(const std::string& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& e : std::filesystem::directory_iterator(corpus / folder)) {
    files.push_back(e.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

void expectCleanError(const std::filesystem::path& file, MeshFormat format) {
  SCOPED_TRACE(file.filename().string());
  try {
    const Mesh m = readMesh(file, format);
    ADD_FAILURE() << "read without error: " << m.nodeCount() << " nodes, " << m.cellCount() << " cells";
  } catch (const UserError& e) {
    EXPECT_EQ(e.first().id.rfind("MESHFILE_", 0), 0u) << e.first().id;
    EXPECT_NE(e.first().message.find(file.filename().string()), std::string::npos) << e.first().message;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a UserError: " << e.what();
  }
}

TEST(DamagedFiles, GoodFilesLoad) {
  for (const char* f : {"good22.msh", "good41.msh"}) {
    const Mesh m = readGmshMesh(corpus / "good" / f);
    EXPECT_EQ(m.nodeCount(), 9) << f;
    EXPECT_TRUE(m.hasCellGroup("SURFACE")) << f;
  }
  EXPECT_EQ(readAsterMesh(corpus / "good/good.mail").cellCount(), 10);
  EXPECT_EQ(readMedMesh(corpus / "good/good.med").nodeCount(), 12);
}

TEST(DamagedFiles, Gmsh) {
  const auto files = filesIn("msh");
  EXPECT_GE(files.size(), 20u);
  for (const auto& f : files) {
    expectCleanError(f, MeshFormat::Gmsh);
  }
}

TEST(DamagedFiles, Aster) {
  const auto files = filesIn("mail");
  EXPECT_GE(files.size(), 20u);
  for (const auto& f : files) {
    expectCleanError(f, MeshFormat::Aster);
  }
}

TEST(DamagedFiles, Med) {
  const auto files = filesIn("med");
  EXPECT_GE(files.size(), 20u);
  for (const auto& f : files) {
    expectCleanError(f, MeshFormat::Med);
  }
}

TEST(DamagedFiles, MissingFile) {
  for (const auto format : {MeshFormat::Gmsh, MeshFormat::Aster, MeshFormat::Med}) {
    try {
      readMesh(corpus / "no_such_file", format);
      ADD_FAILURE() << "no error";
    } catch (const UserError& e) {
      EXPECT_EQ(e.first().id, "MESHFILE_1");
    }
  }
}

} // namespace
} // namespace stella

// The .export reader: the lines code_aster users write, and clear errors naming the line.

#include "solver/job/Export.hpp"
#include "solver/job/BatchJob.hpp"
#include "solver/job/ExportParameters.hpp"

#include "interpreter/Diagnostics.hpp"
#include "solver/linalg/BlasThreads.hpp"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>

namespace stella {
namespace {

namespace fs = std::filesystem;

class ExportTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("stella-export-test-" + std::to_string(::getpid()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "study.comm") << "DEBUT()\nFIN()\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& text) {
    fs::path p = dir_ / "study.export";
    std::ofstream(p) << text;
    return p;
  }

  // The id and line of the error reading `text`.
  std::pair<std::string, int> errorOf(const std::string& text) {
    try {
      Export::read(write(text));
    } catch (const UserError& e) {
      return {e.first().id, e.first().location.line};
    }
    return {"", 0};
  }

  fs::path dir_;
};

TEST_F(ExportTest, ReadsParametersFilesAndUnits) {
  Export ex = Export::read(write("P time_limit 120\nP testlist submit verification sequential\n\n"
                                 "F comm study.comm D 1\nF mmed mesh.med D 20\nF mess out/study.mess R 6\n"
                                 "R base out/base RC 0\n"));
  EXPECT_EQ(ex.parameter("time_limit"), std::vector<std::string>{"120"});
  EXPECT_EQ(ex.parameter("testlist").size(), 3u);
  ASSERT_EQ(ex.entries.size(), 4u);
  EXPECT_EQ(ex.commandFiles().size(), 1u);
  EXPECT_EQ(ex.entries[1].unit, 20);
  EXPECT_TRUE(ex.entries[1].data);
  EXPECT_EQ(ex.entries[1].path, dir_ / "mesh.med"); // relative to the export's folder
  EXPECT_TRUE(ex.entries[2].result);
  EXPECT_TRUE(ex.entries[3].directory);
  EXPECT_EQ(ex.entries[3].line, 7);
}

TEST_F(ExportTest, UnknownLineTypeNamesTheLine) {
  auto [id, line] = errorOf("F comm study.comm D 1\nX foo bar\n");
  EXPECT_EQ(id, "EXPORT_1");
  EXPECT_EQ(line, 2);
}

TEST_F(ExportTest, MissingCommandFileNamesTheLine) {
  auto [id, line] = errorOf("P ncpus 1\nF comm missing.comm D 1\n");
  EXPECT_EQ(id, "EXPORT_7");
  EXPECT_EQ(line, 2);
}

TEST_F(ExportTest, MalformedFileLines) {
  EXPECT_EQ(errorOf("F comm study.comm D\n").first, "EXPORT_2");
  EXPECT_EQ(errorOf("F comm study.comm D 1\nF mmed m.med X 20\n").first, "EXPORT_3");
  EXPECT_EQ(errorOf("F comm study.comm D 1\nF mmed m.med D twenty\n").first, "EXPORT_4");
  EXPECT_EQ(errorOf("F comm study.comm D 1\nF mmed m.med D 6\n").first, "EXPORT_5");
  EXPECT_EQ(errorOf("P ncpus 1\n").first, "EXPORT_8");
}

TEST_F(ExportTest, NcpusIsAWholeNumberOfThreads) {
  for (const char* bad : {"0", "two", "2.5", "1 2"}) {
    RunOptions options;
    options.echo = false;
    try {
      runExport(Export::read(write(std::string("P ncpus ") + bad + "\nF comm study.comm D 1\n")), options);
      ADD_FAILURE() << "P ncpus " << bad << " accepted";
    } catch (const UserError& e) {
      EXPECT_EQ(e.first().id, "EXPORT_10") << bad;
    }
  }
}

// P mpi_nbcpu (doc/parallel.md): a whole number of MPI processes from 1 to 1024, EXPORT_12 else.
TEST_F(ExportTest, MpiNbcpuIsAWholeNumberOfProcesses) {
  EXPECT_EQ(mpiProcessesOf(Export::read(write("F comm study.comm D 1\n"))), 1);
  EXPECT_EQ(mpiProcessesOf(Export::read(write("P mpi_nbcpu 4\nF comm study.comm D 1\n"))), 4);
  for (const char* bad : {"0", "two", "2.5", "1 2", "2000"}) {
    try {
      mpiProcessesOf(Export::read(write(std::string("P mpi_nbcpu ") + bad + "\nF comm study.comm D 1\n")));
      ADD_FAILURE() << "P mpi_nbcpu " << bad << " accepted";
    } catch (const UserError& e) {
      EXPECT_EQ(e.first().id, "EXPORT_12") << bad;
    }
  }
}

// P ncpus sets the BLAS threads of the job's factorisations (OpenBLAS pthread, tools/install-deps)
// and the message file says so; the default (1) says nothing.
TEST_F(ExportTest, NcpusSetsTheBlasThreads) {
  if (linalg::blasDescription().find("SINGLE_THREADED") != std::string::npos ||
      linalg::blasDescription().empty()) {
    GTEST_SKIP() << "serial BLAS: " << linalg::blasDescription();
  }
  unsetenv("STELLA_BLAS_THREADS");
  RunOptions options;
  options.echo = false;
  auto message = [&](const std::string& ncpus) {
    runExport(Export::read(write(ncpus + "F comm study.comm D 1\nF mess study.mess R 6\n")), options);
    std::ifstream in(dir_ / "study.mess");
    return std::string(std::istreambuf_iterator<char>(in), {});
  };
  EXPECT_NE(message("P ncpus 2\n").find("BLAS threads of the factorisations: 2 (P ncpus)"),
            std::string::npos);
  EXPECT_EQ(linalg::blasThreads(), 2);
  EXPECT_EQ(message("").find("BLAS threads"), std::string::npos);
  EXPECT_EQ(linalg::blasThreads(), 1);
}

TEST_F(ExportTest, MissingDataFileIsNotAnErrorAtRead) {
  // A data file the study never opens may be missing: that is an alarm at the end of the run.
  Export ex = Export::read(write("F comm study.comm D 1\nF datg absent.datg D 16\n"));
  EXPECT_EQ(ex.entries.size(), 2u);
}

} // namespace
} // namespace stella

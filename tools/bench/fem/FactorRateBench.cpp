// The factorisation's achieved rate against the machine's dense limit (issue 20 "know the
// limit"; report: doc/bench/factor-rate.md).
//
//   stella-bench-factor-rate [--threads 1,2] [--dgemm N] [--cholmod METIS] [--mumps AUTO] DIVISIONS...
//
// For each BLAS thread count: the rate of dgemm (C = A B, N x N, 2 N^3 flops, best of 3) and,
// for each size of the clamped HEXA8 cube (CubeStiffness.hpp), one analysis and factorisation by
// CHOLMOD (MULT_FRONT) and by MUMPS with the given RENUM (default: the catalogue's defaults,
// METIS and AUTO; the sequential MUMPS has no METIS); the backend's own flop count
// (cholmod_common::fl, MUMPS RINFOG(3)) divided by the factorisation's wall time is the achieved
// rate, given as a fraction of dgemm's at the same thread count. The solution of each is checked
// (relative residual) and the two backends' solutions compared.
// Output: one line "key=value ..." per measurement.

#include "solver/linalg/BlasThreads.hpp"
#include "solver/linalg/LinearSolver.hpp"
#include "solver/nonlinear/PhaseTimes.hpp"
#include "tools/bench/fem/CubeStiffness.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <string>
#include <vector>

extern "C" void dgemm_(const char* ta, const char* tb, const int* m, const int* n, const int* k,
                       const double* alpha, const double* a, const int* lda, const double* b, const int* ldb,
                       const double* beta, double* c, const int* ldc);

using namespace stella;

namespace {

double seconds(std::chrono::steady_clock::time_point since) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - since).count();
}

// GFLOP/s of an n x n dgemm, best of three.
double dgemmRate(int n) {
  const Eigen::MatrixXd a = Eigen::MatrixXd::Random(n, n), b = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(n, n);
  const double one = 1.0, zero = 0.0;
  double best = 1e300;
  for (int r = 0; r < 3; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    dgemm_("N", "N", &n, &n, &n, &one, a.data(), &n, b.data(), &n, &zero, c.data(), &n);
    best = std::min(best, seconds(t0));
  }
  return 2.0 * n * static_cast<double>(n) * n / best / 1e9;
}

std::vector<int> parseList(const char* text) {
  std::vector<int> v;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    v.push_back(std::stoi(item));
  }
  return v;
}

} // namespace

int main(int argc, char** argv) {
  std::vector<int> threads{1, 2}, sizes;
  int dgemmSize = 2000;
  std::string cholmodRenum = "METIS", mumpsRenum = "AUTO";
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--threads") == 0 && i + 1 < argc) {
      threads = parseList(argv[++i]);
    } else if (std::strcmp(argv[i], "--dgemm") == 0 && i + 1 < argc) {
      dgemmSize = std::stoi(argv[++i]);
    } else if (std::strcmp(argv[i], "--cholmod") == 0 && i + 1 < argc) {
      cholmodRenum = argv[++i];
    } else if (std::strcmp(argv[i], "--mumps") == 0 && i + 1 < argc) {
      mumpsRenum = argv[++i];
    } else {
      sizes.push_back(std::stoi(argv[i]));
    }
  }
  if (sizes.empty()) {
    std::fprintf(stderr, "usage: stella-bench-factor-rate [--threads 1,2] [--dgemm N] [--cholmod R] [--mumps "
                         "R] DIVISIONS...\n");
    return 2;
  }
  std::printf("blas=\"%s\"\n", linalg::blasDescription().c_str());
  std::map<int, double> dgemm;
  for (int t : threads) {
    const int effective = linalg::setBlasThreads(t);
    dgemm[t] = dgemmRate(dgemmSize);
    std::printf("dgemm n=%d threads=%d effective_threads=%d gflops=%.2f\n", dgemmSize, t, effective,
                dgemm[t]);
    std::fflush(stdout);
  }
  for (int n : sizes) {
    const bench::CubeSystem cube = bench::hexa8Cube(n);
    for (int t : threads) {
      linalg::setBlasThreads(t);
      Eigen::VectorXd first;
      for (auto method : {linalg::SolverMethod::MultFront, linalg::SolverMethod::Mumps}) {
        linalg::SolverOptions o;
        o.method = method;
        o.renumbering = method == linalg::SolverMethod::Mumps ? mumpsRenum : cholmodRenum;
        auto solver = linalg::makeLinearSolver(o, linalg::MatrixKind::SymmetricPositiveDefinite);
        auto t0 = std::chrono::steady_clock::now();
        solver->analyse(cube.k);
        const double tAnalyse = seconds(t0);
        t0 = std::chrono::steady_clock::now();
        solver->factorise(cube.k);
        const double tFactorise = seconds(t0);
        Eigen::VectorXd u = cube.f;
        solver->solve(u);
        const double residual = (cube.k.multiply(u) - cube.f).norm() / cube.f.norm();
        const double difference = first.size() == 0 ? 0.0 : (u - first).norm() / first.norm();
        if (first.size() == 0) {
          first = u;
        }
        const double gflops = solver->factorisationFlops() / tFactorise / 1e9;
        std::printf("factor divisions=%d dofs=%d threads=%d backend=%s ordering=%s t_analyse=%.3f "
                    "t_factorise=%.3f gflop=%.2f gflops=%.2f dgemm_fraction=%.3f residual=%.1e "
                    "difference=%.1e peak_mb=%.0f\n",
                    n, cube.k.pattern().size, t, std::string(solver->backendName()).c_str(),
                    solver->orderingUsed().c_str(), tAnalyse, tFactorise, solver->factorisationFlops() / 1e9,
                    gflops, gflops / dgemm[t], residual, difference, peakResidentMegabytes());
        std::fflush(stdout);
      }
    }
  }
  return 0;
}

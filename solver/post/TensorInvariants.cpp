// TensorInvariants: von Mises, Tresca, principal values and the SIEQ vector.

#include "solver/post/TensorInvariants.hpp"

#include "interpreter/Diagnostics.hpp"

#include <algorithm>
#include <cmath>

namespace stella {

Eigen::Matrix3d tensorFromComponents(std::span<const double> c) {
  STELLA_ASSERT(c.size() == 4 || c.size() == 6, "a tensor has 4 or 6 components");
  const double xz = c.size() == 6 ? c[4] : 0.0;
  const double yz = c.size() == 6 ? c[5] : 0.0;
  Eigen::Matrix3d t;
  t << c[0], c[3], xz, c[3], c[1], yz, xz, yz, c[2];
  return t;
}

double vonMises(const Eigen::Matrix3d& t) {
  const Eigen::Matrix3d s = t - t.trace() / 3.0 * Eigen::Matrix3d::Identity();
  return std::sqrt(1.5 * s.cwiseProduct(s).sum());
}

PrincipalValues principalValues(const Eigen::Matrix3d& t) {
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(t); // ascending eigenvalues
  PrincipalValues p{solver.eigenvalues(), solver.eigenvectors()};
  for (int i = 0; i < 3; ++i) {
    Eigen::Index k = 0;
    p.vectors.col(i).cwiseAbs().maxCoeff(&k);
    if (p.vectors(k, i) < 0.0) {
      p.vectors.col(i) = -p.vectors.col(i);
    }
  }
  return p;
}

double tresca(const Eigen::Matrix3d& t) {
  const Eigen::Vector3d v = principalValues(t).values;
  return v(2) - v(0);
}

const std::vector<std::string>& equivalentStressComponents() {
  static const std::vector<std::string> names{"VMIS",     "TRESCA",   "PRIN_1",   "PRIN_2",   "PRIN_3",
                                              "VMIS_SG",  "VECT_1_X", "VECT_1_Y", "VECT_1_Z", "VECT_2_X",
                                              "VECT_2_Y", "VECT_2_Z", "VECT_3_X", "VECT_3_Y", "VECT_3_Z",
                                              "TRSIG",    "TRIAX"};
  return names;
}

void equivalentStress(const Eigen::Matrix3d& t, std::span<double> out) {
  STELLA_ASSERT(out.size() == 17, "SIEQ has 17 components");
  const double vmis = vonMises(t);
  const PrincipalValues p = principalValues(t);
  const double trace = t.trace();
  out[0] = vmis;
  out[1] = p.values(2) - p.values(0);
  for (int i = 0; i < 3; ++i) {
    out[2 + static_cast<std::size_t>(i)] = p.values(i);
    for (int k = 0; k < 3; ++k) {
      out[6 + static_cast<std::size_t>(3 * i + k)] = p.vectors(k, i);
    }
  }
  out[5] = trace >= 0.0 ? vmis : -vmis;
  out[15] = trace;
  out[16] = vmis > 1.0e-10 * std::fabs(trace) ? trace / 3.0 / vmis : 0.0;
}

} // namespace stella

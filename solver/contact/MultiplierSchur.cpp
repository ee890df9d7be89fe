// The dense solve of the multipliers' Schur complement (MultiplierSchur.hpp).

#include "solver/contact/MultiplierSchur.hpp"

#include "solver/nonlinear/SaddleSolver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace stella::contact {

Eigen::VectorXd solveMultiplierSchur(const Eigen::MatrixXd& s, const Eigen::VectorXd& rhs, bool symmetric,
                                     const std::function<void(Eigen::Index)>& redundant) {
  if (!symmetric) {
    // The only non-symmetric factorisation (dense, of the multipliers); K itself stays symmetric.
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(s);
    if (!lu.isInvertible()) {
      redundant(0);
      throw std::logic_error("solveMultiplierSchur: the redundancy report returned");
    }
    return lu.solve(rhs);
  }
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(0.5 * (s + s.transpose()));
  const Eigen::VectorXd d = ldlt.vectorD();
  const double scale = d.cwiseAbs().maxCoeff();
  for (Eigen::Index p = 0; p < s.rows(); ++p) {
    if (!(std::fabs(d(p)) > 1e-12 * scale)) {
      const Eigen::PermutationMatrix<Eigen::Dynamic> perm(ldlt.transpositionsP());
      const Eigen::PermutationMatrix<Eigen::Dynamic> inverse(perm.inverse());
      redundant(inverse.indices()(p));
      throw std::logic_error("solveMultiplierSchur: the redundancy report returned");
    }
  }
  return ldlt.solve(rhs);
}

void applyMultiplierForces(const Eigen::VectorXd& f, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                           SaddleSolver& solver) {
  Eigen::VectorXd dx;
  Eigen::VectorXd dy;
  solver.solve(f, Eigen::VectorXd::Zero(dlambda.size()), Eigen::VectorXd::Zero(ddu.size()), dx, dy);
  ddu -= dx;
  if (dy.size() == dlambda.size()) {
    dlambda -= dy;
  }
}

Eigen::MatrixXd
schurByColumnBlocks(Eigen::Index m, Eigen::Index n, SaddleSolver& solver,
                    const std::function<void(Eigen::Index, Eigen::Ref<Eigen::VectorXd>)>& column,
                    const std::function<void(Eigen::Index, const Eigen::MatrixXd&,
                                             Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>)>& row) {
  constexpr Eigen::Index block = 64;
  Eigen::MatrixXd s = Eigen::MatrixXd::Zero(m, m);
  for (Eigen::Index first = 0; first < m; first += block) {
    const Eigen::Index cols = std::min(block, m - first);
    Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n, cols);
    for (Eigen::Index j = 0; j < cols; ++j) {
      column(first + j, x.col(j));
    }
    solver.solveHomogeneous(x); // K^-1 C^T
    for (Eigen::Index i = 0; i < m; ++i) {
      row(i, x, s.row(i).segment(first, cols));
    }
  }
  return s;
}

} // namespace stella::contact

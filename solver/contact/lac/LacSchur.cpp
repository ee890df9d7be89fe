// The Schur complement of the LAC multipliers in contact and in stick (LacContactConstraint.hpp,
// LacFriction.cpp).

#include "solver/contact/lac/LacContactConstraint.hpp"

#include "solver/contact/MultiplierSchur.hpp"

#include "solver/nonlinear/SaddleSolver.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace stella::contact::lac {

// Eliminates the multipliers of `rows` (B = dG_P / L_P or dS_P / L_P, y = L_P dlambda) by their
// Schur complement. Force columns the same, but for the pressure of a patch sliding with friction:
// its friction force -mu |lambda_P| sum_a qhat_a dS_P,a (qhat = q/|q|, sign(q) in 2D) follows
// lambda_P, the column (dG_P - mu sum_a qhat_a dS_P,a) / L_P, and the (small, dense) Schur
// complement is non-symmetric (LU).
void LacContactConstraint::eliminate(const Eigen::VectorXd& u, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                                     SaddleSolver& solver, const std::vector<SchurRow>& rows) {
  const auto gradientOf = [this](const SchurRow& r) -> const std::vector<std::pair<int, double>>& {
    return r.slip() ? rows_[r.patch].slipGradients[static_cast<std::size_t>(r.direction)]
                    : rows_[r.patch].gradient;
  };
  // the rows' coefficients (the gap rows: gapRow, already divided by L_P)
  std::vector<std::vector<std::pair<int, double>>> rowCoefficients(rows.size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const SchurRow& r = rows[i];
    if (r.slip()) {
      const double length = rows_[r.patch].pairedLength;
      for (const auto& [e, v] : gradientOf(r)) {
        rowCoefficients[i].emplace_back(e, v / length);
      }
    } else {
      rowCoefficients[i] = gapRow(r.patch);
    }
  }
  const auto mc = static_cast<Eigen::Index>(rows.size());
  const Eigen::Index n = ddu.size();
  std::vector<std::map<int, double>> columns(rows.size());
  bool symmetric = !consistent_; // the consistent gap rows differ from the force columns
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const SchurRow& r = rows[j];
    for (const auto& [e, v] : gradientOf(r)) {
      columns[j][e] += v;
    }
    if (r.slip()) {
      continue;
    }
    const Tangential slide = slidingCoupling(r.patch, u);
    for (std::size_t a = 0; a < directions(); ++a) {
      if (slide[a] != 0.0) {
        symmetric = false;
        for (const auto& [e, v] : rows_[r.patch].slipGradients[a]) {
          columns[j][e] += slide[a] * v;
        }
      }
    }
  }
  const Eigen::MatrixXd s = schurByColumnBlocks(
      mc, n, solver,
      [&](Eigen::Index j, Eigen::Ref<Eigen::VectorXd> x) {
        const auto k = static_cast<std::size_t>(j);
        const double length = rows_[rows[k].patch].pairedLength;
        for (const auto& [e, v] : columns[k]) {
          x(e) += v / length;
        }
      },
      [&](Eigen::Index i, const Eigen::MatrixXd& x,
          Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> out) {
        for (const auto& [e, v] : rowCoefficients[static_cast<std::size_t>(i)]) {
          out += v * x.row(e);
        }
      });
  Eigen::VectorXd rhs(mc);
  for (Eigen::Index i = 0; i < mc; ++i) {
    const SchurRow& r = rows[static_cast<std::size_t>(i)];
    double bdu = 0.0;
    for (const auto& [e, v] : rowCoefficients[static_cast<std::size_t>(i)]) {
      bdu += v * ddu(e);
    }
    const double value =
        r.slip() ? slipAt(r.patch, u)[static_cast<std::size_t>(r.direction)] : gapAt(r.patch, u);
    rhs(i) = value + bdu;
  }
  const Eigen::VectorXd y = solveMultiplierSchur(s, rhs, symmetric, [&](Eigen::Index i) {
    const SchurRow& r = rows[static_cast<std::size_t>(i)];
    redundant(r.patch, r.slip());
  });
  applyMultipliers(y, ddu, dlambda, solver, rows, columns);
}

void LacContactConstraint::applyMultipliers(const Eigen::VectorXd& y, Eigen::VectorXd& ddu,
                                            Eigen::VectorXd& dlambda, SaddleSolver& solver,
                                            const std::vector<SchurRow>& rows,
                                            const std::vector<std::map<int, double>>& columns) {
  const Eigen::Index n = ddu.size();
  Eigen::VectorXd f = Eigen::VectorXd::Zero(n);
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const SchurRow& r = rows[j];
    const double length = rows_[r.patch].pairedLength;
    const auto jj = static_cast<Eigen::Index>(j);
    for (const auto& [e, v] : columns[j]) {
      f(e) += y(jj) * v / length;
    }
    if (r.slip()) {
      lagsT_[r.patch][static_cast<std::size_t>(r.direction)] += y(jj) / length;
    } else {
      lagsC_[r.patch] += y(jj) / length;
    }
  }
  applyMultiplierForces(f, ddu, dlambda, solver);
}

} // namespace stella::contact::lac

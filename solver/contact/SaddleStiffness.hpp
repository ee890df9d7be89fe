#pragma once
// K^-1 with homogeneous relations and prescribed DOFs, through the Newton driver's last
// factorisation: what the condensed contact resolutions (CONTRAINTE, GCP, the statuses of
// PENALISATION) apply to the contact rows.

#include "solver/contact/DiscreteContact.hpp"
#include "solver/nonlinear/SaddleSolver.hpp"

namespace stella::contact {

class SaddleStiffness : public StiffnessInverse {
public:
  SaddleStiffness(SaddleSolver& solver, Eigen::Index relations, Eigen::Index equations)
      : solver_(solver), zeroRelations_(Eigen::VectorXd::Zero(relations)),
        zeroPrescribed_(Eigen::VectorXd::Zero(equations)) {}
  // All the columns in one backend call (NB_RESOL right-hand sides per solve).
  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override {
    solver_.solveHomogeneous(rhs);
    solves += static_cast<int>(rhs.cols());
  }
  // x = K^-1 f and the multipliers' part y.
  void solveWithMultipliers(const Eigen::VectorXd& f, Eigen::VectorXd& x, Eigen::VectorXd& y) {
    solver_.solve(f, zeroRelations_, zeroPrescribed_, x, y);
    ++solves;
  }

private:
  SaddleSolver& solver_;
  Eigen::VectorXd zeroRelations_;
  Eigen::VectorXd zeroPrescribed_;
};

} // namespace stella::contact

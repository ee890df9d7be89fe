#pragma once
// The dense solve of the Schur complement of the contact multipliers shared by the continuous
// formulations (ContinuousContactConstraint, ContinuousPointContactConstraint, lac::LacContactConstraint).

#include <Eigen/Core>

#include <functional>

namespace stella {
class SaddleSolver;
} // namespace stella

namespace stella::contact {

// Solves s y = rhs for the multipliers' unknowns. Symmetric: the LDLT of the symmetric part of s, a
// pivot below 1e-12 of the largest one naming its unknown (in the order of s) as redundant; otherwise
// (friction following the contact pressure): a full-pivoting LU, a singular s naming unknown 0.
// `redundant` reports the redundant unknown and must not return (it throws CONTACT_11).
Eigen::VectorXd solveMultiplierSchur(const Eigen::MatrixXd& s, const Eigen::VectorXd& rhs, bool symmetric,
                                     const std::function<void(Eigen::Index)>& redundant);

// After the multipliers' update: the structure's correction ddu -= K^-1 f, f the multipliers'
// force columns times their increments, through the driver's factorisation (and dlambda, the
// driver's own multipliers, corrected alike).
void applyMultiplierForces(const Eigen::VectorXd& f, Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                           SaddleSolver& solver);

// S = B K^-1 C^T (m x m, K of n equations) by blocks of 64 columns, one backend call each (n x 64
// doubles at a time): `column(j, x)` adds C^T's column j into x (zero on entry), `row(i, x, out)`
// adds B's row i times x (n x the block's columns) into out.
Eigen::MatrixXd
schurByColumnBlocks(Eigen::Index m, Eigen::Index n, SaddleSolver& solver,
                    const std::function<void(Eigen::Index, Eigen::Ref<Eigen::VectorXd>)>& column,
                    const std::function<void(Eigen::Index, const Eigen::MatrixXd&,
                                             Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>)>& row);

} // namespace stella::contact

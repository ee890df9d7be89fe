#pragma once
// Extra columns of the convergence table (SUIVI_DDL): a header given the state at the start of
// the step, and a row of values for the state of each iteration.

#include "solver/nonlinear/PointState.hpp"

#include <Eigen/Dense>
#include <string>

namespace stella {

class IterationColumns {
public:
  virtual ~IterationColumns() = default;
  // " TITLE          |" per column (the same width as the rows).
  virtual std::string header(const Eigen::VectorXd& u, const PointState& points) const = 0;
  // " 1.234567e-04   |" per column for the displacement `u` (physical size) and Gauss-point state.
  virtual std::string row(const Eigen::VectorXd& u, const PointState& points) const = 0;
};

} // namespace stella

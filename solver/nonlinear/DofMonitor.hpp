#pragma once
// SUIVI_DDL of STAT_NON_LINE: values of the state shown in the convergence table, one column per
// value at each iteration (FieldExtraction: DEPL on nodes; SIEF_ELGA, VARI_ELGA, EPSI_ELGA at
// Gauss points; EVAL_CHAM / EVAL_ELGA reductions). The column title is TITRE (its lines joined),
// else the component, node or cell and point, or the reduction (e.g. "DY N3", "MAX SIXX").

#include "solver/assembly/MechanicalSystem.hpp"
#include "solver/nonlinear/FieldExtraction.hpp"
#include "solver/nonlinear/IterationColumns.hpp"

#include <memory>
#include <vector>

namespace stella {

class DofMonitor : public IterationColumns {
public:
  // One SUIVI_DDL occurrence.
  struct Item {
    FieldExtraction what;
    std::string title; // TITRE, or empty
  };
  DofMonitor(const MechanicalSystem& system, std::vector<Item> items)
      : system_(system), items_(std::move(items)) {}

  std::string header(const Eigen::VectorXd& u, const PointState& points) const override;
  std::string row(const Eigen::VectorXd& u, const PointState& points) const override;

  static constexpr int width = 14;

private:
  // The values of every occurrence, in column order, with their titles.
  std::vector<std::pair<std::string, double>> values(const Eigen::VectorXd& u,
                                                     const PointState& points) const;

  const MechanicalSystem& system_;
  std::vector<Item> items_;
};

} // namespace stella

// DofMonitor: SUIVI_DDL, values of the state as columns of the convergence table.

#include "solver/nonlinear/DofMonitor.hpp"

#include "solver/nonlinear/ResultFields.hpp"

#include <fmt/format.h>

namespace stella {

std::vector<std::pair<std::string, double>> DofMonitor::values(const Eigen::VectorXd& u,
                                                               const PointState& points) const {
  std::vector<std::pair<std::string, double>> out;
  std::shared_ptr<Field> depl;
  for (const Item& item : items_) {
    const Field* f = nullptr;
    if (item.what.field == "DEPL") {
      if (!depl) {
        depl = nodalField(system_.model(), system_.dofs(), u, "DEPL");
      }
      f = depl.get();
    } else if (item.what.field == "SIEF_ELGA") {
      f = &points.stress;
    } else if (item.what.field == "VARI_ELGA") {
      f = &points.internal;
    } else {
      f = &points.strain;
    }
    for (const ExtractedValue& v : item.what.extract(*f, *system_.model().mesh)) {
      std::string title = item.title;
      if (title.empty()) {
        title = item.what.evalField != "VALE" ? fmt::format("{} {}", item.what.evalField, v.component)
                : !v.node.empty()             ? fmt::format("{} {}", v.component, v.node)
                : v.point > 0                 ? fmt::format("{} {} {}", v.component, v.cell, v.point)
                              : fmt::format("{} {} {}", item.what.evalPoint, v.component, v.cell);
      }
      out.emplace_back(title, v.value);
    }
  }
  return out;
}

std::string DofMonitor::header(const Eigen::VectorXd& u, const PointState& points) const {
  std::string h;
  for (const auto& [title, value] : values(u, points)) {
    h += fmt::format(" {:<{}} |", title.substr(0, width), width);
  }
  return h;
}

std::string DofMonitor::row(const Eigen::VectorXd& u, const PointState& points) const {
  std::string r;
  for (const auto& [title, value] : values(u, points)) {
    r += fmt::format(" {:>{}.6e} |", value, width);
  }
  return r;
}

} // namespace stella

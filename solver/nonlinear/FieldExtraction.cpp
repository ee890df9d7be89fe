// FieldExtraction: the values an OBSERVATION / SUIVI_DDL occurrence takes from a field.

#include "solver/nonlinear/FieldExtraction.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella {

namespace {

// MIN, MAX, MOY, MAXI_ABS or MINI_ABS of values (not empty).
double reduce(const std::vector<double>& v, const std::string& how) {
  if (how == "MIN") {
    return *std::min_element(v.begin(), v.end());
  }
  if (how == "MAX") {
    return *std::max_element(v.begin(), v.end());
  }
  if (how == "MOY") {
    double sum = 0.0;
    for (double x : v) {
      sum += x;
    }
    return sum / static_cast<double>(v.size());
  }
  double best = how == "MAXI_ABS" ? 0.0 : std::numeric_limits<double>::infinity();
  for (double x : v) {
    best = how == "MAXI_ABS" ? std::max(best, std::fabs(x)) : std::min(best, std::fabs(x));
  }
  return best;
}

[[noreturn]] void missing(const FieldExtraction& e, const std::string& what,
                          const std::vector<std::string>& has) {
  throw UserError(msg::make("SNL_20", {{"field", e.field}, {"what", what}}, e.at)
                      .withNote(has.empty() ? msg::text("SNL_20.n1")
                                            : msg::text("SNL_20.n2", {{"join", fmt::join(has, ", ")}})));
}

} // namespace

bool FieldExtraction::gaussPointField(const std::string& name) {
  return name == "SIEF_ELGA" || name == "VARI_ELGA" || name == "EPSI_ELGA";
}

std::vector<ExtractedValue> FieldExtraction::extract(const Field& f, const Mesh& mesh) const {
  std::vector<ExtractedValue> out;
  for (const std::string& cmp : components) {
    const auto c = f.componentIndex(cmp);
    if (!c) {
      missing(*this, fmt::format("component {}", cmp), f.components());
    }
    std::vector<ExtractedValue> values; // one per node, or per (cell, point)
    if (nodal()) {
      for (NodeId n : nodes) {
        const auto i = static_cast<std::size_t>(n);
        if (i < f.entityCount() && f.defined(i, *c)) {
          values.push_back({cmp, mesh.nodeName(n), "", 0, f.value(i, *c)});
        }
      }
    } else {
      for (CellId cell : cells) {
        const auto k = static_cast<std::size_t>(cell);
        const int count = k < f.cellCount() ? f.pointCount(k) : 0;
        if (count == 0) {
          continue; // a cell outside the model (a skin cell of the group)
        }
        const std::size_t first = f.firstPoint(k);
        if (evalPoint == "VALE") {
          for (int p : points) {
            if (p < 1 || p > count) {
              missing(*this, fmt::format("point {} in cell {} ({} point(s))", p, mesh.cellName(cell), count),
                      {});
            }
            values.push_back(
                {cmp, "", mesh.cellName(cell), p, f.value(first + static_cast<std::size_t>(p - 1), *c)});
          }
        } else {
          std::vector<double> inCell;
          for (int p = 0; p < count; ++p) {
            inCell.push_back(f.value(first + static_cast<std::size_t>(p), *c));
          }
          values.push_back({cmp, "", mesh.cellName(cell), 0, reduce(inCell, evalPoint)});
        }
      }
    }
    if (evalField == "VALE") {
      out.insert(out.end(), values.begin(), values.end());
    } else if (!values.empty()) {
      std::vector<double> v;
      for (const auto& x : values) {
        v.push_back(x.value);
      }
      out.push_back({cmp, "", "", 0, reduce(v, evalField)});
    }
  }
  return out;
}

} // namespace stella

// DerivedFields: ELGA -> ELNO -> NOEU, strains from displacements, equivalent stresses.

#include "solver/post/DerivedFields.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/fem/CellCoordinates.hpp"
#include "solver/fem/GaussExtrapolation.hpp"
#include "solver/fem/Kinematics.hpp"
#include "solver/post/TensorInvariants.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

fem::IntegrationRole volumeRole(const ModelCell& cell) {
  return cell.modelling == fem::Modelling::Axisymmetric ? fem::IntegrationRole::AxisymmetricVolume
                                                        : fem::IntegrationRole::Volume;
}

std::vector<std::string> strainComponents(int dim) {
  if (dim == 3) {
    return {"EPXX", "EPYY", "EPZZ", "EPXY", "EPXZ", "EPYZ"};
  }
  return {"EPXX", "EPYY", "EPZZ", "EPXY"};
}

} // namespace

std::vector<bool> selectedVolumeCells(const Model& model, const std::vector<CellId>& group) {
  std::vector<bool> selected(model.cells.size(), false);
  if (group.empty()) {
    for (CellId c : model.cellsOfKind(ElementKind::Volume)) {
      selected[static_cast<std::size_t>(c)] = true;
    }
    return selected;
  }
  for (CellId c : group) {
    selected[static_cast<std::size_t>(c)] = model.cell(c).kind == ElementKind::Volume;
  }
  return selected;
}

Field extrapolateToCellNodes(const Model& model, const Field& elga, const std::vector<bool>& cells) {
  const Mesh& mesh = *model.mesh;
  std::vector<int> perCell(cells.size(), 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c] && c < elga.cellCount() && elga.pointCount(c) > 0) {
      perCell[c] = static_cast<int>(mesh.cellNodes(static_cast<CellId>(c)).size());
    }
  }
  Field out = Field::perPoint(FieldSupport::CellNode, elga.quantity(), elga.components(), perCell);
  const auto ncmp = static_cast<Eigen::Index>(elga.componentCount());
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (perCell[c] == 0) {
      continue;
    }
    const auto cell = static_cast<CellId>(c);
    const Eigen::MatrixXd& g = fem::gaussToNodeMatrix(mesh.cellType(cell), volumeRole(model.cell(cell)));
    STELLA_ASSERT(g.cols() == elga.pointCount(c),
                  "Gauss point count of the field and of the RIGI rule differ");
    const Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> values(
        &elga.values()[elga.firstPoint(c) * elga.componentCount()], g.cols(), ncmp);
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> target(
        &out.values()[out.firstPoint(c) * out.componentCount()], g.rows(), ncmp);
    target = g * values;
  }
  return out;
}

Field averageAtNodes(const Mesh& mesh, const Field& elno) {
  STELLA_ASSERT(elno.support() == FieldSupport::CellNode, "NOEU fields are averaged from ELNO fields");
  const auto nodes = static_cast<std::size_t>(mesh.nodeCount());
  const std::size_t ncmp = elno.componentCount();
  Field out = Field::nodal(elno.quantity(), elno.components(), nodes);
  std::vector<int> count(nodes, 0);
  for (std::size_t c = 0; c < elno.cellCount(); ++c) {
    if (elno.pointCount(c) == 0) {
      continue;
    }
    const auto cellNodes = mesh.cellNodes(static_cast<CellId>(c));
    for (std::size_t k = 0; k < cellNodes.size(); ++k) {
      const auto n = static_cast<std::size_t>(cellNodes[k]);
      const auto v = elno.entity(elno.firstPoint(c) + k);
      for (std::size_t i = 0; i < ncmp; ++i) {
        out.value(n, i) += v[i];
      }
      ++count[n];
    }
  }
  bool partial = false;
  for (int k : count) {
    partial = partial || k == 0;
  }
  if (partial) {
    out.markPartial();
  }
  for (std::size_t n = 0; n < nodes; ++n) {
    if (count[n] == 0) {
      continue;
    }
    for (std::size_t i = 0; i < ncmp; ++i) {
      out.value(n, i) /= count[n];
      if (partial) {
        out.setDefined(n, i);
      }
    }
  }
  return out;
}

Field strainAtGaussPoints(const Model& model, const Field& depl, const MaterialField* materials,
                          const std::vector<bool>& cells) {
  const Mesh& mesh = *model.mesh;
  const int dim = model.components;
  std::vector<int> perCell(cells.size(), 0);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (cells[c]) {
      perCell[c] =
          fem::shapeTable(mesh.cellType(static_cast<CellId>(c)), volumeRole(model.cells[c])).pointCount();
    }
  }
  Field out = Field::perPoint(FieldSupport::GaussPoint, "EPSI_R", strainComponents(dim), perCell);
  std::vector<std::size_t> componentOf;
  for (int k = 0; k < dim; ++k) {
    auto i = depl.componentIndex(Model::componentName(k));
    STELLA_ASSERT(i.has_value(), "DEPL lacks a displacement component");
    componentOf.push_back(*i);
  }
  fem::ElementKinematics kin;
  Eigen::VectorXd u;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    if (perCell[c] == 0) {
      continue;
    }
    const auto cell = static_cast<CellId>(c);
    const fem::Modelling modelling = model.cell(cell).modelling;
    try {
      fem::computeKinematics(mesh.cellType(cell), modelling, cellCoordinates(mesh, cell, dim), kin,
                             model.cell(cell).volumeStrain);
    } catch (const fem::DegenerateElementError& e) {
      throw UserError(msg::make("CALC_8", {{"cell_name", mesh.cellName(cell)},
                                           {"jacobian", e.jacobian()},
                                           {"gauss_point", e.gaussPoint() + 1}}));
    }
    const auto nodes = mesh.cellNodes(cell);
    u.resize(static_cast<Eigen::Index>(nodes.size()) * dim);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
      for (int k = 0; k < dim; ++k) {
        u(static_cast<Eigen::Index>(i) * dim + k) =
            depl.value(static_cast<std::size_t>(nodes[i]), componentOf[static_cast<std::size_t>(k)]);
      }
    }
    double nu = 0.0;
    if (modelling == fem::Modelling::PlaneStress) {
      const Material* m = materials != nullptr ? materials->material(cell) : nullptr;
      if (m == nullptr || !m->elastic) {
        throw UserError(msg::make("CALC_7", {{"cell_name", mesh.cellName(cell)}}));
      }
      nu = m->elastic->poissonRatio;
    }
    for (int q = 0; q < kin.pointCount(); ++q) {
      const Eigen::VectorXd e = fem::strainAt(kin, q, u); // engineering shears
      auto target = out.entity(out.firstPoint(c) + static_cast<std::size_t>(q));
      target[0] = e(0);
      target[1] = e(1);
      target[2] = modelling == fem::Modelling::PlaneStress ? -nu / (1.0 - nu) * (e(0) + e(1)) : e(2);
      for (int s = 3; s < e.size(); ++s) {
        target[static_cast<std::size_t>(s)] = 0.5 * e(s);
      }
    }
  }
  return out;
}

Field equivalentStressField(const Field& stress) {
  const auto& names = equivalentStressComponents();
  Field out = stress.support() == FieldSupport::Node
                  ? Field::nodal("SIEF_R", names, stress.entityCount())
                  : Field::perPoint(stress.support(), "SIEF_R", names, [&] {
                      std::vector<int> counts(stress.cellCount());
                      for (std::size_t c = 0; c < counts.size(); ++c) {
                        counts[c] = stress.pointCount(c);
                      }
                      return counts;
                    }());
  STELLA_ASSERT(stress.componentCount() == 4 || stress.componentCount() == 6,
                "a stress field has 4 or 6 components");
  for (std::size_t e = 0; e < stress.entityCount(); ++e) {
    equivalentStress(tensorFromComponents(stress.entity(e)), out.entity(e));
  }
  return out;
}

} // namespace stella

// ADAPTATION='ADAPT_COEF' / 'TOUT' of the continuous formulation: the coefficients of a zone relative
// to the stiffness of its bodies (see the header).

#include "solver/contact/ContinuousAdaptation.hpp"

#include "messages/Messages.hpp"
#include "solver/model/MaterialField.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <limits>

namespace stella::contact {

namespace {

int vertexCount(CellType t) {
  switch (dimension(t)) {
  case 1:
    return 2;
  case 2:
    return t == CellType::TRIA3 || t == CellType::TRIA6 || t == CellType::TRIA7 ? 3 : 4;
  default:
    return nodeCount(t);
  }
}

double distance(const Mesh& mesh, NodeId a, NodeId b) {
  const auto& x = mesh.coordinates();
  double d2 = 0.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const double d = x[3 * static_cast<std::size_t>(a) + k] - x[3 * static_cast<std::size_t>(b) + k];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

// The shortest edge of the group's cells (between vertices; the diagonals of a quadrangle are longer
// than one of its edges).
double shortestEdge(const Mesh& mesh, const std::string& group) {
  double h = std::numeric_limits<double>::infinity();
  const auto* cells = mesh.cellGroup(group);
  if (cells == nullptr) {
    return h;
  }
  for (CellId c : *cells) {
    const auto nodes = mesh.cellNodes(c);
    const int v = std::min(vertexCount(mesh.cellType(c)), static_cast<int>(nodes.size()));
    for (int i = 0; i < v; ++i) {
      for (int j = i + 1; j < v; ++j) {
        const double d =
            distance(mesh, nodes[static_cast<std::size_t>(i)], nodes[static_cast<std::size_t>(j)]);
        if (d > 0.0) {
          h = std::min(h, d);
        }
      }
    }
  }
  return h;
}

// E / (1 - NU^2) averaged over the volume cells holding a node of the group; 0 when none has ELAS.
double surfaceModulus(const Mesh& mesh, const MaterialField& materials, const std::string& group, int dim) {
  const auto* cells = mesh.cellGroup(group);
  if (cells == nullptr) {
    return 0.0;
  }
  std::vector<char> onSurface(static_cast<std::size_t>(mesh.nodeCount()), 0);
  for (NodeId n : mesh.nodesOfCells(*cells)) {
    onSurface[static_cast<std::size_t>(n)] = 1;
  }
  double sum = 0.0;
  int count = 0;
  for (CellId c = 0; c < mesh.cellCount(); ++c) {
    if (dimension(mesh.cellType(c)) != dim) {
      continue;
    }
    const auto nodes = mesh.cellNodes(c);
    const bool touches = std::any_of(nodes.begin(), nodes.end(),
                                     [&](NodeId n) { return onSurface[static_cast<std::size_t>(n)] != 0; });
    const Material* m =
        touches && c < static_cast<CellId>(materials.cellMaterial.size()) ? materials.material(c) : nullptr;
    if (m == nullptr || !m->elastic) {
      continue;
    }
    const double nu = m->elastic->poissonRatio;
    sum += m->elastic->youngModulus / (1.0 - nu * nu);
    ++count;
  }
  return count > 0 ? sum / count : 0.0;
}

} // namespace

bool adaptsCoefficients(const ContinuousZone& zone) {
  return zone.adaptation == "ADAPT_COEF" || zone.adaptation == "TOUT";
}

std::shared_ptr<const ContactDefinition>
adaptContinuousCoefficients(std::shared_ptr<const ContactDefinition> definition,
                            const MaterialField& materials, int dimension) {
  const bool any = std::any_of(definition->zones.begin(), definition->zones.end(), [](const ContactZone& z) {
    return z.resolve && adaptsCoefficients(z.continuous);
  });
  if (!any) {
    return definition;
  }
  auto adapted = std::make_shared<ContactDefinition>(*definition);
  const Mesh& mesh = *adapted->mesh;
  for (ContactZone& z : adapted->zones) {
    ContinuousZone& c = z.continuous;
    if (!z.resolve || !adaptsCoefficients(c)) {
      continue;
    }
    const double slave = surfaceModulus(mesh, materials, z.slaveGroup, dimension);
    const double master = surfaceModulus(mesh, materials, z.masterGroup, dimension);
    const double h = shortestEdge(mesh, z.slaveGroup);
    if (!(slave > 0.0) || !(master > 0.0) || !std::isfinite(h)) {
      throw UserError(
          msg::make("CONTACT_ADAPT_1",
                    {{"adaptation", c.adaptation},
                     {"slave_group", z.slaveGroup},
                     {"master_group", z.masterGroup},
                     {"isfinite", !std::isfinite(h) ? "its slave cells have no edge"
                                                    : "a surface touches no volume cell with ELAS"}},
                    c.adaptationAt));
    }
    c.stiffness = 1.0 / (1.0 / slave + 1.0 / master) / h;
    c.augmentation *= c.stiffness;
    c.penalty *= c.stiffness;
    c.frictionAugmentation *= c.stiffness;
    c.frictionPenalty *= c.stiffness;
    if (!c.maxPenetration) {
      c.maxPenetration = 1e-2 * std::min(h, shortestEdge(mesh, z.masterGroup));
    }
  }
  return adapted;
}

} // namespace stella::contact

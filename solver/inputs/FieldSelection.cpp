// FieldSelection: steps, fields, components and entities of results for TEST_RESU and tables.

#include "solver/inputs/FieldSelection.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/post/TestReport.hpp"

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

namespace stella {

namespace {

std::string stepList(const Result& r) {
  std::vector<std::string> items;
  for (const auto& s : r.steps) {
    items.push_back(fmt::format("{} (INST {})", s.number, s.time));
    if (items.size() == 12) {
      items.push_back("...");
      break;
    }
  }
  return items.empty() ? "none" : fmt::format("{}", fmt::join(items, ", "));
}

// The nodes of every group of GROUP_NO, in order (a node in two groups counts twice).
std::vector<NodeId> nodesOfGroups(const Mesh& mesh, const KeywordTree& occ) {
  std::vector<NodeId> nodes;
  for (const auto& g : occ.texts("GROUP_NO")) {
    const auto& group = nodeGroupOrThrow(mesh, g, occ, "GROUP_NO");
    nodes.insert(nodes.end(), group.begin(), group.end());
  }
  return nodes;
}

std::size_t singleNodeOfGroup(const Mesh& mesh, const std::string& group, const KeywordTree& occ) {
  const auto* nodes = &nodeGroupOrThrow(mesh, group, occ, "GROUP_NO");
  if (nodes->size() != 1) {
    throw UserError(
        msg::make("RESU_4", {{"group", group}, {"nodes_count", nodes->size()}}, occ.locationOf("GROUP_NO")));
  }
  return static_cast<std::size_t>(nodes->front());
}

// ELNO values at the nodes NOEUD / GROUP_NO of the cells: one value per (cell, node) pair.
EntitySelection cellNodeEntities(const Mesh& mesh, const Field& field, const std::vector<CellId>& cells,
                                 const KeywordTree& occ) {
  std::vector<NodeId> nodes;
  if (occ.has("NOEUD")) {
    nodes.push_back(nodeOrThrow(mesh, occ.text("NOEUD"), occ, "NOEUD"));
  } else {
    nodes = nodesOfGroups(mesh, occ);
  }
  EntitySelection s;
  for (CellId c : cells) {
    const auto uc = static_cast<std::size_t>(c);
    if (uc >= field.cellCount() || field.pointCount(uc) == 0) {
      continue;
    }
    const auto cellNodes = mesh.cellNodes(c);
    for (std::size_t k = 0; k < cellNodes.size(); ++k) {
      if (std::find(nodes.begin(), nodes.end(), cellNodes[k]) != nodes.end()) {
        s.entities.push_back(field.firstPoint(uc) + k);
        s.label = fmt::format("{} {}", mesh.cellName(c), mesh.nodeName(cellNodes[k]));
      }
    }
  }
  s.single = s.entities.size() == 1 && !occ.has("TYPE_TEST");
  if (s.entities.empty()) {
    throw UserError(msg::make("RESU_5", {}, occ.location()));
  }
  return s;
}

} // namespace

const ResultStep& selectStep(const Result& result, const std::string& resultName, const KeywordTree& occ,
                             double precision, bool absolute) {
  const ResultStep* step = nullptr;
  std::string what;
  if (occ.has("NUME_ORDRE")) {
    step = result.stepNumber(static_cast<int>(occ.integer("NUME_ORDRE")));
    what = fmt::format("NUME_ORDRE {}", occ.integer("NUME_ORDRE"));
  } else if (occ.has("INST")) {
    step = result.stepAtTime(occ.real("INST"), precision, absolute);
    what = fmt::format("INST {}", occ.real("INST"));
  } else if (!result.steps.empty()) {
    step = &result.steps.back();
  }
  if (step == nullptr) {
    throw UserError(msg::make("RESU_1",
                              {{"result_name", resultName}, {"what", what}, {"step_list", stepList(result)}},
                              occ.location()));
  }
  return *step;
}

const Field& selectField(const ResultStep& step, const std::string& resultName, const std::string& fieldName,
                         const KeywordTree& occ) {
  const Field* f = step.field(fieldName);
  if (f == nullptr) {
    std::vector<std::string> names;
    for (const auto& [n, v] : step.fields) {
      names.push_back(n);
    }
    throw UserError(msg::make("RESU_2",
                              {{"result_name", resultName},
                               {"field_name", fieldName},
                               {"number", step.number},
                               {"empty", names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", "))}},
                              occ.locationOf("NOM_CHAM")));
  }
  return *f;
}

std::size_t selectComponent(const Field& field, const std::string& fieldName, const std::string& component,
                            const KeywordTree& occ) {
  auto c = field.componentIndex(component);
  if (!c) {
    throw UserError(msg::make(
        "RESU_3",
        {{"field_name", fieldName}, {"component", component}, {"join", fmt::join(field.components(), ", ")}},
        occ.locationOf("NOM_CMP")));
  }
  return *c;
}

EntitySelection selectEntities(const Mesh& mesh, const Field& field, const KeywordTree& occ) {
  EntitySelection s;
  if (field.support() == FieldSupport::Node) {
    if (occ.has("NOEUD")) {
      const std::string name = occ.text("NOEUD");
      return {{static_cast<std::size_t>(nodeOrThrow(mesh, name, occ, "NOEUD"))}, true, name};
    }
    if (occ.has("GROUP_NO") && !occ.has("TYPE_TEST")) {
      const std::string group = occ.texts("GROUP_NO").front();
      const std::size_t n = singleNodeOfGroup(mesh, group, occ);
      return {{n}, true, mesh.nodeName(static_cast<NodeId>(n))};
    }
    std::vector<NodeId> nodes;
    if (occ.has("GROUP_NO")) {
      nodes = nodesOfGroups(mesh, occ);
    } else if (occ.has("GROUP_MA")) {
      nodes = mesh.nodesOfCells(cellGroupOrThrow(mesh, occ.text("GROUP_MA"), occ, "GROUP_MA"));
    } else {
      for (std::size_t n = 0; n < field.entityCount(); ++n) {
        s.entities.push_back(n);
      }
      return s;
    }
    for (NodeId n : nodes) {
      s.entities.push_back(static_cast<std::size_t>(n));
    }
    return s;
  }
  // Per-point and per-cell fields.
  std::vector<CellId> cells;
  if (occ.has("MAILLE")) {
    cells.push_back(cellOrThrow(mesh, occ.text("MAILLE"), occ, "MAILLE"));
  } else if (occ.has("GROUP_MA")) {
    cells = cellGroupOrThrow(mesh, occ.text("GROUP_MA"), occ, "GROUP_MA");
  } else {
    for (std::size_t c = 0;
         c < (field.support() == FieldSupport::Cell ? field.entityCount() : field.cellCount()); ++c) {
      cells.push_back(static_cast<CellId>(c));
    }
  }
  if (field.support() == FieldSupport::Cell) {
    for (CellId c : cells) {
      s.entities.push_back(static_cast<std::size_t>(c));
    }
    s.single = cells.size() == 1 && !occ.has("TYPE_TEST");
    s.label = cells.size() == 1 ? mesh.cellName(cells.front()) : "";
    return s;
  }
  if (field.support() == FieldSupport::CellNode && !occ.has("POINT") &&
      (occ.has("NOEUD") || occ.has("GROUP_NO"))) {
    return cellNodeEntities(mesh, field, cells, occ);
  }
  if (occ.has("POINT")) {
    if (cells.size() != 1) {
      throw UserError(msg::make("RESU_4.2", {{"cells_count", cells.size()}}, occ.locationOf("POINT")));
    }
    const auto c = static_cast<std::size_t>(cells.front());
    const auto p = occ.integer("POINT");
    if (c >= field.cellCount() || p < 1 || p > field.pointCount(c)) {
      throw UserError(msg::make("RESU_5.2",
                                {{"cell_name", mesh.cellName(cells.front())},
                                 {"c", c < field.cellCount() ? field.pointCount(c) : 0},
                                 {"p", p}},
                                occ.locationOf("POINT")));
    }
    if (occ.integerOr("SOUS_POINT", 1) != 1) {
      throw UserError(msg::make("RESU_5.3", {}, occ.locationOf("SOUS_POINT")));
    }
    return {{field.firstPoint(c) + static_cast<std::size_t>(p - 1)},
            true,
            fmt::format("{} point {}", mesh.cellName(cells.front()), p)};
  }
  for (CellId c : cells) {
    const auto uc = static_cast<std::size_t>(c);
    if (uc >= field.cellCount()) {
      continue;
    }
    for (int q = 0; q < field.pointCount(uc); ++q) {
      s.entities.push_back(field.firstPoint(uc) + static_cast<std::size_t>(q));
    }
  }
  return s;
}

double reduceValues(const Field& field, std::size_t component, const std::vector<std::size_t>& entities,
                    const std::string& type, const KeywordTree& occ) {
  std::vector<double> values;
  for (std::size_t e : entities) {
    if (field.defined(e, component)) {
      values.push_back(field.value(e, component));
    }
  }
  if (values.empty()) {
    throw UserError(msg::make("RESU_6", {}, occ.location()));
  }
  return reduceByTestType(type, values);
}

} // namespace stella

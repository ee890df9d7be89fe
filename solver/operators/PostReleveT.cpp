// POST_RELEVE_T: tables of values of the nodal fields of a RESULTAT (DEPL, REAC_NODA, SIEF_NOEU,
// SIEQ_NOEU, EPSI_NOEU...) on the nodes of GROUP_NO / NOEUD, one block per stored step
// (TOUT_ORDRE, NUME_ORDRE, INST, LIST_INST with CRITERE / PRECISION). Every row starts with
// INTITULE, RESU, NOM_CHAM, NUME_ORDRE, INST. The values are the components NOM_CMP / TOUT_CMP,
// or INVARIANT (tensor fields SIxx / EPxx: VMIS, TRESCA, TRACE, DETER; vector fields: NORME), or
// the sums RESULTANTE.
//   OPERATION='EXTRACTION': one row per node (NOEUD, COOR_X, COOR_Y[, COOR_Z], values); RESULTANTE
//     gives one row of sums.
//   OPERATION='MOYENNE': the moments of the values along the path of the nodes in the order of the
//     group (solver/post/PathAverage.hpp), one row per QUANTITE: MOMENT_0 (mean), MOMENT_1
//     (linearised part), MINIMUM, MAXIMUM.
// EXTREMA, MOYENNE_ARITH, CHAM_GD, element fields, local frames (REPERE other than GLOBAL),
// TRAC_NOR / TRAC_DIR, MOMENT and ELEM_PRINCIPAUX are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/inputs/FieldSelection.hpp"
#include "solver/inputs/Selection.hpp"
#include "solver/post/PathAverage.hpp"
#include "solver/post/Table.hpp"
#include "solver/post/TensorInvariants.hpp"
#include "solver/session/OperatorRegistry.hpp"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <optional>

namespace stella {

namespace {

void refuse(const KeywordTree& a, const std::string& what, const std::string& keyword) {
  throw UserError(msg::make("RELEVE_1", {{"what", what}}, a.locationOf(keyword)));
}

void refuseUnsupported(const KeywordTree& a) {
  for (const char* k : {"CHAM_GD", "MOMENT", "ELEM_PRINCIPAUX", "NOEUD_CMP", "NOM_CAS", "FREQ", "LIST_FREQ",
                        "LIST_ORDRE", "NUME_MODE", "LIST_MODE", "TRAC_NOR", "TRAC_DIR", "GROUP_MA", "TOUT"}) {
    if (a.has(k)) {
      refuse(a, k, k);
    }
  }
  const auto operations = a.texts("OPERATION");
  for (const auto& op : operations) {
    if (op != "EXTRACTION" && op != "MOYENNE") {
      refuse(a, msg::text("RELEVE_1.f1", {{"op", op}}), "OPERATION");
    }
  }
  if (a.text("REPERE") != "GLOBAL") { // in the block of every OPERATION but EXTREMA and MOYENNE_ARITH
    refuse(a, msg::text("RELEVE_1.f2", {{"text", a.text("REPERE")}}), "REPERE");
  }
  if (a.has("RESULTANTE") && std::find(operations.begin(), operations.end(), "MOYENNE") != operations.end()) {
    refuse(a, msg::text("RELEVE_1.f3"), "RESULTANTE");
  }
}

std::vector<const ResultStep*> wantedSteps(const Result& result, const std::string& name,
                                           const KeywordTree& a) {
  std::vector<const ResultStep*> out;
  if (a.has("NUME_ORDRE")) {
    for (auto n : a.integers("NUME_ORDRE")) {
      const ResultStep* s = result.stepNumber(static_cast<int>(n));
      if (s == nullptr) {
        throw UserError(msg::make("RESU_1.2", {{"name", name}, {"n", n}}, a.locationOf("NUME_ORDRE")));
      }
      out.push_back(s);
    }
    return out;
  }
  if (a.has("INST") || a.has("LIST_INST")) {
    const double precision = a.real("PRECISION");
    const bool absolute = a.text("CRITERE") == "ABSOLU";
    std::vector<double> times;
    if (a.has("INST")) {
      times = a.reals("INST");
    } else {
      auto list = conceptData<RealList>(a.conceptValue("LIST_INST"));
      STELLA_ASSERT(list != nullptr, "LIST_INST holds no list of reals");
      times = list->values;
    }
    for (double t : times) {
      const ResultStep* s = result.stepAtTime(t, precision, absolute);
      if (s == nullptr) {
        throw UserError(msg::make("RESU_1.3", {{"name", name}, {"t", t}},
                                  a.locationOf(a.has("INST") ? "INST" : "LIST_INST")));
      }
      out.push_back(s);
    }
    return out;
  }
  for (const ResultStep& s : result.steps) {
    out.push_back(&s);
  }
  return out;
}

// The nodes of GROUP_NO (each group in its stored order) then NOEUD (in the given order), each
// node once: the path of MOYENNE.
std::vector<NodeId> orderedNodes(const Mesh& mesh, const KeywordTree& a) {
  std::vector<NodeId> nodes;
  auto add = [&](NodeId n) {
    if (std::find(nodes.begin(), nodes.end(), n) == nodes.end()) {
      nodes.push_back(n);
    }
  };
  if (a.has("GROUP_NO")) {
    for (const auto& g : a.texts("GROUP_NO")) {
      for (NodeId n : nodeGroupOrThrow(mesh, g, a, "GROUP_NO")) {
        add(n);
      }
    }
  }
  if (a.has("NOEUD")) {
    for (const auto& name : a.texts("NOEUD")) {
      add(nodeOrThrow(mesh, name, a, "NOEUD"));
    }
  }
  return nodes;
}

bool isTensor(const Field& f) {
  const auto& c = f.components();
  return (c.size() == 4 || c.size() == 6) && (c[0] == "SIXX" || c[0] == "EPXX");
}

// The value columns of a field at a node: NOM_CMP / TOUT_CMP components, or the invariants.
struct ValueColumns {
  std::vector<std::string> names;
  std::vector<std::size_t> components; // for NOM_CMP / TOUT_CMP
  bool invariant = false;
  bool tensor = false;
};

ValueColumns valueColumns(const Field& field, const std::string& fieldName, const KeywordTree& a) {
  ValueColumns v;
  if (a.has("INVARIANT")) {
    v.invariant = true;
    v.tensor = isTensor(field);
    v.names = v.tensor ? std::vector<std::string>{"VMIS", "TRESCA", "TRACE", "DETER"}
                       : std::vector<std::string>{"NORME"};
    return v;
  }
  v.names = a.has("NOM_CMP") ? a.texts("NOM_CMP") : field.components();
  for (const auto& cmp : v.names) {
    v.components.push_back(selectComponent(field, fieldName, cmp, a));
  }
  return v;
}

// The values at node n (nullopt where a component has no value there).
std::vector<std::optional<double>> valuesAt(const Field& field, const ValueColumns& v, std::size_t n) {
  std::vector<std::optional<double>> out;
  if (!v.invariant) {
    for (std::size_t c : v.components) {
      out.push_back(field.defined(n, c) ? std::optional<double>(field.value(n, c)) : std::nullopt);
    }
    return out;
  }
  for (std::size_t c = 0; c < field.componentCount(); ++c) {
    if (!field.defined(n, c)) {
      return std::vector<std::optional<double>>(v.names.size());
    }
  }
  const auto values = field.entity(n);
  if (v.tensor) {
    const Eigen::Matrix3d t = tensorFromComponents(values);
    return {vonMises(t), tresca(t), t.trace(), t.determinant()};
  }
  double norm2 = 0.0;
  for (double x : values) {
    norm2 += x * x;
  }
  return {std::sqrt(norm2)};
}

using Row = std::vector<std::pair<std::string, Value>>;

void extraction(const Mesh& mesh, const Field& field, const std::string& fieldName, const KeywordTree& a,
                const Row& head, const std::vector<NodeId>& nodes, Table& table) {
  if (a.has("RESULTANTE")) {
    auto row = head;
    for (const auto& cmp : a.texts("RESULTANTE")) {
      const std::size_t c = selectComponent(field, fieldName, cmp, a);
      double sum = 0.0;
      for (NodeId n : nodes) {
        if (field.defined(static_cast<std::size_t>(n), c)) {
          sum += field.value(static_cast<std::size_t>(n), c);
        }
      }
      row.emplace_back(cmp, Value(sum));
    }
    table.addRow(row);
    return;
  }
  const ValueColumns columns = valueColumns(field, fieldName, a);
  for (NodeId n : nodes) {
    auto row = head;
    row.emplace_back("NOEUD", Value(mesh.nodeName(n)));
    const Point3 x = mesh.point(n);
    row.emplace_back("COOR_X", Value(x[0]));
    row.emplace_back("COOR_Y", Value(x[1]));
    if (mesh.dimension() == 3) {
      row.emplace_back("COOR_Z", Value(x[2]));
    }
    const auto values = valuesAt(field, columns, static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < values.size(); ++i) {
      row.emplace_back(columns.names[i], values[i] ? Value(*values[i]) : Value());
    }
    table.addRow(row);
  }
}

void average(const Mesh& mesh, const Field& field, const std::string& fieldName, const KeywordTree& a,
             const Row& head, const std::vector<NodeId>& nodes, Table& table) {
  const ValueColumns columns = valueColumns(field, fieldName, a);
  std::vector<Point3> points;
  std::vector<std::vector<double>> series(columns.names.size());
  for (NodeId n : nodes) {
    points.push_back(mesh.point(n));
    const auto values = valuesAt(field, columns, static_cast<std::size_t>(n));
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!values[i]) {
        throw UserError(msg::make(
            "RELEVE_2",
            {{"names", columns.names[i]}, {"field_name", fieldName}, {"node_name", mesh.nodeName(n)}},
            a.location()));
      }
      series[i].push_back(*values[i]);
    }
  }
  std::vector<PathMoments> moments;
  for (const auto& s : series) {
    moments.push_back(pathMoments(points, s));
  }
  const std::vector<std::pair<std::string, double PathMoments::*>> quantities{
      {"MOMENT_0", &PathMoments::moment0},
      {"MOMENT_1", &PathMoments::moment1},
      {"MINIMUM", &PathMoments::minimum},
      {"MAXIMUM", &PathMoments::maximum}};
  for (const auto& [quantity, member] : quantities) {
    auto row = head;
    row.emplace_back("QUANTITE", Value(quantity));
    for (std::size_t i = 0; i < moments.size(); ++i) {
      row.emplace_back(columns.names[i], Value(moments[i].*member));
    }
    table.addRow(row);
  }
}

void action(const KeywordTree& a, Table& table) {
  refuseUnsupported(a);
  auto concept_ = a.conceptValue("RESULTAT");
  auto result = conceptData<Result>(concept_);
  STELLA_ASSERT(result != nullptr, "RESULTAT holds no result");
  const Mesh& mesh = *result->mesh;
  const std::string fieldName = a.text("NOM_CHAM");
  const auto nodes = orderedNodes(mesh, a);
  for (const ResultStep* step : wantedSteps(*result, concept_->name, a)) {
    const Field& field = selectField(*step, concept_->name, fieldName, a);
    if (field.support() != FieldSupport::Node) {
      throw UserError(msg::make("RELEVE_1.2", {{"field_name", fieldName}}, a.locationOf("NOM_CHAM")));
    }
    const Row head{{"INTITULE", Value(a.text("INTITULE"))},
                   {"RESU", Value(concept_->name)},
                   {"NOM_CHAM", Value(fieldName)},
                   {"NUME_ORDRE", Value(static_cast<std::int64_t>(step->number))},
                   {"INST", Value(step->time)}};
    for (const auto& op : a.texts("OPERATION")) {
      if (op == "EXTRACTION") {
        extraction(mesh, field, fieldName, a, head, nodes, table);
      } else {
        average(mesh, field, fieldName, a, head, nodes, table);
      }
    }
  }
}

Value runPostReleveT(OperatorCall& call) {
  auto table = std::make_shared<Table>();
  table->title = call.keywords.textOr("TITRE", "");
  for (const KeywordTree& a : call.keywords.occurrences("ACTION")) {
    action(a, *table);
  }
  return call.makeConcept(table);
}

} // namespace

STELLA_OPERATOR("POST_RELEVE_T", runPostReleveT);

} // namespace stella

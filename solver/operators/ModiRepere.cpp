// MODI_REPERE: the components of fields expressed in another frame (solver/post/FrameChange.hpp).
//   RESULTAT + MODI_CHAM(NOM_CHAM, TYPE_CHAM, NOM_CMP) on the steps of TOUT_ORDRE (default),
//   NUME_ORDRE, INST or LIST_INST (CRITERE, PRECISION); or CHAM_GD (a field concept) with
//   MODI_CHAM(TYPE_CHAM, NOM_CMP).
//   TYPE_CHAM VECT_2D, VECT_3D, TENS_2D, TENS_3D; fields on nodes (DEPL, CONT_NOEU, SIEF_NOEU...),
//   cells, cell nodes (ELNO) or Gauss points (ELGA, the points of the cell's RIGI family).
//   REPERE='UTILISATEUR' (AFFE: ANGL_NAUT, one angle in 2D, three in 3D; or VECT_X + VECT_Y in
//   3D) and 'CYLINDRIQUE' (AFFE: ORIGINE, and AXE_Z in 3D; in 2D the axis is Z). Each AFFE
//   occurrence applies to TOUT (the default), or the cells of GROUP_MA (and their nodes), or for
//   nodal fields the nodes of GROUP_NO.
// A point on the cylinder's axis takes the frame of the centre of its cell (a node: of the first
// cell that holds it), as code_aster. An entity where one of the NOM_CMP is absent is left as it
// is. Without reuse=, the new result holds the selected steps with the changed fields only; with
// reuse=, the fields are replaced in the result. TITRE is printed in the message file; INFO=2
// prints the rotation of each UTILISATEUR frame (rows = local axes). REPERE='COQUE...',
// TYPE_CHAM '*_GENE' and LIST_ORDRE are refused as not implemented yet.

#include "interpreter/Diagnostics.hpp"
#include "messages/Messages.hpp"
#include "solver/database/ConceptStore.hpp"
#include "solver/database/Result.hpp"
#include "solver/fem/Quadrature.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/functions/RealFunction.hpp"
#include "solver/mesh/MeshGeometry.hpp"
#include "solver/operators/MeshOperatorUtil.hpp"
#include "solver/post/FieldConcept.hpp"
#include "solver/post/FrameChange.hpp"
#include "solver/session/OperatorRegistry.hpp"
#include "solver/session/Session.hpp"

#include <fmt/format.h>

namespace stella {

namespace {

UserError refused(const std::string& what, const SourceLocation& at) {
  return UserError(msg::make("MODI_REPERE_1", {{"what", what}}, at));
}

UserError invalid(std::string_view key, msg::Args args, const SourceLocation& at) {
  return UserError(msg::make(key, args, at));
}

// One AFFE occurrence: the frame and where it applies.
struct FrameSpec {
  bool cylindrical = false;
  Rotation fixed{};
  Point3 origin{0.0, 0.0, 0.0};
  Point3 axis{0.0, 0.0, 1.0};
  bool everywhere = true;
  std::vector<bool> cells; // when !everywhere
  std::vector<bool> nodes; // when !everywhere
  bool byNodeGroup = false;
  SourceLocation location;
};

Point3 point3(const std::vector<double>& v) {
  return {v[0], v.size() > 1 ? v[1] : 0.0, v.size() > 2 ? v[2] : 0.0};
}

void userFrame(const KeywordTree& occ, int dim, FrameSpec& spec) {
  if (occ.has("ORIGINE")) {
    throw invalid("MODI_REPERE_2", {}, occ.locationOf("ORIGINE"));
  }
  if (occ.has("VECT_X")) {
    if (dim != 3) {
      throw invalid("MODI_REPERE_2.2", {}, occ.locationOf("VECT_X"));
    }
    const auto r = rotationFromVectors(point3(occ.reals("VECT_X")), point3(occ.reals("VECT_Y")));
    if (!r) {
      throw invalid("MODI_REPERE_2.3", {}, occ.locationOf("VECT_X"));
    }
    spec.fixed = *r;
    return;
  }
  const auto angles = occ.reals("ANGL_NAUT");
  if (dim == 3 && angles.size() != 3) {
    throw invalid("MODI_REPERE_2.4", {}, occ.locationOf("ANGL_NAUT"));
  }
  if (dim == 2 && angles.size() != 1) {
    throw invalid("MODI_REPERE_2.5", {}, occ.locationOf("ANGL_NAUT"));
  }
  spec.fixed = nauticalRotation(angles[0], dim == 3 ? angles[1] : 0.0, dim == 3 ? angles[2] : 0.0);
}

void cylindricalFrame(const KeywordTree& occ, int dim, FrameSpec& spec) {
  spec.cylindrical = true;
  if (!occ.has("ORIGINE")) {
    const char* k = occ.has("ANGL_NAUT") ? "ANGL_NAUT" : "VECT_X";
    throw invalid(dim == 3 ? "MODI_REPERE_2.origin_3d" : "MODI_REPERE_2.origin_2d", {{"keyword", k}},
                  occ.locationOf(k));
  }
  const auto origin = occ.reals("ORIGINE");
  if (static_cast<int>(origin.size()) != dim) {
    throw invalid("MODI_REPERE_2.6", {{"origin_count", origin.size()}, {"dim", dim}},
                  occ.locationOf("ORIGINE"));
  }
  spec.origin = point3(origin);
  if (dim == 2) {
    if (occ.has("AXE_Z")) {
      throw invalid("MODI_REPERE_2.7", {}, occ.locationOf("AXE_Z"));
    }
    return;
  }
  if (!occ.has("AXE_Z")) {
    throw invalid("MODI_REPERE_2.8", {}, occ.locationOf("ORIGINE"));
  }
  const Point3 a = point3(occ.reals("AXE_Z"));
  if (norm(a) < 1.0e-12) {
    throw invalid("MODI_REPERE_2.9", {}, occ.locationOf("AXE_Z"));
  }
  spec.axis = (1.0 / norm(a)) * a;
}

void placeOf(const KeywordTree& occ, const Mesh& mesh, FrameSpec& spec) {
  if (!occ.has("GROUP_MA") && !occ.has("GROUP_NO")) {
    return; // TOUT='OUI' or nothing: everywhere
  }
  spec.everywhere = false;
  spec.cells.assign(static_cast<std::size_t>(mesh.cellCount()), false);
  spec.nodes.assign(static_cast<std::size_t>(mesh.nodeCount()), false);
  if (occ.has("GROUP_MA")) {
    for (const CellId c : cellsOfGroups(mesh, occ, "GROUP_MA")) {
      spec.cells[static_cast<std::size_t>(c)] = true;
      for (const NodeId n : mesh.cellNodes(c)) {
        spec.nodes[static_cast<std::size_t>(n)] = true;
      }
    }
  }
  if (occ.has("GROUP_NO")) {
    spec.byNodeGroup = true;
    for (const NodeId n : nodesOfGroups(mesh, occ, "GROUP_NO")) {
      spec.nodes[static_cast<std::size_t>(n)] = true;
    }
  }
}

std::vector<FrameSpec> frames(const KeywordTree& kw, const Mesh& mesh) {
  const std::string repere = kw.text("REPERE");
  if (repere != "UTILISATEUR" && repere != "CYLINDRIQUE") {
    throw refused(msg::text("MODI_REPERE_1.f1", {{"repere", repere}}), kw.locationOf("REPERE"));
  }
  const auto& occurrences = kw.occurrences("AFFE");
  if (occurrences.empty()) {
    throw invalid(repere == "UTILISATEUR" ? "MODI_REPERE_2.affe_user" : "MODI_REPERE_2.affe_cylinder",
                  {{"repere", repere}}, kw.locationOf("REPERE"));
  }
  const int dim = mesh.dimension();
  std::vector<FrameSpec> out;
  for (const auto& occ : occurrences) {
    FrameSpec spec;
    spec.location = occ.location();
    if (repere == "UTILISATEUR") {
      userFrame(occ, dim, spec);
    } else {
      cylindricalFrame(occ, dim, spec);
    }
    placeOf(occ, mesh, spec);
    out.push_back(std::move(spec));
  }
  return out;
}

// One MODI_CHAM occurrence.
struct Change {
  std::string field; // NOM_CHAM (empty for CHAM_GD)
  FrameQuantity quantity;
  std::vector<std::string> components;
  const KeywordTree* occ;
};

std::vector<Change> changes(const KeywordTree& kw, bool ofResult, int dim) {
  std::vector<Change> out;
  const auto& occurrences = kw.occurrences("MODI_CHAM");
  if (occurrences.empty()) {
    throw invalid("MODI_REPERE_2.10", {}, kw.location());
  }
  for (const auto& occ : occurrences) {
    const std::string type = occ.text("TYPE_CHAM");
    const auto q = frameQuantity(type);
    if (!q) {
      throw refused(msg::text("MODI_REPERE_1.f2", {{"type", type}}), occ.locationOf("TYPE_CHAM"));
    }
    if (dim == 3 && (*q == FrameQuantity::Vector2D || *q == FrameQuantity::Tensor2D)) {
      throw invalid("MODI_REPERE_2.11", {{"type", type}}, occ.locationOf("TYPE_CHAM"));
    }
    const auto cmp = occ.texts("NOM_CMP");
    if (static_cast<int>(cmp.size()) != frameComponentCount(*q)) {
      throw invalid(
          "MODI_REPERE_2.12",
          {{"type", type}, {"frame_component_count", frameComponentCount(*q)}, {"cmp_count", cmp.size()}},
          occ.locationOf("NOM_CMP"));
    }
    if (ofResult && !occ.has("NOM_CHAM")) {
      throw invalid("MODI_REPERE_2.13", {}, occ.location());
    }
    if (!ofResult && occ.has("NOM_CHAM")) {
      throw invalid("MODI_REPERE_2.14", {}, occ.locationOf("NOM_CHAM"));
    }
    out.push_back({ofResult ? occ.text("NOM_CHAM") : std::string(), *q, cmp, &occ});
  }
  return out;
}

// Where the values of a field live: node, cell centre, cell node or Gauss point.
class Positions {
public:
  explicit Positions(const Mesh& mesh) : mesh_(mesh) {}

  Point3 node(NodeId n) const { return mesh_.point(n); }
  Point3 cellCentre(CellId c) const { return cellCentroid(mesh_, c); }
  // The centre of the first cell holding node n (the fallback of a node on the axis).
  std::optional<Point3> firstCellCentre(NodeId n) {
    if (firstCell_.empty()) {
      firstCell_.assign(static_cast<std::size_t>(mesh_.nodeCount()), -1);
      for (CellId c = mesh_.cellCount() - 1; c >= 0; --c) {
        for (const NodeId k : mesh_.cellNodes(c)) {
          firstCell_[static_cast<std::size_t>(k)] = c;
        }
      }
    }
    const CellId c = firstCell_[static_cast<std::size_t>(n)];
    return c < 0 ? std::nullopt : std::optional<Point3>(cellCentre(c));
  }
  // The `count` Gauss points of cell c (its RIGI family), empty when no rule has that many.
  std::vector<Point3> gaussPoints(CellId c, int count) const {
    const CellType t = mesh_.cellType(c);
    for (const auto role : {fem::IntegrationRole::Volume, fem::IntegrationRole::AxisymmetricVolume,
                            fem::IntegrationRole::Skin}) {
      try {
        const auto& rule = fem::rigiRule(t, role);
        if (rule.size() != count) {
          continue;
        }
        const auto& ref = fem::referenceElement(t);
        const auto nodes = mesh_.cellNodes(c);
        std::vector<Point3> out;
        for (const auto& xi : rule.points) {
          const Eigen::VectorXd n = ref.values(Eigen::Vector3d(xi[0], xi[1], xi[2]));
          Point3 x{0.0, 0.0, 0.0};
          for (std::size_t i = 0; i < nodes.size(); ++i) {
            x = x + n(static_cast<Eigen::Index>(i)) * mesh_.point(nodes[i]);
          }
          out.push_back(x);
        }
        return out;
      } catch (const std::exception&) {
        // No rule of this role for this type: try the next one.
      }
    }
    return {};
  }
  const Mesh& mesh() const { return mesh_; }

private:
  const Mesh& mesh_;
  std::vector<CellId> firstCell_;
};

class FieldRotator {
public:
  FieldRotator(const Change& change, const FrameSpec& frame, Positions& positions,
               const std::string& fieldLabel)
      : change_(change), frame_(frame), positions_(positions), label_(fieldLabel) {}

  void apply(Field& f) {
    for (const auto& name : change_.components) {
      const auto i = f.componentIndex(name);
      if (!i) {
        throw invalid("MODI_REPERE_2.15",
                      {{"label", label_}, {"name", name}, {"join", fmt::join(f.components(), ", ")}},
                      change_.occ->locationOf("NOM_CMP"));
      }
      index_.push_back(*i);
    }
    if (frame_.byNodeGroup && f.support() != FieldSupport::Node) {
      throw refused(msg::text("MODI_REPERE_1.f3", {{"label", label_}}), frame_.location);
    }
    switch (f.support()) {
    case FieldSupport::Node:
      for (NodeId n = 0; n < static_cast<NodeId>(f.entityCount()); ++n) {
        if (frame_.everywhere || frame_.nodes[static_cast<std::size_t>(n)]) {
          rotate(f, static_cast<std::size_t>(n), positions_.node(n),
                 [&] { return positions_.firstCellCentre(n); });
        }
      }
      return;
    case FieldSupport::Cell:
      for (CellId c = 0; c < static_cast<CellId>(f.entityCount()); ++c) {
        if (selected(c)) {
          rotate(f, static_cast<std::size_t>(c), positions_.cellCentre(c),
                 [] { return std::optional<Point3>(); });
        }
      }
      return;
    case FieldSupport::CellNode:
    case FieldSupport::GaussPoint:
      perPoint(f);
      return;
    }
  }

private:
  bool selected(CellId c) const { return frame_.everywhere || frame_.cells[static_cast<std::size_t>(c)]; }

  void perPoint(Field& f) {
    const Mesh& mesh = positions_.mesh();
    for (CellId c = 0; c < static_cast<CellId>(f.cellCount()); ++c) {
      const int count = f.pointCount(static_cast<std::size_t>(c));
      if (count == 0 || !selected(c)) {
        continue;
      }
      std::vector<Point3> points;
      if (f.support() == FieldSupport::CellNode) {
        for (const NodeId n : mesh.cellNodes(c)) {
          points.push_back(mesh.point(n));
        }
      } else if (frame_.cylindrical) {
        points = positions_.gaussPoints(c, count);
      } else {
        points.assign(static_cast<std::size_t>(count), Point3{0.0, 0.0, 0.0}); // not used
      }
      if (static_cast<int>(points.size()) != count) {
        throw refused(msg::text("MODI_REPERE_1.f4", {{"label", label_},
                                                     {"cell_name", mesh.cellName(c)},
                                                     {"count", count},
                                                     {"name", name(mesh.cellType(c))}}),
                      change_.occ->location());
      }
      const Point3 centre = positions_.cellCentre(c);
      for (int q = 0; q < count; ++q) {
        rotate(f, f.firstPoint(static_cast<std::size_t>(c)) + static_cast<std::size_t>(q),
               points[static_cast<std::size_t>(q)], [&] { return std::optional<Point3>(centre); });
      }
    }
  }

  template <class Fallback> void rotate(Field& f, std::size_t entity, const Point3& at, Fallback fallback) {
    double v[6];
    for (std::size_t k = 0; k < index_.size(); ++k) {
      if (!f.defined(entity, index_[k])) {
        return; // a component is absent here: left as it is
      }
      v[k] = f.value(entity, index_[k]);
    }
    Rotation r = frame_.fixed;
    if (frame_.cylindrical) {
      auto local = cylindricalRotation(frame_.origin, frame_.axis, at);
      if (!local) {
        const auto other = fallback();
        local = other ? cylindricalRotation(frame_.origin, frame_.axis, *other) : std::nullopt;
      }
      if (!local) {
        throw invalid("MODI_REPERE_2.16",
                      {{"label", label_}, {"at", at[0]}, {"at_2", at[1]}, {"at_3", at[2]}}, frame_.location);
      }
      r = *local;
    }
    rotateComponents(change_.quantity, r, frame_.cylindrical, std::span<double>(v, index_.size()));
    for (std::size_t k = 0; k < index_.size(); ++k) {
      f.value(entity, index_[k]) = v[k];
    }
  }

  const Change& change_;
  const FrameSpec& frame_;
  Positions& positions_;
  std::string label_;
  std::vector<std::size_t> index_;
};

// A copy of `field` in the frames of every AFFE occurrence.
std::shared_ptr<Field> changed(const Field& field, const Change& change, const std::vector<FrameSpec>& specs,
                               Positions& positions, const std::string& label) {
  auto out = std::make_shared<Field>(field);
  for (const FrameSpec& spec : specs) {
    FieldRotator(change, spec, positions, label).apply(*out);
  }
  return out;
}

std::vector<const ResultStep*> selectedSteps(const Result& r, const std::string& name,
                                             const KeywordTree& kw) {
  if (kw.has("LIST_ORDRE")) {
    throw refused("LIST_ORDRE", kw.locationOf("LIST_ORDRE"));
  }
  std::vector<const ResultStep*> out;
  if (kw.has("NUME_ORDRE")) {
    for (const auto n : kw.integers("NUME_ORDRE")) {
      const ResultStep* s = r.stepNumber(static_cast<int>(n));
      if (s == nullptr) {
        throw invalid("MODI_REPERE_2.17", {{"name", name}, {"n", n}}, kw.locationOf("NUME_ORDRE"));
      }
      out.push_back(s);
    }
    return out;
  }
  if (kw.has("INST") || kw.has("LIST_INST")) {
    std::vector<double> times;
    if (kw.has("INST")) {
      times = kw.reals("INST");
    } else {
      auto list = conceptData<RealList>(kw.conceptValue("LIST_INST"));
      STELLA_ASSERT(list != nullptr, "LIST_INST holds no list of reals");
      times = list->values;
    }
    const char* key = kw.has("INST") ? "INST" : "LIST_INST";
    for (const double t : times) {
      const ResultStep* s = r.stepAtTime(t, kw.real("PRECISION"), kw.text("CRITERE") == "ABSOLU");
      if (s == nullptr) {
        throw invalid("MODI_REPERE_2.18", {{"name", name}, {"t", t}}, kw.locationOf(key));
      }
      out.push_back(s);
    }
    return out;
  }
  for (const auto& s : r.steps) {
    out.push_back(&s);
  }
  return out;
}

Value ofResult(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const auto concept_ = kw.conceptValue("RESULTAT");
  auto source = conceptData<Result>(concept_);
  STELLA_ASSERT(source != nullptr && source->mesh != nullptr, "RESULTAT holds no result");
  const Mesh& mesh = *source->mesh;
  const auto specs = frames(kw, mesh);
  const auto todo = changes(kw, true, mesh.dimension());
  std::shared_ptr<Result> result = source;
  if (!call.reused) {
    result = std::make_shared<Result>();
    result->type = source->type;
    result->mesh = source->mesh;
    result->model = source->model;
    result->material = source->material;
  }
  Positions positions(mesh);
  const auto steps = selectedSteps(*source, concept_->name, kw);
  for (const ResultStep* s : steps) {
    std::map<std::string, std::shared_ptr<Field>> fields;
    for (const Change& ch : todo) {
      const auto it = fields.find(ch.field);
      const Field* f = it != fields.end() ? it->second.get() : s->field(ch.field);
      if (f == nullptr) {
        throw invalid("MODI_REPERE_2.19",
                      {{"name", concept_->name}, {"field", ch.field}, {"number", s->number}},
                      ch.occ->locationOf("NOM_CHAM"));
      }
      fields[ch.field] = changed(*f, ch, specs, positions, fmt::format("{} of {}", ch.field, concept_->name));
    }
    ResultStep* target = call.reused ? result->stepNumber(s->number) : nullptr;
    if (target == nullptr) {
      ResultStep& added = result->steps.emplace_back();
      added.number = s->number;
      added.time = s->time;
      added.parameters = s->parameters;
      target = &added;
    }
    for (auto& [name, f] : fields) {
      target->fields[name] = f;
    }
  }
  call.session.message() << fmt::format("  MODI_REPERE: REPERE='{}' on {} of {} step(s) of {}\n",
                                        kw.text("REPERE"), todo.size() == 1 ? todo[0].field : "the fields",
                                        steps.size(), concept_->name);
  return call.makeConcept(result);
}

Value ofField(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  const auto concept_ = kw.conceptValue("CHAM_GD");
  auto source = conceptData<FieldConcept>(concept_);
  if (source == nullptr || source->field == nullptr || source->mesh == nullptr) {
    throw refused(msg::text("MODI_REPERE_1.f5"), kw.locationOf("CHAM_GD"));
  }
  const auto specs = frames(kw, *source->mesh);
  const auto todo = changes(kw, false, source->mesh->dimension());
  Positions positions(*source->mesh);
  std::shared_ptr<const Field> f = source->field;
  for (const Change& ch : todo) {
    f = changed(*f, ch, specs, positions, "the field " + concept_->name);
  }
  auto out = std::make_shared<FieldConcept>(*source);
  out->field = f;
  return call.makeConcept(out);
}

// TITRE and, with INFO=2, the rotation of each UTILISATEUR frame.
void report(OperatorCall& call) {
  const KeywordTree& kw = call.keywords;
  if (kw.has("TITRE")) {
    call.session.message() << "  MODI_REPERE: TITRE " << kw.text("TITRE") << "\n";
  }
  if (kw.integer("INFO") < 2 || kw.text("REPERE") != "UTILISATEUR") {
    return;
  }
  const int dim = kw.has("RESULTAT")
                      ? conceptData<Result>(kw.conceptValue("RESULTAT"))->mesh->dimension()
                      : conceptData<FieldConcept>(kw.conceptValue("CHAM_GD"))->mesh->dimension();
  for (const auto& occ : kw.occurrences("AFFE")) {
    FrameSpec spec;
    userFrame(occ, dim, spec);
    call.session.message() << "  MODI_REPERE: frame (rows = local axes in global coordinates)\n";
    for (const auto& row : spec.fixed) {
      call.session.message() << fmt::format("    {: .9f} {: .9f} {: .9f}\n", row[0], row[1], row[2]);
    }
  }
}

Value runModiRepere(OperatorCall& call) {
  Value out = call.keywords.has("RESULTAT") ? ofResult(call) : ofField(call);
  report(call);
  return out;
}

} // namespace

STELLA_OPERATOR("MODI_REPERE", runModiRepere);

} // namespace stella

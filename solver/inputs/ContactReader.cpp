// Reading DEFI_CONTACT's keyword tree (validated by the catalogue) into a ContactDefinition: one
// function per keyword group (the global settings, those of FORMULATION='CONTINUE', a ZONE, the
// continuous keywords of a ZONE). The checks against the mesh are in ContactDefinition.cpp.

#include "solver/inputs/ContactReader.hpp"

#include "catalog/KeywordTree.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace stella::contact {

namespace {

VectorChoice vectorChoice(const std::string& s) {
  if (s == "FIXE") {
    return VectorChoice::Fixed;
  }
  return s == "VECT_Y" ? VectorChoice::VectY : VectorChoice::Auto;
}

std::array<double, 3> vector3(const KeywordTree& kw, const std::string& name) {
  std::array<double, 3> v{0, 0, 0};
  if (kw.has(name)) {
    const auto r = kw.reals(name);
    for (std::size_t i = 0; i < std::min<std::size_t>(3, r.size()); ++i) {
      v[i] = r[i];
    }
  }
  return v;
}

ContactAlgorithm algorithmFromName(const std::string& s) {
  if (s == "GCP") {
    return ContactAlgorithm::Gcp;
  }
  if (s == "PENALISATION") {
    return ContactAlgorithm::Penalty;
  }
  if (s == "STANDARD") {
    return ContactAlgorithm::Standard;
  }
  if (s == "LAC") {
    return ContactAlgorithm::Lac;
  }
  return ContactAlgorithm::Constraint;
}

// A keyword whose value is not implemented yet is recorded with its location.
void refuseUnless(const KeywordTree& kw, const std::string& name, const std::string& allowed,
                  std::vector<Unimplemented>& refused) {
  if (kw.has(name) && kw.textOr(name, allowed) != allowed) {
    refused.push_back({fmt::format("{}='{}'", name, kw.textOr(name, allowed)), kw.locationOf(name)});
  }
}

void refusePresent(const KeywordTree& kw, const std::string& name, std::vector<Unimplemented>& refused) {
  if (kw.has(name)) {
    refused.push_back({name, kw.locationOf(name)});
  }
}

ContinuousZone readContinuousZone(const KeywordTree& z) {
  ContinuousZone c;
  if (z.has("COEF_CONT")) { // ALGO_CONT='STANDARD' only
    c.augmentation = z.real("COEF_CONT");
  }
  c.penalty = z.realOr("COEF_PENA_CONT", 0.0);
  const std::string init = z.text("CONTACT_INIT");
  c.init = init == "OUI" ? ContactInit::Yes : init == "NON" ? ContactInit::No : ContactInit::Interpenetrated;
  c.initDistance = z.realOr("DIST_MAXI", -1.0);
  if (z.has("ADAPTATION")) { // not in a LAC zone
    c.adaptation = z.text("ADAPTATION");
  }
  c.adaptationAt = z.locationOf("ADAPTATION");
  if (z.has("ALGO_FROT")) { // FROTTEMENT='COULOMB'
    c.frictionPenalised = z.text("ALGO_FROT") == "PENALISATION";
  }
  if (z.has("COEF_FROT")) { // ALGO_FROT='STANDARD'
    c.frictionAugmentation = z.real("COEF_FROT");
  }
  c.frictionPenalty = z.realOr("COEF_PENA_FROT", 0.0);
  if (z.has("TYPE_APPA")) { // ALGO_CONT='LAC'
    c.lacBruteForce = z.text("TYPE_APPA") == "ROBUSTE";
    c.lacCurrentJacobian = z.text("TYPE_JACOBIEN") == "ACTUALISE";
  }
  refuseUnless(z, "GRAND_GLIS", "NON", c.refused);
  if (z.has("INTEGRATION")) { // not in a LAC zone
    const std::string scheme = z.text("INTEGRATION");
    c.integration = scheme == "GAUSS"     ? ContactIntegration::Gauss
                    : scheme == "SIMPSON" ? ContactIntegration::Simpson
                    : scheme == "NCOTES"  ? ContactIntegration::NewtonCotes
                                          : ContactIntegration::Auto;
    c.integrationAt = z.locationOf("INTEGRATION");
    if (c.integration != ContactIntegration::Auto) { // the scheme's block
      c.integrationOrder = static_cast<int>(z.integer("ORDRE_INT"));
    }
  }
  refuseUnless(z, "DIST_POUTRE", "NON", c.refused);
  refuseUnless(z, "DIST_COQUE", "NON", c.refused);
  refusePresent(z, "DIST_MAIT", c.refused);
  refusePresent(z, "DIST_ESCL", c.refused);
  if (z.has("PENE_MAXI")) { // ADAPTATION='ADAPT_COEF' or 'TOUT' with ALGO_CONT='PENALISATION'
    c.maxPenetration = z.real("PENE_MAXI");
    c.maxPenetrationAt = z.locationOf("PENE_MAXI");
  }
  refusePresent(z, "GLIS_MAXI", c.refused);
  if (z.has("SEUIL_INIT")) { // FROTTEMENT='COULOMB'
    c.initialThreshold = z.real("SEUIL_INIT");
  }
  if (z.has("SANS_GROUP_NO_FR")) {
    c.frictionExcludedGroups = z.texts("SANS_GROUP_NO_FR");
    c.frictionExcludedAt = z.locationOf("SANS_GROUP_NO_FR");
  }
  if (z.has("DIRE_EXCL_FROT")) {
    c.excludedDirection = vector3(z, "DIRE_EXCL_FROT");
    c.excludedDirectionAt = z.locationOf("DIRE_EXCL_FROT");
  }
  if (z.has("TOLE_INTERP") && z.real("TOLE_INTERP") != 0.0) {
    c.refused.push_back({"TOLE_INTERP (other than its default 0)", z.locationOf("TOLE_INTERP")});
  }
  return c;
}

ContinuousSettings readContinuousSettings(const KeywordTree& kw) {
  ContinuousSettings c;
  c.statusLoop = kw.text("ALGO_RESO_CONT") == "POINT_FIXE" ? StatusLoop::FixedPoint : StatusLoop::Newton;
  if (c.statusLoop == StatusLoop::FixedPoint) { // the keywords of the status loop's block
    c.iterationsPerNode = kw.text("ITER_CONT_TYPE") == "MULT";
    if (c.iterationsPerNode) {
      c.statusIterationFactor = static_cast<int>(kw.integer("ITER_CONT_MULT"));
    } else {
      c.maxStatusIterations = static_cast<int>(kw.integer("ITER_CONT_MAXI"));
    }
  }
  if (kw.has("ALGO_RESO_FROT")) { // FROTTEMENT='COULOMB'
    c.frictionFixedPoint = kw.text("ALGO_RESO_FROT") == "POINT_FIXE";
    c.frictionResidual = kw.real("RESI_FROT");
    if (c.frictionFixedPoint) {
      c.maxFrictionIterations = static_cast<int>(kw.integer("ITER_FROT_MAXI"));
    }
  }
  // refused unless every zone is LAC (absent from trees built without the catalogue's defaults)
  c.geometryNewton = kw.has("ALGO_RESO_GEOM") && kw.text("ALGO_RESO_GEOM") == "NEWTON";
  c.geometryAt = kw.locationOf("ALGO_RESO_GEOM");
  if (kw.real("RESI_CONT") != -1.0) {
    c.refused.push_back({"RESI_CONT (other than its default -1)", kw.locationOf("RESI_CONT")});
  }
  if (kw.integer("CONT_STAT_ELAS") != 0) {
    c.refused.push_back({"CONT_STAT_ELAS > 0", kw.locationOf("CONT_STAT_ELAS")});
  }
  refuseUnless(kw, "STOP_INTERP", "NON", c.refused);
  return c;
}

ContactZone readZone(const KeywordTree& z, Formulation formulation, bool friction) {
  ContactZone zone;
  zone.location = z.location();
  zone.masterGroup = z.textOr("GROUP_MA_MAIT", "");
  zone.slaveGroup = z.textOr("GROUP_MA_ESCL", "");
  const std::string pairing = z.textOr("APPARIEMENT", "MAIT_ESCL");
  zone.pairing = pairing == "NODAL"    ? Pairing::Nodal
                 : pairing == "MORTAR" ? Pairing::Mortar
                                       : Pairing::MasterSlave;
  const std::string normal = z.textOr("NORMALE", "MAIT");
  zone.normal = normal == "ESCL"        ? NormalChoice::Slave
                : normal == "MAIT_ESCL" ? NormalChoice::MasterSlave
                                        : NormalChoice::Master;
  zone.masterVector = vectorChoice(z.textOr("VECT_MAIT", "AUTO"));
  zone.masterVectorValue =
      zone.masterVector == VectorChoice::Fixed ? vector3(z, "MAIT_FIXE") : vector3(z, "MAIT_VECT_Y");
  zone.slaveVector = vectorChoice(z.textOr("VECT_ESCL", "AUTO"));
  zone.slaveVectorValue =
      zone.slaveVector == VectorChoice::Fixed ? vector3(z, "ESCL_FIXE") : vector3(z, "ESCL_VECT_Y");
  zone.projection =
      z.textOr("TYPE_PROJECTION", "ORTHOGONALE") == "FIXE" ? Projection::Fixed : Projection::Orthogonal;
  zone.projectionDirection = vector3(z, "DIRE_APPA");
  zone.pairingDistance = z.realOr("DIST_APPA", -1.0);
  zone.extensionTolerance = z.realOr("TOLE_PROJ_EXT", 0.5);
  if (z.has("SANS_GROUP_NO")) {
    zone.excludedNodeGroups = z.texts("SANS_GROUP_NO");
  }
  if (z.has("SANS_GROUP_MA")) {
    zone.excludedCellGroups = z.texts("SANS_GROUP_MA");
  }
  zone.resolve = z.textOr("RESOLUTION", "OUI") == "OUI";
  zone.interpolationTolerance = z.realOr("TOLE_INTERP", 0.0);
  const std::string defaultAlgorithm = formulation == Formulation::Continue ? "STANDARD" : "CONTRAINTE";
  zone.algorithm = algorithmFromName(z.textOr("ALGO_CONT", defaultAlgorithm));
  if (formulation == Formulation::Continue && zone.algorithm == ContactAlgorithm::Penalty) {
    zone.algorithm = ContactAlgorithm::ContinuePenalty;
  }
  zone.slide = z.textOr("GLISSIERE", "NON") == "OUI";
  zone.gapAlarm = z.realOr("ALARME_JEU", 0.0);
  zone.normalPenalty = z.realOr("E_N", 0.0);
  zone.friction = friction;
  zone.coulomb = z.realOr("COULOMB", 0.0);
  zone.tangentPenalty = z.realOr("E_T", 0.0);
  zone.frictionMatrixCoefficient = z.realOr("COEF_MATR_FROT", 0.0);
  if (formulation == Formulation::Continue) {
    zone.continuous = readContinuousZone(z);
  }
  return zone;
}

ContactSettings readSettings(const KeywordTree& kw) {
  ContactSettings s;
  const std::string formulation = kw.textOr("FORMULATION", "DISCRETE");
  s.formulation = formulation == "CONTINUE"       ? Formulation::Continue
                  : formulation == "LIAISON_UNIL" ? Formulation::LiaisonUnil
                                                  : Formulation::Discrete;
  s.friction = kw.textOr("FROTTEMENT", "SANS") == "COULOMB";
  s.frictionAt = kw.locationOf("FROTTEMENT");
  s.stopInterpenetration = kw.textOr("STOP_INTERP", "NON") == "OUI";
  s.smoothing = kw.textOr("LISSAGE", "NON") == "OUI";
  s.checkNormals = kw.textOr("VERI_NORM", "OUI") == "OUI";
  const std::string reac = kw.textOr("REAC_GEOM", "AUTOMATIQUE");
  s.geometricUpdate = reac == "SANS"       ? GeometricUpdate::None
                      : reac == "CONTROLE" ? GeometricUpdate::Controlled
                                           : GeometricUpdate::Automatic;
  s.maxGeometricIterations = static_cast<int>(kw.integerOr("ITER_GEOM_MAXI", 10));
  s.geometricResidual = kw.realOr("RESI_GEOM", 0.01);
  s.geometricIterations = static_cast<int>(kw.integerOr("NB_ITER_GEOM", 2));
  s.contactIterationFactor = static_cast<int>(kw.integerOr("ITER_CONT_MULT", 4));
  s.stopIfSingular = kw.textOr("STOP_SINGULIER", "OUI") == "OUI";
  s.rightHandSidesPerSolve = static_cast<int>(kw.integerOr("NB_RESOL", 10));
  if (kw.has("RESI_ABSO")) {
    s.gcpTolerance = kw.real("RESI_ABSO");
  }
  s.gcpMaxIterations = static_cast<int>(kw.integerOr("ITER_GCP_MAXI", 0));
  s.lineSearch = kw.textOr("RECH_LINEAIRE", "ADMISSIBLE") == "NON_ADMISSIBLE" ? LineSearch::NonAdmissible
                                                                              : LineSearch::Admissible;
  s.dirichletPreconditioner = kw.textOr("PRE_COND", "SANS") == "DIRICHLET";
  s.preconditionerResidual = kw.realOr("COEF_RESI", -1.0);
  s.preconditionerMaxIterations = static_cast<int>(kw.integerOr("ITER_PRE_MAXI", 0));
  if (s.formulation == Formulation::Continue) {
    s.continuous = readContinuousSettings(kw);
  }
  return s;
}

} // namespace

std::shared_ptr<ContactDefinition> readContactDefinition(const KeywordTree& keywords,
                                                         std::shared_ptr<const Mesh> mesh) {
  auto def = std::make_shared<ContactDefinition>();
  def->mesh = std::move(mesh);
  def->location = keywords.location();
  def->settings = readSettings(keywords);
  for (const KeywordTree& z : keywords.occurrences("ZONE")) {
    def->zones.push_back(readZone(z, def->settings.formulation, def->settings.friction));
  }
  return def;
}

} // namespace stella::contact

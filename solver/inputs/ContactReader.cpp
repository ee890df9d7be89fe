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
  if (kw.has(name) && kw.text(name) != allowed) {
    refused.push_back({fmt::format("{}='{}'", name, kw.text(name)), kw.locationOf(name)});
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
  // LAC, and the nodal continuous formulation (ContinuousGeometricTangent.hpp); absent from trees built
  // without the catalogue's defaults
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

// The pairing and resolution keywords of a ZONE of FORMULATION='DISCRETE', or 'CONTINUE' with
// ALGO_CONT='STANDARD' or 'PENALISATION' (a LAC zone has APPARIEMENT only).
void readZonePairing(const KeywordTree& z, Formulation formulation, ContactZone& zone) {
  const std::string normal = z.text("NORMALE");
  zone.normal = normal == "ESCL"        ? NormalChoice::Slave
                : normal == "MAIT_ESCL" ? NormalChoice::MasterSlave
                                        : NormalChoice::Master;
  zone.masterVector = vectorChoice(z.text("VECT_MAIT"));
  zone.masterVectorValue =
      zone.masterVector == VectorChoice::Fixed ? vector3(z, "MAIT_FIXE") : vector3(z, "MAIT_VECT_Y");
  zone.slaveVector = vectorChoice(z.text("VECT_ESCL"));
  zone.slaveVectorValue =
      zone.slaveVector == VectorChoice::Fixed ? vector3(z, "ESCL_FIXE") : vector3(z, "ESCL_VECT_Y");
  zone.projection = z.text("TYPE_PROJECTION") == "FIXE" ? Projection::Fixed : Projection::Orthogonal;
  zone.projectionDirection = vector3(z, "DIRE_APPA");
  zone.pairingDistance = z.real("DIST_APPA");
  zone.extensionTolerance = z.real("TOLE_PROJ_EXT");
  zone.resolve = z.text("RESOLUTION") == "OUI";
  if (!zone.resolve) { // TOLE_INTERP: RESOLUTION='NON' only
    zone.interpolationTolerance = z.real("TOLE_INTERP");
  }
  // GLISSIERE: ALGO_CONT='CONTRAINTE' in the discrete formulation, every zone of this function in
  // the continuous one; ALARME_JEU: GLISSIERE='OUI' of the discrete formulation.
  if (formulation == Formulation::Continue || zone.algorithm == ContactAlgorithm::Constraint) {
    zone.slide = z.text("GLISSIERE") == "OUI";
  }
  if (formulation == Formulation::Discrete && zone.slide) {
    zone.gapAlarm = z.real("ALARME_JEU");
  }
}

ContactZone readZone(const KeywordTree& z, Formulation formulation, bool friction) {
  ContactZone zone;
  zone.location = z.location();
  zone.masterGroup = z.textOr("GROUP_MA_MAIT", "");
  zone.slaveGroup = z.textOr("GROUP_MA_ESCL", "");
  zone.algorithm = algorithmFromName(z.text("ALGO_CONT"));
  if (formulation == Formulation::Continue && zone.algorithm == ContactAlgorithm::Penalty) {
    zone.algorithm = ContactAlgorithm::ContinuePenalty;
  }
  if (formulation != Formulation::LiaisonUnil) {
    const std::string pairing = z.text("APPARIEMENT"); // MORTAR by default with ALGO_CONT='LAC'
    zone.pairing = pairing == "NODAL"    ? Pairing::Nodal
                   : pairing == "MORTAR" ? Pairing::Mortar
                                         : Pairing::MasterSlave;
    if (zone.algorithm != ContactAlgorithm::Lac) {
      readZonePairing(z, formulation, zone);
    }
  }
  if (z.has("SANS_GROUP_NO")) {
    zone.excludedNodeGroups = z.texts("SANS_GROUP_NO");
  }
  if (z.has("SANS_GROUP_MA")) {
    zone.excludedCellGroups = z.texts("SANS_GROUP_MA");
  }
  zone.normalPenalty = z.realOr("E_N", 0.0);
  zone.friction = friction;
  zone.coulomb = z.realOr("COULOMB", 0.0);
  zone.tangentPenalty = z.realOr("E_T", 0.0);
  if (formulation == Formulation::Discrete && friction) {
    zone.frictionMatrixCoefficient = z.real("COEF_MATR_FROT");
  }
  if (formulation == Formulation::Continue) {
    zone.continuous = readContinuousZone(z);
  }
  return zone;
}

// REAC_GEOM and its block: FORMULATION='DISCRETE', or 'CONTINUE' with ALGO_RESO_GEOM='POINT_FIXE'.
void readGeometricLoop(const KeywordTree& kw, ContactSettings& s) {
  const std::string reac = kw.text("REAC_GEOM");
  s.geometricUpdate = reac == "SANS"       ? GeometricUpdate::None
                      : reac == "CONTROLE" ? GeometricUpdate::Controlled
                                           : GeometricUpdate::Automatic;
  if (s.geometricUpdate == GeometricUpdate::Automatic) {
    s.maxGeometricIterations = static_cast<int>(kw.integer("ITER_GEOM_MAXI"));
    s.geometricResidual = kw.real("RESI_GEOM");
  } else if (s.geometricUpdate == GeometricUpdate::Controlled) {
    s.geometricIterations = static_cast<int>(kw.integer("NB_ITER_GEOM"));
  }
}

// The global keywords of FORMULATION='DISCRETE'.
void readDiscreteSettings(const KeywordTree& kw, ContactSettings& s) {
  readGeometricLoop(kw, s);
  s.contactIterationFactor = static_cast<int>(kw.integer("ITER_CONT_MULT"));
  s.stopIfSingular = kw.text("STOP_SINGULIER") == "OUI";
  s.rightHandSidesPerSolve = static_cast<int>(kw.integer("NB_RESOL"));
  if (kw.has("RESI_ABSO")) {
    s.gcpTolerance = kw.real("RESI_ABSO");
  }
  s.gcpMaxIterations = static_cast<int>(kw.integer("ITER_GCP_MAXI"));
  s.lineSearch =
      kw.text("RECH_LINEAIRE") == "NON_ADMISSIBLE" ? LineSearch::NonAdmissible : LineSearch::Admissible;
  s.dirichletPreconditioner = kw.text("PRE_COND") == "DIRICHLET";
  if (s.dirichletPreconditioner) {
    s.preconditionerResidual = kw.real("COEF_RESI");
    s.preconditionerMaxIterations = static_cast<int>(kw.integer("ITER_PRE_MAXI"));
  }
}

ContactSettings readSettings(const KeywordTree& kw) {
  ContactSettings s;
  const std::string formulation = kw.text("FORMULATION");
  s.formulation = formulation == "CONTINUE"       ? Formulation::Continue
                  : formulation == "LIAISON_UNIL" ? Formulation::LiaisonUnil
                                                  : Formulation::Discrete;
  s.friction = kw.text("FROTTEMENT") == "COULOMB";
  s.frictionAt = kw.locationOf("FROTTEMENT");
  if (s.formulation == Formulation::LiaisonUnil) {
    return s; // none of the keywords below
  }
  s.stopInterpenetration = kw.text("STOP_INTERP") == "OUI";
  s.smoothing = kw.text("LISSAGE") == "OUI";
  s.checkNormals = kw.text("VERI_NORM") == "OUI";
  if (s.formulation == Formulation::Discrete) {
    readDiscreteSettings(kw, s);
  } else {
    if (kw.text("ALGO_RESO_GEOM") == "POINT_FIXE") {
      readGeometricLoop(kw, s);
    } else { // NEWTON
      s.geometricResidual = kw.real("RESI_GEOM");
    }
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

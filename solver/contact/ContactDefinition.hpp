#pragma once
// The data of a `char_contact` concept (DEFI_CONTACT): the formulation, the global settings of
// the geometric loop and of the discrete algorithms, and the contact zones with their pairing
// and resolution settings, as read from the validated keyword tree (solver/inputs/ContactReader).
// The definition keeps every formulation the catalogue accepts (DISCRETE, CONTINUE, LAC);
// STAT_NON_LINE refuses the ones not implemented yet. Checks against the mesh (groups, shared nodes, disjoint
// slave surfaces, outward normals) run when the definition is built (checkContactDefinition).

#include "interpreter/Diagnostics.hpp"
#include "interpreter/Value.hpp"
#include "solver/contact/ContinuousIntegrationRule.hpp"
#include "solver/mesh/Mesh.hpp"

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace stella {

class Model;

namespace contact {

enum class Formulation { Discrete, Continue, LiaisonUnil };
enum class Pairing { MasterSlave, Nodal, Mortar };      // APPARIEMENT
enum class NormalChoice { Master, MasterSlave, Slave }; // NORMALE
enum class VectorChoice { Auto, Fixed, VectY };         // VECT_MAIT / VECT_ESCL
enum class Projection { Orthogonal, Fixed };            // TYPE_PROJECTION
enum class ContactAlgorithm { Constraint, Gcp, Penalty, Standard, ContinuePenalty, Lac }; // ALGO_CONT
enum class GeometricUpdate { Automatic, Controlled, None };                               // REAC_GEOM
enum class LineSearch { Admissible, NonAdmissible };                                      // RECH_LINEAIRE

enum class ContactInit { Yes, Interpenetrated, No }; // CONTACT_INIT (CONTINUE)

// A keyword value the catalogue accepts that stella does not implement yet: STAT_NON_LINE
// refuses it (CONTACT_20) at the keyword's location.
struct Unimplemented {
  std::string what;
  SourceLocation location;
};

// The keywords of a ZONE of FORMULATION='CONTINUE' (ignored by the other formulations).
struct ContinuousZone {
  double augmentation = 100.0;                     // COEF_CONT (ALGO_CONT='STANDARD')
  double penalty = 0.0;                            // COEF_PENA_CONT (ALGO_CONT='PENALISATION')
  ContactInit init = ContactInit::Interpenetrated; // CONTACT_INIT
  double initDistance = -1.0;                      // DIST_MAXI (< 0: no limit)
  std::string adaptation = "CYCLAGE";              // ADAPTATION
  SourceLocation adaptationAt;
  std::optional<double> maxPenetration; // PENE_MAXI (ADAPT_COEF/TOUT; default: ContinuousAdaptation)
  SourceLocation maxPenetrationAt;
  double stiffness = 0.0; // ADAPT_COEF/TOUT: E*/h, the scale of the coefficients (ContinuousAdaptation)
  bool frictionPenalised = false;                  // ALGO_FROT='PENALISATION' (else STANDARD)
  double frictionAugmentation = 100.0;             // COEF_FROT (ALGO_FROT='STANDARD')
  double frictionPenalty = 0.0;                    // COEF_PENA_FROT (ALGO_FROT='PENALISATION')
  std::optional<double> initialThreshold;          // SEUIL_INIT (FROTTEMENT='COULOMB')
  std::vector<std::string> frictionExcludedGroups; // SANS_GROUP_NO_FR
  SourceLocation frictionExcludedAt;
  std::optional<std::array<double, 3>> excludedDirection; // DIRE_EXCL_FROT
  SourceLocation excludedDirectionAt;
  ContactIntegration integration = ContactIntegration::Auto; // INTEGRATION
  int integrationOrder = 0;                                  // ORDRE_INT (0 with AUTO)
  SourceLocation integrationAt;
  bool lacBruteForce = false;         // TYPE_APPA='ROBUSTE' (ALGO_CONT='LAC'; else RAPIDE)
  bool lacCurrentJacobian = false;    // TYPE_JACOBIEN='ACTUALISE' (ALGO_CONT='LAC'; else INITIAL)
  std::vector<Unimplemented> refused; // DIST_*...
};

// One ZONE occurrence.
struct ContactZone {
  std::string masterGroup; // GROUP_MA_MAIT
  std::string slaveGroup;  // GROUP_MA_ESCL
  Pairing pairing = Pairing::MasterSlave;
  NormalChoice normal = NormalChoice::Master;
  VectorChoice masterVector = VectorChoice::Auto;
  std::array<double, 3> masterVectorValue{0, 0, 0}; // MAIT_FIXE or MAIT_VECT_Y
  VectorChoice slaveVector = VectorChoice::Auto;
  std::array<double, 3> slaveVectorValue{0, 0, 0}; // ESCL_FIXE or ESCL_VECT_Y
  Projection projection = Projection::Orthogonal;
  std::array<double, 3> projectionDirection{0, 0, 0}; // DIRE_APPA
  double pairingDistance = -1.0;                      // DIST_APPA (< 0: no limit)
  double extensionTolerance = 0.5;                    // TOLE_PROJ_EXT
  std::vector<std::string> excludedNodeGroups;        // SANS_GROUP_NO
  std::vector<std::string> excludedCellGroups;        // SANS_GROUP_MA
  bool resolve = true;                                // RESOLUTION
  double interpolationTolerance = 0.0;                // TOLE_INTERP
  ContactAlgorithm algorithm = ContactAlgorithm::Constraint;
  bool slide = false;                     // GLISSIERE (permanent bilateral contact)
  double gapAlarm = 0.0;                  // ALARME_JEU
  double normalPenalty = 0.0;             // E_N
  bool friction = false;                  // FROTTEMENT='COULOMB'
  double coulomb = 0.0;                   // COULOMB
  double tangentPenalty = 0.0;            // E_T
  double frictionMatrixCoefficient = 0.0; // COEF_MATR_FROT
  ContinuousZone continuous;              // FORMULATION='CONTINUE'
  SourceLocation location;
};

enum class StatusLoop { Newton, FixedPoint }; // ALGO_RESO_CONT (CONTINUE)

// The global keywords of FORMULATION='CONTINUE'.
struct ContinuousSettings {
  StatusLoop statusLoop = StatusLoop::Newton; // ALGO_RESO_CONT
  bool iterationsPerNode = false;             // ITER_CONT_TYPE='MULT'
  int maxStatusIterations = 30;               // ITER_CONT_MAXI
  int statusIterationFactor = 4;              // ITER_CONT_MULT
  bool frictionFixedPoint = false;            // ALGO_RESO_FROT='POINT_FIXE' (else NEWTON)
  int maxFrictionIterations = 10;             // ITER_FROT_MAXI (POINT_FIXE)
  double frictionResidual = 1e-4;             // RESI_FROT
  bool geometryNewton = false;                // ALGO_RESO_GEOM='NEWTON'
  SourceLocation geometryAt;                  // where ALGO_RESO_GEOM is
  std::vector<Unimplemented> refused;         // RESI_CONT, CONT_STAT_ELAS, ...
};

// Global keywords.
struct ContactSettings {
  Formulation formulation = Formulation::Discrete;
  bool friction = false; // FROTTEMENT
  SourceLocation frictionAt;
  bool stopInterpenetration = false;                            // STOP_INTERP
  bool smoothing = false;                                       // LISSAGE
  bool checkNormals = true;                                     // VERI_NORM
  GeometricUpdate geometricUpdate = GeometricUpdate::Automatic; // REAC_GEOM
  int maxGeometricIterations = 10;                              // ITER_GEOM_MAXI
  double geometricResidual = 0.01;                              // RESI_GEOM
  int geometricIterations = 2;                                  // NB_ITER_GEOM (CONTROLE)
  int contactIterationFactor = 4;                               // ITER_CONT_MULT
  bool stopIfSingular = true;                                   // STOP_SINGULIER
  int rightHandSidesPerSolve = 10;                              // NB_RESOL
  std::optional<double> gcpTolerance;                           // RESI_ABSO
  int gcpMaxIterations = 0;                                     // ITER_GCP_MAXI (0: automatic)
  LineSearch lineSearch = LineSearch::Admissible;               // RECH_LINEAIRE
  bool dirichletPreconditioner = false;                         // PRE_COND='DIRICHLET'
  double preconditionerResidual = -1.0;                         // COEF_RESI
  int preconditionerMaxIterations = 0;                          // ITER_PRE_MAXI
  ContinuousSettings continuous;                                // FORMULATION='CONTINUE'
};

class ContactDefinition : public ConceptData {
public:
  std::shared_ptr<const Mesh> mesh;
  std::shared_ptr<const Model> model; // may be null in unit tests
  ContactSettings settings;
  std::vector<ContactZone> zones;
  SourceLocation location;

  bool hasFriction() const { return settings.friction; }
  // Whether any zone resolves contact (RESOLUTION='OUI').
  bool resolvesAny() const;
};

// The checks of DEFI_CONTACT against the mesh: every group exists (CONTACT_1), master and
// slave surfaces of a zone share no node unless excluded (CONTACT_2), slave surfaces of
// distinct zones are disjoint (CONTACT_3), contact cells have the right dimension (CONTACT_4),
// and with VERI_NORM the normals of both surfaces point out of the volume cells they bound
// (CONTACT_5). Throws UserError naming groups and nodes.
void checkContactDefinition(const ContactDefinition& definition);

// Slave nodes of a zone (nodes of GROUP_MA_ESCL minus SANS_GROUP_NO and nodes of SANS_GROUP_MA),
// sorted; master cells of a zone.
std::vector<NodeId> zoneSlaveNodes(const Mesh& mesh, const ContactZone& zone);
std::vector<CellId> zoneMasterCells(const Mesh& mesh, const ContactZone& zone);

std::string algorithmName(ContactAlgorithm a);

} // namespace contact
} // namespace stella

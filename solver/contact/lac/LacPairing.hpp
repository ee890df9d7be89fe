#pragma once
// Mortar pairing of LAC contact in 2D and 3D (3D: LacPairing3d.cpp) (DEFI_CONTACT ALGO_CONT='LAC',
// APPARIEMENT='MORTAR', notice §2.3, §3.1.4): the slave cells (SEG2, SEG3) of each LAC patch
// (Mesh::lacPatches(), made by CREA_MAILLAGE/DECOUPE_LAC) are intersected exactly with the master cells
// (SEG2, SEG3) by the segment clipping of mortar/MortarSegments.hpp; candidates come from the search of
// mortar pairing (mortar::findCandidates, the R-tree of MasterCellIndex, TYPE_APPA='RAPIDE') or are every
// master cell ('ROBUSTE'): see lacCandidates below for the margin.
//
// For each patch P, on the overlaps (Gauss points q with slave xi_s, master xi_m, weight w_q):
//   g_q = n_s . (x_m(xi_m) - x_s(xi_s))       the gap along the slave's outward normal n_s
//   L_P = sum w_q                              the paired length (x r in AXIS, per radian)
//   G_P = sum w_q g_q                          the integrated gap; the mean gap is G_P / L_P
//   dG_P = sum w_q n_s . (N_m du_m - N_s du_s) its gradient (normals and overlaps held fixed)
// The weights are |dx/dxi| on the initial configuration (TYPE_JACOBIEN='INITIAL') or on the
// current one ('ACTUALISE'); the overlaps and the gaps are always those of the current positions.

#include "solver/assembly/DofMap.hpp"
#include "solver/contact/MasterCellIndex.hpp"
#include "solver/contact/mortar/MortarSearch.hpp"
#include "solver/contact/mortar/MortarSegments.hpp"

#include <array>
#include <map>
#include <span>
#include <vector>

namespace stella::contact::lac {

struct LacSlaveCell {
  CellId cell = -1;
  int patch = -1;    // index in Mesh::lacPatches()
  double sign = 1.0; // +1 when (ty, -tx) points out of the slave body
};

struct LacZoneCells {
  int zone = -1; // index of the ZONE occurrence
  std::vector<LacSlaveCell> slaves;
  std::vector<CellId> masters;
  bool bruteForce = false;      // TYPE_APPA='ROBUSTE'
  bool currentJacobian = false; // TYPE_JACOBIEN='ACTUALISE'
  bool smoothing = false;       // LISSAGE='OUI' (2D): the averaged nodal normals (averagedNormals)
};

// LISSAGE='OUI' (notice §2.3.2), 2D: at each node of the zone's slave cells the mean of the outward
// unit normals of the slave cells it belongs to, at the current positions `u` (3 per node),
// normalised; the normal at a point of a slave cell is then the interpolation of its nodes'
// normals (LacOverlapTerms.hpp), continuous from cell to cell. On a uniformly faceted circle the
// nodal normals are the circle's.
std::map<NodeId, mortar::Point2> averagedNormals(const Mesh& mesh, const LacZoneCells& zone,
                                                 const std::vector<double>& u);

// One patch's mortar quantities at a configuration.
struct LacPatchRow {
  double length = 0.0;        // the patch's whole length (same Jacobian and r as the weights)
  double pairedLength = 0.0;  // L_P
  double integratedGap = 0.0; // G_P
  std::vector<std::pair<int, double>> gradient; // dG_P on the physical equations (merged)
  // dS_P,a = sum w_q tau_a . (N_s du_s - N_m du_m): the slip of the slave on the master along
  // tau_a integrated over the overlaps (LacFriction.cpp). 2D: one direction, tau = n_s turned by
  // +90 degrees. 3D: two, tau_1 the patch's reference tangent (patchTangent, from the initial
  // mesh, so that the tangential multipliers keep their meaning from one pairing to the next)
  // projected on the slave face's plane, tau_2 = tau_1 x n_s.
  std::vector<std::vector<std::pair<int, double>>> slipGradients;
  // ALGO_RESO_GEOM='NEWTON' in 2D (LacPairingOptions::geometricTangent): the exact derivatives with
  // respect to the nodal positions (through the overlap ends, Gauss points, normals, master points
  // and Jacobians: LacOverlapTerms.hpp), for the consistent tangent (LacGeometricTangent.cpp).
  struct Entry {
    int row = -1;
    int column = -1;
    double value = 0.0;
  };
  std::vector<std::pair<int, double>> gapDerivative;    // dG_P/du
  std::vector<std::pair<int, double>> lengthDerivative; // dL_P/du
  std::vector<Entry> gradientDerivative;                // d(gradient_row)/du_column
};

struct LacPairingOptions {
  bool axisymmetric = false;
  int gaussPoints = 3;
  bool geometricTangent = false; // fill the exact derivatives of the rows (2D zones)
};

// The search margin of a LAC slave cell. The segment and polygon kernels send the slave normals to
// the masters without a distance limit: the search is LAC's only distance cut-off. A master is
// a candidate when its box (mortar::slaveBox with no margin: the vertices, the SEG3 curve) meets
// the slave's box inflated by the absolute margin `size + 2 moved`: `size` the slave cell's size
// (its chord in 2D, the diagonal of its box in 3D: the surfaces of a study start within about a
// cell of each other), `moved` the largest displacement of the zone's nodes from the mesh
// (largestZoneDisplacement). A slave point that was outside the master body in the mesh cannot be
// deeper inside it than the two displacements |u_s| + |u_m| <= 2 moved (small rotations), so no
// interpenetrated patch is left unpaired, even in a first Newton iterate that drives the bodies
// into each other (the Hertz cases: 1 mm in one iterate, 4 slave cells). MortarSearch's default
// (0.25 x the size, no displacement) would drop them.
inline mortar::SearchMargin lacMargin(double size, double moved) {
  return {size + 2.0 * moved, 0.0};
}

// The largest |u| over the nodes of the zone's slave and master cells (`u`: 3 per node).
double largestZoneDisplacement(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u);

// Candidate masters of every slave (boxes as above): mortar::findCandidates, or every master in
// ascending order when `bruteForce` (TYPE_APPA='ROBUSTE', the reference RAPIDE must equal).
mortar::Candidates lacCandidates(std::span<const Box3> slaves, std::span<const Box3> masters,
                                 bool bruteForce);

// The slip gradients of one patch being summed: one map per tangent direction.
using SlipSums = std::array<std::map<int, double>, 2>;

// One 3D zone (LacPairing3d.cpp): slave and master faces.
void pairZone3d(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u, const DofMap& dofs,
                std::vector<LacPatchRow>& rows, std::vector<std::map<int, double>>& gradients,
                std::vector<SlipSums>& slips);

// The reference tangent of a 3D patch: the global axis least aligned with the patch's outward
// normal on the initial mesh (the first of x, y, z among equals), made orthogonal to it. On a
// face z = const: x, so tau_1 = x and tau_2 = x x n = y for n = -z (-y for n = +z).
Point3 patchTangent(const Point3& normal);

// Rows of every patch of mesh.lacPatches() (patches of no zone stay empty, length 0), at the
// positions X + u (`displacement`: 3 per node, ContactRows.hpp's nodalDisplacement).
std::vector<LacPatchRow> pairLacPatches(const Mesh& mesh, const std::vector<LacZoneCells>& zones,
                                        const std::vector<double>& displacement, const DofMap& dofs,
                                        const LacPairingOptions& options);

} // namespace stella::contact::lac

#pragma once
// The integration schemes of the continuous contact terms on a slave cell (DEFI_CONTACT
// FORMULATION='CONTINUE', ZONE/INTEGRATION and ORDRE_INT, notice §3.1.5), with code_aster's
// point sets on the reference cells of stella (SEG [-1, 1], TRIA (0,0)-(1,0)-(0,1), QUAD [-1, 1]^2):
//   AUTO     SEG2, TRIA3, QUAD4: the nodes (trapezoid weights); SEG3, QUAD9: the nodes (Simpson,
//            3 and 3 x 3 points); QUAD8: the 3 x 3 Simpson points (its nodes and the centre);
//            TRIA6: the 6-point Gauss rule of degree 4 (GAUSS, ORDRE_INT=4).
//   GAUSS    ORDRE_INT = n (1..6): SEG n Gauss-Legendre points (degree 2n - 1), QUAD n x n, TRIA the
//            symmetric rule of degree n (1, 3, 4, 6, 7, 12 points; the 4-point one has a negative
//            weight).
//   SIMPSON  ORDRE_INT = m subdivisions (1..4): SEG composite Simpson on 2m intervals (2m + 1
//            points, degree 3), QUAD its tensor product; TRIA the m^2 sub-triangles each with the
//            6 points of its vertices (weight 1/15 of its area) and edge midpoints (4/15): exact for
//            degree 1 only (code_aster's weights).
//   NCOTES   ORDRE_INT = p (3..8): the interpolatory rule on the lattice of step 2/p (SEG, p + 1
//            points; QUAD its tensor product) or 1/p (TRIA, (p + 1)(p + 2)/2 points): closed
//            Newton-Cotes, exact for degree p (p + 1 on SEG and QUAD with even p); some weights are
//            negative (SEG p = 8, TRIA p = 4, 6, 7, 8).
// The weights integrate over the reference cell (they sum to its measure).

#include "solver/mesh/CellType.hpp"
#include "solver/mesh/Mesh.hpp"

#include <Eigen/Dense>
#include <vector>

namespace stella::fem {
class ReferenceElement;
}

namespace stella::contact {

enum class ContactIntegration { Auto, Gauss, Simpson, NewtonCotes };

struct ContactIntegrationRule {
  std::vector<Eigen::Vector3d> points; // reference coordinates on the slave cell
  std::vector<double> weights;
  std::vector<int> node; // per point: the local node of the cell it lies on, -1 if none
  int cellNodes = 0;     // nodes of the cell
  // Polynomials integrated exactly: every monomial of total degree <= degree (SEG, TRIA); every
  // x^a y^b with a, b <= degree (QUAD, tensor rules).
  int degree = 0;
  int size() const { return static_cast<int>(weights.size()); }
  // Every point is a node of the cell and every node a point: the nodal formulation ("méthode
  // des noeuds", one contact condition per slave node) applies.
  bool atNodes() const;
};

// The rule of a slave cell type (SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9) for a scheme and
// its ORDRE_INT (ignored by AUTO). Throws std::invalid_argument for another cell type or an order
// outside the scheme's range (the catalogue bounds ORDRE_INT: a program error here).
ContactIntegrationRule contactIntegrationRule(CellType type, ContactIntegration scheme, int order);

// Whether the cell type can be a slave cell of the continuous formulation's integration
// (SEG2, SEG3, TRIA3, TRIA6, QUAD4, QUAD8, QUAD9).
bool contactIntegrationDefined(CellType type);

// The scheme's keyword value (for messages): "AUTO", "GAUSS", "SIMPSON", "NCOTES".
const char* integrationName(ContactIntegration scheme);

// |J| of a skin cell of nodes x at the reference point xi (its length or area scale): what a
// rule's weights are multiplied by on the real cell.
double skinCellJacobian(const fem::ReferenceElement& ref, const std::vector<Point3>& x,
                        const Eigen::Vector3d& xi);

} // namespace stella::contact

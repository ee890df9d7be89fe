// Mortar pairing of LAC contact in 3D (see LacPairing.hpp): slave and master faces TRIA3, TRIA6,
// QUAD4, QUAD8, QUAD9 intersected by the polygon clipping of mortar/MortarPolygons.hpp (on the
// faces' vertex polygons, degree-2 triangle rule on the intersection). The slave normal is the
// Newell normal of its vertices turned outward; the weights are the polygon areas in the slave
// plane times |J_config(xi)| / |J_current(xi)| (TYPE_JACOBIEN). Exact for flat faces whose
// middle nodes sit at the middle of their edges (the linear hull's parametrisation is then the
// face's own); curved quadratic faces are approximated by their vertex polygon. The slip
// gradients (friction) use the two tangents of LacPairing.hpp.

#include "solver/contact/lac/LacPairing.hpp"

#include "solver/contact/mortar/MortarPolygons.hpp"
#include "solver/fem/ReferenceElement.hpp"
#include "solver/mesh/CellTopology.hpp"
#include "solver/mesh/MeshGeometry.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>

namespace stella::contact::lac {

namespace {

using mortar::Face;

Face faceOf(const Mesh& mesh, CellId c, const std::vector<double>* u) {
  Face f;
  f.type = mesh.cellType(c);
  for (NodeId n : mesh.cellNodes(c)) {
    Point3 x = mesh.point(n);
    if (u != nullptr) {
      const auto i = static_cast<std::size_t>(n) * 3;
      x = x + Point3{(*u)[i], (*u)[i + 1], (*u)[i + 2]};
    }
    f.nodes.push_back(x);
  }
  return f;
}

// Shape values at the parametric point of the linear face, and |dx/dxi x dx/deta|.
struct FacePoint {
  Eigen::VectorXd n;
  Point3 x{0, 0, 0};
  double jacobian = 0.0;
};

FacePoint facePoint(const Face& f, const std::array<double, 2>& xi) {
  const auto& ref = fem::referenceElement(f.type);
  const Eigen::Vector3d p(xi[0], xi[1], 0.0);
  FacePoint out;
  out.n = ref.values(p);
  const Eigen::MatrixXd g = ref.gradients(p);
  Point3 t1{0, 0, 0};
  Point3 t2{0, 0, 0};
  for (std::size_t i = 0; i < f.nodes.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    out.x = out.x + out.n(k) * f.nodes[i];
    t1 = t1 + g(k, 0) * f.nodes[i];
    t2 = t2 + g(k, 1) * f.nodes[i];
  }
  out.jacobian = norm(cross(t1, t2));
  return out;
}

// Newell's vector of the vertex polygon (twice the area times the unit normal of a flat face).
Point3 newell(const Face& f) {
  const auto nv = static_cast<std::size_t>(vertexCount(f.type));
  Point3 n{0, 0, 0};
  for (std::size_t i = 0; i < nv; ++i) {
    n = n + cross(f.nodes[i], f.nodes[(i + 1) % nv]);
  }
  return n;
}

double faceArea(const Face& f) {
  return 0.5 * norm(newell(f));
}

Point3 outwardNormal(const Face& f, double sign) {
  const Point3 n = newell(f);
  return (sign / norm(n)) * n;
}

void addGradient(std::map<int, double>& g, const DofMap& dofs, NodeId n, const Point3& v, double f) {
  for (int c = 0; c < 3; ++c) {
    const int e = dofs.dof(n, c);
    if (e >= 0) {
      g[e] += f * v[static_cast<std::size_t>(c)];
    }
  }
}

// The reference tangent of every patch of the zone (patchTangent of the summed outward Newell
// vectors of its slave faces on the initial mesh).
std::map<int, Point3> patchTangents(const Mesh& mesh, const LacZoneCells& zone) {
  std::map<int, Point3> normals;
  for (const LacSlaveCell& sc : zone.slaves) {
    Point3& n = normals[sc.patch];
    n = n + sc.sign * newell(faceOf(mesh, sc.cell, nullptr));
  }
  for (auto& [patch, n] : normals) {
    n = patchTangent((1.0 / norm(n)) * n);
  }
  return normals;
}

// tau_1 = the patch's tangent projected on the face's plane (normal n), tau_2 = tau_1 x n.
std::array<Point3, 2> faceTangents(const Point3& reference, const Point3& n) {
  const Point3 t = reference - dot(reference, n) * n;
  const Point3 t1 = (1.0 / norm(t)) * t;
  return {t1, cross(t1, n)};
}

} // namespace

Point3 patchTangent(const Point3& normal) {
  std::size_t axis = 0;
  for (std::size_t d = 1; d < 3; ++d) {
    axis = std::fabs(normal[d]) < std::fabs(normal[axis]) ? d : axis;
  }
  Point3 e{0, 0, 0};
  e[axis] = 1.0;
  const Point3 t = e - normal[axis] * normal;
  return (1.0 / norm(t)) * t;
}

void pairZone3d(const Mesh& mesh, const LacZoneCells& zone, const std::vector<double>& u, const DofMap& dofs,
                std::vector<LacPatchRow>& rows, std::vector<std::map<int, double>>& gradients,
                std::vector<SlipSums>& slips) {
  const std::map<int, Point3> tangents = patchTangents(mesh, zone);
  std::vector<Face> masters;
  std::vector<Box3> masterBoxes;
  for (CellId c : zone.masters) {
    masters.push_back(faceOf(mesh, c, &u));
    const Face& m = masters.back();
    masterBoxes.push_back(mortar::slaveBox(m.type, m.nodes.data(), static_cast<int>(m.nodes.size()),
                                           mortar::SearchMargin{0.0, 0.0}));
  }
  const double moved = largestZoneDisplacement(mesh, zone, u);
  std::vector<Box3> slaveBoxes;
  for (const LacSlaveCell& sc : zone.slaves) {
    const Face f = faceOf(mesh, sc.cell, &u);
    const Box3 own = cellBox(f.type, f.nodes.data(), static_cast<int>(f.nodes.size()), 0.0);
    slaveBoxes.push_back(mortar::slaveBox(f.type, f.nodes.data(), static_cast<int>(f.nodes.size()),
                                          lacMargin(norm(own.hi - own.lo), moved)));
  }
  const mortar::Candidates candidates = lacCandidates(slaveBoxes, masterBoxes, zone.bruteForce);
  mortar::PolygonOptions polygonOptions;
  polygonOptions.degree = 5; // 7 points per triangle: the shape functions of a QUAD4 that is not a
                             // parallelogram are not polynomials of the position
  for (std::size_t k = 0; k < zone.slaves.size(); ++k) {
    const LacSlaveCell& sc = zone.slaves[k];
    const Face current = faceOf(mesh, sc.cell, &u);
    const Face initial = faceOf(mesh, sc.cell, nullptr);
    const Face& jacobianOn = zone.currentJacobian ? current : initial;
    LacPatchRow& row = rows[static_cast<std::size_t>(sc.patch)];
    row.length += faceArea(jacobianOn);
    const Point3 n = outwardNormal(current, sc.sign);
    const std::array<Point3, 2> tau = faceTangents(tangents.at(sc.patch), n);
    auto& slip = slips[static_cast<std::size_t>(sc.patch)];
    const auto overlaps = mortar::intersectFaces(current, masters, candidates.of(k), polygonOptions);
    const auto slaveNodes = mesh.cellNodes(sc.cell);
    auto& grad = gradients[static_cast<std::size_t>(sc.patch)];
    for (const auto& o : overlaps) {
      const Face& m = masters[static_cast<std::size_t>(o.master)];
      const auto masterNodes = mesh.cellNodes(zone.masters[static_cast<std::size_t>(o.master)]);
      for (const auto& q : o.points) {
        const FacePoint s = facePoint(current, q.slave);
        const FacePoint mp = facePoint(m, q.master);
        const double gap = dot(n, mp.x - s.x);
        const double w =
            zone.currentJacobian ? q.weight : q.weight * facePoint(jacobianOn, q.slave).jacobian / s.jacobian;
        row.pairedLength += w;
        row.integratedGap += w * gap;
        for (std::size_t i = 0; i < slaveNodes.size(); ++i) {
          const double ns = s.n(static_cast<Eigen::Index>(i));
          addGradient(grad, dofs, slaveNodes[i], n, -w * ns);
          for (std::size_t a = 0; a < 2; ++a) {
            addGradient(slip[a], dofs, slaveNodes[i], tau[a], w * ns);
          }
        }
        for (std::size_t j = 0; j < masterNodes.size(); ++j) {
          const double nm = mp.n(static_cast<Eigen::Index>(j));
          addGradient(grad, dofs, masterNodes[j], n, w * nm);
          for (std::size_t a = 0; a < 2; ++a) {
            addGradient(slip[a], dofs, masterNodes[j], tau[a], -w * nm);
          }
        }
      }
    }
  }
}

} // namespace stella::contact::lac

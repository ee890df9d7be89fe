// Contact links written as sparse rows on the mechanical equations.

#include "solver/contact/ContactRows.hpp"

#include <algorithm>

namespace stella::contact {

namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Appends the row `row` of vector v: +v on the slave DOFs, -w_j v on master node j.
void addRow(Triplets& t, int row, const ContactLink& l, const Point3& v, const DofMap& dofs) {
  const int nc = dofs.components();
  for (int c = 0; c < nc; ++c) {
    const auto cc = static_cast<std::size_t>(c);
    if (v[cc] == 0.0) {
      continue;
    }
    const int s = dofs.dof(l.slave, c);
    if (s >= 0) {
      t.emplace_back(row, s, v[cc]);
    }
    for (std::size_t j = 0; j < l.masterNodes.size(); ++j) {
      const int m = dofs.dof(l.masterNodes[j], c);
      if (m >= 0 && l.weights[j] != 0.0) {
        t.emplace_back(row, m, -l.weights[j] * v[cc]);
      }
    }
  }
}

SparseRows fromTriplets(const Triplets& t, int rows, int cols) {
  SparseRows a(rows, cols);
  a.setFromTriplets(t.begin(), t.end());
  return a;
}

} // namespace

LinkRows buildLinkRows(const std::vector<ContactLink>& links, const DofMap& dofs,
                       const std::vector<bool>& resolved, const std::vector<char>& bilateral,
                       bool withFriction) {
  LinkRows r;
  for (std::size_t k = 0; k < links.size(); ++k) {
    const ContactLink& l = links[k];
    if (l.paired && resolved[static_cast<std::size_t>(l.zone)]) {
      r.link.push_back(static_cast<int>(k));
    }
  }
  const auto m = static_cast<int>(r.link.size());
  const int n = dofs.physicalCount();
  Triplets a;
  Triplets t1;
  Triplets t2;
  r.problem.gap.resize(m);
  r.problem.bilateral.assign(static_cast<std::size_t>(m), false);
  const bool threeD = dofs.components() == 3;
  for (int i = 0; i < m; ++i) {
    const std::size_t k = static_cast<std::size_t>(r.link[static_cast<std::size_t>(i)]);
    const ContactLink& l = links[k];
    addRow(a, i, l, l.normal, dofs);
    r.problem.gap(i) = l.gap;
    r.problem.bilateral[static_cast<std::size_t>(i)] = !bilateral.empty() && bilateral[k] != 0;
    if (withFriction) {
      addRow(t1, i, l, l.tangent1, dofs);
      if (threeD) {
        addRow(t2, i, l, l.tangent2, dofs);
      }
    }
  }
  r.problem.A = fromTriplets(a, m, n);
  if (withFriction) {
    r.friction.T1 = fromTriplets(t1, m, n);
    r.friction.T2 = fromTriplets(t2, threeD ? m : 0, n);
  }
  return r;
}

std::vector<double> nodalDisplacement(const DofMap& dofs, NodeId nodeCount, const Eigen::VectorXd& u) {
  std::vector<double> d(static_cast<std::size_t>(nodeCount) * 3, 0.0);
  for (NodeId node = 0; node < nodeCount; ++node) {
    for (int c = 0; c < dofs.components(); ++c) {
      const int e = dofs.dof(node, c);
      if (e >= 0) {
        d[static_cast<std::size_t>(node) * 3 + static_cast<std::size_t>(c)] = u(e);
      }
    }
  }
  return d;
}

std::vector<int> contactEquations(const ContactDefinition& definition, const DofMap& dofs) {
  const Mesh& mesh = *definition.mesh;
  std::vector<NodeId> nodes;
  for (const auto& zone : definition.zones) {
    for (const std::string& group : {zone.masterGroup, zone.slaveGroup}) {
      if (const auto* cells = mesh.cellGroup(group)) {
        const auto ns = mesh.nodesOfCells(*cells);
        nodes.insert(nodes.end(), ns.begin(), ns.end());
      }
    }
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  std::vector<int> equations;
  for (NodeId node : nodes) {
    for (int c = 0; c < dofs.components(); ++c) {
      if (const int e = dofs.dof(node, c); e >= 0) {
        equations.push_back(e);
      }
    }
  }
  return equations;
}

} // namespace stella::contact

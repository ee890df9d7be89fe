// The Newton correction of frictionless continuous contact with ALGO_RESO_CONT='NEWTON': the
// contact status of the linearised problem, solved exactly inside the Newton iteration.
//
// Why. The generalised Newton of the notice evaluates the status once per iteration from the
// current (u, LAGS_C): a primal-dual active set. From an active set much larger than the contact
// zone (CONTACT_INIT='OUI' glues every slave node, whatever its gap) it shrinks slowly: with the
// nodes glued, the tension concentrates at the edge of the glued zone (the edge singularity of a
// bonded punch) and only the 2 to 7 nodes there are released per iteration, so the active set
// needs one Newton iteration per ring of nodes: 13 iterations on the Hertz sphere at H = 0.25
// (52 glued nodes, 24 in contact at the end), more than ITER_GLOB_MAXI = 10 on H <= 0.25 and on
// the NAFEMS roller at H = 0.0625 (doc/accuracy-cost/).
//
// What. At a Newton iteration the problem is linear: K du = r with the gaps g + A du. Its
// complementarity problem (the nodes in contact have g + A du = 0 and LAGS_C < 0, the others
// LAGS_C = 0 and g + A du >= 0) is small in the multipliers: the Schur complement S = A M^-1 A^T
// (M the factorised matrix) of the candidate nodes. It is solved here by the same status rule,
// LAGS_C + COEF_CONT g < 0, iterated on the linearised problem (an active set on S, columns of S
// computed once per node that enters it, through the factorisation of the iteration), and the
// Newton correction is that of the final status. The converged solution is the same (the same
// equations and status rule); the number of Newton iterations is that of the mechanics and of
// the geometric loop, not of the rings of nodes.
//
// The matrix M factorised by the driver holds the augmented term COEF_CONT w a a^T of the nodes
// of the assembled status s. For a node of s that the linearised problem releases, that term is
// removed exactly (Woodbury): an unknown mu = COEF_CONT w (g + a du) with the equation
// a du - mu / (COEF_CONT w) = -g, i.e. a diagonal -1 / (COEF_CONT w) in the Schur matrix (then
// symmetric indefinite: LU). A node that enters (not in s) needs no term. Penalised rows
// (ALGO_CONT='PENALISATION') keep the status they were assembled with, as before.

#include "solver/contact/ContinuousContactConstraint.hpp"
#include "solver/contact/MultiplierSchur.hpp"

#include "solver/nonlinear/SaddleSolver.hpp"

#include <algorithm>
#include <cmath>

namespace stella::contact {

namespace {

// The rounds of the linearised status loop before the correction is applied with the last
// status (the next Newton iteration then goes on from it, as the plain generalised Newton does).
constexpr int maxLinearisedRounds = 30;

// Schur columns a_i . M^-1 a_j over every row i, computed once per row j that needs one.
class SchurColumns {
public:
  SchurColumns(const SparseRows& a, Eigen::Index n)
      : a_(a), n_(n), slot_(static_cast<std::size_t>(a.rows()), -1), s_(a.rows(), 0) {}

  // Computes the columns of the rows not computed yet (one backend call per 64).
  void require(const std::vector<Eigen::Index>& rows, SaddleSolver& solver) {
    std::vector<Eigen::Index> missing;
    for (Eigen::Index j : rows) {
      if (slot_[static_cast<std::size_t>(j)] < 0) {
        missing.push_back(j);
      }
    }
    constexpr std::size_t block = 64;
    for (std::size_t first = 0; first < missing.size(); first += block) {
      const std::size_t cols = std::min(block, missing.size() - first);
      const auto c0 = static_cast<Eigen::Index>(cols);
      Eigen::MatrixXd x = Eigen::MatrixXd::Zero(n_, c0);
      for (std::size_t c = 0; c < cols; ++c) {
        for (SparseRows::InnerIterator it(a_, missing[first + c]); it; ++it) {
          x(it.col(), static_cast<Eigen::Index>(c)) += it.value();
        }
      }
      solver.solveHomogeneous(x); // M^-1 a_j
      const Eigen::Index base = s_.cols();
      s_.conservativeResize(Eigen::NoChange, base + c0);
      s_.rightCols(c0) = a_ * x;
      for (std::size_t c = 0; c < cols; ++c) {
        slot_[static_cast<std::size_t>(missing[first + c])] = base + static_cast<Eigen::Index>(c);
      }
    }
  }
  // a_i . M^-1 a_j for every row i (j required before)
  auto column(Eigen::Index j) const { return s_.col(slot_[static_cast<std::size_t>(j)]); }

private:
  const SparseRows& a_;
  Eigen::Index n_;
  std::vector<Eigen::Index> slot_;
  Eigen::MatrixXd s_;
};

// One trial status t of the linearised problem and its solution.
struct Trial {
  std::vector<char> in;               // per row: in contact in t
  std::vector<Eigen::Index> unknowns; // J: the rows of t and the released rows of s
  Eigen::VectorXd y;                  // per unknown: w dLAGS_C (t), -(w LAGS_C + mu) (released)
  Eigen::VectorXd lambda;             // per row: LAGS_C after the correction (0 outside t)
  Eigen::VectorXd gap;                // per row: the linearised gap after the correction
};

// The rows' data the linearised problem needs (per row of the contact rows).
struct RowData {
  Eigen::VectorXd gap;        // g at u
  Eigen::VectorXd adu;        // a . M^-1 r: the driver's correction
  Eigen::VectorXd lambda;     // LAGS_C at u
  Eigen::VectorXd weight;     // w
  Eigen::VectorXd rho;        // COEF_CONT
  std::vector<char> was;      // in the assembled status s
  std::vector<char> resolved; // its status is solved here (else kept as assembled)
};

// a . du0' where du0' = M^-1 (r - sum over t - s of w LAGS_C a): an entering node's force is
// that of its new multiplier, and the residual did not hold the old one.
Eigen::VectorXd entryShift(const RowData& d, const Trial& t, const SchurColumns& columns) {
  Eigen::VectorXd adu0 = d.adu;
  for (Eigen::Index j : t.unknowns) {
    const auto r = static_cast<std::size_t>(j);
    if (t.in[r] != 0 && d.was[r] == 0) {
      adu0 -= d.weight(j) * d.lambda(j) * columns.column(j);
    }
  }
  return adu0;
}

// Solves the trial status t: -1 when solved, else the row whose pivot vanished (the trial's
// conditions are redundant, or it leaves the structure unsupported).
Eigen::Index solveTrial(const RowData& d, Trial& t, const SchurColumns& columns) {
  const Eigen::VectorXd adu0 = entryShift(d, t, columns);
  const auto size = static_cast<Eigen::Index>(t.unknowns.size());
  Eigen::MatrixXd s(size, size);
  Eigen::VectorXd rhs(size);
  bool indefinite = false;
  for (Eigen::Index p = 0; p < size; ++p) {
    const Eigen::Index i = t.unknowns[static_cast<std::size_t>(p)];
    const auto col = columns.column(i);
    for (Eigen::Index q = 0; q < size; ++q) {
      s(q, p) = col(t.unknowns[static_cast<std::size_t>(q)]);
    }
    rhs(p) = d.gap(i) + adu0(i);
    if (t.in[static_cast<std::size_t>(i)] == 0) { // released: mu's equation, -1 / (rho w)
      s(p, p) -= 1.0 / (d.rho(i) * d.weight(i));
      rhs(p) += d.lambda(i) / d.rho(i);
      indefinite = true;
    }
  }
  s = 0.5 * (s + s.transpose());
  if (!indefinite) {
    const Eigen::LDLT<Eigen::MatrixXd> ldlt(s);
    if (size > 0) {
      const Eigen::VectorXd diag = ldlt.vectorD();
      const double scale = diag.cwiseAbs().maxCoeff();
      for (Eigen::Index p = 0; p < size; ++p) {
        if (!(std::fabs(diag(p)) > 1e-12 * scale)) {
          const Eigen::PermutationMatrix<Eigen::Dynamic> perm(ldlt.transpositionsP());
          const Eigen::PermutationMatrix<Eigen::Dynamic> inverse(perm.inverse());
          return t.unknowns[static_cast<std::size_t>(inverse.indices()(p))];
        }
      }
    }
    t.y = size > 0 ? Eigen::VectorXd(ldlt.solve(rhs)) : Eigen::VectorXd();
  } else {
    // symmetric indefinite (the released rows): LU; singular when the released nodes held the
    // structure
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(s);
    if (!lu.isInvertible()) {
      return t.unknowns.front();
    }
    t.y = lu.solve(rhs);
  }
  if (!t.y.allFinite()) {
    return t.unknowns.front();
  }
  t.lambda = Eigen::VectorXd::Zero(d.gap.size());
  t.gap = d.gap + adu0;
  for (Eigen::Index p = 0; p < size; ++p) {
    const Eigen::Index j = t.unknowns[static_cast<std::size_t>(p)];
    t.gap -= t.y(p) * columns.column(j);
    if (t.in[static_cast<std::size_t>(j)] != 0) {
      t.lambda(j) = d.lambda(j) + t.y(p) / d.weight(j);
    }
  }
  return -1;
}

} // namespace

void ContinuousContactConstraint::correctWithLinearisedStatus(const Eigen::VectorXd& u,
                                                              const std::vector<char>& assembled,
                                                              Eigen::VectorXd& ddu, Eigen::VectorXd& dlambda,
                                                              SaddleSolver& solver) {
  const SparseRows& a = rows_.problem.A;
  const Eigen::Index m = a.rows();
  RowData d;
  d.gap = gapsAt(u);
  d.adu = a * ddu;
  d.lambda.resize(m);
  d.weight = weight_;
  d.rho = coefficient_;
  d.was.assign(static_cast<std::size_t>(m), 0);
  d.resolved.assign(static_cast<std::size_t>(m), 0);
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto k = static_cast<std::size_t>(rows_.link[static_cast<std::size_t>(i)]);
    const auto r = static_cast<std::size_t>(i);
    d.lambda(i) = lagsC_[k];
    if (penalised(i)) {
      continue; // its status and force stay as assembled
    }
    d.was[r] = assembled[k] != 0 ? 1 : 0;
    // a node frozen by CYCLAGE, held closed by GLISSIERE, or of zero weight keeps its status
    d.resolved[r] = weight_(i) > 0.0 && !(k < frozen_.size() && frozen_[k] >= 0) && !heldClosed(k) ? 1 : 0;
  }
  SchurColumns columns(a, ddu.size());
  const auto unknownsOf = [&](Trial& t) {
    t.unknowns.clear();
    for (Eigen::Index i = 0; i < m; ++i) {
      if (t.in[static_cast<std::size_t>(i)] != 0 || d.was[static_cast<std::size_t>(i)] != 0) {
        t.unknowns.push_back(i);
      }
    }
    columns.require(t.unknowns, solver);
  };
  Trial current;
  current.in = d.was;
  unknownsOf(current);
  if (const Eigen::Index singular = solveTrial(d, current, columns); singular >= 0) {
    redundant(singular); // the assembled status (no released row): redundant conditions
  }
  int rounds = 1;
  for (; rounds < maxLinearisedRounds; ++rounds) {
    // the status rule of statusAt at the corrected (u, LAGS_C)
    Trial next;
    next.in = current.in;
    bool changed = false;
    for (Eigen::Index i = 0; i < m; ++i) {
      const auto r = static_cast<std::size_t>(i);
      if (d.resolved[r] != 0) {
        next.in[r] = current.lambda(i) + d.rho(i) * current.gap(i) < 0.0 ? 1 : 0;
        changed = changed || next.in[r] != current.in[r];
      }
    }
    if (!changed) {
      break;
    }
    unknownsOf(next);
    if (solveTrial(d, next, columns) >= 0) {
      break; // that status would leave the structure unsupported: keep the last one
    }
    current = std::move(next);
  }
  addContactIterations(rounds);
  // the correction of the final status: ddu - M^-1 (sum_J y a + sum over t - s of w LAGS_C a)
  Eigen::VectorXd f = Eigen::VectorXd::Zero(ddu.size());
  for (std::size_t p = 0; p < current.unknowns.size(); ++p) {
    const Eigen::Index j = current.unknowns[p];
    const auto r = static_cast<std::size_t>(j);
    double factor = current.y(static_cast<Eigen::Index>(p));
    if (current.in[r] != 0 && d.was[r] == 0) {
      factor += d.weight(j) * d.lambda(j);
    }
    for (SparseRows::InnerIterator it(a, j); it; ++it) {
      f(it.col()) += factor * it.value();
    }
  }
  if (!current.unknowns.empty()) {
    applyMultiplierForces(f, ddu, dlambda, solver);
  }
  for (Eigen::Index i = 0; i < m; ++i) {
    const auto r = static_cast<std::size_t>(i);
    if (penalised(i)) {
      continue;
    }
    const auto k = static_cast<std::size_t>(rows_.link[r]);
    lagsC_[k] = current.in[r] != 0 ? current.lambda(i) : 0.0; // -(w / rho) LAGS_C = 0 outside
    status_[k] = current.in[r];
    lastStatus_[k] = current.in[r];
  }
}

} // namespace stella::contact

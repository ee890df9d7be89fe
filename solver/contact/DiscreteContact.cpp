// Dual discrete contact algorithms: active set on the explicit Schur complement (CONTRAINTE)
// and projected conjugate gradient on the dual problem (GCP).

#include "solver/contact/DiscreteContact.hpp"

#include "solver/linalg/LinearSolver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace stella::contact {

void FactorisedStiffness::solve(Eigen::Ref<Eigen::MatrixXd> rhs) {
  solver_.solve(rhs);
  solves += static_cast<int>(rhs.cols());
}

namespace {

using Eigen::Index;
using Eigen::MatrixXd;
using Eigen::VectorXd;

// Columns of the Schur complement S(:, i) = A K^-1 A_i^T, computed in blocks of NB_RESOL
// right-hand sides and kept (m entries each).
class SchurColumns {
public:
  SchurColumns(const SparseRows& a, StiffnessInverse& k, int block)
      : a_(a), k_(k), block_(std::max(block, 1)) {
    slot_.assign(static_cast<std::size_t>(a.rows()), -1);
  }
  void ensure(const std::vector<Index>& links) {
    std::vector<Index> missing;
    for (Index i : links) {
      if (slot_[static_cast<std::size_t>(i)] < 0) {
        missing.push_back(i);
      }
    }
    if (missing.empty()) {
      return;
    }
    const Index first = columns_.cols();
    columns_.conservativeResize(a_.rows(), first + static_cast<Index>(missing.size()));
    for (std::size_t b = 0; b < missing.size(); b += static_cast<std::size_t>(block_)) {
      const std::size_t e = std::min(missing.size(), b + static_cast<std::size_t>(block_));
      MatrixXd rhs = MatrixXd::Zero(a_.cols(), static_cast<Index>(e - b));
      for (std::size_t j = b; j < e; ++j) {
        for (SparseRows::InnerIterator it(a_, missing[j]); it; ++it) {
          rhs(it.col(), static_cast<Index>(j - b)) = it.value();
        }
      }
      k_.solve(rhs);
      columns_.middleCols(first + static_cast<Index>(b), static_cast<Index>(e - b)) = a_ * rhs;
      for (std::size_t j = b; j < e; ++j) {
        slot_[static_cast<std::size_t>(missing[j])] = first + static_cast<Index>(j);
      }
    }
  }
  // S(i, j) and the column S(:, j).
  double entry(Index i, Index j) const { return columns_(i, slot(j)); }
  auto column(Index j) const { return columns_.col(slot(j)); }

private:
  Index slot(Index link) const { return slot_[static_cast<std::size_t>(link)]; }
  const SparseRows& a_;
  StiffnessInverse& k_;
  int block_;
  std::vector<Index> slot_;
  MatrixXd columns_;
};

// Cholesky factor L of S restricted to the active links, extended one link at a time.
class ActiveCholesky {
public:
  ActiveCholesky(const SchurColumns& s, const VectorXd& compliance, bool symmetric)
      : s_(s), compliance_(compliance), symmetric_(symmetric) {}
  const std::vector<Index>& links() const { return links_; }
  // Adds a link; false (nothing changed) when its pivot vanishes: the active links are then
  // linearly dependent. An unsymmetric S (penalised friction's tangent) is not factorised link
  // by link: solve() factorises its active block by LU.
  bool add(Index link) {
    if (!symmetric_) {
      links_.push_back(link);
      return true;
    }
    const auto n = static_cast<Index>(links_.size());
    VectorXd y(n);
    for (Index a = 0; a < n; ++a) {
      y(a) = s_.entry(links_[static_cast<std::size_t>(a)], link);
    }
    if (n > 0) {
      l_.topLeftCorner(n, n).triangularView<Eigen::Lower>().solveInPlace(y);
    }
    const double diagonal =
        s_.entry(link, link) + (compliance_.size() > 0 ? compliance_(link) : 0.0); // S + C
    const double pivot = diagonal - y.squaredNorm();
    scale_ = std::max(scale_, std::abs(diagonal));
    if (!(pivot > 1e-12 * scale_)) {
      return false;
    }
    if (l_.rows() < n + 1) {
      const Index capacity = std::max<Index>(2 * n, 16);
      MatrixXd grown = MatrixXd::Zero(capacity, capacity);
      grown.topLeftCorner(n, n) = l_.topLeftCorner(n, n);
      l_.swap(grown);
    }
    l_.row(n).head(n) = y.transpose();
    l_(n, n) = std::sqrt(pivot);
    links_.push_back(link);
    return true;
  }
  void clear() { links_.clear(); }
  // S_active^-1 b (b ordered like links()).
  VectorXd solve(const VectorXd& b) const {
    const auto n = static_cast<Index>(links_.size());
    if (!symmetric_) {
      MatrixXd block(n, n);
      for (Index a = 0; a < n; ++a) {
        for (Index c = 0; c < n; ++c) {
          block(a, c) = s_.entry(links_[static_cast<std::size_t>(a)], links_[static_cast<std::size_t>(c)]);
        }
        block(a, a) += compliance_.size() > 0 ? compliance_(links_[static_cast<std::size_t>(a)]) : 0.0;
      }
      return block.partialPivLu().solve(b);
    }
    VectorXd x = b;
    l_.topLeftCorner(n, n).triangularView<Eigen::Lower>().solveInPlace(x);
    l_.topLeftCorner(n, n).triangularView<Eigen::Lower>().transpose().solveInPlace(x);
    return x;
  }

private:
  const SchurColumns& s_;
  const VectorXd& compliance_;
  bool symmetric_ = true;
  std::vector<Index> links_;
  MatrixXd l_;
  double scale_ = 0.0;
};

double maxInterpenetration(const VectorXd& gap) {
  return gap.size() == 0 ? 0.0 : std::max(0.0, -gap.minCoeff());
}

VectorXd applyKinvAt(const SparseRows& a, StiffnessInverse& k, const VectorXd& lambda) {
  MatrixXd rhs = a.transpose() * lambda;
  k.solve(rhs);
  return rhs.col(0);
}

// Rounds of the active-set method that move every violated link and every negative multiplier
// at once before falling back to one change per iteration.
constexpr int blockRounds = 20;

} // namespace

DualResult solveActiveSet(const ContactProblem& p, StiffnessInverse& k, const VectorXd& du0,
                          const DualOptions& o, const DualStart* start) {
  const Index m = p.A.rows();
  const int solvesBefore = k.solves;
  const VectorXd q = p.gap + p.A * du0;
  const double scale = m > 0 ? std::max(q.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min()) : 1.0;
  const double tol = o.tolerance > 0.0 ? o.tolerance : 1e-10 * scale;
  SchurColumns cols(p.A, k, o.rightHandSidesPerSolve);
  ActiveCholesky chol(cols, o.compliance, o.symmetric);
  std::vector<char> active(static_cast<std::size_t>(m), 0);
  std::vector<char> excluded(static_cast<std::size_t>(m), 0);
  // Links waiting to enter: the start's (only they: a link they leave violated enters at the
  // next iteration, so no column is computed for a link that would leave at once), else the
  // violated ones.
  const bool warm = start != nullptr && start->lambda.size() == m && m > 0 && start->lambda.maxCoeff() > 0.0;
  std::vector<Index> entering;
  for (Index i = 0; i < m; ++i) {
    const bool started = warm && start->lambda(i) > 0.0;
    if (p.isBilateral(i) || started || (!warm && q(i) < -tol)) {
      entering.push_back(i);
    }
  }
  const auto priority = [&](Index i) {
    const bool first =
        p.isBilateral(i) || (start != nullptr && start->lambda.size() == m && start->lambda(i) > 0.0);
    return std::pair<int, double>(first ? 0 : 1, q(i));
  };
  std::stable_sort(entering.begin(), entering.end(),
                   [&](Index a, Index b) { return priority(a) < priority(b); });
  DualResult r;
  r.lambda = VectorXd::Zero(m);
  VectorXd gap = q;
  VectorXd lambdaSet;
  const int maxIterations = std::max(1, o.iterationFactor) * static_cast<int>(std::max<Index>(m, 1)) + 1;
  for (r.iterations = 1; r.iterations <= maxIterations; ++r.iterations) {
    cols.ensure(entering);
    for (Index i : entering) {
      if (chol.add(i)) {
        active[static_cast<std::size_t>(i)] = 1;
        continue;
      }
      if (o.stopIfSingular) {
        throw SingularContactError(static_cast<int>(i));
      }
      excluded[static_cast<std::size_t>(i)] = 1;
    }
    entering.clear();
    const std::vector<Index>& set = chol.links();
    const auto na = static_cast<Index>(set.size());
    VectorXd rhs(na);
    for (Index a = 0; a < na; ++a) {
      rhs(a) = -q(set[static_cast<std::size_t>(a)]);
    }
    lambdaSet = na > 0 ? chol.solve(rhs) : VectorXd();
    // Negative multipliers of unilateral links leave (all of them, or the most negative one).
    const bool block = r.iterations <= blockRounds;
    const double lambdaScale = na > 0 ? lambdaSet.cwiseAbs().maxCoeff() : 0.0;
    std::vector<Index> leaving;
    Index worst = -1;
    for (Index a = 0; a < na; ++a) {
      const Index i = set[static_cast<std::size_t>(a)];
      if (!p.isBilateral(i) && lambdaSet(a) < -1e-13 * lambdaScale) {
        leaving.push_back(a);
        if (worst < 0 || lambdaSet(a) < lambdaSet(worst)) {
          worst = a;
        }
      }
    }
    if (!leaving.empty()) {
      if (!block) {
        leaving.assign(1, worst);
      }
      std::vector<char> drop(static_cast<std::size_t>(na), 0);
      for (Index a : leaving) {
        drop[static_cast<std::size_t>(a)] = 1;
        active[static_cast<std::size_t>(set[static_cast<std::size_t>(a)])] = 0;
      }
      std::vector<Index> kept;
      for (Index a = 0; a < na; ++a) {
        if (drop[static_cast<std::size_t>(a)] == 0) {
          kept.push_back(set[static_cast<std::size_t>(a)]);
        }
      }
      chol.clear(); // refactorised from the kept links (in their order) at the next iteration
      entering = std::move(kept);
      continue;
    }
    gap = q;
    for (Index a = 0; a < na; ++a) {
      gap += lambdaSet(a) * cols.column(set[static_cast<std::size_t>(a)]);
    }
    for (Index i = 0; i < m; ++i) {
      if (!active[static_cast<std::size_t>(i)] && !excluded[static_cast<std::size_t>(i)] && gap(i) < -tol) {
        entering.push_back(i);
      }
    }
    if (entering.empty()) {
      r.converged = true;
      break;
    }
    std::sort(entering.begin(), entering.end(), [&](Index a, Index b) { return gap(a) < gap(b); });
    if (!block) {
      entering.resize(1);
    }
  }
  const std::vector<Index>& set = chol.links();
  for (std::size_t a = 0; a < set.size() && a < static_cast<std::size_t>(lambdaSet.size()); ++a) {
    r.lambda(set[a]) = lambdaSet(static_cast<Index>(a));
  }
  r.finalGap = gap;
  if (o.computeDisplacement) {
    r.du = du0;
    if (r.lambda.size() > 0 && r.lambda.cwiseAbs().maxCoeff() > 0.0) {
      r.du += applyKinvAt(p.A, k, r.lambda);
    }
  }
  r.activeLinks = static_cast<int>(set.size());
  r.solves = k.solves - solvesBefore;
  r.maxInterpenetration = maxInterpenetration(r.finalGap);
  if (!r.converged) {
    throw ContactNotConverged("CONTRAINTE: no convergence in ITER_CONT_MULT x links iterations", r);
  }
  return r;
}

namespace {

struct GcpState {
  const ContactProblem& p;
  StiffnessInverse& k;
  VectorXd lambda;
  VectorXd gap; // q + S lambda
  VectorXd w;   // K^-1 A^T lambda

  bool free(Index i) const { return p.isBilateral(i) || lambda(i) > 0.0 || gap(i) < 0.0; }
  // Projected gradient.
  VectorXd projected() const {
    VectorXd g = VectorXd::Zero(gap.size());
    for (Index i = 0; i < gap.size(); ++i) {
      if (free(i)) {
        g(i) = gap(i);
      }
    }
    return g;
  }
  // S restricted to `mask`, applied to v (one K solve); x receives K^-1 A^T v.
  VectorXd schur(const VectorXd& v, VectorXd& x) const {
    x = applyKinvAt(p.A, k, v);
    return p.A * x;
  }
};

// Dirichlet preconditioner: approximate S_FF^-1 g_F by `iterations` conjugate-gradient steps.
VectorXd dirichlet(const GcpState& st, const VectorXd& g, const std::vector<char>& mask, int iterations) {
  VectorXd z = VectorXd::Zero(g.size());
  VectorXd res = g;
  VectorXd dir = res;
  double rr = res.squaredNorm();
  const double stop = 1e-24 * rr;
  for (int it = 0; it < iterations && rr > stop; ++it) {
    VectorXd x;
    VectorXd sd = st.schur(dir, x);
    for (Index i = 0; i < sd.size(); ++i) {
      if (!mask[static_cast<std::size_t>(i)]) {
        sd(i) = 0.0;
      }
    }
    const double curvature = dir.dot(sd);
    if (curvature <= 0.0) {
      break;
    }
    const double alpha = rr / curvature;
    z += alpha * dir;
    res -= alpha * sd;
    const double rrNew = res.squaredNorm();
    dir = res + (rrNew / rr) * dir;
    rr = rrNew;
  }
  return z;
}

} // namespace

int gcpIterationCap(Index links, int iterGcpMaxi) {
  return std::max(10 * static_cast<int>(std::max<Index>(links, 1)), iterGcpMaxi);
}

DualResult solveProjectedGradient(const ContactProblem& p, StiffnessInverse& k, const VectorXd& du0,
                                  const DualOptions& o, const DualStart* start) {
  const Index m = p.A.rows();
  const int solvesBefore = k.solves;
  GcpState st{p, k, VectorXd::Zero(m), p.gap + p.A * du0, VectorXd::Zero(du0.size())};
  if (start != nullptr && start->lambda.size() == m && m > 0 && start->lambda.cwiseAbs().maxCoeff() > 0.0) {
    st.lambda = start->lambda;
    for (Index i = 0; i < m; ++i) {
      if (!p.isBilateral(i)) {
        st.lambda(i) = std::max(0.0, st.lambda(i));
      }
    }
    st.w = start->w.size() == du0.size() && st.lambda == start->lambda ? start->w
                                                                       : applyKinvAt(p.A, k, st.lambda);
    st.gap += p.A * st.w;
  }
  const double tol = o.tolerance;
  const int maxIterations = gcpIterationCap(m, o.maxIterations);
  double preconditionFrom = -1.0; // projected-gradient norm below which DIRICHLET applies
  DualResult r;
  VectorXd d;
  VectorXd z;
  VectorXd gPrev;
  VectorXd zPrev;
  std::vector<char> maskPrev;
  for (r.iterations = 0; r.iterations <= maxIterations; ++r.iterations) {
    const VectorXd g = st.projected();
    const double residual = m > 0 ? g.cwiseAbs().maxCoeff() : 0.0;
    if (m == 0 || residual <= tol) {
      r.converged = true;
      break;
    }
    if (r.iterations == maxIterations) {
      break;
    }
    if (r.iterations == 0) {
      preconditionFrom = o.preconditionerResidual * residual;
    }
    std::vector<char> mask(static_cast<std::size_t>(m));
    for (Index i = 0; i < m; ++i) {
      mask[static_cast<std::size_t>(i)] = st.free(i) ? 1 : 0;
    }
    const bool precondition =
        o.dirichletPreconditioner && (preconditionFrom <= 0.0 || residual <= preconditionFrom);
    if (precondition) {
      const int count = static_cast<int>(std::count(mask.begin(), mask.end(), 1));
      z = dirichlet(st, g, mask, o.preconditionerIterations > 0 ? o.preconditionerIterations : count);
    } else {
      z = g;
    }
    const bool restart = d.size() == 0 || mask != maskPrev || zPrev.dot(gPrev) <= 0.0;
    if (restart) {
      d = -z;
    } else {
      const double beta = std::max(0.0, z.dot(g - gPrev) / zPrev.dot(gPrev)); // Polak-Ribiere
      d = -z + beta * d;
      for (Index i = 0; i < m; ++i) {
        if (!mask[static_cast<std::size_t>(i)]) {
          d(i) = 0.0;
        }
      }
      if (d.dot(g) >= 0.0) {
        d = -z;
      }
    }
    gPrev = g;
    zPrev = z;
    maskPrev = mask;
    VectorXd x;
    const VectorXd sd = st.schur(d, x);
    const double curvature = d.dot(sd);
    if (curvature <= 0.0) {
      break;
    }
    double alpha = -g.dot(d) / curvature;
    if (o.admissibleLineSearch) {
      Index blocking = -1;
      for (Index i = 0; i < m; ++i) {
        if (!p.isBilateral(i) && d(i) < 0.0 && -st.lambda(i) / d(i) < alpha) {
          alpha = -st.lambda(i) / d(i);
          blocking = i;
        }
      }
      st.lambda += alpha * d;
      st.gap += alpha * sd;
      st.w += alpha * x;
      if (blocking >= 0) {
        st.lambda(blocking) = 0.0;
      }
    } else {
      VectorXd trial = st.lambda + alpha * d;
      for (Index i = 0; i < m; ++i) {
        if (!p.isBilateral(i)) {
          trial(i) = std::max(0.0, trial(i));
        }
      }
      const VectorXd step = trial - st.lambda;
      if ((step - alpha * d).cwiseAbs().maxCoeff() == 0.0) {
        st.gap += alpha * sd;
        st.w += alpha * x;
      } else {
        VectorXd x2;
        st.gap += st.schur(step, x2);
        st.w += x2;
      }
      st.lambda = trial;
    }
  }
  r.lambda = st.lambda;
  if (o.computeDisplacement) {
    r.du = du0 + st.w;
  }
  r.finalGap = st.gap;
  r.activeLinks = static_cast<int>((st.lambda.array() != 0.0).count());
  r.solves = k.solves - solvesBefore;
  r.maxInterpenetration = maxInterpenetration(st.gap);
  if (!r.converged) {
    throw ContactNotConverged("GCP: no convergence in ITER_GCP_MAXI iterations", r);
  }
  return r;
}

} // namespace stella::contact

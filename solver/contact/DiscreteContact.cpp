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

// Columns K^-1 A_i^T, computed in blocks of NB_RESOL right-hand sides and kept.
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
    for (std::size_t b = 0; b < missing.size(); b += static_cast<std::size_t>(block_)) {
      const std::size_t e = std::min(missing.size(), b + static_cast<std::size_t>(block_));
      MatrixXd rhs = MatrixXd::Zero(a_.cols(), static_cast<Index>(e - b));
      for (std::size_t j = b; j < e; ++j) {
        for (SparseRows::InnerIterator it(a_, missing[j]); it; ++it) {
          rhs(it.col(), static_cast<Index>(j - b)) = it.value();
        }
      }
      k_.solve(rhs);
      for (std::size_t j = b; j < e; ++j) {
        slot_[static_cast<std::size_t>(missing[j])] = static_cast<Index>(columns_.size());
        columns_.push_back(rhs.col(static_cast<Index>(j - b)));
      }
    }
  }
  const VectorXd& column(Index link) const {
    return columns_[static_cast<std::size_t>(slot_[static_cast<std::size_t>(link)])];
  }
  double entry(Index i, Index j) const { return a_.row(i).dot(column(j)); }

private:
  const SparseRows& a_;
  StiffnessInverse& k_;
  int block_;
  std::vector<Index> slot_;
  std::vector<VectorXd> columns_;
};

double maxInterpenetration(const VectorXd& gap) {
  return gap.size() == 0 ? 0.0 : std::max(0.0, -gap.minCoeff());
}

VectorXd applyKinvAt(const SparseRows& a, StiffnessInverse& k, const VectorXd& lambda) {
  MatrixXd rhs = a.transpose() * lambda;
  k.solve(rhs);
  return rhs.col(0);
}

} // namespace

DualResult solveActiveSet(const ContactProblem& p, StiffnessInverse& k, const VectorXd& du0,
                          const DualOptions& o) {
  const Index m = p.A.rows();
  const int solvesBefore = k.solves;
  const VectorXd q = p.gap + p.A * du0;
  const double scale = m > 0 ? std::max(q.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min()) : 1.0;
  const double tol = o.tolerance > 0.0 ? o.tolerance : 1e-10 * scale;
  SchurColumns cols(p.A, k, o.rightHandSidesPerSolve);
  std::vector<char> active(static_cast<std::size_t>(m), 0);
  std::vector<char> excluded(static_cast<std::size_t>(m), 0);
  std::vector<Index> set;
  for (Index i = 0; i < m; ++i) {
    if (p.isBilateral(i) || q(i) < -tol) {
      active[static_cast<std::size_t>(i)] = 1;
      set.push_back(i);
    }
  }
  DualResult r;
  r.lambda = VectorXd::Zero(m);
  VectorXd w = VectorXd::Zero(du0.size());
  Index lastAdded = set.empty() ? -1 : set.back();
  const int maxIterations = std::max(1, o.iterationFactor) * static_cast<int>(std::max<Index>(m, 1)) + 1;
  VectorXd lambdaSet;
  for (r.iterations = 1; r.iterations <= maxIterations; ++r.iterations) {
    cols.ensure(set);
    const auto na = static_cast<Index>(set.size());
    MatrixXd s(na, na);
    VectorXd rhs(na);
    for (Index a = 0; a < na; ++a) {
      rhs(a) = -q(set[static_cast<std::size_t>(a)]);
      for (Index b = 0; b < na; ++b) {
        s(a, b) = cols.entry(set[static_cast<std::size_t>(a)], set[static_cast<std::size_t>(b)]);
      }
    }
    lambdaSet = VectorXd::Zero(na);
    if (na > 0) {
      Eigen::LDLT<MatrixXd> ldlt(s);
      const VectorXd d = ldlt.vectorD().cwiseAbs();
      if (ldlt.info() != Eigen::Success || d.minCoeff() <= 1e-12 * d.maxCoeff()) {
        const Index culprit = lastAdded >= 0 ? lastAdded : set.back();
        if (o.stopIfSingular) {
          throw SingularContactError(static_cast<int>(culprit));
        }
        excluded[static_cast<std::size_t>(culprit)] = 1;
        active[static_cast<std::size_t>(culprit)] = 0;
        set.erase(std::find(set.begin(), set.end(), culprit));
        lastAdded = -1;
        continue;
      }
      lambdaSet = ldlt.solve(rhs);
    }
    // Remove the most negative multiplier (unilateral links only).
    Index worst = -1;
    double worstValue = 0.0;
    const double lambdaScale = na > 0 ? lambdaSet.cwiseAbs().maxCoeff() : 0.0;
    for (Index a = 0; a < na; ++a) {
      const Index i = set[static_cast<std::size_t>(a)];
      if (!p.isBilateral(i) && lambdaSet(a) < -1e-13 * lambdaScale && lambdaSet(a) < worstValue) {
        worstValue = lambdaSet(a);
        worst = a;
      }
    }
    if (worst >= 0) {
      active[static_cast<std::size_t>(set[static_cast<std::size_t>(worst)])] = 0;
      set.erase(set.begin() + worst);
      lastAdded = -1;
      continue;
    }
    w.setZero();
    for (Index a = 0; a < na; ++a) {
      w += lambdaSet(a) * cols.column(set[static_cast<std::size_t>(a)]);
    }
    const VectorXd gap = q + p.A * w;
    Index add = -1;
    double most = -tol;
    for (Index i = 0; i < m; ++i) {
      if (!active[static_cast<std::size_t>(i)] && !excluded[static_cast<std::size_t>(i)] && gap(i) < most) {
        most = gap(i);
        add = i;
      }
    }
    if (add < 0) {
      r.converged = true;
      r.finalGap = gap;
      break;
    }
    active[static_cast<std::size_t>(add)] = 1;
    set.push_back(add);
    lastAdded = add;
  }
  for (std::size_t a = 0; a < set.size(); ++a) {
    r.lambda(set[a]) = lambdaSet(static_cast<Index>(a));
  }
  r.du = du0 + w;
  if (!r.converged) {
    r.finalGap = q + p.A * w;
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

DualResult solveProjectedGradient(const ContactProblem& p, StiffnessInverse& k, const VectorXd& du0,
                                  const DualOptions& o) {
  const Index m = p.A.rows();
  const int solvesBefore = k.solves;
  GcpState st{p, k, VectorXd::Zero(m), p.gap + p.A * du0, VectorXd::Zero(du0.size())};
  const double tol = o.tolerance;
  const int maxIterations =
      o.maxIterations > 0 ? o.maxIterations : 2 * static_cast<int>(std::max<Index>(m, 1));
  const double initialPenetration = maxInterpenetration(st.gap);
  DualResult r;
  VectorXd d;
  VectorXd z;
  VectorXd gPrev;
  VectorXd zPrev;
  std::vector<char> maskPrev;
  for (r.iterations = 0; r.iterations <= maxIterations; ++r.iterations) {
    const VectorXd g = st.projected();
    if (m == 0 || g.cwiseAbs().maxCoeff() <= tol) {
      r.converged = true;
      break;
    }
    if (r.iterations == maxIterations) {
      break;
    }
    std::vector<char> mask(static_cast<std::size_t>(m));
    for (Index i = 0; i < m; ++i) {
      mask[static_cast<std::size_t>(i)] = st.free(i) ? 1 : 0;
    }
    const bool precondition = o.dirichletPreconditioner &&
                              (o.preconditionerResidual < 0.0 ||
                               maxInterpenetration(st.gap) <= o.preconditionerResidual * initialPenetration);
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
  r.du = du0 + st.w;
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

// Discrete contact algorithms on small spring systems with hand solutions: an elastic bar
// (chain of springs) pushed into a wall, a row of grounded springs against a wall with varied
// gaps (reference: enumeration of every active set), CONTRAINTE = GCP = PENALISATION as E_N
// grows (error ~ 1/E_N), GLISSIERE, a singular Schur complement, and a block pressed and sheared
// on a rigid plane with Coulomb friction (sticking and sliding).

#include "solver/contact/DiscreteContact.hpp"
#include "solver/contact/PenaltyContact.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace stella::contact {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

class DenseInverse : public StiffnessInverse {
public:
  explicit DenseInverse(const MatrixXd& k) : ldlt_(k) {}
  void solve(Eigen::Ref<MatrixXd> rhs) override {
    rhs = ldlt_.solve(MatrixXd(rhs));
    solves += static_cast<int>(rhs.cols());
  }

private:
  Eigen::LDLT<MatrixXd> ldlt_;
};

SparseSolve sparseSolve() {
  return [](const Eigen::SparseMatrix<double>& a, const VectorXd& b, bool symmetric) -> VectorXd {
    if (symmetric) {
      Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> s(a);
      return s.solve(b);
    }
    Eigen::SparseLU<Eigen::SparseMatrix<double>> lu;
    lu.compute(a);
    return lu.solve(b);
  };
}

// Chain of n springs of stiffness k from the ground to DOF n-1.
MatrixXd chain(int n, double k) {
  MatrixXd K = MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    K(i, i) += k;
    if (i + 1 < n) {
      K(i, i) += k;
      K(i, i + 1) -= k;
      K(i + 1, i) -= k;
    }
  }
  return K;
}

SparseRows rows(const MatrixXd& a) {
  return a.sparseView();
}

struct BarCase {
  int n = 5;
  double k = 100.0;
  double force = 30.0;
  double gap0 = 0.5;
  MatrixXd K = chain(5, 100.0);
  ContactProblem problem() const {
    ContactProblem p;
    MatrixXd a = MatrixXd::Zero(1, n);
    a(0, n - 1) = -1.0; // gap = gap0 - u_tip
    p.A = rows(a);
    p.gap = VectorXd::Constant(1, gap0);
    return p;
  }
  VectorXd load() const {
    VectorXd f = VectorXd::Zero(n);
    f(n - 1) = force;
    return f;
  }
  // Closed form: the bar's stiffness is k/n; free tip displacement F n/k = 1.5 > 0.5.
  double reaction() const { return force - k / n * gap0; } // 20
};

TEST(DiscreteContact, ElasticBarPushedIntoWall) {
  const BarCase bar;
  DenseInverse kinv(bar.K);
  MatrixXd du0 = bar.load();
  kinv.solve(du0);
  ASSERT_NEAR(du0(bar.n - 1), 1.5, 1e-12);
  const auto p = bar.problem();
  DualOptions o;
  const auto r = solveActiveSet(p, kinv, du0.col(0), o);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.activeLinks, 1);
  EXPECT_NEAR(r.lambda(0), bar.reaction(), 1e-10);
  EXPECT_NEAR(r.du(bar.n - 1), bar.gap0, 1e-12);
  // Interior nodes displace linearly: u_i = (i+1)/n * gap0.
  for (int i = 0; i < bar.n; ++i) {
    EXPECT_NEAR(r.du(i), (i + 1.0) / bar.n * bar.gap0, 1e-12);
  }
  o.tolerance = 1e-12;
  const auto g = solveProjectedGradient(p, kinv, du0.col(0), o);
  EXPECT_NEAR(g.lambda(0), bar.reaction(), 1e-8);
  EXPECT_NEAR(g.du(bar.n - 1), bar.gap0, 1e-12);
}

TEST(DiscreteContact, PenaltyErrorDecreasesLikeOneOverEN) {
  const BarCase bar;
  const auto p = bar.problem();
  std::vector<double> errors;
  for (double en : {1e3, 1e4, 1e5, 1e6}) {
    PenaltyParameters par;
    par.normalPenalty = VectorXd::Constant(1, en);
    const auto r = solvePenaltyNewton(bar.K.sparseView(), bar.load(), p, nullptr, par, sparseSolve());
    ASSERT_TRUE(r.converged);
    // Closed form: interpenetration lambda/E_N with lambda = E_N (F n/k - g0)/(n/k E_N + 1).
    const double pen = r.du(bar.n - 1) - bar.gap0;
    const double exact = (bar.force - bar.k / bar.n * bar.gap0) / (bar.k / bar.n + en);
    EXPECT_NEAR(pen, exact, 1e-10 * std::max(1.0, exact));
    EXPECT_NEAR(r.state.normalForce(0), en * exact, 1e-8);
    errors.push_back(std::abs(r.state.normalForce(0) - bar.reaction()));
    EXPECT_FALSE(r.usedUnsymmetric);
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    EXPECT_NEAR(errors[i - 1] / errors[i], 10.0, 0.25); // error ~ 1/E_N
  }
}

// m nodes in a row, each grounded (stiffness kg) and tied to its neighbours (kc), pushed towards
// a wall by forces f_i with gaps g_i. Reference: the one active set (of 2^m) whose solution
// satisfies lambda >= 0 and gap >= 0.
struct RowCase {
  int m = 8;
  MatrixXd K;
  VectorXd f;
  VectorXd g;
  RowCase() {
    K = MatrixXd::Zero(m, m);
    f.resize(m);
    g.resize(m);
    for (int i = 0; i < m; ++i) {
      K(i, i) += 10.0 + i;
      if (i + 1 < m) {
        K(i, i) += 40.0;
        K(i + 1, i + 1) += 40.0;
        K(i, i + 1) -= 40.0;
        K(i + 1, i) -= 40.0;
      }
      f(i) = 2.0 + 5.0 * std::sin(1.7 * i);
      g(i) = 0.05 + 0.08 * ((i * 5) % 7) / 7.0;
    }
  }
  ContactProblem problem() const {
    ContactProblem p;
    p.A = rows(-MatrixXd::Identity(m, m));
    p.gap = g;
    return p;
  }
  VectorXd reference(VectorXd& lambda) const {
    for (int mask = 0; mask < (1 << m); ++mask) {
      // Unknowns: u free where inactive, lambda where active (u_i = g_i).
      MatrixXd sys = K;
      VectorXd rhs = f;
      for (int i = 0; i < m; ++i) {
        if (mask & (1 << i)) {
          sys.col(i).setZero();
          sys(i, i) = 1.0; // lambda_i enters equation i: K u - f + lambda e_i = 0
          rhs -= K.col(i) * g(i);
        }
      }
      const VectorXd x = sys.fullPivLu().solve(rhs);
      bool ok = true;
      VectorXd u(m);
      lambda = VectorXd::Zero(m);
      for (int i = 0; i < m; ++i) {
        if (mask & (1 << i)) {
          u(i) = g(i);
          lambda(i) = x(i);
          ok = ok && x(i) >= -1e-12;
        } else {
          u(i) = x(i);
          ok = ok && u(i) <= g(i) + 1e-12;
        }
      }
      if (ok) {
        return u;
      }
    }
    return VectorXd();
  }
};

TEST(DiscreteContact, ConstraintGcpAndPenaltyAgreeWithEnumeration) {
  const RowCase c;
  VectorXd lambdaRef;
  const VectorXd uRef = c.reference(lambdaRef);
  ASSERT_EQ(uRef.size(), c.m);
  const int activeRef = static_cast<int>((lambdaRef.array() > 0).count());
  ASSERT_GT(activeRef, 1);
  ASSERT_LT(activeRef, c.m); // a mixed state: some links open, some closed
  DenseInverse kinv(c.K);
  MatrixXd du0 = c.f;
  kinv.solve(du0);
  const auto p = c.problem();
  DualOptions o;
  const auto a = solveActiveSet(p, kinv, du0.col(0), o);
  EXPECT_EQ(a.activeLinks, activeRef);
  EXPECT_LT((a.du - uRef).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((a.lambda - lambdaRef).cwiseAbs().maxCoeff(), 1e-10);
  for (bool admissible : {true, false}) {
    for (bool dirichlet : {false, true}) {
      DualOptions og;
      og.tolerance = 1e-11;
      og.admissibleLineSearch = admissible;
      og.dirichletPreconditioner = dirichlet;
      og.preconditionerResidual = dirichlet ? 0.1 : -1.0;
      const auto gcp = solveProjectedGradient(p, kinv, du0.col(0), og);
      EXPECT_LT((gcp.du - uRef).cwiseAbs().maxCoeff(), 1e-9) << admissible << dirichlet;
      EXPECT_LT((gcp.lambda - lambdaRef).cwiseAbs().maxCoeff(), 1e-7) << admissible << dirichlet;
      EXPECT_LE(gcp.maxInterpenetration, 1e-11);
    }
  }
  PenaltyParameters par;
  par.normalPenalty = VectorXd::Constant(c.m, 1e7);
  const auto pen = solvePenaltyNewton(c.K.sparseView(), c.f, p, nullptr, par, sparseSolve(), 50, 1e-9);
  ASSERT_TRUE(pen.converged);
  EXPECT_EQ(pen.state.activeLinks, activeRef);
  // Penalty errors: interpenetration lambda/E_N (lambda < 10), force error ~ lambda K/E_N.
  EXPECT_LT((pen.du - uRef).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_LT((pen.state.normalForce - lambdaRef).cwiseAbs().maxCoeff(), 1e-3);
}

TEST(DiscreteContact, ComplianceOnTheSchurIsThePenalisedLaw) {
  // CONTRAINTE's active set with the compliance 1/E_N on the Schur diagonal solves the penalised
  // law lambda = E_N max(0, -gap) exactly: the same forces and displacements as Newton on the
  // penalised equations (E_N = 1e2 ... 1e4, converged to 1e-13), with the Cholesky and with the LU of the
  // unsymmetric path; as E_N grows it tends to the exact contact solution.
  const RowCase c;
  VectorXd lambdaRef;
  const VectorXd uRef = c.reference(lambdaRef);
  DenseInverse kinv(c.K);
  MatrixXd du0 = c.f;
  kinv.solve(du0);
  const auto p = c.problem();
  for (double en : {1.0e2, 1.0e3, 1.0e4}) {
    PenaltyParameters par;
    par.normalPenalty = VectorXd::Constant(c.m, en);
    const auto pen = solvePenaltyNewton(c.K.sparseView(), c.f, p, nullptr, par, sparseSolve(), 50, 1e-13);
    ASSERT_TRUE(pen.converged) << en;
    for (bool symmetric : {true, false}) {
      DualOptions o;
      o.compliance = VectorXd::Constant(c.m, 1.0 / en);
      o.symmetric = symmetric;
      const auto r = solveActiveSet(p, kinv, du0.col(0), o);
      EXPECT_EQ(r.activeLinks, pen.state.activeLinks) << en;
      EXPECT_LT((r.lambda - pen.state.normalForce).cwiseAbs().maxCoeff(), 1e-10 * lambdaRef.maxCoeff()) << en;
      EXPECT_LT((r.du - pen.du).cwiseAbs().maxCoeff(), 1e-12) << en;
      // the gap returned is the penetration -lambda/E_N of the active links
      EXPECT_NEAR(r.maxInterpenetration, pen.state.maxInterpenetration, 1e-14) << en;
    }
  }
  DualOptions o;
  o.compliance = VectorXd::Constant(c.m, 1e-12);
  const auto r = solveActiveSet(p, kinv, du0.col(0), o);
  EXPECT_LT((r.lambda - lambdaRef).cwiseAbs().maxCoeff(), 1e-8);
}

TEST(DiscreteContact, SchurBuiltInBlocksOfNbResol) {
  const RowCase c;
  DenseInverse kinv(c.K);
  MatrixXd du0 = c.f;
  kinv.solve(du0);
  DualOptions o;
  o.rightHandSidesPerSolve = 3;
  const auto a = solveActiveSet(c.problem(), kinv, du0.col(0), o);
  // Every column K^-1 A_i^T is computed once: at most one solve per link ever active.
  EXPECT_LE(a.solves, c.m);
  EXPECT_GE(a.solves, a.activeLinks);
}

TEST(DiscreteContact, IterationCapReported) {
  const RowCase c;
  DenseInverse kinv(c.K);
  MatrixXd du0 = c.f;
  kinv.solve(du0);
  // code_aster's cap: 10 x links, which ITER_GCP_MAXI can only raise.
  EXPECT_EQ(gcpIterationCap(c.m, 0), 10 * c.m);
  EXPECT_EQ(gcpIterationCap(c.m, 1), 10 * c.m);
  EXPECT_EQ(gcpIterationCap(c.m, 1000), 1000);
  DualOptions o;
  o.tolerance = -1.0; // never met
  o.maxIterations = 1;
  try {
    solveProjectedGradient(c.problem(), kinv, du0.col(0), o);
    ADD_FAILURE() << "no ContactNotConverged";
  } catch (const ContactNotConverged& e) {
    EXPECT_EQ(e.result.iterations, 10 * c.m);
  }
}

TEST(DiscreteContact, ConstraintActivatesEveryViolatedLinkAtOnce) {
  // 20 grounded springs k_i pushed by f_i into walls at g_i: every link closes, lambda_i =
  // f_i - k_i g_i. The links enter together: one iteration (one at a time would take 20), and the
  // Schur columns are built in ceil(20 / NB_RESOL) solves of NB_RESOL columns.
  const int m = 20;
  MatrixXd K = MatrixXd::Zero(m, m);
  VectorXd f(m);
  ContactProblem p;
  MatrixXd a = MatrixXd::Zero(m, m);
  p.gap.resize(m);
  for (int i = 0; i < m; ++i) {
    K(i, i) = 100.0 + 10.0 * i;
    f(i) = 50.0 + i;
    a(i, i) = -1.0;
    p.gap(i) = 0.1 + 0.005 * i;
  }
  p.A = rows(a);
  DenseInverse kinv(K);
  MatrixXd du0 = f;
  kinv.solve(du0);
  const int solvesBefore = kinv.solves;
  const auto r = solveActiveSet(p, kinv, du0.col(0), DualOptions{});
  EXPECT_EQ(r.iterations, 1);
  EXPECT_EQ(r.activeLinks, m);
  EXPECT_EQ(kinv.solves - solvesBefore, m + 1); // the columns, then du
  for (int i = 0; i < m; ++i) {
    EXPECT_NEAR(r.lambda(i), f(i) - K(i, i) * p.gap(i), 1e-10);
    EXPECT_NEAR(r.du(i), p.gap(i), 1e-13);
  }
}

TEST(DiscreteContact, WarmStartFromTheSolutionConvergesAtOnce) {
  // Started from the multipliers of the solution (the previous Newton iteration's, converged):
  // CONTRAINTE needs one iteration and only the active links' columns, GCP no iteration at all.
  const RowCase c;
  VectorXd lambdaRef;
  c.reference(lambdaRef);
  DenseInverse kinv(c.K);
  MatrixXd du0 = c.f;
  kinv.solve(du0);
  const auto p = c.problem();
  DualStart start;
  start.lambda = lambdaRef;
  const auto a = solveActiveSet(p, kinv, du0.col(0), DualOptions{}, &start);
  EXPECT_EQ(a.iterations, 1);
  EXPECT_LT((a.lambda - lambdaRef).cwiseAbs().maxCoeff(), 1e-10);
  DualOptions og;
  og.tolerance = 1e-9;
  const auto g = solveProjectedGradient(p, kinv, du0.col(0), og, &start);
  EXPECT_EQ(g.iterations, 0);
  EXPECT_EQ(g.solves, 1); // w = K^-1 A^T lambda of the start
  EXPECT_LT((g.lambda - lambdaRef).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(DiscreteContact, BilateralLinkPulls) {
  // GLISSIERE: an open link of the bar stays closed and pulls (negative multiplier).
  BarCase bar;
  bar.force = -10.0;
  DenseInverse kinv(bar.K);
  MatrixXd du0 = bar.load();
  kinv.solve(du0);
  auto p = bar.problem();
  p.bilateral = {true};
  const auto r = solveActiveSet(p, kinv, du0.col(0), DualOptions{});
  EXPECT_NEAR(r.du(bar.n - 1), bar.gap0, 1e-12);
  EXPECT_NEAR(r.lambda(0), bar.force - bar.k / bar.n * bar.gap0, 1e-10); // -20
}

TEST(DiscreteContact, SingularSchurDetected) {
  const BarCase bar;
  DenseInverse kinv(bar.K);
  MatrixXd du0 = bar.load();
  kinv.solve(du0);
  ContactProblem p;
  MatrixXd a = MatrixXd::Zero(2, bar.n);
  a(0, bar.n - 1) = -1.0;
  a(1, bar.n - 1) = -1.0; // the same link twice
  p.A = rows(a);
  p.gap = VectorXd::Constant(2, bar.gap0);
  EXPECT_THROW(solveActiveSet(p, kinv, du0.col(0), DualOptions{}), SingularContactError);
  DualOptions o;
  o.stopIfSingular = false;
  const auto r = solveActiveSet(p, kinv, du0.col(0), o);
  EXPECT_EQ(r.activeLinks, 1);
  EXPECT_NEAR(r.lambda.sum(), bar.reaction(), 1e-10);
}

// A block (DOFs u tangential, v normal, springs kx, ky to its driver) pressed by N and sheared by
// T on a rigid plane; penalised contact and Coulomb friction.
struct BlockCase {
  double kx = 1000.0;
  double ky = 2000.0;
  double en = 1e6;
  double et = 1e5;
  double mu = 0.3;
  double n = 100.0;
  MatrixXd K() const { return Eigen::Vector2d(kx, ky).asDiagonal(); }
  ContactProblem problem() const {
    ContactProblem p;
    MatrixXd a(1, 2);
    a << 0.0, 1.0; // gap = v
    p.A = rows(a);
    p.gap = VectorXd::Zero(1);
    return p;
  }
  FrictionRows friction() const {
    FrictionRows fr;
    MatrixXd t(1, 2);
    t << 1.0, 0.0;
    fr.T1 = rows(t);
    fr.T2 = SparseRows(0, 2);
    return fr;
  }
  PenaltyParameters parameters(double coef) const {
    PenaltyParameters par;
    par.normalPenalty = VectorXd::Constant(1, en);
    par.friction = true;
    par.tangentPenalty = VectorXd::Constant(1, et);
    par.coulomb = VectorXd::Constant(1, mu);
    par.matrixCoefficient = VectorXd::Constant(1, coef);
    return par;
  }
  double lambda() const { return en * n / (ky + en); }
};

TEST(DiscreteContact, CoulombFrictionSticking) {
  const BlockCase b;
  const double t = 20.0; // E_T u = E_T T/(kx + E_T) = 19.8 < mu lambda = 29.94
  const auto r = solvePenaltyNewton(b.K().sparseView(), Eigen::Vector2d(t, -b.n), b.problem(), nullptr,
                                    b.parameters(1.0), sparseSolve());
  // Without friction rows: the block slides freely, u = T/kx.
  EXPECT_NEAR(r.du(0), t / b.kx, 1e-12);
  const auto fr = b.friction();
  const auto s = solvePenaltyNewton(b.K().sparseView(), Eigen::Vector2d(t, -b.n), b.problem(), &fr,
                                    b.parameters(1.0), sparseSolve());
  ASSERT_TRUE(s.converged);
  EXPECT_EQ(s.state.status[0], LinkStatus::Sticking);
  EXPECT_NEAR(s.du(0), t / (b.kx + b.et), 1e-14);
  EXPECT_NEAR(s.du(1), -b.n / (b.ky + b.en), 1e-14);
  EXPECT_NEAR(s.state.normalForce(0), b.lambda(), 1e-9);
  EXPECT_NEAR(s.state.frictionForce(0, 0), -b.et * t / (b.kx + b.et), 1e-9);
}

TEST(DiscreteContact, CoulombFrictionSlidingUnsymmetricTangent) {
  const BlockCase b;
  const double t = 60.0; // > mu lambda: slides, u = (T - mu lambda)/kx
  const auto fr = b.friction();
  const auto consistent = solvePenaltyNewton(b.K().sparseView(), Eigen::Vector2d(t, -b.n), b.problem(), &fr,
                                             b.parameters(1.0), sparseSolve());
  ASSERT_TRUE(consistent.converged);
  EXPECT_EQ(consistent.state.status[0], LinkStatus::Sliding);
  EXPECT_NEAR(consistent.du(0), (t - b.mu * b.lambda()) / b.kx, 1e-12);
  EXPECT_NEAR(consistent.state.frictionForce(0, 0), -b.mu * b.lambda(), 1e-9);
  EXPECT_TRUE(consistent.usedUnsymmetric);
  // COEF_MATR_FROT = 0: no sliding matrix, symmetric, same solution, more iterations.
  const auto plain = solvePenaltyNewton(b.K().sparseView(), Eigen::Vector2d(t, -b.n), b.problem(), &fr,
                                        b.parameters(0.0), sparseSolve(), 200);
  ASSERT_TRUE(plain.converged);
  EXPECT_FALSE(plain.usedUnsymmetric);
  EXPECT_NEAR(plain.du(0), consistent.du(0), 1e-10);
  EXPECT_LE(consistent.iterations, plain.iterations);
}

} // namespace
} // namespace stella::contact

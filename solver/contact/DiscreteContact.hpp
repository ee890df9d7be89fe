#pragma once
// The discrete contact algorithms on an abstract linear system (notice §3.2, §3.3.2).
//
// One sub-problem: the stiffness K (n x n, factorised once), the free step du0 = K^-1 r, the
// contact matrix A (one row per link: the gradient of the gap, gap(du) = g + A du) and the
// gaps g. The dual methods find multipliers lambda >= 0 (normal forces, compressive positive)
// with
//     du = du0 + K^-1 A^T lambda,   gap(du) >= 0,   lambda . gap(du) = 0,
// i.e. the linear complementarity problem on the Schur complement S = A K^-1 A^T (code_aster
// writes it -A C^-1 A^T with multipliers of the opposite sign):
//   CONTRAINTE  active-set method on the explicit Schur complement: the columns S_i = A K^-1 A_i^T
//               of the links that become active are computed NB_RESOL right-hand sides per K
//               solve and kept (only their m link entries: the n-vectors K^-1 A_i^T are not
//               stored, one more solve gives du at the end); the active matrix is factorised
//               by Cholesky extended one link at a time (a link whose pivot vanishes makes it
//               singular: STOP_SINGULIER) and refactorised only when links leave. Every
//               violated link enters at once and every negative multiplier leaves at once
//               (most violated first); after a few such rounds without convergence it falls
//               back to one link at a time (the classical finite algorithm). At most
//               ITER_CONT_MULT x (number of links) iterations.
//   GCP         projected conjugate gradient on the dual: one K solve per iteration; converged
//               when the projected gradient (interpenetration of free links, gap of active ones)
//               is below RESI_ABSO; at most max(10 x links, ITER_GCP_MAXI) iterations (a user
//               value only raises the default); RECH_LINEAIRE ADMISSIBLE (steps stop at the
//               bound lambda = 0) or NON_ADMISSIBLE (full step, then projection);
//               PRE_COND='DIRICHLET': the direction is preconditioned by an approximate inverse
//               of S on the free links (ITER_PRE_MAXI inner conjugate-gradient iterations, 0:
//               as many as free links, each one K solve), once the projected gradient has fallen
//               below COEF_RESI x its value at the first iteration (COEF_RESI < 0: always).
//   Both start from given multipliers when there are some (the previous Newton iteration's):
//   CONTRAINTE takes their links as the initial active set, GCP starts from them.
//   PENALISATION  (PenaltyContact.hpp) works on the tangent matrix instead.
// GLISSIERE links are bilateral: always active, multiplier of any sign.

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <stdexcept>
#include <vector>

namespace stella::linalg {
class LinearSolver;
}

namespace stella::contact {

using SparseRows = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct ContactProblem {
  SparseRows A;                // links x DOFs
  Eigen::VectorXd gap;         // g, one per link
  std::vector<bool> bilateral; // GLISSIERE (empty: none)
  bool isBilateral(Eigen::Index i) const {
    return !bilateral.empty() && bilateral[static_cast<std::size_t>(i)];
  }
};

// K^-1 applied in place to a block of right-hand sides (the factorised stiffness).
class StiffnessInverse {
public:
  virtual ~StiffnessInverse() = default;
  virtual void solve(Eigen::Ref<Eigen::MatrixXd> rhs) = 0;
  int solves = 0; // right-hand sides solved so far (counted by implementations)
};

// The LinearSolver facade with its last factorisation.
class FactorisedStiffness : public StiffnessInverse {
public:
  explicit FactorisedStiffness(linalg::LinearSolver& solver) : solver_(solver) {}
  void solve(Eigen::Ref<Eigen::MatrixXd> rhs) override;

private:
  linalg::LinearSolver& solver_;
};

struct DualOptions {
  int rightHandSidesPerSolve = 10; // NB_RESOL
  int iterationFactor = 4;         // ITER_CONT_MULT
  bool stopIfSingular = true;      // STOP_SINGULIER
  // GCP
  double tolerance = 0.0; // RESI_ABSO (GCP, mandatory there); CONTRAINTE: 0 = automatic
  int maxIterations = 0;  // ITER_GCP_MAXI (the cap is max(10 x links, ITER_GCP_MAXI))
  bool admissibleLineSearch = true;
  bool dirichletPreconditioner = false;
  double preconditionerResidual = -1.0; // COEF_RESI (< 0: from the start)
  int preconditionerIterations = 0;     // ITER_PRE_MAXI (0: free links)
  // false: du and finalGap are not computed (saves the final K solve when the caller applies
  // the multipliers itself).
  bool computeDisplacement = true;
  // CONTRAINTE only: a compliance c_i >= 0 per link (empty: none) added to the diagonal of the
  // Schur complement, i.e. the regularised complementarity lambda >= 0, gap + c lambda >= 0,
  // lambda (gap + c lambda) = 0. With c = 1/E_N this is the penalised law lambda = E_N max(0, -gap)
  // solved on the condensed rows (PENALISATION, PenaltyContactConstraint::correct); the gap
  // returned is the penetration -c lambda of the active links.
  Eigen::VectorXd compliance;
  // CONTRAINTE only: whether K (so S) is symmetric; false (an unsymmetric tangent: penalised
  // friction with COEF_MATR_FROT) solves the active block by LU instead of Cholesky.
  bool symmetric = true;
};

// Initial multipliers (per link) and, when known, w = K^-1 A^T lambda (empty: computed).
struct DualStart {
  Eigen::VectorXd lambda;
  Eigen::VectorXd w;
};

struct DualResult {
  Eigen::VectorXd lambda;   // per link
  Eigen::VectorXd du;       // du0 + K^-1 A^T lambda
  Eigen::VectorXd finalGap; // g + A du
  int iterations = 0;
  int activeLinks = 0;
  int solves = 0; // right-hand sides solved with K
  bool converged = false;
  double maxInterpenetration = 0.0; // max(0, -min gap)
};

// The active Schur matrix is singular: `link` is the link whose addition made it so.
class SingularContactError : public std::runtime_error {
public:
  explicit SingularContactError(int link)
      : std::runtime_error("singular contact Schur complement at link " + std::to_string(link)), link_(link) {
  }
  int link() const { return link_; }

private:
  int link_;
};

// A dual method reached its iteration cap (ITER_CONT_MULT x links or ITER_GCP_MAXI).
class ContactNotConverged : public std::runtime_error {
public:
  ContactNotConverged(std::string what, DualResult r)
      : std::runtime_error(std::move(what)), result(std::move(r)) {}
  DualResult result;
};

DualResult solveActiveSet(const ContactProblem& problem, StiffnessInverse& k, const Eigen::VectorXd& du0,
                          const DualOptions& options, const DualStart* start = nullptr);
DualResult solveProjectedGradient(const ContactProblem& problem, StiffnessInverse& k,
                                  const Eigen::VectorXd& du0, const DualOptions& options,
                                  const DualStart* start = nullptr);
// The iteration cap of GCP for `links` links.
int gcpIterationCap(Eigen::Index links, int iterGcpMaxi);

} // namespace stella::contact

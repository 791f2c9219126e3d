#pragma once
// The contact step shared by the Super-Helix's frictional statics (frictional_statics.hpp for one rod,
// bundle_frictional_statics.hpp for many): the Signorini-Coulomb problem u = W r + b of one Newton
// iteration by a primal-dual active set, and the factored matrix of the iteration's step.
#include <optional>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix::detail {

// The contact problem u = W r + b under Signorini-Coulomb by a primal-dual active set: each contact open
// (r = 0), sticking (u = 0) or sliding (u_N = 0, r_T = -mu r_N s with the slip direction s frozen), the
// statuses guessed from u at the guess r (closed if r_N > 0 or u_N < 0; sliding if its slip is not 0),
// the linear system of the statuses solved (dense LU), the statuses corrected where the result breaks its
// law (r_N < 0: open; u_N < 0: closed; |r_T| > mu r_N: sliding against r_T; slip against s: sticking) and
// s turned to the new slip, until nothing changes: all violated statuses at once for 30 rounds, then one at
// a time, the least index first (Murty's rule, finite for the frictionless LCP, W positive definite), up to
// 8 m more rounds. Newton's iterations converge together with the slip directions. It returns nothing
// when the statuses have not settled: the block Gauss-Seidel takes over. The Gauss-Seidel alone slows down
// as contacts along one inextensible strand multiply (W couples them all: 10^5 sweeps do not reach 1e-12 at
// 40 contacts of the capstan).
std::optional<VecX> active_set_contact_solve(const MatX& W, const VecX& b, const VecX& mu, const VecX& guess);

// The step's matrix of a frictional Newton iteration (frictional_statics.hpp): A if positive definite,
// else A + rho G^T G with G the rows of the first augmentation, then of the second (rho = rho_0 x 10^j,
// j = 0 .. 6, the first that makes it positive definite), else the first's with rho_0 and a Levenberg
// shift sigma diag(k) on top (sigma = 1e-6 x 10^j up to 1e12; SolverError `method` at `iteration` with
// `residual` beyond). An augmentation holds G^T G and G^T g (g the rows' values at the iterate); an
// empty one (no rows) is skipped. Solves by the Cholesky factor of the symmetric part when the matrix is
// symmetric to round-off (1e-12 of its largest entry), else by LU.
struct Augmentation {
  MatX normal_matrix;  // G^T G
  VecX rhs;            // G^T g
  bool empty = true;
};
Augmentation augmentation_of(const MatX& G, const VecX& g);

class StepMatrix {
 public:
  StepMatrix(const MatX& A, const std::vector<Augmentation>& augmentations, double rho_0, const VecX& k,
             const char* method, std::size_t iteration, double residual);
  // rho G^T g of the augmentation taken (0 if none): the step solves (A + rho G^T G) dq = -R - this + ...
  const VecX& augmented_rhs() const noexcept { return augmented_rhs_; }
  MatX solve(const MatX& rhs) const;

 private:
  VecX augmented_rhs_;
  bool symmetric_ = true;
  Eigen::LLT<MatX> cholesky_;
  Eigen::PartialPivLU<MatX> lu_;
};

}  // namespace rodvv::solvers::superhelix::detail

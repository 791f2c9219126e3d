#pragma once
// Internal building block of solve_static_contact (contact.hpp) for ContactMethod::NewtonLcp
// (namespace detail; not a stable interface): one load step of a Josephy-Newton (SQP) iteration
// on the discrete contact problem
//
//     F(z, lambda) = grad L(z) - G(z)^T lambda = 0,    0 <= lambda _|_ g(z) >= 0,
//
// z the KKT unknowns of lagrangian.hpp, g the gaps of the (node, obstacle) pairs, G = dg/dz (the
// unit normals grad g at the node's x, y). Josephy 1979 (MRC TSR 1965), Robinson 1980: at each
// iterate the equilibrium and the gaps are linearised,
//
//     K dz = -grad L(z) + G^T lambda+,    K = Hessian of L - sum_p lambda_p grad^2 g_p (banded),
//     0 <= lambda+ _|_ g + G dz >= 0,
//
// and condensed onto the contact forces: dz = dz0 + Z lambda+ with dz0 = -K^-1 grad L and
// Z = K^-1 G^T (one banded solve per candidate pair, O(N) each), which leaves the LCP
//
//     0 <= lambda+ _|_ W lambda+ + b >= 0,    W = G K^-1 G^T (Delassus), b = g + G dz0,
//
// solved by contact::solve_lcp (Lemke: exact, or projected Gauss-Seidel), and the solution is
// verified: one with a natural-map residual above 1e-6 max|b| is never taken as a step. Lemke is
// then run again on the Jacobi-scaled LCP (D W D, D b), D = diag(W)^-1/2: on line contacts from
// N ~ 128 on, the unscaled tableau (nodal compliances from ~h^3 / EI to ~L^3 / EI, a near-singular
// block on the flat run) returned wrong solutions (residual 5e-3 .. 2e-1 max|b|) whose steps
// derailed the iteration (the SolverError from N = 256 of the earlier version); contact_lcp.cpp.
// W is symmetric positive semidefinite where the rod is stable (K^-1 restricted to the positions
// is the compliance on the constraint manifold); rows of pairs that cannot both be active (the
// two walls at one node) make it singular, which Lemke's lexicographic rule and PGS both tolerate. W is
// symmetrised ((W + W^T)/2) against the round-off of the solves. The step dz is then recomputed
// by one solve with the full right-hand side (no cancellation between dz0 and Z lambda+).
//
// Stabilisation. Where the rod is held only by its contacts (line contact: P above the second
// Euler load of the free rod) K is indefinite on the constraint manifold and so is W, which the
// LCP solvers reject. The loaded pairs A = {p : lambda_p > 0} of the iterate are then held by the
// augmented-Lagrangian penalty rho/2 sum_A g_p^2 (K += rho G_A^T G_A + rho g grad^2 g, grad L +=
// rho G_A^T g_A): by Finsler's / Debreu's lemma K + rho G_A^T G_A is positive definite for rho
// large enough when the rod with A held is stable. The penalty vanishes where g_A = 0, so a fixed
// point is a solution of the unpenalised problem, and while the LCP keeps A active the step IS
// the Josephy-Newton step (quadratic convergence is kept). rho = contact.stabilisation x max EI /
// L^3, raised x 100 (at most 3 times) when W still has a negative diagonal or the LCP fails.
// Limitation: an iterate that is unstable even with A held (an overshooting step loads a free
// span beyond its own Euler load) ends in SolverError. Measured on the cavity line contact
// (shortening 0.0345, 8 displacement steps, Lemke): converges at N = 256 (every pair or
// candidate_distance = a/2) and N = 512 (candidate_distance = a/2), polygon and arcs, in 31-35
// Newton iterations, agreeing with the active set (tests NewtonLcpLineContact.*).
//
// Globalisation: the step is the exact Newton direction of the smooth system selected by the
// LCP, (F_rho, g_p for lambda+_p > 0, lambda_p otherwise), so the backtracking runs on its 2-norm
// along (z + a dz, lambda + a (lambda+ - lambda)), Armijo 1e-4, a halved down to 2^-30, as the
// other Newton loops of this folder (the natural map min(lambda, g) mixes a force and a length and
// is not decreased by a contact-engaging step).
// Convergence: ||Phi||_inf <= options.tolerance, Phi = (F, min(lambda, g)) unpenalised and in the problem's
// units (F over detail::residual_scales, lambda over EI/L^2, g over L: the active-set path's tolerance on its
// KKT residual), or a step at round-off (||dz||_inf <= 64 eps (1 +
// ||z||_inf)). Candidate pairs: gap <= contact.candidate_distance at the iterate, plus every
// pair with lambda > 0. Failure: SolverError (Newton iterations, last ||Phi||_inf) when the LCP
// fails (the message carries the LCP solver's), the KKT matrix is singular, the line search fails
// or max_iterations is reached.
#include <Eigen/Core>
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/solvers/elastica2d/contact.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/newton.hpp"
#include "rodvv/solvers/elastica2d/obstacle.hpp"

namespace rodvv::solvers::elastica2d::detail {

struct ContactPair {
  std::size_t node = 0;
  std::size_t obstacle = 0;
};

// Counters of the LCP subproblems, accumulated over the load steps.
struct LcpNewtonStats {
  std::size_t solves = 0;
  std::size_t iterations = 0;      // pivots / sweeps summed
  std::size_t max_iterations = 0;  // largest single solve
  std::size_t candidates = 0;      // size of the last LCP
  std::size_t set_changes = 0;     // iterations whose set {p : lambda_p > 0} changed
  double residual = 0.0;           // last LCP: natural-map residual
  double fischer_burmeister = 0.0;
  double scale = 0.0;              // last LCP: max |b|
  std::size_t rescaled = 0;        // Lemke solves repeated on the Jacobi-scaled LCP (inaccurate)
};

// One load step (the load factor and the boundary targets of lag already set). z and lambda (one
// entry per pair, >= 0) are the starting point and the result.
void newton_lcp(const DiscreteLagrangian& lag, const std::vector<Obstacle>& obstacles,
                const std::vector<ContactPair>& pairs, Eigen::VectorXd& z, Eigen::VectorXd& lambda,
                const SolverOptions& options, const ContactOptions& contact, NewtonState& state,
                LcpNewtonStats& stats, const std::string& method);

}  // namespace rodvv::solvers::elastica2d::detail

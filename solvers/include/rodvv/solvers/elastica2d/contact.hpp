#pragma once
// Static equilibrium of a planar elastica (problem.hpp) in hard, frictionless contact with rigid
// obstacles (obstacle.hpp): the nodes r_i of the discretisation must satisfy g(r_i) >= 0 for every
// obstacle acting on them (Signorini, PHYSICS.md §1.2).
//
// Method: primal-dual active set (Hintermueller, Ito & Kunisch 2003, SIAM J. Optim. 13:865) around
// the KKT Newton solver of solve_static.hpp. For a fixed active set A of (node, obstacle) pairs the
// Lagrangian gains the term
//     - sum_{(i,o) in A} lambda_io g_o(r_i),
// i.e. one equality row g_o(r_i) = 0 per active pair and the nodal force lambda_io grad g_o(r_i) on
// the rod; Newton (analytic Hessian, -lambda grad^2 g for curved obstacles, the same backtracking
// line search) solves it to the tolerance, on the residual in the problem's units as solve_static does
// (detail::residual_scales; a gap row over L), so that it converges alike at any L and EI. Then A is updated:
// pairs with lambda < -tolerance EI/L^2 leave; of every run of consecutive inactive nodes with g < -gap
// tolerance (gap tolerance = 64 eps (L + max|r|), i.e. round-off) the deepest enters (adding a whole run at once can
// over-constrain the rod); the solve repeats until no pair changes. Point contacts (one active node) and
// line contacts (a run of active nodes; inside it lambda is zero to round-off, PHYSICS.md §1.2) come
// out of the same iteration. Each multiplier row is inserted right after its node's (x, y) in the
// interleaved unknowns of lagrangian.hpp, so the KKT matrix stays banded and one Newton step is
// still O(N) (banded_lu.hpp). Without obstacles the result is bit-identical to solve_static.
//
// Load / displacement stepping as in solve_static (options.load_steps); the active set of one step
// starts the next. The initial state built from the guess must not penetrate any obstacle (InputError
// "guess.theta" naming the node and the obstacle).
// Failure: SolverError when Newton fails for an active set or the active set has not settled after
// options.max_active_set_iterations updates in a step.
//
// Second method, ContactMethod::NewtonLcp: a Josephy-Newton (SQP) iteration whose subproblem is
// the LCP of the shared solver (solvers/contact/lcp.hpp, Lemke or projected Gauss-Seidel);
// see contact_lcp.hpp. It solves the same discrete complementarity problem, so both methods agree
// up to their tolerances (measured: forces within 3.5e2 x the sum of the two final residuals).
// Cost: one banded solve per candidate pair per iteration, O(N m) (m = 2(N + 1) for the cavity
// with every pair): ~10 x (N = 32) to ~100 x (N = 256) the active set (bench_contact2d), plus the
// dense Lemke tableau, O(m^2) per pivot (cavity line contact, N = 512, every pair: 19 s; with
// candidate_distance = a/2: 1 s). It fails (SolverError) where an iterate is unstable even with
// its loaded pairs held; the active set is the default.
#include <cstddef>
#include <limits>
#include <vector>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/contact/lcp.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/obstacle.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::solvers::elastica2d {

enum class ContactMethod { ActiveSet, NewtonLcp };

struct ContactOptions {
  std::size_t max_active_set_iterations = 200;  // ActiveSet: per load step, >= 1
  ContactMethod method = ContactMethod::ActiveSet;
  // NewtonLcp: the LCP solver of each Newton iterate and its settings (tolerance in (0, 1),
  // max_iterations >= 1; see solvers/contact/lcp.hpp).
  contact::LcpMethod lcp = contact::LcpMethod::Lemke;
  contact::LcpSettings lcp_settings{};
  // NewtonLcp: the LCP of an iterate holds the pairs with gap <= candidate_distance there, plus
  // every pair carrying a force; > 0, +inf (default) = every (node, obstacle) pair.
  double candidate_distance = std::numeric_limits<double>::infinity();
  // NewtonLcp: the penalty rho/2 g_p^2 on the loaded pairs that keeps the condensed tangent
  // positive definite (see contact_lcp.hpp), rho = stabilisation x max EI / L^3; >= 0 (0 = off).
  double stabilisation = 1e3;
};

// One active (node, obstacle) pair at the solution.
struct NodeContact {
  std::size_t node = 0;
  std::size_t obstacle = 0;
  double force = 0.0;      // multiplier lambda >= 0 (force magnitude, |grad g| = 1)
  double gap = 0.0;        // g at the solution (0 to round-off)
  Eigen::Vector2d direction = Eigen::Vector2d::Zero();  // grad g: the force acts along it
};

struct ContactSolution {
  PlanarRodSolution rod;               // as solve_static (internal force from the edge multipliers)
  std::vector<NodeContact> contacts;   // active pairs, sorted by node (NewtonLcp: the pairs with
                                       // lambda > 0 or touching, gap <= 64 eps (1 + max|r|))
  std::vector<double> contact_force_x;  // total contact force on each node (nodes() values)
  std::vector<double> contact_force_y;
  std::vector<double> min_gap;          // min over the obstacles acting on the node (+inf if none)
  std::size_t active_set_iterations = 0;  // active-set updates summed over the load steps
                                          // (NewtonLcp: iterations whose set of loaded pairs changed)
  // Both methods: max over the acting pairs of |min(lambda, g)| at the solution (lambda = 0 off the
  // contacts): the complementarity part of the residual.
  double complementarity_residual = 0.0;
  // NewtonLcp only (0 for ActiveSet): one LCP per Newton iteration.
  std::size_t lcp_solves = 0;
  std::size_t lcp_iterations = 0;      // Lemke pivots or PGS sweeps, summed over the solves
  std::size_t lcp_max_iterations = 0;  // the largest single solve
  std::size_t lcp_candidates = 0;      // size of the last LCP (candidate pairs)
  double lcp_residual = 0.0;           // natural-map residual of the last LCP (gap units)
  double lcp_fischer_burmeister = 0.0;  // Fischer-Burmeister residual of the last LCP
  double lcp_scale = 0.0;              // max |b| of the last LCP (its residual is relative to it)
  std::size_t lcp_rescaled = 0;        // Lemke solves repeated on the Jacobi-scaled LCP because
                                        // the unscaled one was inaccurate (contact_lcp.cpp)
};

void validate(const ContactOptions& options);

ContactSolution solve_static_contact(const Problem& problem, const Discretisation& discretisation,
                                     const std::vector<Obstacle>& obstacles,
                                     const SolverOptions& options = {},
                                     const InitialGuess& guess = {},
                                     const ContactOptions& contact = {});

}  // namespace rodvv::solvers::elastica2d

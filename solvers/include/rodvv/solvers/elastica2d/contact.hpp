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
// line search) solves it to the tolerance. Then A is updated: pairs with lambda < -tolerance
// leave; of every run of consecutive inactive nodes with g < -gap tolerance (gap tolerance =
// 64 eps (1 + max|r|), i.e. round-off) the deepest enters (adding a whole run at once can
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
#include <cstddef>
#include <vector>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/obstacle.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::solvers::elastica2d {

struct ContactOptions {
  std::size_t max_active_set_iterations = 200;  // per load step, >= 1
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
  std::vector<NodeContact> contacts;   // active pairs, sorted by node
  std::vector<double> contact_force_x;  // total contact force on each node (nodes() values)
  std::vector<double> contact_force_y;
  std::vector<double> min_gap;          // min over the obstacles acting on the node (+inf if none)
  std::size_t active_set_iterations = 0;  // active-set updates summed over the load steps
};

void validate(const ContactOptions& options);

ContactSolution solve_static_contact(const Problem& problem, const Discretisation& discretisation,
                                     const std::vector<Obstacle>& obstacles,
                                     const SolverOptions& options = {},
                                     const InitialGuess& guess = {},
                                     const ContactOptions& contact = {});

}  // namespace rodvv::solvers::elastica2d

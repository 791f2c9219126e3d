#pragma once
// Pseudo-arc-length continuation of a static equilibrium branch (Keller 1977) in the load factor
// lambda, which scales every dead end load and the potential of the problem (prescribed positions
// and angles stay at their values). Use it to follow a post-buckled branch: e.g. a pinned-pinned
// column with end load force_x = -1 traced from lambda = P_0 (first mode selected by the initial
// guess theta = theta_amp cos(pi s / L)) to lambda = P_1.
//
// The first point is a Newton solve (solve_static.hpp) at lambda = initial_load_factor. Each step
// predicts along the tangent in (z, lambda) and corrects with Newton on the bordered system
//   grad L(z, lambda) = 0,   w t_z.(z - z_k) + t_lambda (lambda - lambda_k) = ds,
// w = 1 / dim(z), solved by block elimination with two banded LU solves per iteration (so it also
// passes folds in lambda, where the KKT matrix alone is singular only at the fold itself). The
// step ds grows x1.5 after a corrector of <= 3 iterations, shrinks x0.7 after > 6, and halves on
// failure down to min_step (then SolverError). The tangent after the first step is the secant.
// The branch stops at the first point with lambda beyond final_load_factor; that last point is
// replaced by a Newton solve at exactly final_load_factor.
#include <cstddef>
#include <vector>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::solvers::elastica2d {

struct ContinuationOptions {
  double initial_load_factor = 1.0;  // finite
  double final_load_factor = 2.0;    // finite, != initial
  double step = 0.1;                 // initial ds > 0
  double max_step = 1.0;             // >= step
  double min_step = 1e-8;            // in (0, step]
  std::size_t max_points = 500;      // >= 2
};

struct BranchPoint {
  double load_factor = 0.0;
  PlanarRodSolution solution;
};

void validate(const ContinuationOptions& options);

// options.load_steps is ignored (the first point is a single Newton solve from the guess).
std::vector<BranchPoint> trace_branch(const Problem& problem, const Discretisation& discretisation,
                                      const SolverOptions& options, const InitialGuess& guess,
                                      const ContinuationOptions& continuation);

}  // namespace rodvv::solvers::elastica2d

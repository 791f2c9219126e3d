#pragma once
// Soft walls (PHYSICS.md §4.2): the distributed potential V(y) = b/(a - y) + b/(a + y) per unit
// length (the slides' wall at y = +a and its mirror at y = -a), plugged into the solver's Potential
// hook. As the softness b -> 0 the equilibrium tends to the hard-contact one of contact.hpp.
// V is +infinity and its gradient NaN outside the open strip |y| < a, so the Newton line search
// (which rejects non-finite residuals) never accepts a step through a wall.
//
// A stiff barrier defeats plain load stepping for small b (Newton crawls along the wall), so
// solve_soft_walls continues in b instead: it solves at b_start (default 1e-4, where stepping from
// the guess converges) and then lowers b geometrically (factor softness_ratio per stage) down to the
// requested b, each stage a Newton solve started from the previous stage's state. The problem's
// own potential must be empty (it is replaced).
#include <cstddef>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/discretisation.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::solvers::elastica2d {

// InputError "wall_gap" for a <= 0, "wall_softness" for b <= 0 (both must be finite).
Potential soft_walls(double gap, double softness);

struct SoftWallOptions {
  // b of the first (load-stepped) solve in units of EI(0) / L (so that the continuation does not depend on the
  // units: 1e-4 is a wall the column barely touches at any L and EI), > 0
  double start_softness = 1e-4;
  double softness_ratio = 0.5;    // b_{k+1} = ratio * b_k, in (0, 1)
};

// InputError: "wall_gap", "wall_softness", "soft.start_softness", "soft.softness_ratio",
// "potential" (the problem already has one).
PlanarRodSolution solve_soft_walls(const Problem& problem, const Discretisation& discretisation,
                                   double gap, double softness, const SolverOptions& options = {},
                                   const InitialGuess& guess = {}, const SoftWallOptions& soft = {});

}  // namespace rodvv::solvers::elastica2d

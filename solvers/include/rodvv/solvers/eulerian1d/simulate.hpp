#pragma once
// Time stepping of the 1-D reference-map solid (ALGORITHMS.md §6.2), explicit with a CFL step:
//   1. v* = v - dt v D_up v (upwind advection of the velocity)
//   2. v* += dt (f + m g) / m on nodes with mass
//   3. contact: v = argmin 1/2 (v - v*)^T M (v - v*) s.t. the solid edge does not cross a wall,
//      J v >= c (one row per wall; solved through the LCP of solvers/contact; seed slides 001)
//   4. v extrapolated to the nodes without mass
//   5. xi <- xi - dt v D_up xi with the new v; if the advected edge crossed a wall (by O(dt^2)),
//      xi is shifted locally to put it back on the wall (position projection, recorded).
// Deviation from ALGORITHMS.md §6.2: the CFL speed is max|v| + c max(F + |F - 1|), not
// max(|v| + F c), see simulate.cpp.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/eulerian1d/problem.hpp"

namespace rodvv::solvers::eulerian1d {

struct Snapshot {
  double t = 0.0;
  VecX xi;
  VecX v;
  VecX density;  // per cell
};

// One entry per time level (the initial state included).
struct History {
  std::vector<double> t;
  std::vector<double> x_left, x_right;  // solid ends: xi = 0 and xi = L0
  std::vector<double> mass;             // sum m_j
  std::vector<double> momentum;         // sum m_j v_j
  std::vector<double> kinetic, elastic;
  std::vector<double> left_wall_force, right_wall_force;  // impulse / dt of the step ending here
  // Signed distance the solid end has crossed a wall (> 0: penetration) measured from xi after
  // the step, and the constraint violation of the QP itself (c - J v, > 0: violated).
  std::vector<double> penetration;
  std::vector<double> constraint_violation;
  // Distance the edge was moved back onto a wall after the advection of xi (simulate.cpp:
  // post-stabilisation); 0 when no wall was crossed.
  std::vector<double> projection;
};

struct Result {
  Grid grid;
  std::vector<Snapshot> snapshots;
  History history;
  std::size_t steps = 0;
  std::size_t contact_solves = 0;  // steps with at least one wall constraint assembled
};

// Throws InputError (validate) for bad input and SolverError if xi loses monotonicity or a
// field becomes non-finite.
Result simulate(const Problem& problem, const Settings& settings);

}  // namespace rodvv::solvers::eulerian1d

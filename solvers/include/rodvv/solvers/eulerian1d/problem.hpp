#pragma once
// The 1-D Eulerian (reference-map) elastic solid (ALGORITHMS.md §6; seed slides 001; Levin et al.,
// SIGGRAPH 2011; Kamrin, Rycroft & Nave, JMPS 60, 2012): a bar of reference length L0 lives on a
// fixed grid; each node carries the reference map xi (the material coordinate X of the point at x)
// and the velocity v. Parameters, state and settings are separate structs (ARCHITECTURE.md,
// convention 3).
#include <cstddef>
#include <optional>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::eulerian1d {

// Fixed grid of `cells` equal cells on [x_min, x_max]; nodes x_j = x_min + j dx, j = 0..cells.
struct Grid {
  double x_min = 0.0;
  double x_max = 1.0;
  std::size_t cells = 100;

  double dx() const { return (x_max - x_min) / static_cast<double>(cells); }
  double node(std::size_t j) const { return x_min + static_cast<double>(j) * dx(); }
  std::size_t nodes() const { return cells + 1; }
};

// sigma = kappa (F - 1): stored energy psi(F) = kappa (F - 1)^2 / 2 per reference length.
struct Material {
  double rho0 = 1.0;    // reference density (mass per reference length)
  double kappa = 1.0;   // stiffness
  double length = 1.0;  // reference length L0: the solid is 0 <= xi <= L0
  double wave_speed() const;  // c = sqrt(kappa / rho0), the Lagrangian wave speed
};

struct Problem {
  Grid grid;
  Material material;
  double gravity = 0.0;  // body acceleration along +x
  std::optional<double> left_wall;   // rigid barrier: the solid stays at x >= left_wall
  std::optional<double> right_wall;  // rigid barrier: the solid stays at x <= right_wall
  VecX xi0;  // initial reference map on the nodes (strictly increasing)
  VecX v0;   // initial velocity on the nodes
};

struct Settings {
  double t_end = 1.0;
  double cfl = 0.4;  // dt = cfl dx / (max|v| + c max(F + |F - 1|)); see simulate.cpp
  std::vector<double> snapshot_times;  // fields are stored at these times (stepped onto exactly)
  std::size_t max_steps = 10'000'000;
  // Work budget of one run, in cell updates (steps x cells): checked before the first step
  // against least_cell_updates, so that a run that cannot finish within it fails at once (a
  // SolverError naming the budget) instead of after hours. 1e10 is about 3 minutes on the CI
  // machine class (measured: eulerian1d/impact at N = 1600, 11202 steps x 1601 nodes = 1.8e7 cell
  // updates in 0.29 s of CPU, 6e7 per second, with the contact QP).
  double max_cell_updates = 1e10;
  // Move an edge that the advection of xi pushed across a wall back onto it (simulate.cpp). Off
  // only to measure the crossing that the velocity-level constraint alone leaves (O(dt^2)).
  bool project_positions = true;
};

// A lower bound on the work of simulate() to t_end, in cell updates: every step has
// dt <= cfl dx / c (the step's speed bound max|v| + c max(F + |F - 1|) is at least c, since
// F + |F - 1| >= 1), so there are at least t_end c / (cfl dx) steps over grid.cells cells.
double least_cell_updates(const Grid& grid, const Material& material, const Settings& settings);

// Checks every parameter and the initial state (monotone xi, walls outside the initial solid);
// throws InputError naming the parameter and its allowed range.
void validate(const Problem& problem, const Settings& settings);

// xi = (x - x_left) / stretch at every node: a uniformly stretched bar whose end X = 0 is at
// x_left (the solid spans [x_left, x_left + stretch L0]), extended linearly outside.
VecX linear_reference_map(const Grid& grid, double x_left, double stretch);

}  // namespace rodvv::solvers::eulerian1d

// solvers/eulerian1d: the discrete operators of ALGORITHMS.md §6.2 (clipping, lumped masses,
// energy-consistent force, upwind transport, extrapolation), exact behaviours of the time stepper
// (rigid translation, free fall, a compressed bar held by two walls), the barrier, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/eulerian1d/discretisation.hpp"
#include "rodvv/solvers/eulerian1d/simulate.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::VecX;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
namespace eu = rodvv::solvers::eulerian1d;

eu::Problem bar_problem(std::size_t cells, double x_min, double x_max, double x_left, double stretch,
                        double velocity) {
  eu::Problem p;
  p.grid = {x_min, x_max, cells};
  p.xi0 = eu::linear_reference_map(p.grid, x_left, stretch);
  p.v0 = VecX::Constant(static_cast<Eigen::Index>(p.grid.nodes()), velocity);
  return p;
}

// A random strictly increasing piecewise-linear map across [-0.3, 1.3] (the solid is [0, 1]).
VecX random_monotone_map(std::mt19937& rng, Eigen::Index nodes) {
  std::uniform_real_distribution<double> u(0.2, 1.0);
  VecX xi(nodes);
  xi(0) = -0.3;
  for (Eigen::Index j = 1; j < nodes; ++j) xi(j) = xi(j - 1) + u(rng);
  return -0.3 + (xi.array() - xi(0)) * (1.6 / (xi(nodes - 1) - xi(0)));
}

TEST(EulerianDiscretisation, ClippedSolidLengthsAndMassesAreExact) {
  // Hand example: dx = 1, xi = (-0.5, 0.25, 0.75, 1.5) with L0 = 1: the solid lengths are
  // 0.25, 0.5, 0.25 (the clipped increments), fractions 1/3, 1, 1/3.
  const eu::Grid grid{0.0, 3.0, 3};
  const eu::Material material{2.0, 1.0, 1.0};
  const VecX xi = (VecX(4) << -0.5, 0.25, 0.75, 1.5).finished();
  const auto cells = eu::cell_fields(grid, material, xi);
  EXPECT_EQ(cells.solid_length(0), 0.25);
  EXPECT_EQ(cells.solid_length(1), 0.5);
  EXPECT_EQ(cells.solid_length(2), 0.25);
  EXPECT_TRUE(is_close(cells.fraction(0), 1.0 / 3.0, 0.0, kEpsilon));
  EXPECT_EQ(cells.fraction(1), 1.0);
  const VecX m = eu::lumped_masses(material, cells);
  EXPECT_EQ(m(0), 0.25);  // rho0 l_0 / 2
  EXPECT_EQ(m(1), 0.75);
  EXPECT_EQ(m.sum(), 2.0);

  // Random monotone maps: sum m = rho0 L0 to round-off (the clipped lengths telescope to
  // clip(xi_last) - clip(xi_0) = L0; n additions of O(1) terms: n eps).
  std::mt19937 rng(3);
  for (int trial = 0; trial < 50; ++trial) {
    const eu::Grid g{-1.0, 2.0, 37};
    const auto f = eu::cell_fields(g, material, random_monotone_map(rng, 38));
    EXPECT_TRUE(is_close(eu::lumped_masses(material, f).sum(), 2.0, 0.0, 38 * 2 * kEpsilon));
  }
}

TEST(EulerianDiscretisation, ForceIsMinusTheEnergyGradient) {
  // W(x) = sum_c l_c psi((x_{c+1} - x_c)/dxi_c) with l_c, dxi_c frozen; f_j = -dW/dx_j. W is
  // quadratic in x, so the central difference is exact up to round-off: error ~ eps W / h with
  // W = O(1) and h = 1e-4 -> ~1e-12; bound 1e-9 (x 1000).
  std::mt19937 rng(11);
  const eu::Grid grid{-1.0, 2.0, 24};
  const eu::Material material{1.3, 2.7, 1.0};
  const VecX xi = random_monotone_map(rng, 25);
  const auto cells = eu::cell_fields(grid, material, xi);
  const VecX f = eu::nodal_forces(cells);
  VecX x(25);
  for (std::size_t j = 0; j < 25; ++j) x(static_cast<Eigen::Index>(j)) = grid.node(j);
  auto energy = [&](const VecX& nodes) {
    double w = 0.0;
    for (Eigen::Index c = 0; c < 24; ++c) {
      const double F = (nodes(c + 1) - nodes(c)) / (xi(c + 1) - xi(c));
      w += cells.solid_length(c) * 0.5 * material.kappa * (F - 1.0) * (F - 1.0);
    }
    return w;
  };
  EXPECT_TRUE(is_close(energy(x), eu::elastic_energy(material, cells), 1e3 * kEpsilon, 0.0));
  const double h = 1e-4;
  for (Eigen::Index j = 0; j < 25; ++j) {
    VecX xp = x, xm = x;
    xp(j) += h;
    xm(j) -= h;
    EXPECT_TRUE(is_close(f(j), -(energy(xp) - energy(xm)) / (2 * h), 0.0, 1e-9, j));
  }
  // Momentum balance: the internal forces sum to zero (they telescope).
  EXPECT_LE(std::abs(f.sum()), 25 * kEpsilon * f.cwiseAbs().maxCoeff());
}

TEST(EulerianDiscretisation, UniformlyStretchedBarLoadsOnlyItsSurface) {
  // F = 1.25 uniform: interior nodes feel no force; the traction sigma = kappa (F - 1) appears
  // on the nodes of each edge cell and adds up to -sigma at the right end, +sigma at the left.
  const auto p = bar_problem(40, -1.0, 1.0, -0.61, 1.25, 0.0);
  const eu::Material material{1.0, 2.0, 1.0};
  const auto cells = eu::cell_fields(p.grid, material, p.xi0);
  const VecX f = eu::nodal_forces(cells);
  const double sigma = 2.0 * 0.25;
  double left = 0.0, right = 0.0;
  for (Eigen::Index j = 0; j < f.size(); ++j) (p.grid.node(static_cast<std::size_t>(j)) < 0.0 ? left : right) += f(j);
  // sigma_c = kappa (dx/dxi_c - 1) with dxi_c = 0.04 a difference of values |xi| <= 1.6: relative
  // error ~ 2 eps 1.6 / 0.04 in F, so |sigma error| <= 2 kappa F eps 1.6 / 0.04 ~ 200 eps; x 2 for
  // the sums of two edge-cell terms.
  const double tol = 2 * 2 * material.kappa * 1.25 * kEpsilon * 1.6 / 0.04;
  EXPECT_TRUE(is_close(right, -sigma, 0.0, tol));
  EXPECT_TRUE(is_close(left, sigma, 0.0, tol));
  for (Eigen::Index j = 1; j + 1 < f.size(); ++j) {
    if (cells.fraction(j - 1) == 1.0 && cells.fraction(j) == 1.0) {
      EXPECT_LE(std::abs(f(j)), tol) << j;
    }
  }
}

TEST(EulerianDiscretisation, UpwindIsExactOnLinearFieldsAndExtrapolationCopiesNearestSolid) {
  const eu::Grid grid{0.0, 1.0, 10};
  VecX a(11), u(11);
  for (Eigen::Index j = 0; j < 11; ++j) {
    a(j) = j % 3 == 0 ? -0.7 : 0.4;
    u(j) = 3.0 * grid.node(static_cast<std::size_t>(j)) - 1.0;
  }
  const VecX transport = eu::upwind_transport(grid, a, u);
  // Slope 3 recovered from differences of O(1) values over dx = 0.1: error ~ 2 eps / 0.1 x 3.
  for (Eigen::Index j = 0; j < 11; ++j) EXPECT_TRUE(is_close(transport(j), 3.0 * a(j), 0.0, 100 * kEpsilon, j));
  // Upwind picks the side the flow comes from: a jump at node 5 reaches node 6 only for a > 0.
  VecX step = VecX::Zero(11);
  step.tail(6).setOnes();  // nodes 5..10
  const VecX right = eu::upwind_transport(grid, VecX::Constant(11, 1.0), step);
  const VecX leftward = eu::upwind_transport(grid, VecX::Constant(11, -1.0), step);
  EXPECT_EQ(right(5), 10.0);
  EXPECT_EQ(right(4), 0.0);
  EXPECT_EQ(leftward(4), -10.0);
  EXPECT_EQ(leftward(5), 0.0);

  VecX m = VecX::Zero(8), v(8);
  m.segment(2, 3).setOnes();  // solid nodes 2, 3, 4
  v << 9, 9, 1, 2, 3, 9, 9, 9;
  eu::extrapolate_velocity(m, v);
  EXPECT_EQ(v, (VecX(8) << 1, 1, 1, 2, 3, 3, 3, 3).finished());
}

TEST(EulerianSimulation, RigidTranslationIsExactToRoundOff) {
  // xi = x - x0 - v0 t is linear, upwind differences of a linear field are exact, F = 1 gives no
  // force: xi and v are exact up to round-off accumulated over the steps. Bound: steps x 4 eps
  // x max|xi| (one rounding per operation in xi - dt v (dxi)/dx, |xi| <= 3).
  auto p = bar_problem(64, 0.0, 3.0, 0.4, 1.0, 0.7);
  eu::Settings s;
  s.t_end = 1.0;
  s.snapshot_times = {1.0};
  const auto r = eu::simulate(p, s);
  const auto& last = r.snapshots.back();
  const double tol = static_cast<double>(r.steps) * 4 * kEpsilon * 3.0;
  for (Eigen::Index j = 0; j < last.xi.size(); ++j) {
    const double exact = p.grid.node(static_cast<std::size_t>(j)) - 0.4 - 0.7 * 1.0;
    EXPECT_TRUE(is_close(last.xi(j), exact, 0.0, tol, j));
    EXPECT_TRUE(is_close(last.v(j), 0.7, 0.0, tol, j));
  }
  // Mass: sum of clipped lengths telescopes: 64 eps.
  for (double mass : r.history.mass) EXPECT_TRUE(is_close(mass, 1.0, 0.0, 64 * kEpsilon));
  EXPECT_EQ(r.snapshots.back().t, 1.0);
  EXPECT_EQ(r.history.t.back(), 1.0);

  // The check can fail: a velocity perturbed by 1e-9 at one solid node (x = 0.94) breaks
  // exactness well above tol.
  p.v0(20) += 1e-9;
  const auto perturbed = eu::simulate(p, s);
  double worst = 0.0;
  for (Eigen::Index j = 0; j < last.v.size(); ++j) worst = std::max(worst, std::abs(perturbed.snapshots.back().v(j) - 0.7));
  EXPECT_GT(worst, 10 * tol);
}

// A free fall under gravity g identifies the time step: v = v0 + g t exactly (the uniform velocity's transport
// vanishes), and symplectic Euler (velocity first, then xi advected with the new v) leaves the bar ahead by
// (g/2) sum dt_k^2, so xi = x - x_left is behind by as much at every solid node; an explicit-Euler position
// update would leave it ahead by as much.
TEST(EulerianSimulation, FreeFallErrorIsSymplecticEulersOwn) {
  auto p = bar_problem(80, -0.5, 2.5, 0.4, 1.0, -0.3);
  p.gravity = 0.7;
  eu::Settings s;
  s.t_end = 1.3;
  s.snapshot_times = {1.3};
  const auto r = eu::simulate(p, s);
  double dt_squares = 0.0;
  for (std::size_t k = 1; k < r.history.t.size(); ++k)
    dt_squares += std::pow(r.history.t[k] - r.history.t[k - 1], 2);
  const double t = 1.3, x_left = 0.4 - 0.3 * t + 0.5 * 0.7 * t * t;
  const double tol = static_cast<double>(r.steps) * 4 * kEpsilon * 3.0;  // as the translation's
  const auto& last = r.snapshots.back();
  for (Eigen::Index j = 0; j < last.xi.size(); ++j) {
    const double x = p.grid.node(static_cast<std::size_t>(j));
    if (x < x_left || x > x_left + 1.0) continue;
    const double error = last.xi(j) - (x - x_left);
    EXPECT_NEAR(error, -0.35 * dt_squares, tol) << j;
    EXPECT_GT(std::abs(error - 0.35 * dt_squares), 1e6 * tol) << j;  // the other Euler's sign is far off
    EXPECT_NEAR(last.v(j), -0.3 + 0.7 * t, tol) << j;
  }
}

TEST(EulerianSimulation, WorkBudgetBoundsTheStepsAndRefusesAnImpossibleRunAtOnce) {
  // least_cell_updates is a lower bound: dt <= cfl dx / c. For the rigid translation every step has
  // speed |v0| + c exactly (F = 1), so steps = ceil(t_end (|v0| + c) / (cfl dx)), at most
  // (|v0| + c)/c + 1 step above the bound per unit of it; with kappa = 4 (c = 2) and v0 = 0.7
  // the ratio is 1.35.
  auto p = bar_problem(64, 0.0, 3.0, 0.4, 1.0, 0.7);
  p.material.kappa = 4.0;
  eu::Settings s;
  s.t_end = 1.3;
  const double least = eu::least_cell_updates(p.grid, p.material, s);
  const auto r = eu::simulate(p, s);
  const double actual = static_cast<double>(r.steps) * static_cast<double>(p.grid.cells);
  EXPECT_GE(actual, least);
  EXPECT_NEAR(actual / least, (0.7 + 2.0) / 2.0, static_cast<double>(p.grid.cells) / least);

  // A run that cannot fit its budget fails before its first step, naming the budget (a level
  // failure, exit 1, not an hour-long run): t_end = 1e11 needs >= 1.6e15 cell updates here.
  s.t_end = 1e11;
  try {
    eu::simulate(p, s);
    ADD_FAILURE() << "no SolverError for a run above the work budget";
  } catch (const rodvv::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("work budget"), std::string::npos) << e.what();
    EXPECT_EQ(e.iterations(), 0u);
  }
  // At the budget's edge the bound decides: just above refused, just below runs.
  s.t_end = 1.3;
  s.max_cell_updates = 0.99 * least;
  EXPECT_THROW(eu::simulate(p, s), rodvv::SolverError);
  s.max_cell_updates = 1.01 * least;
  EXPECT_NO_THROW(eu::simulate(p, s));
}

TEST(EulerianSimulation, FreeFallKeepsAUniformVelocity) {
  // Gravity g on an unstressed bar: v = v0 + g t exactly up to round-off (the update adds dt g
  // each step, the advection of a uniform field is zero), momentum rho0 L0 (v0 + g t).
  auto p = bar_problem(50, -1.0, 4.0, 0.0, 1.0, 0.2);
  p.gravity = 0.5;
  eu::Settings s;
  s.t_end = 2.0;
  s.snapshot_times = {2.0};
  const auto r = eu::simulate(p, s);
  const double tol = static_cast<double>(r.steps) * 4 * kEpsilon * 1.2;
  for (Eigen::Index j = 0; j < r.snapshots.back().v.size(); ++j)
    EXPECT_TRUE(is_close(r.snapshots.back().v(j), 1.2, 0.0, tol, j));
  EXPECT_TRUE(is_close(r.history.momentum.back(), 1.2, 0.0, 50 * tol));
}

TEST(EulerianSimulation, CompressedBarBetweenTwoWallsStaysInEquilibrium) {
  // A bar compressed to F0 = 0.5 whose ends touch walls on both sides is in static equilibrium
  // (uniform stress -kappa/2); both wall constraints are active in every step (a two-row LCP).
  // With the ends on grid nodes the discrete state is static up to round-off; each wall carries
  // the force kappa (1 - F0) = 0.5 kappa.
  auto p = bar_problem(40, -1.0, 1.0, -0.25, 0.5, 0.0);
  p.material.kappa = 2.0;
  p.left_wall = -0.25;
  p.right_wall = 0.25;
  eu::Settings s;
  s.t_end = 0.5;
  s.snapshot_times = {0.5};
  const auto r = eu::simulate(p, s);
  EXPECT_EQ(r.contact_solves, r.steps);
  // Velocities arise from round-off in xi at the end nodes (|xi| ~ 1, dxi ~ 0.1): forces of
  // ~ kappa eps / 0.1 -> v ~ steps dt force / m; bound 1e-12 (measured ~1e-14, x 100).
  EXPECT_LE(r.snapshots.back().v.cwiseAbs().maxCoeff(), 1e-12);
  for (std::size_t i = 1; i < r.history.t.size(); ++i) {
    EXPECT_TRUE(is_close(r.history.left_wall_force[i], 1.0, 1e-10, 0.0)) << "step " << i;
    EXPECT_TRUE(is_close(r.history.right_wall_force[i], 1.0, 1e-10, 0.0)) << "step " << i;
    EXPECT_LE(r.history.penetration[i], 4 * kEpsilon);
  }
}

TEST(EulerianSimulation, BarrierStopsTheBarAndRemovingItLetsTheBarThrough) {
  // Impact at v0 = 0.1 on a wall: the edge never crosses it (penetration <= round-off of the
  // positions, 4 eps x max|x| with |x| <= 1.5); without the wall the edge passes it by v0 t.
  auto p = bar_problem(200, -1.0, 1.5, -0.9, 1.0, 0.1);
  p.right_wall = 0.2;
  eu::Settings s;
  s.t_end = 2.5;
  const auto r = eu::simulate(p, s);
  const double worst = *std::max_element(r.history.penetration.begin(), r.history.penetration.end());
  EXPECT_LE(worst, 4 * kEpsilon * 1.5);
  EXPECT_GT(*std::max_element(r.history.right_wall_force.begin(), r.history.right_wall_force.end()), 0.05);
  p.right_wall.reset();
  const auto free = eu::simulate(p, s);
  EXPECT_TRUE(is_close(free.history.x_right.back(), 0.1 + 0.1 * 2.5, 0.0, 1e-12));
}

TEST(EulerianSimulation, BadInputNamesTheParameter) {
  auto expect_input_error = [](const eu::Problem& p, const eu::Settings& s, const std::string& name) {
    try {
      eu::simulate(p, s);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  const auto good = bar_problem(20, -1.0, 2.0, 0.0, 1.0, 0.0);
  const eu::Settings s;
  auto p = good;
  p.grid.cells = 1;
  expect_input_error(p, s, "cells");
  p = good;
  p.grid.x_max = -2.0;
  expect_input_error(p, s, "x_max");
  p = good;
  p.material.kappa = 0.0;
  expect_input_error(p, s, "kappa");
  p = good;
  p.material.rho0 = -1.0;
  expect_input_error(p, s, "rho0");
  eu::Settings bad_cfl;
  bad_cfl.cfl = 0.0;
  expect_input_error(good, bad_cfl, "cfl");
  bad_cfl.cfl = 1.5;
  expect_input_error(good, bad_cfl, "cfl");
  p = good;
  p.xi0(7) = p.xi0(6);  // det F = 1/xi_x infinite: not a valid reference map
  expect_input_error(p, s, "xi0");
  p = good;
  p.xi0(7) = p.xi0(6) - 0.01;
  expect_input_error(p, s, "xi0");
  p = good;
  p.right_wall = 0.5;  // inside the initial solid [0, 1]
  expect_input_error(p, s, "right_wall");
  p = good;
  p.left_wall = 0.1;
  expect_input_error(p, s, "left_wall");
  p = good;
  p.v0.resize(3);
  expect_input_error(p, s, "v0");
}

}  // namespace

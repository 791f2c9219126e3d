// solvers/eulerian1d/solid_fraction: the solid fraction of a general monotone reference map
// (bisection for the ends xi = 0 and xi = L0, then clipping; issue 6, ALGORITHMS.md §6.2).
//   - a piecewise-linear map agrees with the exact clipping of cell_fields to round-off;
//   - curved maps (sine perturbation, quadratic) give the exact fraction and lengths to round-off;
//   - a shifted end or a subsampled fraction is caught by the same tolerances (the tests can fail);
//   - a non-monotone map is an InputError naming xi0.
//
// Tolerance of a cell fraction (derived, used by every comparison below). The end x* is where the
// floating-point map crosses X; bisection returns it to one ulp, ulp(x*) <= eps x_scale with
// x_scale = max(|x_min|, |x_max|). The map is evaluated near the crossing with an error of about
// eps xi_scale (xi_scale >= |xi| there), which moves the crossing by eps xi_scale / min xi_x. The
// fraction (min(x1, x_R) - max(x0, x_L)) / dx then divides by dx. So
//   |phi - phi_exact| <~ eps (x_scale + xi_scale / min xi_x) / dx,
// and we allow twice that plus 2 eps (the rounding of the node positions, the difference and the
// division). Measured: 0.05 to 0.08 of this tolerance (36 eps of phi for the piecewise-linear maps,
// 46 for the sine map, 33 for the quadratic one: about one ulp(x*) / dx).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/eulerian1d/discretisation.hpp"
#include "rodvv/solvers/eulerian1d/simulate.hpp"
#include "rodvv/solvers/eulerian1d/solid_fraction.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::VecX;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
namespace eu = rodvv::solvers::eulerian1d;

double fraction_tolerance(const eu::Grid& grid, double xi_scale, double min_slope) {
  const double x_scale = std::max(std::abs(grid.x_min), std::abs(grid.x_max));
  return 2.0 * kEpsilon * (x_scale + xi_scale / min_slope) / grid.dx() + 2.0 * kEpsilon;
}

// The largest |phi - expected| over the cells, in units of the tolerance (<= 1 passes).
double worst_ratio(const VecX& phi, const VecX& expected, double tolerance) {
  const double worst = (phi - expected).cwiseAbs().maxCoeff();
  ::testing::Test::RecordProperty("worst_difference_in_eps", std::to_string(worst / kEpsilon));
  ::testing::Test::RecordProperty("tolerance_in_eps", std::to_string(tolerance / kEpsilon));
  return worst / tolerance;
}

// The exact fraction of each cell occupied by the interval [a, b].
VecX interval_fraction(const eu::Grid& grid, double a, double b) {
  VecX phi(static_cast<Eigen::Index>(grid.cells));
  for (std::size_t c = 0; c < grid.cells; ++c) {
    const double lo = std::max(grid.node(c), a), hi = std::min(grid.node(c + 1), b);
    phi(static_cast<Eigen::Index>(c)) = hi > lo ? (hi - lo) / grid.dx() : 0.0;
  }
  return phi;
}

// The piecewise-linear interpolant of nodal values as a general map (returns xi_k at node k exactly).
eu::ReferenceMap piecewise_linear(const eu::Grid& grid, const VecX& xi) {
  return [grid, xi](double x) {
    const auto k = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::floor((x - grid.x_min) / grid.dx())),
                                            0, static_cast<Eigen::Index>(grid.cells) - 1);
    const double s = (x - grid.node(static_cast<std::size_t>(k))) / grid.dx();
    return xi(k) + s * (xi(k + 1) - xi(k));
  };
}

// xi(x) = s + A sin(2 pi s / L0), s = x - x0: ends exactly at x0 and x0 + L0, xi_x >= 1 - 2 pi A / L0.
struct SineMap {
  double x0, amplitude, L0;
  double operator()(double x) const {
    const double s = x - x0;
    return s + amplitude * std::sin(2.0 * std::numbers::pi * s / L0);
  }
  double min_slope() const { return 1.0 - 2.0 * std::numbers::pi * amplitude / L0; }
};

// xi(x) = L0 s (1 + s) / 2, s = (x - a) / (b - a): ends exactly at a and b, increasing for s > -1/2.
struct QuadraticMap {
  double a, b, L0;
  double operator()(double x) const {
    const double s = (x - a) / (b - a);
    return L0 * s * (1.0 + s) / 2.0;
  }
};

template <class F>
void expect_input_error(F&& call, const std::string& name) {
  try {
    call();
    ADD_FAILURE() << "no InputError for " << name;
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), name) << e.what();
  }
}

TEST(EulerianSolidFraction, PiecewiseLinearMapAgreesWithExactClipping) {
  // Random strictly increasing nodal maps across [-0.3, 1.3] (the solid [0, 1] inside), evaluated
  // through their linear interpolant: the general path must reproduce cell_fields' l_c / dxi_c.
  const eu::Grid grid{0.25, 2.25, 64};
  const eu::Material material{1.0, 1.0, 1.0};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0.2, 1.0);
  double worst = 0.0;
  for (int trial = 0; trial < 50; ++trial) {
    VecX xi(static_cast<Eigen::Index>(grid.nodes()));
    xi(0) = 0.0;
    for (Eigen::Index j = 1; j < xi.size(); ++j) xi(j) = xi(j - 1) + u(rng);
    xi = -0.3 + xi.array() * (1.6 / xi(xi.size() - 1));
    const auto cells = eu::cell_fields(grid, material, xi);
    const auto general = eu::solid_fraction(grid, material, piecewise_linear(grid, xi));
    // Increments dxi >= 0.2 * 1.6 / (64 * 1.0) = 0.005, so xi_x = dxi / dx >= 0.16; |xi| <= 1.3.
    const double tol = fraction_tolerance(grid, 1.3, 0.005 / grid.dx());
    worst = std::max(worst, worst_ratio(general.fraction, cells.fraction, tol));
    // Same nodal values, same clipping formula: the reference lengths are bitwise equal.
    EXPECT_EQ((general.solid_length - cells.solid_length).cwiseAbs().maxCoeff(), 0.0);
    // Ends against the linear interpolation of material_point_position: a few ulps of x (<= 2.25).
    EXPECT_TRUE(is_close(general.x_left, *eu::material_point_position(grid, xi, 0.0), 0.0, 8 * kEpsilon * 2.25));
    EXPECT_TRUE(is_close(general.x_right, *eu::material_point_position(grid, xi, 1.0), 0.0, 8 * kEpsilon * 2.25));
  }
  EXPECT_LE(worst, 1.0) << "worst fraction difference in units of the tolerance";
  RecordProperty("worst_over_tolerance", std::to_string(worst));
}

TEST(EulerianSolidFraction, SineMapGivesTheExactFractionAndLengths) {
  const eu::Grid grid{-0.5, 1.7, 110};
  const eu::Material material{2.0, 1.0, 1.0};
  const SineMap map{0.3137, 0.1, 1.0};  // ends inside cells 40 and 90; xi_x in [1 - 0.628, 1 + 0.628]: monotone
  const auto r = eu::solid_fraction(grid, material, map);
  RecordProperty("evaluations", std::to_string(r.evaluations));
  // The ends x0 and x0 + L0 (sin(2 pi) = -2.4e-16 moves the right one by ~eps / xi_x).
  EXPECT_TRUE(is_close(r.x_left, 0.3137, 0.0, 4 * kEpsilon * 1.7));
  EXPECT_TRUE(is_close(r.x_right, 0.3137 + 1.0, 0.0, 4 * kEpsilon * 1.7 / map.min_slope()));
  const double tol = fraction_tolerance(grid, 1.7, map.min_slope());
  const VecX exact = interval_fraction(grid, 0.3137, 1.3137);
  EXPECT_LE(worst_ratio(r.fraction, exact, tol), 1.0);
  RecordProperty("worst_over_tolerance", std::to_string(worst_ratio(r.fraction, exact, tol)));
  // Total occupied length sum phi dx = x_R - x_L = 1: only the two edge cells carry an error (<= tol
  // each), plus 110 additions of O(1) terms (110 eps).
  EXPECT_TRUE(is_close(r.fraction.sum() * grid.dx(), 1.0, 0.0, 110 * kEpsilon + 2 * tol * grid.dx()));
  // Mass: sum rho0 l_c = rho0 L0 (telescoping clipped values; 110 additions).
  EXPECT_TRUE(is_close(material.rho0 * r.solid_length.sum(), 2.0, 0.0, 2.0 * 110 * kEpsilon));
  // Cell lengths against the independent formula xi(min(x1, x_R)) - xi(max(x0, x_L)) with the
  // analytic end values 0 and L0: differences of O(1) values, 4 eps.
  for (std::size_t c = 0; c < grid.cells; ++c) {
    const double x0 = grid.node(c), x1 = grid.node(c + 1);
    double expected = 0.0;
    const double a = 0.3137, b = 0.3137 + 1.0;
    if (x1 > a && x0 < b) expected = (x1 >= b ? 1.0 : map(x1)) - (x0 <= a ? 0.0 : map(x0));
    EXPECT_TRUE(is_close(r.solid_length(static_cast<Eigen::Index>(c)), expected, 0.0, 4 * kEpsilon,
                         static_cast<std::ptrdiff_t>(c)));
  }
}

TEST(EulerianSolidFraction, QuadraticMapGivesTheExactFraction) {
  // Ends a = 0.2 and b = 1.1 (not on nodes: dx = 1.7 / 70). xi_x = L0 (1 + 2 s) / (2 (b - a)) >=
  // (1 - 0.889) / 1.8 = 0.062 at x_min (s = -0.444); near the ends xi_x >= 1 / 1.8.
  const eu::Grid grid{-0.2, 1.5, 70};
  const eu::Material material{1.0, 1.0, 1.0};
  const QuadraticMap map{0.2, 1.1, 1.0};
  const auto r = eu::solid_fraction(grid, material, map);
  const double tol = fraction_tolerance(grid, 2.0, 1.0 / 1.8);
  EXPECT_LE(worst_ratio(r.fraction, interval_fraction(grid, 0.2, 1.1), tol), 1.0);
  RecordProperty("worst_over_tolerance",
                 std::to_string(worst_ratio(r.fraction, interval_fraction(grid, 0.2, 1.1), tol)));
  EXPECT_TRUE(is_close(r.fraction.sum() * grid.dx(), 0.9, 0.0, 70 * kEpsilon + 2 * tol * grid.dx()));
  EXPECT_TRUE(is_close(r.solid_length.sum(), 1.0, 0.0, 70 * kEpsilon));
  // The nodal clipping of the same map is wrong by O(dx) in the two edge cells (the map is curved):
  // the general path is needed. Its error is at least ~ xi_xx dx^2 / xi_x ~ 1e-4 here.
  const VecX nodal = eu::sample_reference_map(grid, map);
  const auto clipped = eu::cell_fields(grid, material, nodal);
  EXPECT_GT(worst_ratio(clipped.fraction, interval_fraction(grid, 0.2, 1.1), tol), 1e6);
}

TEST(EulerianSolidFraction, PerturbedEndOrSubsamplingIsCaught) {
  // The same comparisons go red for an end moved by 1e-12 (shifted map) and for the fraction of
  // Levin et al.'s subsampling with 64 midpoint samples per cell (error up to 1 / 128).
  const eu::Grid grid{-0.5, 1.7, 110};
  const eu::Material material{1.0, 1.0, 1.0};
  const SineMap map{0.3137, 0.1, 1.0};
  const double tol = fraction_tolerance(grid, 1.7, map.min_slope());
  const VecX exact = interval_fraction(grid, 0.3137, 1.3137);
  EXPECT_LE(worst_ratio(eu::solid_fraction(grid, material, map).fraction, exact, tol), 1.0);
  const SineMap shifted{0.3137 + 1e-12, 0.1, 1.0};
  EXPECT_GT(worst_ratio(eu::solid_fraction(grid, material, shifted).fraction, exact, tol), 1.0);

  constexpr int samples = 64;
  VecX subsampled(static_cast<Eigen::Index>(grid.cells));
  for (std::size_t c = 0; c < grid.cells; ++c) {
    int inside = 0;
    for (int i = 0; i < samples; ++i) {
      const double xi = map(grid.node(c) + grid.dx() * (i + 0.5) / samples);
      inside += (xi >= 0.0 && xi <= 1.0) ? 1 : 0;
    }
    subsampled(static_cast<Eigen::Index>(c)) = static_cast<double>(inside) / samples;
  }
  EXPECT_GT(worst_ratio(subsampled, exact, tol), 1.0);
}

TEST(EulerianSolidFraction, BisectionReachesAdjacentDoubles) {
  // x^3 = 2: the root is cbrt(2) to within the last bit (cbrt itself is correctly rounded to 1 ulp).
  std::size_t evaluations = 0;
  const auto cube = [](double x) { return x * x * x; };
  const double root = eu::locate_material_point(cube, 2.0, 1.0, 2.0, &evaluations);
  EXPECT_TRUE(is_close(root, std::cbrt(2.0), 0.0, 2.0 * std::nextafter(std::cbrt(2.0), 2.0) - 2.0 * std::cbrt(2.0)));
  EXPECT_LE(evaluations, 60u);  // 52 halvings of [1, 2] plus the two ends
  // The exact root on an end returns it without bisection.
  EXPECT_EQ(eu::locate_material_point(cube, 8.0, 0.0, 2.0), 2.0);
  expect_input_error([&] { eu::locate_material_point(cube, 9.0, 0.0, 2.0); }, "X");
}

TEST(EulerianSolidFraction, NonMonotoneOrBadMapIsAnInputError) {
  const eu::Grid grid{-0.5, 1.7, 110};
  const eu::Material material{1.0, 1.0, 1.0};
  // 2 pi A / L0 = 1.9 > 1: xi_x < 0 on part of the bar (det F <= 0).
  expect_input_error([&] { eu::solid_fraction(grid, material, SineMap{0.3137, 0.3, 1.0}); }, "xi0");
  // A fold inside each cell that the nodes do not see: x + A sin(2 pi x / dx) with dx = 1/64 is
  // x at every node, but xi_x = 1 + 2 pi A / dx cos(.) < 0 for A = dx / 4. The interior samples
  // catch it; the nodes alone (samples_per_cell = 1) do not (the documented limit).
  const eu::Grid fine{0.0, 2.0, 128};
  const double dx = fine.dx();
  const auto folded = [dx](double x) { return x - 0.5 + dx / 4 * std::sin(2.0 * std::numbers::pi * x / dx); };
  expect_input_error([&] { eu::solid_fraction(fine, material, folded); }, "xi0");
  EXPECT_NO_THROW(eu::solid_fraction(fine, material, folded, eu::MapSampling{1}));
  expect_input_error([&] { eu::sample_reference_map(fine, folded); }, "xi0");
  // Not finite, empty, solid outside the grid, no samples.
  expect_input_error([&] { eu::solid_fraction(grid, material, [](double x) { return x > 1.0 ? NAN : x; }); }, "xi0");
  expect_input_error([&] { eu::solid_fraction(grid, material, eu::ReferenceMap{}); }, "xi0");
  expect_input_error([&] { eu::solid_fraction(grid, material, [](double x) { return x + 0.6; }); }, "xi0");
  expect_input_error([&] { eu::solid_fraction(grid, material, [](double x) { return x; }, eu::MapSampling{0}); },
                     "samples_per_cell");
  // A constant map is not strictly increasing (det F infinite).
  expect_input_error([&] { eu::sample_reference_map(grid, [](double) { return 0.5; }); }, "xi0");
}

TEST(EulerianSolidFraction, SampledCurvedMapStartsASimulationWithExactMass) {
  // The general map as an initial condition: xi0 = the sine map on the nodes, at rest, free ends.
  // The mass is rho0 L0 at every step (the clipped lengths telescope: 100 additions, 100 eps) and
  // the initial ends agree with the bisected ones to the O(dx^2) interpolation error of a curved
  // map (|xi_xx| <= 4 pi^2 A / L0 = 3.95, dx = 0.022, xi_x >= 0.372: xi_xx dx^2 / (8 xi_x) <= 6.5e-4).
  eu::Problem p;
  p.grid = {-0.5, 1.7, 100};
  const SineMap map{0.3137, 0.1, 1.0};
  p.xi0 = eu::sample_reference_map(p.grid, map);
  p.v0 = VecX::Zero(static_cast<Eigen::Index>(p.grid.nodes()));
  eu::Settings s;
  s.t_end = 0.2;
  const auto result = eu::simulate(p, s);
  for (double m : result.history.mass) EXPECT_TRUE(is_close(m, 1.0, 0.0, 100 * kEpsilon));
  const auto exact = eu::solid_fraction(p.grid, p.material, map);
  EXPECT_TRUE(is_close(result.history.x_left.front(), exact.x_left, 0.0, 6.5e-4));
  EXPECT_TRUE(is_close(result.history.x_right.front(), exact.x_right, 0.0, 6.5e-4));
}

}  // namespace

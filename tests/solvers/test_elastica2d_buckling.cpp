// Tests of the Euler critical loads from the linearised stiffness eigenproblem of the discrete
// Lagrangian (solvers/include/rodvv/solvers/elastica2d/buckling.hpp), both discretisations:
//  - the pinned-pinned spectrum equals the closed-form discrete spectrum to round-off (polygon:
//    lumped geometric stiffness, finite differences; arcs: linear elements, consistent matrix);
//  - the first two loads of the four supports converge to Euler's at second order, inside C h^2
//    bounds, arcs from above (a conforming Ritz method), polygon from below;
//  - trigonometric mode shapes (pinned-pinned cos(k pi s / L), ...) are sampled exactly, the
//    clamped-pinned one converges at second order;
//  - P scales as EI / L^2; the size of the reduced problem counts the free perturbations;
//  - perturbed references and wrong orders turn the checks red; bad input names the parameter.
// Reference loads: PHYSICS.md §3.4 and, for the second modes, x1 = 4.49340945790906417530788 and
// x2 = 7.72525183693770716419507, the first two positive roots of tan x = x (mpmath findroot at 30
// digits on sin x - x cos x): clamped-clamped antisymmetric mode (2 x1)^2, clamped-pinned x2^2.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/elastica2d/buckling.hpp"
#include "rodvv/testing/elastica2d_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace e2 = rodvv::solvers::elastica2d;
using e2::EndSupports;
using e2::Scheme;
using rodvv::testing::input_error_parameter_of;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
using rodvv::testing::observed_order;
using rodvv::testing::elastica2d::name_of;

constexpr double kPi = std::numbers::pi;
constexpr double kX1 = 4.49340945790906417530788;  // first positive root of tan x = x
constexpr double kX2 = 7.72525183693770716419507;  // second

// Euler coefficients c_k (P_k = c_k EI / L^2) of the first two modes.
struct Coefficients {
  double first, second;
};
Coefficients euler_coefficients(EndSupports supports) {
  switch (supports) {
    case EndSupports::PinnedPinned:
      return {kPi * kPi, 4.0 * kPi * kPi};  // (k pi)^2
    case EndSupports::ClampedFree:
      return {kPi * kPi / 4.0, 9.0 * kPi * kPi / 4.0};  // ((2k - 1) pi / 2)^2
    case EndSupports::ClampedClamped:
      return {4.0 * kPi * kPi, 4.0 * kX1 * kX1};  // symmetric (2 pi)^2, antisymmetric tan(x/2) = x/2
    case EndSupports::ClampedPinned:
      return {kX1 * kX1, kX2 * kX2};  // tan x = x
  }
  return {0.0, 0.0};
}

const EndSupports kAllSupports[] = {EndSupports::PinnedPinned, EndSupports::ClampedFree,
                                    EndSupports::ClampedClamped, EndSupports::ClampedPinned};

e2::BucklingResult loads(EndSupports supports, Scheme scheme, std::size_t n, std::size_t modes,
                         double length = 1.0, double stiffness = 1.0) {
  return e2::critical_loads({supports, length, stiffness}, {scheme, n}, modes);
}

// Relative error constants C = (P_h - P) / P * N^2 measured at N = 128 (probe run, 2026-11-21) for
// modes 1 and 2; bounds below are 2 |C| h^2. Pinned-pinned has them in closed form: -/+ (k pi)^2 / 12
// (from the discrete spectra of the next test): -0.8225 and -3.2899 (polygon).
struct MeasuredConstant {
  Scheme scheme;
  EndSupports supports;
  double first, second;
};
constexpr MeasuredConstant kConstants[] = {
    {Scheme::Polygon, EndSupports::PinnedPinned, -0.8225, -3.2896},
    {Scheme::Polygon, EndSupports::ClampedFree, -0.2056, -1.8505},
    {Scheme::Polygon, EndSupports::ClampedClamped, -3.2896, -8.0620},
    {Scheme::Polygon, EndSupports::ClampedPinned, -2.0158, -5.3060},
    {Scheme::Arcs, EndSupports::PinnedPinned, 0.8225, 3.2901},
    {Scheme::Arcs, EndSupports::ClampedFree, 0.2056, 1.8506},
    {Scheme::Arcs, EndSupports::ClampedClamped, 3.2901, 7.3987},
    {Scheme::Arcs, EndSupports::ClampedPinned, 1.8493, 5.1407},
};
MeasuredConstant constant_of(Scheme scheme, EndSupports supports) {
  for (const auto& c : kConstants)
    if (c.scheme == scheme && c.supports == supports) return c;
  return {};
}

std::string name_of(EndSupports supports) {
  switch (supports) {
    case EndSupports::PinnedPinned:
      return "PinnedPinned";
    case EndSupports::ClampedFree:
      return "ClampedFree";
    case EndSupports::ClampedClamped:
      return "ClampedClamped";
    case EndSupports::ClampedPinned:
      return "ClampedPinned";
  }
  return "Unknown";
}

// Max |c theta_h(s_j) - exact(s_j)| with c the least-squares scale (sign included): the shape error
// independent of normalisation.
template <class Exact>
double shape_error(const e2::BucklingMode& mode, Exact&& exact) {
  double num = 0.0, den = 0.0;
  for (std::size_t j = 0; j < mode.s.size(); ++j) {
    num += mode.theta[j] * exact(mode.s[j]);
    den += mode.theta[j] * mode.theta[j];
  }
  const double c = num / den;
  double error = 0.0;
  for (std::size_t j = 0; j < mode.s.size(); ++j)
    error = std::max(error, std::abs(c * mode.theta[j] - exact(mode.s[j])));
  return error;
}

// ------------------------------------------------------------------------------------------------
// Discrete spectra in closed form (pinned-pinned, both schemes)

// The polygon's pencil is (EI/h) D^T D - P h I on cell-centred edge angles with natural (moment-free)
// ends and the constraint sum phi = 0: the discrete Neumann Laplacian, eigenvectors
// cos(k pi (j + 1/2) / N), P_k = 4 EI / h^2 sin^2(k pi / (2N)). The arcs' pencil is the linear
// element stiffness against the consistent matrix h/6 [2 1; 1 2] with the constraint
// "trapezoid sum of theta = 0" (= B 1, so the constant mode is removed):
// P_k = 6 EI / h^2 (1 - cos(k pi / N)) / (2 + cos(k pi / N)).
// Round-off: the reduced pencil is formed and reduced by backward-stable dense operations, so each
// eigenvalue is off by <= c n eps ||L^-1 A L^-T|| with ||.|| = the largest load (<= 12 EI / h^2);
// tolerance 4 N eps P_max.
TEST(Elastica2dBucklingSpectrum, PinnedPinnedMatchesTheDiscreteSpectrumToRoundOff) {
  for (Scheme scheme : {Scheme::Polygon, Scheme::Arcs})
    for (std::size_t n : {8u, 33u, 100u}) {
      const double stiffness = 2.5, length = 1.7;
      const double h = length / static_cast<double>(n);
      const auto result = loads(EndSupports::PinnedPinned, scheme, n, 4, length, stiffness);
      const double p_max = 12.0 * stiffness / (h * h);
      for (std::size_t k = 1; k <= 4; ++k) {
        const double angle = static_cast<double>(k) * kPi / static_cast<double>(n);
        const double expected = scheme == Scheme::Polygon
                                    ? 4.0 * stiffness / (h * h) * std::pow(std::sin(0.5 * angle), 2)
                                    : 6.0 * stiffness / (h * h) * (1.0 - std::cos(angle)) / (2.0 + std::cos(angle));
        EXPECT_TRUE(is_close(result.modes[k - 1].load, expected, 0.0, 4.0 * n * kEpsilon * p_max))
            << name_of(scheme) << " N = " << n << " mode " << k;
      }
    }
}

// The same closed form with a wrong constant (the arcs' 6 replaced by the polygon's 4, i.e. the
// lumped instead of the consistent geometric stiffness) is far outside the round-off tolerance.
TEST(Elastica2dBucklingSpectrum, WrongDiscreteSpectrumIsRejected) {
  const std::size_t n = 33;
  const double h = 1.0 / n;
  const auto arcs = loads(EndSupports::PinnedPinned, Scheme::Arcs, n, 1);
  const double lumped = 4.0 / (h * h) * std::pow(std::sin(0.5 * kPi / n), 2);
  EXPECT_FALSE(is_close(arcs.modes[0].load, lumped, 0.0, 4.0 * n * kEpsilon * 12.0 / (h * h)));
}

// ------------------------------------------------------------------------------------------------
// Convergence to Euler's loads, every support, both schemes

class Elastica2dBuckling : public ::testing::TestWithParam<std::tuple<Scheme, EndSupports>> {};

const std::vector<std::size_t> kLevels{16, 32, 64, 128};

TEST_P(Elastica2dBuckling, FirstTwoLoadsConvergeAtSecondOrder) {
  const auto [scheme, supports] = GetParam();
  const Coefficients exact = euler_coefficients(supports);
  const MeasuredConstant measured = constant_of(scheme, supports);
  std::vector<double> first, second;
  for (std::size_t n : kLevels) {
    const auto result = loads(supports, scheme, n, 2);
    first.push_back((result.modes[0].load - exact.first) / exact.first);
    second.push_back((result.modes[1].load - exact.second) / exact.second);
    const double h2 = 1.0 / static_cast<double>(n * n);
    // Bound: measured constant x 2, times h^2 (the constants change by < 1 % over N = 16 .. 512).
    EXPECT_LE(std::abs(first.back()), 2.0 * std::abs(measured.first) * h2) << "N = " << n;
    EXPECT_LE(std::abs(second.back()), 2.0 * std::abs(measured.second) * h2) << "N = " << n;
    // Arcs: conforming Ritz (piecewise-linear theta, exact energies and constraints for it), so by
    // min-max every load is an upper bound. Polygon: below (lumped geometric stiffness; observed for
    // every support and N, exact for pinned-pinned by the spectrum above).
    if (scheme == Scheme::Arcs) {
      EXPECT_GT(first.back(), 0.0);
      EXPECT_GT(second.back(), 0.0);
    } else {
      EXPECT_LT(first.back(), 0.0);
      EXPECT_LT(second.back(), 0.0);
    }
  }
  const double p1 = observed_order(kLevels, first), p2 = observed_order(kLevels, second);
  std::printf("[ order    ] %-8s %-15s mode 1: %.3e .. %.3e p = %.3f; mode 2: %.3e .. %.3e p = %.3f\n",
              name_of(scheme).c_str(), name_of(supports).c_str(), first.front(), first.back(), p1,
              second.front(), second.back(), p2);
  // Two-sided window around the theoretical order 2 (ARCHITECTURE.md convention 7).
  EXPECT_GE(p1, 1.9);
  EXPECT_LE(p1, 2.5);
  EXPECT_GE(p2, 1.9);
  EXPECT_LE(p2, 2.5);
}

// The coefficient of a different support (or a perturbed one) is not what the discrete loads
// converge to: at N = 128 the error against it is far outside the C h^2 bound.
TEST_P(Elastica2dBuckling, PerturbedReferenceFails) {
  const auto [scheme, supports] = GetParam();
  const MeasuredConstant measured = constant_of(scheme, supports);
  const std::size_t n = 128;
  const double bound = 2.0 * std::abs(measured.first) / static_cast<double>(n * n);
  const double load = loads(supports, scheme, n, 1).modes[0].load;
  const double perturbed = euler_coefficients(supports).first * (1.0 + 1e-3);
  EXPECT_GT(std::abs(load - perturbed) / perturbed, bound);
}

// P scales exactly as EI / L^2: the pencil is (EI / h) K_b(1) - P h K_g(1), so the loads at
// (L, EI) are EI / L^2 times those at (1, 1) up to round-off in the eigen solve (4 N eps).
TEST_P(Elastica2dBuckling, LoadsScaleAsStiffnessOverLengthSquared) {
  const auto [scheme, supports] = GetParam();
  const std::size_t n = 40;
  const auto unit = loads(supports, scheme, n, 3);
  const auto scaled = loads(supports, scheme, n, 3, 2.5, 7.0);
  for (std::size_t k = 0; k < 3; ++k)
    EXPECT_TRUE(is_close(scaled.modes[k].load, unit.modes[k].load * 7.0 / 6.25,
                         4.0 * n * kEpsilon * 12.0 * n * n / unit.modes[k].load, 0.0))
        << "mode " << k + 1;
}

// At the ends of the ranges the cases offer (L in [1e-6, 1e6], EI up to 1e12) the loads are still
// EI / L^2 times the unit column's (the pencil is solved for the unit column and scaled; solved at
// the user's scales, the geometric stiffness lost eps EI / h^2 to cancellation: at EI = 1e12 it was
// not positive definite, at L = 1e-6 the loads were off by 30 %), and the modes' stations scale by L.
TEST_P(Elastica2dBuckling, LoadsAtExtremeScalesAreTheUnitColumnsScaled) {
  const auto [scheme, supports] = GetParam();
  const std::size_t n = 64;
  const auto unit = loads(supports, scheme, n, 2);
  for (const auto [L, EI] : {std::pair{1e-6, 1e12}, std::pair{1e6, 1e-6}, std::pair{1.0, 1e12}, std::pair{1e-6, 1.0}}) {
    const auto scaled = loads(supports, scheme, n, 2, L, EI);
    for (std::size_t k = 0; k < 2; ++k) {
      EXPECT_TRUE(is_close(scaled.modes[k].load, unit.modes[k].load * EI / (L * L), 4.0 * kEpsilon, 0.0))
          << "L = " << L << ", EI = " << EI << ", mode " << k + 1;
      EXPECT_TRUE(is_close(scaled.modes[k].s.back(), unit.modes[k].s.back() * L, 4.0 * kEpsilon, 0.0));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllSupports, Elastica2dBuckling,
    ::testing::Combine(::testing::Values(Scheme::Polygon, Scheme::Arcs), ::testing::ValuesIn(kAllSupports)),
    [](const ::testing::TestParamInfo<std::tuple<Scheme, EndSupports>>& param_info) {
      return name_of(std::get<0>(param_info.param)) + name_of(std::get<1>(param_info.param));
    });

// ------------------------------------------------------------------------------------------------
// Mode shapes

class Elastica2dBucklingModes : public ::testing::TestWithParam<Scheme> {};

// Where the exact mode is a trigonometric function -- pinned-pinned theta ~ cos(k pi s / L),
// clamped-free sin((2k - 1) pi s / (2L)), clamped-clamped (first) sin(2 pi s / L) -- the discrete
// eigenvectors are that function sampled at the stations (polygon: edge midpoints, arcs: nodes): both
// pencils are translation-invariant difference operators with ends that reflect the sampled
// trigonometric functions. The shape error is then round-off: eigenvector perturbation
// <= ||E|| / gap with ||E|| ~ c N eps P_max (P_max <= 12 EI / h^2) and gap >= 2 pi^2 EI / L^2 (the
// closest neighbouring load); tolerance 4 N eps P_max / gap.
TEST_P(Elastica2dBucklingModes, TrigonometricModesAreSampledExactly) {
  const Scheme scheme = GetParam();
  struct Trig {
    EndSupports supports;
    std::size_t mode;
    double (*shape)(double);
  };
  const Trig cases[] = {
      {EndSupports::PinnedPinned, 1, [](double s) { return std::cos(kPi * s); }},
      {EndSupports::PinnedPinned, 2, [](double s) { return std::cos(2.0 * kPi * s); }},
      {EndSupports::ClampedFree, 1, [](double s) { return std::sin(0.5 * kPi * s); }},
      {EndSupports::ClampedFree, 2, [](double s) { return std::sin(1.5 * kPi * s); }},
      {EndSupports::ClampedClamped, 1, [](double s) { return std::sin(2.0 * kPi * s); }},
  };
  for (const Trig& trig : cases)
    for (std::size_t n : kLevels) {
      const auto result = loads(trig.supports, scheme, n, 2);
      const auto& mode = result.modes[trig.mode - 1];
      ASSERT_EQ(mode.s.size(), scheme == Scheme::Polygon ? n : n + 1);
      const double tolerance = 4.0 * n * kEpsilon * 12.0 * n * n / (2.0 * kPi * kPi);
      EXPECT_LE(shape_error(mode, trig.shape), tolerance)
          << name_of(trig.supports) << " mode " << trig.mode << " N = " << n;
      // Normalisation: max |theta| = 1 and positive at the first station where |theta| >= 1/2.
      double largest = 0.0;
      for (double t : mode.theta) largest = std::max(largest, std::abs(t));
      EXPECT_TRUE(is_close(largest, 1.0, 4 * kEpsilon, 0.0));
      const auto first = std::find_if(mode.theta.begin(), mode.theta.end(),
                                      [](double t) { return std::abs(t) >= 0.5; });
      ASSERT_NE(first, mode.theta.end());
      EXPECT_GT(*first, 0.0);
    }
}

// Clamped-pinned (L = 1, x = x1): y = c1 + c2 s + c3 cos(x s) + c4 sin(x s) with y(0) = y'(0) =
// y(1) = y''(1) = 0 gives tan x = x and y ~ x (1 - s) - x cos(x s) + sin(x s), so
// theta = y' ~ x sin(x s) + cos(x s) - 1. Not a sampled trigonometric function: the shape error converges as h^2. Bound 2 x the
// constant measured at N = 128 (polygon 0.444, arcs 0.436; probe run 2026-11-21).
TEST_P(Elastica2dBucklingModes, ClampedPinnedShapeConvergesAtSecondOrder) {
  const Scheme scheme = GetParam();
  const double constant = scheme == Scheme::Polygon ? 0.444 : 0.436;
  // Max of the exact shape on [0, 1] (for the error in units of it), sampled finely: O(1e-8) accurate.
  auto raw = [](double s) { return kX1 * std::sin(kX1 * s) + std::cos(kX1 * s) - 1.0; };
  double peak = 0.0;
  for (int i = 0; i <= 100000; ++i) peak = std::max(peak, std::abs(raw(i * 1e-5)));
  std::vector<double> errors;
  for (std::size_t n : kLevels) {
    const auto result = loads(EndSupports::ClampedPinned, scheme, n, 1);
    errors.push_back(shape_error(result.modes[0], [&](double s) { return raw(s) / peak; }));
    EXPECT_LE(errors.back(), 2.0 * constant / static_cast<double>(n * n)) << "N = " << n;
  }
  const double p = observed_order(kLevels, errors);
  std::printf("[ order    ] %-8s clamped-pinned mode 1 shape: %.3e .. %.3e p = %.3f\n", name_of(scheme).c_str(),
              errors.front(), errors.back(), p);
  EXPECT_GE(p, 1.9);
  EXPECT_LE(p, 2.5);
}

// The cosine of the wrong mode number is not the shape.
TEST_P(Elastica2dBucklingModes, WrongShapeIsRejected) {
  const auto result = loads(EndSupports::PinnedPinned, GetParam(), 64, 1);
  EXPECT_GT(shape_error(result.modes[0], [](double s) { return std::cos(2.0 * kPi * s); }), 0.5);
}

INSTANTIATE_TEST_SUITE_P(AllSchemes, Elastica2dBucklingModes, ::testing::Values(Scheme::Polygon, Scheme::Arcs),
                         [](const ::testing::TestParamInfo<Scheme>& param_info) { return name_of(param_info.param); });

// ------------------------------------------------------------------------------------------------
// Sizes and input validation

// Free perturbations: angles (N polygon, N + 1 arcs) + (dx0, dy0) minus the independent support
// rows (the two prescribed x are one row about the straight state: dx is uniform).
TEST(Elastica2dBucklingSize, ReducedSizeCountsTheFreePerturbations) {
  const std::size_t n = 10;
  EXPECT_EQ(loads(EndSupports::PinnedPinned, Scheme::Polygon, n, 1).reduced_size, n - 1);
  EXPECT_EQ(loads(EndSupports::ClampedFree, Scheme::Polygon, n, 1).reduced_size, n);
  EXPECT_EQ(loads(EndSupports::ClampedClamped, Scheme::Polygon, n, 1).reduced_size, n - 1);
  EXPECT_EQ(loads(EndSupports::ClampedPinned, Scheme::Polygon, n, 1).reduced_size, n - 1);
  EXPECT_EQ(loads(EndSupports::PinnedPinned, Scheme::Arcs, n, 1).reduced_size, n);
  EXPECT_EQ(loads(EndSupports::ClampedFree, Scheme::Arcs, n, 1).reduced_size, n);
  EXPECT_EQ(loads(EndSupports::ClampedClamped, Scheme::Arcs, n, 1).reduced_size, n - 2);
  EXPECT_EQ(loads(EndSupports::ClampedPinned, Scheme::Arcs, n, 1).reduced_size, n - 1);
  // All of them may be asked for; loads ascend.
  const auto all = loads(EndSupports::ClampedClamped, Scheme::Arcs, n, n - 2);
  ASSERT_EQ(all.modes.size(), n - 2);
  for (std::size_t k = 1; k < all.modes.size(); ++k) EXPECT_GT(all.modes[k].load, all.modes[k - 1].load);
}

TEST(Elastica2dBucklingInput, BadInputNamesTheParameter) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  auto call = [](double length, double stiffness, std::size_t n, std::size_t modes) {
    return [=] { e2::critical_loads({EndSupports::PinnedPinned, length, stiffness}, {Scheme::Arcs, n}, modes); };
  };
  EXPECT_EQ(input_error_parameter_of(call(1.0, 1.0, 1, 1)), "elements");
  EXPECT_EQ(input_error_parameter_of(call(1.0, 1.0, 0, 1)), "elements");
  EXPECT_EQ(input_error_parameter_of(call(0.0, 1.0, 8, 1)), "length");
  EXPECT_EQ(input_error_parameter_of(call(-1.0, 1.0, 8, 1)), "length");
  EXPECT_EQ(input_error_parameter_of(call(nan, 1.0, 8, 1)), "length");
  EXPECT_EQ(input_error_parameter_of(call(inf, 1.0, 8, 1)), "length");
  EXPECT_EQ(input_error_parameter_of(call(1.0, 0.0, 8, 1)), "bending_stiffness");
  EXPECT_EQ(input_error_parameter_of(call(1.0, -2.0, 8, 1)), "bending_stiffness");
  EXPECT_EQ(input_error_parameter_of(call(1.0, nan, 8, 1)), "bending_stiffness");
  EXPECT_EQ(input_error_parameter_of(call(1.0, inf, 8, 1)), "bending_stiffness");
  EXPECT_EQ(input_error_parameter_of(call(1.0, 1.0, 8, 0)), "modes");
  EXPECT_EQ(input_error_parameter_of(call(1.0, 1.0, 8, 9)), "modes");  // reduced size is 8
  EXPECT_EQ(input_error_parameter_of(call(1.0, 1.0, 8, 8)), "<no InputError>");
  // Arcs clamped-clamped with N = 2 has no free perturbation at all.
  EXPECT_EQ(input_error_parameter_of([] {
              e2::critical_loads({EndSupports::ClampedClamped, 1.0, 1.0}, {Scheme::Arcs, 2}, 1);
            }),
            "modes");
  EXPECT_EQ(input_error_parameter_of([] {
              e2::critical_loads({static_cast<EndSupports>(7), 1.0, 1.0}, {Scheme::Arcs, 8}, 1);
            }),
            "supports");
  EXPECT_EQ(input_error_parameter_of([] { e2::end_supports_from_id("pinned-free"); }), "supports");
  for (EndSupports s : kAllSupports) EXPECT_EQ(e2::end_supports_from_id(e2::end_supports_id(s)), s);
}

}  // namespace

// Super-Helix statics (ALGORITHMS.md §1.4, §1.7): uniform strains are exact for any N (end-moment
// roll-up, helix under an axial wrench), the Mattiasson cantilever converges to the planar elliptic
// reference at second order, the small-deflection self-weight limit, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/elastica.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/superhelix_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;
constexpr double kPi = std::numbers::pi;

TEST(SuperHelixStatics, EndMomentRollUpIsExactForAnyN) {
  // M = 2 pi EI2 / L about n2: a full circle in the n0-n1 plane, u2 = M / EI2 on every element.
  for (std::size_t n : {1u, 2u, 3u, 8u, 32u}) {
    const sh::RodModel model = rodvv::testing::superhelix::roll_up_model(n);
    const auto result = sh::solve_static(model, rodvv::testing::superhelix::roll_up_options());
    for (std::size_t e = 0; e < n; ++e) {
      // Newton to the round-off floor: the strain error is ~ |r| / K ~ N eps (k|q|) / k.
      EXPECT_LE(std::abs(result.q[3 * e + 2] - 2 * kPi), 64.0 * double(n) * kEpsilon * 2 * kPi) << n;
      EXPECT_LE(std::abs(result.q[3 * e]) + std::abs(result.q[3 * e + 1]), 64.0 * double(n) * kEpsilon) << n;
    }
    const sh::Kinematics kin(model, result.q);
    EXPECT_LE(kin.tip_position().norm(), 64.0 * double(n) * kEpsilon) << "the circle closes, N = " << n;
  }
}

// Exact helix of uniform body strain u with natural twist u_hat0 (PHYSICS.md §7.1, body form):
// the end wrench is n = lambda R(L) u, m = R(L) K (u - u_hat), lambda = C (u0 - u_hat0) - B u0.
struct HelixProblem {
  sh::RodModel model;
  VecX exact;
};

HelixProblem helix_problem(std::size_t n, const Vec3& u, double natural_twist) {
  sh::RodModel model;
  model.elements = n;
  model.length = 3.0;
  model.stiffness = Vec3(0.8, 1.3, 1.3);  // C, B, B (isotropic bending)
  model.natural_strain = Vec3(natural_twist, 0.0, 0.0);
  VecX q(static_cast<Eigen::Index>(3 * n));
  for (std::size_t e = 0; e < n; ++e) q.segment<3>(3 * e) = u;
  const sh::Kinematics kin(model, q);
  const double lambda = model.stiffness[0] * (u[0] - natural_twist) - model.stiffness[1] * u[0];
  model.end_force = lambda * kin.tip_frame() * u;
  model.end_moment = kin.tip_frame() * model.stiffness.cwiseProduct(u - model.natural_strain);
  return {model, q};
}

TEST(SuperHelixStatics, HelixUnderAxialWrenchIsExactForAnyN) {
  const Vec3 u(0.665742204262305, 0.455458746802376, 0.0);  // PHYSICS.md §7.1 example: tau, kappa
  for (std::size_t n : {1u, 4u, 16u}) {
    const auto [model, exact] = helix_problem(n, u, 0.2);
    // The residual of the exact strains is at round-off: the discrete weak form is exact.
    const VecX r = sh::static_residual(model, exact);
    EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 256.0 * double(n) * kEpsilon) << n;
    sh::StaticOptions options;
    options.initial_q = 1.02 * exact;  // Newton from a 2 % perturbation returns to the helix
    const auto result = sh::solve_static(model, options);
    EXPECT_LE((result.q - exact).lpNorm<Eigen::Infinity>(), 1e3 * double(n) * kEpsilon) << n;
  }
}

TEST(SuperHelixStatics, MattiassonCantileverConvergesAtSecondOrder) {
  // Clamp along x, dead tip load -P e_z with P L^2 / EI = 2: bending about n1 in the x-z plane.
  const rodvv::references::TipLoadedCantilever cantilever{1.0, 1.0, 2.0};
  const auto tip = rodvv::references::cantilever_tip(cantilever);
  double previous = 0.0;
  for (std::size_t n : {8u, 16u, 32u}) {
    sh::RodModel model;
    model.elements = n;
    model.end_force = Vec3(0.0, 0.0, -cantilever.P);
    sh::StaticOptions options;
    options.load_steps = 2;
    const auto result = sh::solve_static(model, options);
    const sh::Kinematics kin(model, result.q);
    const double error = std::abs(-kin.tip_position().z() - tip.w);
    EXPECT_LE(std::abs(kin.tip_position().y()), 1e-14);  // stays planar
    if (previous > 0.0) {
      const double order = std::log2(previous / error);
      EXPECT_GT(order, 1.9) << n;  // second order: measured 2.00
      EXPECT_LT(order, 2.5) << n;
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-3);
}

TEST(SuperHelixStatics, SmallSelfWeightDeflectionMatchesBeamTheory) {
  // rho S g L^4 / (8 EI) with rho S g = 1e-6: geometric nonlinearity is O(load^2) ~ 1e-12 relative;
  // the discretisation error is O(h^2): measured -3.3e-4 relative at N = 32 -> bound 1e-3 (3x).
  sh::RodModel model;
  model.elements = 32;
  model.gravity = Vec3(0.0, 0.0, -1e-6);
  const auto result = sh::solve_static(model);
  const sh::Kinematics kin(model, result.q);
  const double expected = 1e-6 / 8.0;
  EXPECT_TRUE(rodvv::testing::is_close(-kin.tip_position().z(), expected, 1e-3, 0.0));
  // Teeth: the clamped-pinned or the tip-load formula (1/3) is far off.
  EXPECT_FALSE(rodvv::testing::is_close(-kin.tip_position().z(), 1e-6 / 3.0, 1e-3, 0.0));
}

TEST(SuperHelixStatics, NewtonDirectionSolvesByGmresOrFallsBackToLu) {
  // A stiffness-dominated Jacobian (diagonal K plus a dense, non-symmetric D of relative size 0.3):
  // GMRES's relative tolerance 1e-13 gives J d = -r to 1e-12 |r|.
  const Eigen::Index n = 300;
  std::srand(7);
  rodvv::MatX J = 0.3 * rodvv::MatX::Random(n, n) / std::sqrt(double(n));
  J.diagonal() += VecX::LinSpaced(n, 1.0, 40.0);
  const VecX r = VecX::Random(n);
  EXPECT_LE((J * sh::newton_direction(J, r) + r).norm(), 1e-12 * r.norm());
  // The cyclic shift has a zero diagonal and needs n > 200 GMRES iterations: the LU fallback
  // still returns the exact direction (-r shifted back).
  rodvv::MatX shift = rodvv::MatX::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) shift((i + 1) % n, i) = 2.5;
  const VecX d = sh::newton_direction(shift, r);
  EXPECT_LE((shift * d + r).norm(), 64 * kEpsilon * r.norm());
}

TEST(SuperHelixStatics, BadOptionsNameTheParameter) {
  sh::RodModel model;
  sh::StaticOptions options;
  options.load_steps = 0;
  try {
    sh::solve_static(model, options);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "load_steps");
  }
  options = {};
  options.initial_q = VecX::Zero(5);
  EXPECT_THROW(sh::solve_static(model, options), rodvv::InputError);
  model.length = -1.0;
  try {
    sh::solve_static(model);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "length");
  }
}

}  // namespace

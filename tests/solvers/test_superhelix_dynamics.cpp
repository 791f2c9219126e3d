// Super-Helix dynamics (ALGORITHMS.md §1.4-1.7): the dense and the O(N) recursive paths solve the
// same step (with and without the cross-sections' rotational inertia), the velocity terms are the
// time derivative of the point velocities, a curl at rest stays at rest, the undamped semi-implicit
// Euler loses energy monotonically, and the linearised frequencies converge to Euler-Bernoulli from
// above at O(N^-2). The rotational inertia itself: test_superhelix_rotational_inertia.cpp.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/testing/superhelix_fixtures.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;
using rodvv::testing::superhelix::loaded_model;
using rodvv::testing::superhelix::random_vector;


TEST(SuperHelixDynamics, RecursiveStepEqualsDenseStep) {
  // Same linear system (M + D) dv = b, two factorisations (LDL^T of the assembled matrix vs the
  // articulated-body recursion): they differ by round-off times the condition number of M + D.
  // The gate is 1e-12 relative to |dv|; it holds where D = (h^2 + h gamma) K keeps M + D
  // reasonably conditioned (h >= 1e-3 here: measured, summary line), for the default rotational
  // inertia, a slender solid elliptic section, an anisotropic non-solid J (rho I0 != rho I1 + rho I2)
  // and without J. At h = 1e-4 the relative residual of the recursive dv in the dense system (the
  // backward error, free of the conditioning) is held to 1e-12 instead, with J; without J the light
  // local coordinates (mass ~ rho S ell^5, less for twist) leave M + D nearly singular (cond ~ 1e7
  // and more) and the forward difference is not small (measured 1.3e-7 against |dv|_inf = 4e-10 at
  // N = 20 before issue 11); the harness case superhelix/energy-decay gates the relative residual.
  double worst = 0.0, worst_residual = 0.0;
  const Vec3 inertias[4] = {sh::RodModel{}.rotational_inertia, sh::elliptic_section_inertia(0.02, 0.03, 0.012),
                            Vec3(6e-5, 1.5e-5, 4e-5), Vec3::Zero()};
  for (const Vec3& J : inertias) {
    for (std::size_t n : {1u, 3u, 6u, 20u}) {
      sh::RodModel model = loaded_model(n);
      model.rotational_inertia = J;
      sh::DynamicState state{random_vector(3 * n, 4.0, 1), random_vector(3 * n, 2.0, 2), 0.0};
      for (double h : {1e-4, 1e-3, 1e-2}) {
        if (J.isZero(0.0) && h < 1e-3) continue;
        const VecX dense = sh::velocity_change(model, state, h, sh::DynamicsPath::Dense);
        const VecX fast = sh::velocity_change(model, state, h, sh::DynamicsPath::Recursive);
        if (h < 1e-3) {
          MatX system = sh::mass_matrix(model, sh::Kinematics(model, state.q));
          system.diagonal() += (h * h + h * model.rayleigh_stiffness) * sh::generalised_stiffness(model);
          const double residual = (system * (dense - fast)).norm() / (system * dense).norm();
          worst_residual = std::max(worst_residual, residual);
          EXPECT_LE(residual, 1e-12) << "N = " << n << " h = " << h << " J = " << J.transpose();
          continue;
        }
        const double relative = (dense - fast).lpNorm<Eigen::Infinity>() / dense.lpNorm<Eigen::Infinity>();
        worst = std::max(worst, relative);
        EXPECT_LE(relative, 1e-12) << "N = " << n << " h = " << h << " J = " << J.transpose();
      }
    }
  }
  std::cout << "[ summary  ] h = 1e-4, with J: max relative residual " << worst_residual << "\n";
  std::cout << "[ summary  ] max relative |dv_dense - dv_recursive| = " << worst << "\n";
  // Teeth: dropping the velocity terms from one path is seen at once.
  const sh::RodModel model = loaded_model(6);
  sh::DynamicState state{random_vector(18, 4.0, 1), random_vector(18, 2.0, 2), 0.0};
  sh::DynamicState resting = state;
  resting.qdot.setZero();
  const VecX with_rates = sh::velocity_change(model, state, 1e-2, sh::DynamicsPath::Dense);
  const VecX without = sh::velocity_change(model, resting, 1e-2, sh::DynamicsPath::Recursive);
  EXPECT_GT((with_rates - without).lpNorm<Eigen::Infinity>(), 1e-6 * with_rates.lpNorm<Eigen::Infinity>());
}

TEST(SuperHelixDynamics, BiasAccelerationIsTimeDerivativeOfVelocity) {
  // d/dt v_g(q + t qdot, qdot + t a) at t = 0 equals J_g a + zeta_g (central difference in t with
  // step 1e-5: error ~1e-10 |a| scale; tolerance 1e-7 absolute on O(1..10) accelerations).
  const sh::RodModel model = loaded_model(5);
  const VecX q = random_vector(15, 3.0, 4), qdot = random_vector(15, 2.0, 5), a = random_vector(15, 1.0, 6);
  const sh::Kinematics kin(model, q);
  const auto zeta = sh::bias_accelerations(model, kin, qdot);
  const double t = 1e-5;
  const auto vp = sh::Kinematics(model, q + t * qdot).point_velocities(qdot + t * a);
  const auto vm = sh::Kinematics(model, q - t * qdot).point_velocities(qdot - t * a);
  for (std::size_t g = 0; g < zeta.size(); ++g) {
    const auto& point = kin.points()[g];
    const Vec3 expected = (vp[g] - vm[g]) / (2 * t);
    const Vec3 actual = kin.position_jacobian(point.element, point.sigma) * a + zeta[g];
    EXPECT_LE((actual - expected).norm(), 1e-7 * (1.0 + expected.norm())) << g;
  }
}

TEST(SuperHelixDynamics, AnalyticBiasMatchesGlobalFiniteDifference) {
  // The closed-form zeta (one root-to-tip pass) against the former global central difference of the
  // O(N) point velocities, zeta ~ [v(q + e qdot) - v(q - e qdot)] / 2e with e = cbrt(eps) / (L |qdot|):
  // truncation e^2 |d3v| / 6 and round-off eps |v| / e are both ~ cbrt(eps)^2 ~ 4e-11 relative to the
  // velocity scale |qdot|^2 L. Tolerance 1e-9 x (|zeta|_max + |qdot|^2 L): that estimate x 25
  // (measured in the summary line below).
  double worst = 0.0;
  for (std::size_t n : {1u, 4u, 16u}) {
    const sh::RodModel model = loaded_model(n);
    const VecX q = random_vector(3 * n, 4.0, 14), qdot = random_vector(3 * n, 3.0, 15);
    const sh::Kinematics kin(model, q);
    const auto zeta = sh::bias_accelerations(model, kin, qdot);
    const double rate = qdot.lpNorm<Eigen::Infinity>();
    const double e = std::cbrt(kEpsilon) / (model.length * rate);
    const auto vp = sh::Kinematics(model, q + e * qdot).point_velocities(qdot);
    const auto vm = sh::Kinematics(model, q - e * qdot).point_velocities(qdot);
    double scale = rate * rate * model.length;
    for (const auto& z : zeta) scale = std::max(scale, z.norm());
    for (std::size_t g = 0; g < zeta.size(); ++g) {
      const Vec3 fd = (vp[g] - vm[g]) / (2.0 * e);
      worst = std::max(worst, (fd - zeta[g]).norm() / scale);
      EXPECT_LE((fd - zeta[g]).norm(), 1e-9 * scale) << "N = " << n << " point " << g;
    }
  }
  std::cout << "[ summary  ] max |zeta_analytic - zeta_fd| / scale = " << worst << "\n";
}

TEST(SuperHelixDynamics, ElementRatesAreDirectionalDerivatives) {
  // element_point_rates / element_end_rates against central differences of the element maps along
  // qdot (step t = 1e-4: truncation t^2 |d3c| ~ 1e-8, round-off eps / t ~ 1e-12; tolerance 1e-7
  // absolute on O(1) quantities), on both sides of every series / trigonometric switch
  // (x^2 = sigma^2 |q|^2 across 1e-4, 1e-2, 1, 4).
  const Vec3 qdot(0.7, -1.3, 0.4);
  const double t = 1e-4;
  for (double scale : {0.005, 0.05, 0.5, 1.5, 2.5, 6.0}) {
    const Vec3 q = scale * Vec3(0.3, 0.8, -0.5).normalized();
    const double sigma = 1.0;
    const sh::ElementEndRates end = sh::element_end_rates(q, qdot, sigma);
    const sh::ElementMaps mp = sh::element_maps(q + t * qdot, sigma), m0 = sh::element_maps(q, sigma),
                          mm = sh::element_maps(q - t * qdot, sigma);
    const Vec3 e0 = Vec3::UnitX();
    EXPECT_LE((end.point.offset - m0.G * e0).norm(), 4 * kEpsilon) << scale;
    EXPECT_LE((end.point.velocity - (mp.G * e0 - mm.G * e0) / (2 * t)).norm(), 1e-7) << scale;
    EXPECT_LE((end.point.bias - (mp.dG0 * qdot - mm.dG0 * qdot) / (2 * t)).norm(), 1e-7) << scale;
    EXPECT_LE((end.angular_bias - (mp.G * qdot - mm.G * qdot) / (2 * t)).norm(), 1e-7) << scale;
    // the angular velocity: dE/dt E^T = [G qdot]x (ALGORITHMS.md §1.3 with the base frame = I)
    const Mat3 W = (mp.E - mm.E) / (2 * t) * m0.E.transpose();
    EXPECT_LE((end.angular_velocity - Vec3(W(2, 1), W(0, 2), W(1, 0))).norm(), 1e-7) << scale;
    const sh::ElementRates point = sh::element_point_rates(q, qdot, 0.37 * sigma);
    const sh::PointMaps pp = sh::element_point_maps(q + t * qdot, 0.37 * sigma),
                        pm = sh::element_point_maps(q - t * qdot, 0.37 * sigma);
    EXPECT_LE((point.bias - (pp.dG0 * qdot - pm.dG0 * qdot) / (2 * t)).norm(), 1e-7) << scale;
  }
  // The coefficient rates are continuous across the series / trigonometric switch at x^2 = 4 (both
  // sides within 1e-12 relative: the series truncation ~1e-21, the trigonometric cancellation
  // ~30 x^2 eps ~ 3e-14), and at x^2 = 1 (switch of the term count).
  for (double y : {1.0, 4.0}) {
    const auto below = sh::helix_coefficient_rates(std::nextafter(y, 0.0)), above = sh::helix_coefficient_rates(y);
    EXPECT_TRUE(rodvv::testing::is_close(below.dg1, above.dg1, 1e-12, 0.0)) << y;
    EXPECT_TRUE(rodvv::testing::is_close(below.dg2, above.dg2, 1e-12, 0.0)) << y;
  }
  // Teeth: dg1 / dg2 are the y-derivatives of g1 / g2 (central difference, step 1e-5: ~1e-10).
  for (double y : {0.3, 2.0, 9.0}) {
    const double dy = 1e-5;
    const auto rates = sh::helix_coefficient_rates(y);
    const auto cp = sh::helix_coefficients(y + dy), cm = sh::helix_coefficients(y - dy);
    EXPECT_NEAR(rates.dg1, (cp.g1 - cm.g1) / (2 * dy), 1e-9) << y;
    EXPECT_NEAR(rates.dg2, (cp.g2 - cm.g2) / (2 * dy), 1e-9) << y;
  }
}

TEST(SuperHelixDynamics, KineticEnergyIsQuadraticFormOfMassMatrix) {
  const sh::RodModel model = loaded_model(7);
  const VecX q = random_vector(21, 2.0, 8), qdot = random_vector(21, 1.0, 9);
  const sh::Kinematics kin(model, q);
  const MatX M = sh::mass_matrix(model, kin);
  const double expected = 0.5 * qdot.dot(M * qdot);
  EXPECT_TRUE(rodvv::testing::is_close(sh::kinetic_energy(model, kin, qdot), expected, 1e3 * kEpsilon, 0.0));
  EXPECT_LE((M - M.transpose()).norm(), 64 * kEpsilon * M.norm());
}

TEST(SuperHelixDynamics, CurlAtRestStaysAtRest) {
  // q = q0 (a curled, twisted helix), no gravity, no end loads, qdot = 0: every force vanishes, so
  // both paths return dv = 0 exactly and the state is a fixed point.
  sh::RodModel model = loaded_model(12);
  model.gravity.setZero();
  model.end_force.setZero();
  model.end_moment.setZero();
  sh::DynamicState state{sh::natural_strain_vector(model), VecX::Zero(36), 0.0};
  for (auto path : {sh::DynamicsPath::Dense, sh::DynamicsPath::Recursive}) {
    sh::DynamicState s = state;
    for (int i = 0; i < 50; ++i) s = sh::step(model, s, 1e-3, path);
    EXPECT_EQ((s.q - state.q).lpNorm<Eigen::Infinity>(), 0.0);
    EXPECT_EQ(s.qdot.lpNorm<Eigen::Infinity>(), 0.0);
  }
  // Teeth: with gravity on the same curl moves.
  model.gravity = Vec3(0, 0, -9.81);
  const auto moved = sh::step(model, state, 1e-3, sh::DynamicsPath::Recursive);
  EXPECT_GT(moved.qdot.lpNorm<Eigen::Infinity>(), 1e-3);
}

TEST(SuperHelixDynamics, UndampedEnergyDecreasesMonotonically) {
  // A horizontal cantilever released under gravity, gamma = 0: the semi-implicit Euler step is
  // dissipative (ALGORITHMS.md §1.5), so E_{n+1} <= E_n up to round-off of E (64 eps |E|scale).
  sh::RodModel model;
  model.elements = 8;
  model.line_density = 1.0;
  model.stiffness = Vec3(1.0, 1.0, 1.0);
  model.gravity = Vec3(0, 0, -2.0);
  sh::DynamicState state{VecX::Zero(24), VecX::Zero(24), 0.0};
  double energy = sh::total_energy(model, state);
  const double scale = std::abs(energy) + 1.0;
  double first = energy;
  for (int i = 0; i < 400; ++i) {
    state = sh::step(model, state, 5e-3, sh::DynamicsPath::Recursive);
    const double next = sh::total_energy(model, state);
    EXPECT_LE(next, energy + 64 * kEpsilon * scale) << "step " << i;
    energy = next;
  }
  EXPECT_LT(energy, first);  // it does lose energy
}

TEST(SuperHelixDynamics, FrequenciesConvergeFromAboveAtSecondOrder) {
  // Euler-Bernoulli clamped-free: omega_n = (beta_n L)^2 sqrt(EI / (rho S L^4)); beta_1 L is the
  // first root of 1 + cos x cosh x = 0 (1.8751040687119611664, PHYSICS/ALGORITHMS §1.7). The
  // Euler-Bernoulli rod has no rotary inertia of its sections: rho I1 = 0 (the twist inertia does not
  // enter the bending modes of a straight rod; it is left at its default).
  const double beta1 = 1.8751040687119611664;
  double previous = 0.0;
  for (std::size_t n : {8u, 16u, 32u}) {
    sh::RodModel model;
    model.elements = n;
    model.rotational_inertia[1] = 0.0;
    model.rotational_inertia[2] = 0.0;
    const double omega = sh::bending_frequencies(model, 1)[0];
    const double error = omega / (beta1 * beta1) - 1.0;
    EXPECT_GT(error, 0.0) << "Rayleigh-Ritz bound from above, N = " << n;
    if (previous > 0.0) {
      EXPECT_NEAR(std::log2(previous / error), 2.0, 0.1) << n;
    }
    previous = error;
    // With the default rotary inertia (rho I1 = 5e-3 = rho S r^2, r^2 = 5e-3 L^2) the rod is a
    // Rayleigh beam: its first frequency is lower by ~(beta_1 r)^2 / 2 ~ 1 % (here 1.9 % at N = 8 ..
    // 32, measured), which is what the Euler-Bernoulli comparison must exclude.
    model.rotational_inertia = sh::RodModel{}.rotational_inertia;
    const double rayleigh = sh::bending_frequencies(model, 1)[0] / (beta1 * beta1) - 1.0;
    EXPECT_LT(rayleigh, -0.005) << n;
    EXPECT_GT(rayleigh, -0.05) << n;
  }
}

// The straight rod of superhelix/modes (GJ != EI1 != EI2, tilted clamp, rho I1 = rho I2 = 0).
sh::RodModel straight_model(std::size_t n) {
  sh::RodModel model;
  model.elements = n;
  model.length = 1.3;
  model.stiffness = Vec3(0.55, 1.7, 3.1);
  model.line_density = 0.8;
  model.rotational_inertia = Vec3(0.07, 0.0, 0.0);
  model.root_frame = Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  model.root_position = Vec3(0.26, 0.52, -0.13);
  return model;
}

TEST(SuperHelixDynamics, StraightRodModesSplitIntoTwistAndTwoBendingFamilies) {
  // The full 3N eigenproblem of the straight rod: every mode lives in one strain component (the
  // tilted clamp mixes them at round-off), the twist family is the linear finite element bar with
  // consistent mass, omega_d^2 = 6 c^2 / ell^2 (1 - cos k ell) / (2 + cos k ell), k = (2n - 1) pi / (2L),
  // the kappa1 family is bending_frequencies (the kappa1 block alone), and the kappa2 family is that of
  // the rod with EI1 and EI2 exchanged.
  for (std::size_t n : {3u, 8u, 24u}) {
    const sh::RodModel model = straight_model(n);
    const sh::StraightRodModes modes = sh::straight_rod_modes(model);
    const auto dofs = static_cast<Eigen::Index>(3 * n);
    ASSERT_EQ(modes.frequencies.size(), dofs);
    ASSERT_EQ(modes.shapes.cols(), dofs);
    const MatX M = sh::mass_matrix(model, sh::Kinematics(model, VecX::Zero(dofs)));
    const MatX gram = modes.shapes.transpose() * M * modes.shapes;
    EXPECT_LE((gram - MatX::Identity(dofs, dofs)).cwiseAbs().maxCoeff(), 1e-10) << n;
    std::vector<double> family[3];
    for (Eigen::Index k = 0; k < dofs; ++k) {
      Eigen::Index f = 0;
      const double share = modes.component_share.col(k).maxCoeff(&f);
      EXPECT_GE(share, 1.0 - 1e-10) << n << " mode " << k;
      EXPECT_NEAR(modes.component_share.col(k).sum(), 1.0, 1e-12);
      if (k > 0) {
        EXPECT_GE(modes.frequencies[k], modes.frequencies[k - 1]);
      }
      family[f].push_back(modes.frequencies[k]);
    }
    ASSERT_EQ(family[0].size(), n);
    ASSERT_EQ(family[1].size(), n);
    ASSERT_EQ(family[2].size(), n);
    const double ell = model.length / double(n), c2 = 0.55 / 0.07;
    for (std::size_t m = 1; m <= std::min<std::size_t>(n, 3); ++m) {
      const double k = double(2 * m - 1) * std::numbers::pi / (2.0 * model.length);
      const double discrete = std::sqrt(6.0 * c2 / (ell * ell) * (1.0 - std::cos(k * ell)) / (2.0 + std::cos(k * ell)));
      EXPECT_NEAR(family[0][m - 1] / discrete, 1.0, 1e-9) << n << " " << m;
      EXPECT_GT(family[0][m - 1], k * std::sqrt(c2)) << "from above";
    }
    const VecX about_n1 = sh::bending_frequencies(model, n);
    sh::RodModel exchanged = model;
    exchanged.stiffness = Vec3(0.55, 3.1, 1.7);
    const VecX about_n2 = sh::bending_frequencies(exchanged, n);
    for (std::size_t m = 0; m < std::min<std::size_t>(n, 3); ++m) {
      EXPECT_NEAR(family[1][m] / about_n1[static_cast<Eigen::Index>(m)], 1.0, 1e-9) << n << " " << m;
      EXPECT_NEAR(family[2][m] / about_n2[static_cast<Eigen::Index>(m)], 1.0, 1e-9) << n << " " << m;
    }
    // The bending planes' rotary inertia does not touch the torsion of the straight rod.
    sh::RodModel rayleigh = model;
    rayleigh.rotational_inertia = Vec3(0.07, 2e-3, 3e-3);
    const sh::StraightRodModes with_rotary = sh::straight_rod_modes(rayleigh);
    std::vector<double> twist;
    for (Eigen::Index k = 0; k < dofs; ++k)
      if (with_rotary.component_share(0, k) > 0.5) twist.push_back(with_rotary.frequencies[k]);
    ASSERT_EQ(twist.size(), n);
    EXPECT_NEAR(twist[0] / family[0][0], 1.0, 1e-9) << n;
  }
}

TEST(SuperHelixDynamics, StraightRodModesKeepTheLowModesWhenTheTopReachesRoundOff) {
  // EI1 = 1e12 puts the stiff plane's 1 / omega^2 below the eigensolver's backward error eps / omega_min^2
  // at N = 32: those directions come out as omega = +inf with a zero shape and share (they threw before),
  // and the families that do not involve EI1 (twist, kappa2: decoupled on the straight rod) are those of
  // the rod with a moderate EI1, to the round-off eps (omega / omega_min)^2.
  sh::RodModel stiff = straight_model(32);
  stiff.stiffness = Vec3(0.55, 1e12, 3.1);
  sh::RodModel moderate = straight_model(32);
  moderate.stiffness = Vec3(0.55, 1e3, 3.1);
  const sh::StraightRodModes a = sh::straight_rod_modes(stiff), b = sh::straight_rod_modes(moderate);
  ASSERT_FALSE(std::isfinite(a.frequencies[a.frequencies.size() - 1])) << "the test needs the top at round-off";
  const auto low_families = [](const sh::StraightRodModes& modes) {
    std::vector<double> low;
    for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k) {
      if (!std::isfinite(modes.frequencies[k])) {
        EXPECT_EQ(modes.component_share.col(k).sum(), 0.0);
        EXPECT_EQ(modes.shapes.col(k).norm(), 0.0);
        continue;
      }
      if (modes.component_share(1, k) < 0.5 && low.size() < 6) low.push_back(modes.frequencies[k]);
    }
    return low;
  };
  const std::vector<double> low_a = low_families(a), low_b = low_families(b);
  ASSERT_EQ(low_a.size(), 6u);
  ASSERT_EQ(low_b.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k) {
    const double round_off = 1e3 * std::numeric_limits<double>::epsilon() * std::pow(low_a[k] / a.frequencies[0], 2);
    EXPECT_NEAR(low_a[k] / low_b[k], 1.0, round_off) << k;
  }
}

TEST(SuperHelixDynamics, StraightRodModesRejectAMasslessTwistAndALoadedRod) {
  sh::RodModel model = straight_model(4);
  model.rotational_inertia = Vec3(0.0, 1e-3, 1e-3);
  try {
    sh::straight_rod_modes(model);
    ADD_FAILURE() << "no InputError";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "rotational_inertia.twist (rho I0)");
  }
  for (const char* what : {"natural_strain", "gravity", "end_force", "end_moment"}) {
    sh::RodModel loaded = straight_model(4);
    const std::string name = what;
    (name == "natural_strain" ? loaded.natural_strain
     : name == "gravity"      ? loaded.gravity
     : name == "end_force"    ? loaded.end_force
                              : loaded.end_moment) = Vec3(0.0, 0.1, 0.0);
    try {
      sh::straight_rod_modes(loaded);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  }
}

TEST(SuperHelixDynamics, BadInputNamesTheParameter) {
  sh::RodModel model;
  sh::DynamicState state{VecX::Zero(24), VecX::Zero(24), 0.0};
  try {
    sh::step(model, state, 0.0, sh::DynamicsPath::Dense);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "h");
  }
  state.qdot[3] = std::nan("");
  try {
    sh::step(model, state, 1e-3, sh::DynamicsPath::Recursive);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "state.qdot");
  }
  EXPECT_THROW(sh::bending_frequencies(model, 0), rodvv::InputError);
}

// A step that diverges is the step's numerical failure (SolverError naming the method and the
// quantity), not bad input: the state it returns is never handed, non-finite, to the next step's
// input validation (issue 14, class 4). h = 1e200 is valid input; h^2 K overflows in the step.
TEST(SuperHelixDynamics, DivergedStepIsASolverErrorNotBadInput) {
  const sh::RodModel model = loaded_model(4);
  const auto n = static_cast<Eigen::Index>(sh::dof_count(model));
  const sh::DynamicState state{sh::natural_strain_vector(model), VecX::Constant(n, 0.5), 0.0};
  for (auto path : {sh::DynamicsPath::Dense, sh::DynamicsPath::Recursive}) {
    try {
      sh::step(model, state, 1e200, path);
      ADD_FAILURE() << "no error";
    } catch (const rodvv::SolverError& e) {
      // The dense path's LDL^T of M + D already fails on the overflowed h^2 K; the linear-time path
      // runs through, and the step's guard names the non-finite velocities.
      EXPECT_NE(e.method().find("superhelix"), std::string::npos) << e.method();
      if (path == sh::DynamicsPath::Recursive) {
        EXPECT_NE(std::string(e.what()).find("non-finite"), std::string::npos) << e.what();
        EXPECT_NE(e.method().find("semi-implicit Euler"), std::string::npos) << e.method();
      }
    }
  }
}

}  // namespace

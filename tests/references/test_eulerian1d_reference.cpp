// Tests of the d'Alembert references for the 1-D reference-map bar (references/src/eulerian1d.cpp,
// ALGORITHMS.md §6.1, §6.3): the wave equation and boundary conditions are checked by finite
// differences, the jump solutions against their hand-derived invariants (triangle-wave length,
// wall force, impulse, rebound, energy), and the Eulerian inversion against the Lagrangian map.
// The high-precision table tests/data/eulerian1d_reference.csv (mpmath, an independent method of
// characteristics) is compared where present.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/eulerian1d.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;

const ref::BarMaterial kMaterial{1.7, 2.3, 1.3};  // c = sqrt(2.3/1.7); deliberately not unit values

ref::StandingWave standing_wave() { return {kMaterial, 0.2, 0.05}; }
ref::SqueezeRelease squeeze() { return {kMaterial, 0.1, 0.1}; }
ref::BarrierImpact impact() { return {kMaterial, -0.9, 0.3, 0.7}; }

// Residual of rho0 x_tt = kappa x_XX by central differences with step h in both variables:
// truncation (h^2/12)(|x_tttt| + c^2 |x_XXXX|), round-off 4 eps |x| / h^2 each.
double wave_residual(const ref::BarMotion& motion, double X, double t, double h, double c) {
  auto x = [&](double XX, double tt) { return ref::bar_position(motion, XX, tt); };
  const double x_tt = (x(X, t + h) - 2 * x(X, t) + x(X, t - h)) / (h * h);
  const double x_XX = (x(X + h, t) - 2 * x(X, t) + x(X - h, t)) / (h * h);
  return x_tt - c * c * x_XX;
}

TEST(EulerianReference, StandingWaveSolvesTheWaveEquationWithFreeEnds) {
  const auto sw = standing_wave();
  const double c = ref::bar_wave_speed(kMaterial), L0 = kMaterial.length;
  const double h = 1e-3;
  // |x_tttt| = A w^4, w = pi c / L0 ~ 2.8: truncation ~ 2 (h^2/12) A w^4 ~ 5e-7 x 0.05 x 60 -> 1e-6;
  // round-off 8 eps / h^2 ~ 2e-9. Bound 1e-5.
  for (double X : {0.1, 0.37, 0.8, 1.2})
    for (double t : {0.05, 0.4, 1.1, 3.3})
      EXPECT_LE(std::abs(wave_residual(sw, X, t, h, c)), 1e-5) << X << " " << t;
  // Free ends: F(0) = F(L0) = 1 exactly (sin 0 = 0; sin(pi) ~ 1.2e-16 -> A pi/L0 x 1.2e-16).
  for (double t : {0.0, 0.3, 2.0}) {
    EXPECT_TRUE(is_close(ref::bar_stretch(sw, 0.0, t), 1.0, 0.0, kEpsilon));
    EXPECT_TRUE(is_close(ref::bar_stretch(sw, L0, t), 1.0, 0.0, 4 * kEpsilon));
  }
  // The check can fail: the residual of the same motion with a 1% wrong wave speed is large.
  EXPECT_GT(std::abs(wave_residual(sw, 0.37, 0.4, h, 1.01 * c)), 1e-3);
}

TEST(EulerianReference, StandingWaveEndsPeriodAndEnergy) {
  const auto sw = standing_wave();
  const double c = ref::bar_wave_speed(kMaterial), L0 = kMaterial.length;
  const double period = 2 * L0 / c;
  for (double t : {0.0, 0.21, 0.9}) {
    const auto now = ref::bar_ends(sw, t), later = ref::bar_ends(sw, t + period);
    // Positions O(1), cos evaluated at arguments differing by 2 pi: a few eps.
    EXPECT_TRUE(is_close(later.left, now.left, 0.0, 16 * kEpsilon));
    EXPECT_TRUE(is_close(later.right, now.right, 0.0, 16 * kEpsilon));
    const double a = sw.amplitude * std::cos(std::numbers::pi * c * t / L0);
    EXPECT_TRUE(is_close(now.left, sw.x_left0 + a, 0.0, 4 * kEpsilon));
    EXPECT_TRUE(is_close(now.right, sw.x_left0 + L0 - a, 0.0, 4 * kEpsilon));
  }
  // Energy by the midpoint rule in X at a few times: the integrand is smooth and periodic in
  // X over [0, L0] after symmetrisation; 2000 points give ~1e-7 relative (measured ~1e-8).
  const double expected = ref::bar_energy(sw);
  for (double t : {0.0, 0.33, 1.0}) {
    const int n = 2000;
    double energy = 0.0;
    for (int i = 0; i < n; ++i) {
      const double X = (i + 0.5) * L0 / n;
      const double v = ref::bar_velocity(sw, X, t), e = ref::bar_stretch(sw, X, t) - 1.0;
      energy += (0.5 * kMaterial.rho0 * v * v + 0.5 * kMaterial.kappa * e * e) * L0 / n;
    }
    EXPECT_TRUE(is_close(energy, expected, 1e-7, 0.0)) << t;
  }
}

TEST(EulerianReference, SqueezeLengthIsATriangleWave) {
  const auto sq = squeeze();
  const double c = ref::bar_wave_speed(kMaterial), L0 = kMaterial.length, F0 = sq.stretch0;
  for (double s : {0.0, 0.1, 0.35, 0.5, 0.77, 1.0, 1.2, 1.5, 2.0, 2.4}) {  // s = c t / L0
    const double t = s * L0 / c;
    const auto ends = ref::bar_ends(sq, t);
    const double tri = std::fmod(s, 2.0) <= 1.0 ? std::fmod(s, 2.0) : 2.0 - std::fmod(s, 2.0);
    const double length = F0 * L0 + 2 * (1 - F0) * L0 * tri;
    // O(1) positions through a few operations (fmod exact): 16 eps.
    EXPECT_TRUE(is_close(ends.right - ends.left, length, 0.0, 16 * kEpsilon)) << s;
    // Symmetric about the centre.
    EXPECT_TRUE(is_close(0.5 * (ends.left + ends.right), sq.center, 0.0, 16 * kEpsilon)) << s;
  }
  // The stretch takes only the values F0, 1, 2 - F0, and the ends are free (F = 1) except at t = 0.
  for (double s : {0.13, 0.6, 1.3, 1.8}) {
    const double t = s * L0 / c;
    for (double X : {0.05, 0.4, 0.9, 1.25}) {
      const double F = ref::bar_stretch(sq, X, t);
      EXPECT_TRUE(F == F0 || F == 1.0 || F == 2 - F0) << F;
    }
    EXPECT_EQ(ref::bar_stretch(sq, 0.0, t), 1.0);
  }
  EXPECT_EQ(ref::bar_stretch(sq, 0.5, 0.0), F0);
  // Velocity of the ends: -c (1 - F0) on the left while the release wave crosses (ct < L0).
  EXPECT_TRUE(is_close(ref::bar_velocity(sq, 0.0, 0.3 * L0 / c), -c * (1 - F0), 0.0, 4 * kEpsilon));
}

TEST(EulerianReference, SqueezeEnergyIsConserved) {
  // Piecewise-constant integrands in X: the midpoint rule errs only in the cells holding a jump,
  // by at most (number of jumps = 2) x (L0/n) x max integrand ~ 2 x 1.3e-4 x 1 -> bound 1e-3 relative.
  const auto sq = squeeze();
  const double c = ref::bar_wave_speed(kMaterial), L0 = kMaterial.length;
  const double expected = ref::bar_energy(sq);
  for (double s : {0.0, 0.25, 0.7, 1.3}) {
    const double t = s * L0 / c;
    const int n = 10000;
    double energy = 0.0;
    for (int i = 0; i < n; ++i) {
      const double X = (i + 0.5) * L0 / n;
      const double v = ref::bar_velocity(sq, X, t), e = ref::bar_stretch(sq, X, t) - 1.0;
      energy += (0.5 * kMaterial.rho0 * v * v + 0.5 * kMaterial.kappa * e * e) * L0 / n;
    }
    EXPECT_TRUE(is_close(energy, expected, 1e-3, 0.0)) << s;
  }
}

TEST(EulerianReference, ImpactContactForceImpulseAndRebound) {
  const auto im = impact();
  const double c = ref::bar_wave_speed(kMaterial), L0 = kMaterial.length, v0 = im.velocity;
  const auto s = ref::impact_summary(im);
  EXPECT_TRUE(is_close(s.contact_start, (0.7 - (-0.9) - L0) / v0, 0.0, 8 * kEpsilon));
  EXPECT_TRUE(is_close(s.contact_duration, 2 * L0 / c, 0.0, 4 * kEpsilon));
  EXPECT_TRUE(is_close(s.wall_force, kMaterial.rho0 * c * v0, 0.0, 4 * kEpsilon));
  EXPECT_TRUE(is_close(s.wall_force * s.contact_duration, s.impulse, 0.0, 8 * kEpsilon));
  EXPECT_EQ(s.rebound_velocity, -v0);
  // The wall stress equals -kappa (1 - F) at the wall during contact: F = 1 - v0/c.
  const double t_mid = s.contact_start + 0.5 * s.contact_duration;
  EXPECT_TRUE(is_close(-kMaterial.kappa * (ref::bar_stretch(im, L0, t_mid) - 1.0), s.wall_force, 0.0, 8 * kEpsilon));
  EXPECT_EQ(ref::impact_wall_force(im, s.contact_start - 0.01), 0.0);
  EXPECT_EQ(ref::impact_wall_force(im, s.contact_start + s.contact_duration + 0.01), 0.0);
  // The end X = L0 stays at the wall during contact, and the bar is unstressed, moving at -v0 after.
  for (double f : {0.0, 0.2, 0.5, 0.9, 1.0}) {
    const double t = s.contact_start + f * s.contact_duration;
    EXPECT_TRUE(is_close(ref::bar_position(im, L0, t), im.wall, 0.0, 8 * kEpsilon)) << f;
  }
  const double after = s.contact_start + s.contact_duration + 0.3;
  for (double X : {0.0, 0.5, L0}) {
    EXPECT_EQ(ref::bar_velocity(im, X, after), -v0);
    EXPECT_EQ(ref::bar_stretch(im, X, after), 1.0);
  }
  // Position is continuous in X across the fronts and in t across the phase changes.
  for (double f : {0.3, 0.7}) {
    const double t = s.contact_start + f * s.contact_duration;
    for (double X = 0.01; X < L0; X += 0.01) {
      const double jump = ref::bar_position(im, X + 1e-9, t) - ref::bar_position(im, X, t);
      EXPECT_LE(std::abs(jump), 2e-9) << X;  // |dx/dX| = F <= 1 over dX = 1e-9, plus round-off
    }
  }
  for (double tp : {s.contact_start, s.contact_start + 0.5 * s.contact_duration, s.contact_start + s.contact_duration})
    for (double X : {0.0, 0.6, L0})
      EXPECT_LE(std::abs(ref::bar_position(im, X, tp + 1e-9) - ref::bar_position(im, X, tp - 1e-9)), 3e-9 * v0 + 1e-15);
}

TEST(EulerianReference, EulerianStateInvertsTheMotion) {
  const ref::BarMotion motions[] = {standing_wave(), squeeze(), impact(), ref::RigidTranslation{kMaterial, 0.3, -0.4}};
  for (const auto& motion : motions) {
    for (double t : {0.0, 0.27, 1.9}) {
      const auto ends = ref::bar_ends(motion, t);
      for (int i = 0; i <= 20; ++i) {
        const double x = i == 20 ? ends.right : ends.left + (ends.right - ends.left) * i / 20.0;
        const auto p = ref::bar_eulerian_state(motion, x, t);
        EXPECT_TRUE(p.solid);
        // Bisection to adjacent doubles in X, then x(X) has |dx/dX| = F <= 2: 4 eps x max|x|.
        EXPECT_TRUE(is_close(ref::bar_position(motion, p.xi, t), x, 0.0, 8 * kEpsilon * 2.0)) << i;
        EXPECT_TRUE(is_close(p.density * p.stretch, kMaterial.rho0, 2 * kEpsilon, 0.0));
      }
      // Outside: xi continues linearly, no density.
      const auto outside = ref::bar_eulerian_state(motion, ends.right + 0.1, t);
      EXPECT_FALSE(outside.solid);
      EXPECT_GT(outside.xi, kMaterial.length);
      EXPECT_EQ(outside.density, 0.0);
    }
  }
  // Rigid translation: xi = x - x_left0 - v t to round-off.
  const ref::RigidTranslation tr{kMaterial, 0.3, -0.4};
  EXPECT_TRUE(is_close(ref::bar_eulerian_state(tr, 0.9, 0.5).xi, 0.9 - 0.3 + 0.2, 0.0, 8 * kEpsilon));
  EXPECT_TRUE(is_close(ref::bar_mass(kMaterial), 1.7 * 1.3, 0.0, kEpsilon));
}

// The mpmath table (tests/data/make_eulerian1d_table.py): standing-wave Eulerian fields by
// findroot, squeeze fields by the method of characteristics, squeeze ends by quadrature of the end
// velocities. All values are O(1); the C++ side uses a handful of roundings (bisection to adjacent
// doubles for xi, square waves for the squeeze), so 16 eps absolute (relative above 1) covers them.
TEST(EulerianReference, MatchesTheMpmathTable) {
  const auto rows = rodvv::testing::read_reference_table("eulerian1d_reference.csv", "kind,p1,p2,q1,q2,q3");
  ASSERT_EQ(rows.size(), 51u);
  const ref::StandingWave sw{kMaterial, 0.2, 0.05};
  const ref::SqueezeRelease sq{kMaterial, 0.1, 0.1};
  using rodvv::testing::parse_table_number;
  const double tol = 16 * kEpsilon;
  int checked = 0;
  for (const auto& row : rows) {
    const double p1 = parse_table_number(row[1]), p2 = parse_table_number(row[2]);
    const double q1 = parse_table_number(row[3]), q2 = parse_table_number(row[4]);
    if (row[0] == "standing") {
      const auto point = ref::bar_eulerian_state(sw, p1, p2);
      EXPECT_TRUE(is_close(point.xi, q1, tol, tol)) << "x " << p1 << " t " << p2;
      EXPECT_TRUE(is_close(point.velocity, q2, tol, tol)) << "x " << p1 << " t " << p2;
      EXPECT_TRUE(is_close(point.stretch, parse_table_number(row[5]), tol, tol)) << "x " << p1 << " t " << p2;
    } else if (row[0] == "squeeze_point") {
      EXPECT_TRUE(is_close(ref::bar_velocity(sq, p1, p2), q1, tol, tol)) << "X " << p1 << " t " << p2;
      EXPECT_TRUE(is_close(ref::bar_stretch(sq, p1, p2), q2, tol, tol)) << "X " << p1 << " t " << p2;
    } else if (row[0] == "squeeze_ends") {
      const auto ends = ref::bar_ends(sq, p1);
      EXPECT_TRUE(is_close(ends.left, q1, tol, tol)) << "t " << p1;
      EXPECT_TRUE(is_close(ends.right, q2, tol, tol)) << "t " << p1;
    } else {
      ADD_FAILURE() << "unknown row kind " << row[0];
    }
    ++checked;
  }
  EXPECT_EQ(checked, 51);
  // The comparison can fail: a 1e-3 change of the squeeze F0 moves the ends far beyond tol.
  const ref::SqueezeRelease wrong{kMaterial, 0.1, 0.1001};
  EXPECT_GT(std::abs(ref::bar_ends(wrong, 0.45).left - ref::bar_ends(sq, 0.45).left), 1e-6);
}

// Free fall: x = x0 + X + v0 t + a t^2 / 2, v = v0 + a t, F = 1, and the energy with the body force's potential
// (1/2 M v^2 - M a x_centre) the same at every t.
TEST(EulerianReference, FreeFallPositionVelocityAndEnergy) {
  const ref::RigidTranslation fall{kMaterial, 0.3, -0.4, 0.9};
  const double M = ref::bar_mass(kMaterial), L0 = kMaterial.length;
  for (double t : {0.0, 0.7, 2.3}) {
    for (double X : {0.0, 0.37, L0}) {
      EXPECT_DOUBLE_EQ(ref::bar_position(fall, X, t), 0.3 + X - 0.4 * t + 0.45 * t * t);
      EXPECT_DOUBLE_EQ(ref::bar_velocity(fall, X, t), -0.4 + 0.9 * t);
      EXPECT_DOUBLE_EQ(ref::bar_stretch(fall, X, t), 1.0);
    }
    const double v = -0.4 + 0.9 * t, centre = ref::bar_position(fall, 0.5 * L0, t);
    EXPECT_NEAR(0.5 * M * v * v - M * 0.9 * centre, ref::bar_energy(fall), 1e-14);
  }
}

TEST(EulerianReference, BadInputNamesTheParameter) {
  auto expect_input_error = [](const ref::BarMotion& motion, const std::string& name) {
    try {
      ref::validate(motion);
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name) << e.what();
    }
  };
  expect_input_error(ref::RigidTranslation{{0.0, 1.0, 1.0}, 0.0, 0.0}, "rho0");
  expect_input_error(ref::RigidTranslation{{1.0, -1.0, 1.0}, 0.0, 0.0}, "kappa");
  expect_input_error(ref::RigidTranslation{{1.0, 1.0, 0.0}, 0.0, 0.0}, "length");
  expect_input_error(ref::RigidTranslation{kMaterial, 0.0, 0.0, std::nan("")}, "acceleration");
  expect_input_error(ref::StandingWave{kMaterial, 0.0, 0.5}, "amplitude");  // A pi / L0 > 1: F < 0
  expect_input_error(ref::SqueezeRelease{kMaterial, 0.0, 1.5}, "stretch0");
  expect_input_error(ref::SqueezeRelease{kMaterial, 0.0, 0.0}, "stretch0");
  expect_input_error(ref::BarrierImpact{kMaterial, 0.0, 2.0, 5.0}, "velocity");  // v0 > c
  expect_input_error(ref::BarrierImpact{kMaterial, 0.0, 0.1, 1.0}, "wall");      // overlaps the bar
  EXPECT_THROW(ref::bar_eulerian_state(standing_wave(), 0.1, -1.0), rodvv::InputError);
}

}  // namespace

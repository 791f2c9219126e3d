// The sliding sleeve and the elastica arm scale (solvers/elastica2d/sleeve.hpp, free_arm.hpp) against
// references/sleeve.hpp (PHYSICS.md §6.1, §6.2), the Eshelby identity N_in - N_out = M_e^2/(2B), H
// continuity at the exit, exact derivatives of the arm energy, and bad input.
//
// Tolerances. Discretisation errors: C h^2 with h = 1/N and C = 2 x (error measured at the stated N)
// x N^2, plus the observed order between N and 2N in the window [p - 0.1, p + 0.5] around p = 2.
// Quantities fixed by the length row of the gradient (N_in - S, N1 - N2) are bounded by the Newton
// tolerance. Finite-difference checks: central differences with step d = cbrt(eps) x scale have
// error ~ d^2 |f'''| + eps |f| / d ~ eps^(2/3) relative; bound 1e-7 relative (x ~20 headroom).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/planar_noether.hpp"
#include "rodvv/references/sleeve.hpp"
#include "rodvv/solvers/elastica2d/free_arm.hpp"
#include "rodvv/solvers/elastica2d/sleeve.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {
namespace e2d = rodvv::solvers::elastica2d;
namespace ref = rodvv::references;
using rodvv::testing::is_close;

constexpr double kTolerance = 1e-11;  // Newton tolerance used below
// Largest relative backward error |S_ref(l_N) - S| / S measured in ConvergesOverTheWholePullRange at
// N = 128 (2026-11-21: 3.05e-5, 3.00e-5, 2.78e-5, 2.65e-5, 3.66e-5, 4.95e-5 for S/P = 0.01 .. 0.999).
constexpr double kBackward = 4.946e-5;

// PHYSICS.md §6.1 row alpha = P l^2 / B = 2 with B = 1, P = 2: l = 1, S = 2 x 0.7045223208193.
e2d::SleeveProblem alpha2_sleeve() {
  e2d::SleeveProblem p;
  p.bending_stiffness = 1.0;
  p.tip_load = 2.0;
  p.pull = 2.0 * 0.7045223208193;
  p.rod_length = 3.0;
  return p;
}

e2d::ArmScaleProblem inclined_scale() {
  e2d::ArmScaleProblem p;
  p.angle = 0.3;
  p.weight1 = 1.0;
  p.weight2 = 1.0;
  p.rod_length = 2.0;
  p.sleeve_length = 0.2;
  return p;
}

e2d::SleeveSolverOptions with_elements(std::size_t n) {
  e2d::SleeveSolverOptions o;
  o.elements = n;
  o.tolerance = kTolerance;
  return o;
}

// Observed order from errors at N and 2N.
double order(double coarse, double fine) { return std::log2(coarse / fine); }

::testing::AssertionResult second_order(const char* what, double coarse, double fine) {
  const double p = order(coarse, fine);
  if (p >= 1.9 && p <= 2.5) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << what << ": observed order " << p << " (errors " << coarse << ", "
                                       << fine << ") outside [1.9, 2.5]";
}

// ---- exact derivatives of the arm energy --------------------------------------------------------

TEST(FreeArm, DerivativesMatchCentralDifferences) {
  e2d::FreeArm arm;
  arm.bending_stiffness = 1.3;
  arm.exit = {0.2, -0.1};
  arm.exit_angle = 0.4;
  arm.tip_force = {0.3, -1.7};
  arm.elements = 6;
  Eigen::VectorXd phi(6);
  phi << 0.35, 0.2, 0.0, -0.3, -0.5, -0.6;
  const double l = 0.9;
  const auto d = e2d::free_arm_derivatives(arm, phi, l);
  const double step = std::cbrt(rodvv::testing::kEpsilon);
  const double rel = 1e-7;  // eps^(2/3) ~ 4e-11 per unit scale; x ~10^3 for the 1/h ~ 7 factors
  for (int i = 0; i < 6; ++i) {
    Eigen::VectorXd p = phi, m = phi;
    p[i] += step;
    m[i] -= step;
    const auto dp = e2d::free_arm_derivatives(arm, p, l), dm = e2d::free_arm_derivatives(arm, m, l);
    EXPECT_TRUE(is_close(d.grad_phi[i], (dp.energy - dm.energy) / (2 * step), rel, rel, i));
    EXPECT_TRUE(is_close(d.hess_diag[i], (dp.grad_phi[i] - dm.grad_phi[i]) / (2 * step), rel, rel, i));
    if (i + 1 < 6) {
      EXPECT_TRUE(is_close(d.hess_off[i], (dp.grad_phi[i + 1] - dm.grad_phi[i + 1]) / (2 * step), rel, rel, i));
    }
    if (i + 2 < 6) {  // tridiagonal: nothing beyond the first off-diagonal
      EXPECT_TRUE(is_close(0.0, (dp.grad_phi[i + 2] - dm.grad_phi[i + 2]) / (2 * step), rel, rel, i));
    }
    EXPECT_TRUE(is_close(d.hess_phi_l[i], (dp.grad_l - dm.grad_l) / (2 * step), rel, rel, i));
  }
  const auto lp = e2d::free_arm_derivatives(arm, phi, l + step), lm = e2d::free_arm_derivatives(arm, phi, l - step);
  EXPECT_TRUE(is_close(d.grad_l, (lp.energy - lm.energy) / (2 * step), rel, rel));
  EXPECT_TRUE(is_close(d.hess_ll, (lp.grad_l - lm.grad_l) / (2 * step), rel, rel));
}

// A wrong Hessian term (the load part of d2Pi/dphi2 dropped) is caught by the same check.
TEST(FreeArm, DerivativeCheckHasTeeth) {
  e2d::FreeArm arm;
  arm.tip_force = {0.0, -2.0};
  arm.elements = 4;
  Eigen::VectorXd phi(4);
  phi << -0.1, -0.3, -0.5, -0.6;
  const double step = std::cbrt(rodvv::testing::kEpsilon);
  const auto d = e2d::free_arm_derivatives(arm, phi, 1.0);
  Eigen::VectorXd p = phi, m = phi;
  p[2] += step;
  m[2] -= step;
  const double fd = (e2d::free_arm_derivatives(arm, p, 1.0).grad_phi[2] -
                     e2d::free_arm_derivatives(arm, m, 1.0).grad_phi[2]) / (2 * step);
  const double load_part = 0.25 * arm.tip_force.dot(Eigen::Vector2d(std::cos(phi[2]), std::sin(phi[2])));
  EXPECT_FALSE(is_close(d.hess_diag[2] - load_part, fd, 1e-7, 1e-7));
}

// ---- sliding sleeve -----------------------------------------------------------------------------

// Errors at N = 128 measured 2026-11-21: l 2.556e-5, phi_tip 2.949e-5, |M_e| 3.095e-5, tip x 1.548e-5,
// tip y 1.405e-5, jump - M^2/(2B) 5.196e-5. Bounds 2 x these; orders from N = 64 to 128.
TEST(SleeveSolver, MatchesTheReferenceAtSecondOrder) {
  const e2d::SleeveProblem p = alpha2_sleeve();
  const ref::SleeveEquilibrium r = ref::sleeve_equilibrium({p.tip_load, p.bending_stiffness}, p.pull);
  ASSERT_TRUE(is_close(r.free_length, 1.0, 1e-12, 0.0));  // the §6.1 row (13 digits)
  const auto s64 = e2d::solve_sleeve(p, with_elements(64));
  const auto s128 = e2d::solve_sleeve(p, with_elements(128));
  struct Check {
    const char* name;
    double c64, c128, reference, bound;
  } checks[] = {
      {"free_length", s64.arm.free_length, s128.arm.free_length, r.free_length, 2 * 2.556e-5},
      {"tip_angle", s64.tip_angle_below, s128.tip_angle_below, r.tip_angle, 2 * 2.949e-5},
      {"exit_moment", std::abs(s64.arm.exit_moment), std::abs(s128.arm.exit_moment), r.exit_moment, 2 * 3.095e-5},
      {"tip_x", s64.arm.tip_x, s128.arm.tip_x, r.tip_x, 2 * 1.548e-5},
      {"tip_y", s64.arm.tip_y, s128.arm.tip_y, r.tip_y, 2 * 1.405e-5},
  };
  for (const Check& c : checks) {
    SCOPED_TRACE(c.name);
    EXPECT_TRUE(is_close(c.c128, c.reference, 0.0, c.bound));
    EXPECT_TRUE(second_order(c.name, std::abs(c.c64 - c.reference), std::abs(c.c128 - c.reference)));
  }
}

// The Eshelby-like force comes out of the computation: N_in (from the stationarity in l, = S to the
// Newton tolerance) minus N_out (n.t just outside, = 0 here) equals M_e^2/(2B) to O(h^2), and H is
// continuous at the exit (H_in = N_in vs H along the arm).
TEST(SleeveSolver, TensionJumpIsTheEshelbyForce) {
  const e2d::SleeveProblem p = alpha2_sleeve();
  double previous = 0.0;
  for (std::size_t n : {64, 128}) {
    const auto s = e2d::solve_sleeve(p, with_elements(n));
    EXPECT_TRUE(is_close(s.axial_force_inside, p.pull, 0.0, kTolerance));  // length row of the gradient
    EXPECT_TRUE(is_close(s.arm.exit_axial_force, 0.0, 0.0, 4 * rodvv::testing::kEpsilon * p.tip_load));
    const double m = s.arm.exit_moment;
    const double identity = s.tension_jump - m * m / (2 * p.bending_stiffness);
    // Measured 2.078e-4 (N = 64), 5.196e-5 (N = 128): bound 2 x measured.
    EXPECT_LE(std::abs(identity), 2 * (n == 64 ? 2.078e-4 : 5.196e-5));
    if (n == 128) {
      EXPECT_TRUE(second_order("eshelby identity", previous, std::abs(identity)));
    }
    previous = std::abs(identity);
    // H continuity: H inside = N_in vs H of the arm at every node, exit node included (O(h^2);
    // measured max |H_i - N_in| 2.08e-4 at N = 64, at the exit node): bound 2 x 2.08e-4 (64/N)^2.
    const auto h = rodvv::invariants::planar_noether_h(s.arm.shape);
    for (double value : h)
      EXPECT_TRUE(is_close(value, s.axial_force_inside, 0.0, 2 * 2.08e-4 * 4096.0 / double(n * n)));
  }
  // The tension jump is not zero: a naive model without the configurational force would fail here.
  const auto s = e2d::solve_sleeve(p, with_elements(64));
  EXPECT_GT(s.tension_jump, 0.5 * p.pull);
}

// The unstable branch: a longer arm pulls harder, d2Pi*/dl2 < 0 (dS_eshelby/dl > 0).
TEST(SleeveSolver, LengthStiffnessIsNegative) {
  EXPECT_LT(e2d::solve_sleeve(alpha2_sleeve(), with_elements(32)).length_stiffness, 0.0);
}

// The whole range of S/P converges (S/P -> 1 through the continuation fallback). Near S = P the free
// length is ill-conditioned (l ~ log(1 / (1 - S/P))), so the check is the backward error: the pull
// that the reference needs for the computed l, |S_ref(l_N) - S| / S, at N = 128; bound 2 x the
// largest measured (kBackward).
TEST(SleeveSolver, ConvergesOverTheWholePullRange) {
  for (double ratio : {0.01, 0.2, 0.5, 0.9, 0.99, 0.999}) {
    SCOPED_TRACE(ratio);
    e2d::SleeveProblem p;
    p.tip_load = 1.5;
    p.bending_stiffness = 0.7;
    p.pull = ratio * p.tip_load;
    p.rod_length = 100.0;
    const auto s = e2d::solve_sleeve(p, with_elements(128));
    const auto r = ref::sleeve_equilibrium_for_length({p.tip_load, p.bending_stiffness}, s.arm.free_length);
    EXPECT_TRUE(is_close(r.invariant, p.pull, 2 * kBackward, 0.0));
  }
}

// A perturbed constant turns the reference check red: S (1 + 1e-3) in the reference call moves l by
// far more than the 2 x measured C h^2 bound of MatchesTheReferenceAtSecondOrder.
TEST(SleeveSolver, PerturbedPullInTheReferenceFails) {
  const e2d::SleeveProblem p = alpha2_sleeve();
  const auto s = e2d::solve_sleeve(p, with_elements(128));
  const auto wrong = ref::sleeve_equilibrium({p.tip_load, p.bending_stiffness}, p.pull * (1 + 1e-3));
  EXPECT_FALSE(is_close(s.arm.free_length, wrong.free_length, 0.0, 2 * 2.556e-5));
  // A factor 2 lost in the Eshelby force (M^2/B) is far off too.
  const double m = s.arm.exit_moment;
  EXPECT_GT(std::abs(s.tension_jump - m * m / p.bending_stiffness), 100 * 2 * 5.196e-5);
}

// ---- arm scale ----------------------------------------------------------------------------------

// Errors at N = 128 measured 2026-11-21: l1 1.190e-5, N 8.965e-6, beta1 5.591e-6, beta2 1.347e-5,
// |M1| 9.622e-6, |M2| 9.372e-6, P1 sin b1 - P2 sin b2 1.726e-5, Eshelby balance 1.611e-5.
TEST(ArmScaleSolver, MatchesTheReferenceAndBothBalances) {
  const e2d::ArmScaleProblem p = inclined_scale();
  const auto r = ref::arm_scale_equilibrium({p.angle, p.weight1, p.weight2, p.bending_stiffness, p.rod_length,
                                             p.sleeve_length});
  const auto s64 = e2d::solve_arm_scale(p, with_elements(64));
  const auto s128 = e2d::solve_arm_scale(p, with_elements(128));
  auto tip_balance = [&](const e2d::ArmScaleSolution& s) {
    return p.weight1 * std::sin(s.beta1) - p.weight2 * std::sin(s.beta2);
  };
  auto eshelby_balance = [&](const e2d::ArmScaleSolution& s) {
    const double m1 = s.arm1.exit_moment, m2 = s.arm2.exit_moment;
    return (p.weight1 + p.weight2) * std::sin(p.angle) - (m2 * m2 - m1 * m1) / (2 * p.bending_stiffness);
  };
  struct Check {
    const char* name;
    double e64, e128, bound;
  } checks[] = {
      {"l1", s64.arm1.free_length - r.arm1.length, s128.arm1.free_length - r.arm1.length, 2 * 1.190e-5},
      {"l2", s64.arm2.free_length - r.arm2.length, s128.arm2.free_length - r.arm2.length, 2 * 1.190e-5},
      {"shift", s64.sleeve_shift - r.sleeve_shift, s128.sleeve_shift - r.sleeve_shift, 2 * 2.380e-5},
      {"N", s64.axial_force - r.axial_force, s128.axial_force - r.axial_force, 2 * 8.965e-6},
      {"beta1", s64.beta1 - r.arm1.tip_angle, s128.beta1 - r.arm1.tip_angle, 2 * 5.591e-6},
      {"beta2", s64.beta2 - r.arm2.tip_angle, s128.beta2 - r.arm2.tip_angle, 2 * 1.347e-5},
      {"M1", std::abs(s64.arm1.exit_moment) - r.arm1.exit_moment, std::abs(s128.arm1.exit_moment) - r.arm1.exit_moment,
       2 * 9.622e-6},
      {"M2", std::abs(s64.arm2.exit_moment) - r.arm2.exit_moment, std::abs(s128.arm2.exit_moment) - r.arm2.exit_moment,
       2 * 9.372e-6},
      {"tip balance", tip_balance(s64), tip_balance(s128), 2 * 1.726e-5},
      {"eshelby balance", eshelby_balance(s64), eshelby_balance(s128), 2 * 1.611e-5},
  };
  for (const Check& c : checks) {
    SCOPED_TRACE(c.name);
    EXPECT_LE(std::abs(c.e128), c.bound);
    EXPECT_TRUE(second_order(c.name, std::abs(c.e64), std::abs(c.e128)));
  }
  // Both arms see the same axial force: the length row of the gradient is N2 - N1.
  EXPECT_TRUE(is_close(s128.axial_force_arm2, s128.axial_force, 0.0, kTolerance));
  // The Eshelby forces are visible: (P1 + P2) sin alpha = 0.59 is carried by M2^2 - M1^2.
  EXPECT_GT(std::abs(s128.arm2.exit_moment) - std::abs(s128.arm1.exit_moment), 0.1);
}

// Other scales (weights, inclinations, lengths) converge from the default start l1 = (L - L_s)/2 to the
// reference equilibrium. Relative error of l1 at N = 128 measured 2026-11-21: 2.17e-5, 1.35e-5,
// 1.29e-5, 3.31e-6, 6.48e-6 (sigma = d2Pi*/dl1^2 from -1.2 to -10): bound 2 x the largest.
TEST(ArmScaleSolver, ConvergesForOtherScales) {
  struct Scale {
    double alpha, p1, p2, length, sleeve;
  } scales[] = {{0.3, 1.0, 1.0, 2.0, 0.2}, {0.5, 1.0, 2.0, 2.0, 0.2}, {-0.4, 3.0, 1.0, 1.5, 0.3},
                {0.1, 1.0, 1.0, 3.0, 0.5}, {0.7, 0.5, 4.0, 2.0, 0.1}};
  for (const Scale& k : scales) {
    SCOPED_TRACE(k.alpha);
    e2d::ArmScaleProblem p;
    p.angle = k.alpha;
    p.weight1 = k.p1;
    p.weight2 = k.p2;
    p.rod_length = k.length;
    p.sleeve_length = k.sleeve;
    const auto r = ref::arm_scale_equilibrium({p.angle, p.weight1, p.weight2, p.bending_stiffness, p.rod_length,
                                               p.sleeve_length});
    const auto s = e2d::solve_arm_scale(p, with_elements(128));
    EXPECT_TRUE(is_close(s.arm1.free_length, r.arm1.length, 2 * 2.173e-5, 0.0));
  }
}

// Where no equilibrium exists (the heavier lower arm pulls the upper one fully into the sleeve, as
// the reference reports), the solver does not invent one: SolverError.
TEST(ArmScaleSolver, NoEquilibriumIsASolverError) {
  e2d::ArmScaleProblem p = inclined_scale();
  p.angle = 0.5;
  p.weight1 = 2.0;
  EXPECT_THROW(ref::arm_scale_equilibrium({p.angle, p.weight1, p.weight2, p.bending_stiffness, p.rod_length,
                                           p.sleeve_length}),
               rodvv::SolverError);
  EXPECT_THROW(e2d::solve_arm_scale(p, with_elements(32)), rodvv::SolverError);
}

// Mirror symmetry: alpha -> -alpha with the weights swapped exchanges the arms.
TEST(ArmScaleSolver, MirrorSymmetry) {
  e2d::ArmScaleProblem p = inclined_scale();
  p.weight2 = 1.3;
  e2d::ArmScaleProblem q = p;
  q.angle = -p.angle;
  std::swap(q.weight1, q.weight2);
  const auto a = e2d::solve_arm_scale(p, with_elements(32));
  const auto b = e2d::solve_arm_scale(q, with_elements(32));
  // Same discrete problem mirrored: equal to the Newton tolerance amplified by 1/|sigma| ~ 1.
  EXPECT_TRUE(is_close(a.arm1.free_length, b.arm2.free_length, 0.0, 1e-9));
  EXPECT_TRUE(is_close(a.beta2, b.beta1, 0.0, 1e-9));
}

// Wrong sign of alpha in the reference call: far outside the bounds.
TEST(ArmScaleSolver, WrongInclinationInTheReferenceFails) {
  const e2d::ArmScaleProblem p = inclined_scale();
  const auto s = e2d::solve_arm_scale(p, with_elements(128));
  const auto wrong = ref::arm_scale_equilibrium({-p.angle, p.weight1, p.weight2, p.bending_stiffness,
                                                 p.rod_length, p.sleeve_length});
  EXPECT_FALSE(is_close(s.arm1.free_length, wrong.arm1.length, 0.0, 2 * 1.190e-5));
}

// ---- bad input ----------------------------------------------------------------------------------

template <class F>
std::string input_error_parameter(F&& f) {
  try {
    f();
  } catch (const rodvv::InputError& e) {
    return e.parameter();
  }
  return "<no InputError>";
}

TEST(SleeveSolverInput, BadSleeveInputNamesTheParameter) {
  const double nan = std::nan("");
  auto with = [](auto edit) {
    e2d::SleeveProblem p = alpha2_sleeve();
    edit(p);
    return input_error_parameter([&] { e2d::solve_sleeve(p, with_elements(8)); });
  };
  EXPECT_EQ(with([](auto& p) { p.pull = 0.0; }), "pull");
  EXPECT_EQ(with([](auto& p) { p.pull = -1.0; }), "pull");  // wrong sign of the pull
  EXPECT_EQ(with([](auto& p) { p.pull = p.tip_load; }), "pull");
  EXPECT_EQ(with([](auto& p) { p.pull = 3.0; }), "pull");
  EXPECT_EQ(with([&](auto& p) { p.pull = nan; }), "pull");
  EXPECT_EQ(with([](auto& p) { p.tip_load = 0.0; }), "tip_load");
  EXPECT_EQ(with([&](auto& p) { p.tip_load = nan; }), "tip_load");
  EXPECT_EQ(with([](auto& p) { p.bending_stiffness = -1.0; }), "bending_stiffness");
  EXPECT_EQ(with([&](auto& p) { p.bending_stiffness = nan; }), "bending_stiffness");
  EXPECT_EQ(with([](auto& p) { p.rod_length = 0.0; }), "rod_length");
  e2d::SleeveSolverOptions o = with_elements(0);
  EXPECT_EQ(input_error_parameter([&] { e2d::solve_sleeve(alpha2_sleeve(), o); }), "elements");
  o = with_elements(1);
  EXPECT_EQ(input_error_parameter([&] { e2d::solve_sleeve(alpha2_sleeve(), o); }), "elements");
  o = with_elements(8);
  o.tolerance = 0.0;
  EXPECT_EQ(input_error_parameter([&] { e2d::solve_sleeve(alpha2_sleeve(), o); }), "tolerance");
  o = with_elements(8);
  o.initial_length = 5.0;  // beyond the rod length 3
  EXPECT_EQ(input_error_parameter([&] { e2d::solve_sleeve(alpha2_sleeve(), o); }), "initial_length");
}

TEST(SleeveSolverInput, BadArmScaleInputNamesTheParameter) {
  const double nan = std::nan("");
  auto with = [](auto edit) {
    e2d::ArmScaleProblem p = inclined_scale();
    edit(p);
    return input_error_parameter([&] { e2d::solve_arm_scale(p, with_elements(8)); });
  };
  EXPECT_EQ(with([](auto& p) { p.sleeve_length = 2.5; }), "sleeve_length");  // sleeve longer than the rod
  EXPECT_EQ(with([](auto& p) { p.sleeve_length = 2.0; }), "sleeve_length");
  EXPECT_EQ(with([](auto& p) { p.sleeve_length = 0.0; }), "sleeve_length");
  EXPECT_EQ(with([](auto& p) { p.weight1 = 0.0; }), "weight1");
  EXPECT_EQ(with([&](auto& p) { p.weight2 = nan; }), "weight2");
  EXPECT_EQ(with([](auto& p) { p.angle = 2.0; }), "angle");
  EXPECT_EQ(with([](auto& p) { p.rod_length = -1.0; }), "rod_length");
  EXPECT_EQ(with([](auto& p) { p.bending_stiffness = 0.0; }), "bending_stiffness");
}

// Non-convergence is a SolverError carrying the iterations and the residual.
TEST(SleeveSolverInput, NonConvergenceIsASolverError) {
  e2d::SleeveSolverOptions o = with_elements(32);
  o.max_iterations = 1;
  try {
    e2d::solve_sleeve(alpha2_sleeve(), o);
    FAIL() << "expected a SolverError";
  } catch (const rodvv::SolverError& e) {
    EXPECT_GE(e.iterations(), 1u);
    EXPECT_GT(e.residual(), 0.0);
  }
}

// The rod cannot be pulled out entirely: l = 1 > rod_length = 0.5 is a SolverError.
TEST(SleeveSolverInput, RodLeavingTheSleeveIsASolverError) {
  e2d::SleeveProblem p = alpha2_sleeve();
  p.rod_length = 0.9;
  e2d::SleeveSolverOptions o = with_elements(16);
  o.initial_length = 0.5;
  EXPECT_THROW(e2d::solve_sleeve(p, o), rodvv::SolverError);
}

}  // namespace

namespace {

// The Newton tolerance is in the problem's own units (angle rows / sqrt(B P), the length row / P):
// the same problem stated in other units (lengths x lambda, forces x mu, so B x mu lambda^2) converges
// in the same iterations to the same dimensionless equilibrium. With the former absolute tolerance,
// forces of 1e6 could not reach 1e-11 (round-off eps x 1e6) and forces of 1e-6 met it at once.
TEST(SleeveSolver, ToleranceIsInTheProblemsOwnUnits) {
  const e2d::SleeveProblem unit = alpha2_sleeve();
  const e2d::SleeveSolution reference = e2d::solve_sleeve(unit, with_elements(64));
  for (const auto& [lambda, mu] : {std::pair{1e3, 1e6}, std::pair{1e-3, 1e-6}, std::pair{1e-2, 1e8}}) {
    e2d::SleeveProblem scaled = unit;
    scaled.bending_stiffness *= mu * lambda * lambda;
    scaled.tip_load *= mu;
    scaled.pull *= mu;
    scaled.rod_length *= lambda;
    const e2d::SleeveSolution s = e2d::solve_sleeve(scaled, with_elements(64));
    EXPECT_EQ(s.iterations, reference.iterations) << lambda << " " << mu;
    EXPECT_TRUE(is_close(s.arm.free_length / lambda, reference.arm.free_length, 1e-12, 0.0)) << lambda << " " << mu;
    EXPECT_LE(s.residual, kTolerance);
    EXPECT_LE(std::abs(s.axial_force_inside - scaled.pull), kTolerance * scaled.tip_load);
  }
  e2d::ArmScaleProblem arms = inclined_scale();
  const e2d::ArmScaleSolution arms_reference = e2d::solve_arm_scale(arms, with_elements(64));
  arms.bending_stiffness *= 1e6 * 1e2 * 1e2;
  arms.weight1 *= 1e6;
  arms.weight2 *= 1e6;
  arms.rod_length *= 1e2;
  arms.sleeve_length *= 1e2;
  const e2d::ArmScaleSolution s = e2d::solve_arm_scale(arms, with_elements(64));
  EXPECT_EQ(s.iterations, arms_reference.iterations);
  EXPECT_TRUE(is_close(s.arm1.free_length / 1e2, arms_reference.arm1.free_length, 1e-12, 0.0));
}

}  // namespace

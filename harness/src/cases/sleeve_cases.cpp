// A rod sliding through a frictionless sleeve (solvers/elastica2d/sleeve.hpp), swept over the
// number N of elements per free arm:
//
//   sleeve/eshelby     rod pulled into the sleeve by S, dead tip load P on the free length l:
//                      l, tip angle and exit moment vs references/sleeve.hpp (PHYSICS.md §6.1);
//                      the tension jump N_in - N_out = M_e^2/(2B) and H continuous at the exit
//   sleeve/arm-scale   the elastica arm scale (PHYSICS.md §6.2): arm lengths, axial force N, the
//                      balances P1 sin beta1 = P2 sin beta2 and (P1 + P2) sin alpha = (M2^2 - M1^2)/(2B)
//
// The solver is a variable-length (configurational) model: the free length is an unknown of the
// energy; the Eshelby-like force M^2/(2B) is never put in, it is checked here. Plots: the shapes with
// the sleeve drawn, and n.t and H along the whole rod (inside: n.t = H = N; the tension jumps at an
// exit, H does not).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/invariants/planar_noether.hpp"
#include "rodvv/references/sleeve.hpp"
#include "rodvv/solvers/elastica2d/sleeve.hpp"

namespace rodvv::harness {

namespace {

namespace ref = rodvv::references;
namespace e2d = rodvv::solvers::elastica2d;

constexpr const char* kMethod =
    "variable-length (configurational) discrete elastica: free length(s) and polygon edge angles "
    "(N edges of length l/N per arm, half-cell clamp at the exit) unknowns of the total potential, "
    "joint Newton with exact gradient and Hessian (bordered banded LU); second order in h = l/N";
// Newton tolerance of the cases on ||grad Pi||_inf in the problem's units (the solver scales the length
// row, a force, by the load: P, or the larger weight): that row is S - N_in (sleeve) or N2 - N1 (arm
// scale), so these differences, in units of that load, are bounded by it at every N and any B, P, L.
constexpr double kTolerance = 1e-11;

std::size_t element_count(double level) { return static_cast<std::size_t>(std::llround(level)); }

MetricSample error_sample(double computed, double reference) {
  return {computed, reference, std::abs(computed - reference)};
}
MetricSample deviation(double value) { return {value, 0.0, std::abs(value), std::nullopt}; }
// A deviation from an identity between terms of size `size` (MetricSample::scale).
MetricSample deviation(double value, double size) { return {value, 0.0, std::abs(value), size}; }

MetricSpec error_metric(std::string name, std::string unit, std::string description) {
  return {std::move(name), MetricKind::Error, std::move(unit), std::move(description), false, 2.0};
}
MetricSpec invariant_metric(std::string name, std::string description, std::optional<double> order) {
  return {std::move(name), MetricKind::Invariant, "", std::move(description), false, order};
}
MetricSpec diagnostic(std::string name, std::string description) {
  return {std::move(name), MetricKind::Diagnostic, "", std::move(description), false, std::nullopt};
}

// Order gate (two-sided window around 2) and C h^2 at the finest default level, C = 2 x measured.
void second_order(Case& c, const char* metric, double at_finest, double finest_n, const std::string& why) {
  c.gates.push_back(order_gate(metric, 2.0, why));
  GateSpec gate = scaled_upper_bound_gate(metric, 2.0 * at_finest * finest_n * finest_n, 2.0,
                                          GateScope::FinestLevel,
                                          "C = 2 x the value measured at the finest default level / h^2");
  gate.measured = true;
  c.gates.push_back(gate);
}

// n.t and H along the whole rod for one arm: the straight inside part (n.t = H = N_in) from s_in to
// the exit, then the arm. s runs from the inner end; the exit appears twice (inside and outside
// values), which draws the jump.
void add_profiles(LevelOutput& out, const std::string& label, double s_exit, double inside_length,
                  double n_in, const PlanarRodSolution& arm) {
  std::vector<double> s{s_exit - inside_length, s_exit}, nt{n_in, n_in}, h{n_in, n_in};
  const std::vector<double> h_arm = invariants::planar_noether_h(arm);
  for (std::size_t i = 0; i < arm.nodes(); ++i) {
    s.push_back(s_exit + arm.s[i]);
    nt.push_back(arm.axial_force[i]);
    h.push_back(h_arm[i]);
  }
  out.series.push_back(thin_series("n.t and H along s|n.t " + label, "s", "n.t, H", s, nt));
  out.series.push_back(thin_series("n.t and H along s|H " + label, "s", "n.t, H", s, h));
}

// Sleeve walls drawn as two lines at +/- half_width around the axis from a to b.
void add_sleeve(LevelOutput& out, double ax, double ay, double bx, double by, double half_width) {
  const double len = std::hypot(bx - ax, by - ay);
  const double nx = -(by - ay) / len * half_width, ny = (bx - ax) / len * half_width;
  out.series.push_back(thin_series("shape|sleeve wall +", "x", "y", {ax + nx, bx + nx}, {ay + ny, by + ny}));
  out.series.push_back(thin_series("shape|sleeve wall -", "x", "y", {ax - nx, bx - nx}, {ay - ny, by - ny}));
}

// ---- sleeve/eshelby -----------------------------------------------------------------------------

// The pull S is in (0, P) (sin(phi_tip) = S/P < 1), and not below what the levels resolve: at small S/P
// the finest levels put H_spread at its round-off floor (measured along S at P = 2: S/P = 0.0128 passes,
// 0.0118 gives the H spread order 1.01, R^2 0.82; along P at S = 1.41: 0.0034 passes, 0.0025 gives 1.89).
// S/P >= 0.03 keeps a factor 2.3 from the first failure. The equilibrium must leave part of the rod in the sleeve: l < rod_length
// (at B = 12, or rod_length = 0.95, the free length 3.48 and 1.0 exceeded the rod and every level failed
// with "the rod leaves the sleeve").
constexpr double kEshelbyMinPullRatio = 0.03;
void check_eshelby_parameters(const Parameters& p) {
  const double P = parameter_value(p, "P"), S = parameter_value(p, "S"), B = parameter_value(p, "B");
  require_open_interval("S", S, 0.0, P);
  if (S < kEshelbyMinPullRatio * P)
    throw InputError("S", fmt::format("invalid parameter 'S' = {}: S / P = {} is below {}, where the levels' H "
                                      "spread reaches its round-off floor; the case resolves S in [{} P, P)",
                                      format_value(S), format_value(S / P), kEshelbyMinPullRatio,
                                      kEshelbyMinPullRatio));
  const double rod_length = parameter_value(p, "rod_length");
  const double free_length = ref::sleeve_equilibrium({P, B}, S).free_length;
  if (!(free_length < rod_length))
    throw InputError("rod_length", fmt::format("invalid parameter 'rod_length' = {}: the equilibrium free length "
                                               "l = {} (from P, S and B) is not shorter than the rod, so the rod "
                                               "leaves the sleeve; the rod must be longer than l",
                                               format_value(rod_length), format_value(free_length)));
}

LevelOutput run_eshelby_level(const Parameters& p, double level) {
  e2d::SleeveProblem problem;
  problem.bending_stiffness = parameter_value(p, "B");
  problem.tip_load = parameter_value(p, "P");
  problem.pull = parameter_value(p, "S");
  problem.rod_length = parameter_value(p, "rod_length");
  e2d::SleeveSolverOptions options;
  options.elements = element_count(level);
  options.tolerance = kTolerance;
  const e2d::SleeveSolution s = e2d::solve_sleeve(problem, options);
  const ref::SleeveEquilibrium r =
      ref::sleeve_equilibrium({problem.tip_load, problem.bending_stiffness}, problem.pull);
  const double b = problem.bending_stiffness;
  const double m = s.arm.exit_moment;
  const auto spread = invariants::planar_noether_spread(s.arm.shape);

  LevelOutput out;
  out.metrics["free_length"] = error_sample(s.arm.free_length, r.free_length);
  out.metrics["tip_angle"] = error_sample(s.tip_angle_below, r.tip_angle);
  out.metrics["exit_moment"] = error_sample(std::abs(m), r.exit_moment);
  out.metrics["tip_x"] = error_sample(s.arm.tip_x, r.tip_x);
  out.metrics["tip_y"] = error_sample(s.arm.tip_y, r.tip_y);
  out.metrics["eshelby_identity"] = deviation(s.tension_jump - m * m / (2.0 * b), m * m / (2.0 * b));
  out.metrics["H_continuity"] = deviation(s.axial_force_inside - spread.mean, std::abs(spread.mean));
  out.metrics["H_spread"] = deviation(spread.spread, 1.0);  // in units of H's natural scale
  out.metrics["N_in_vs_S"] = deviation((s.axial_force_inside - problem.pull) / problem.tip_load);
  out.metrics["tension_jump"] = {s.tension_jump, std::nullopt, std::nullopt};
  out.metrics["length_stiffness"] = {s.length_stiffness, std::nullopt, std::nullopt};
  out.metrics["newton_iterations"] = {double(s.iterations), std::nullopt, std::nullopt};

  const double inside = problem.rod_length - s.arm.free_length;
  std::vector<double> x{-inside}, y{0.0};
  x.insert(x.end(), s.arm.shape.x.begin(), s.arm.shape.x.end());
  y.insert(y.end(), s.arm.shape.y.begin(), s.arm.shape.y.end());
  out.series.push_back(thin_series("shape|rod", "x", "y", x, y));
  add_sleeve(out, -std::min(inside, 0.5 * problem.rod_length), 0.0, 0.0, 0.0, 0.02 * problem.rod_length);
  add_profiles(out, "", inside, inside, s.axial_force_inside, s.arm.shape);
  return out;
}

Case eshelby_case() {
  Case c;
  c.info.name = "sleeve/eshelby";
  c.info.family = "sleeve";
  c.info.group = "sleeve/eshelby";
  c.info.title = "rod pulled into a frictionless sleeve, tip load P: Eshelby-like force M^2/(2B)";
  c.info.physics =
      "Planar inextensible rod in a rigid straight frictionless sleeve along e_x (exit at x = 0), pulled "
      "inward by S at its inner end; the free length l outside carries a downward dead load P at its tip. "
      "Inside: straight, n.t = N_in = S; outside n = -P e_y. Equilibrium in l: S = M_e^2/(2B) = P sin(phi_tip).";
  c.info.reference =
      "references/sleeve.hpp sleeve_equilibrium (elliptic closed form of PHYSICS.md §6.1; default S is the "
      "alpha = P l^2/B = 2 row, l = 1); identities N_in - N_out = M_e^2/(2B) (eshelby_identity, the same "
      "number as H_in - H_arm(exit)) and H_in = mean H of the arm (H_continuity)";
  c.info.citation =
      "Bigoni, Dal Corso, Bosi & Misseroni 2015, Mech. Mater. 80:368-374; PHYSICS.md §1.2, §6.1";
  c.info.method = kMethod;
  c.info.parameters = {
      make_parameter("B", 1.0, 0.0, 1e6, true, false, "force length^2", "bending stiffness"),
      make_parameter("P", 2.0, 0.0, 1e6, true, false, "force", "dead tip load (downward)"),
      make_parameter("S", 2.0 * 0.7045223208193, 0.0, 1e6, true, false, "force", "inward pull, in (0, P)"),
      make_parameter("rod_length", 3.0, 0.0, 1e6, true, false, "length", "total rod length")};
  require_window(c,
                 fmt::format("S / P in [{:g}, 1), and the equilibrium free length l(P, S, B) < rod_length (the rod "
                             "stays in the sleeve)",
                             kEshelbyMinPullRatio),
                 check_eshelby_parameters);
  c.info.resolution = {"N", "elements on the free arm", ResolutionScale::Count, {32, 64, 128, 256},
                       {32, 64, 128, 256, 512, 1024, 2048}};
  c.info.metrics = {
      error_metric("free_length", "length", "l vs the reference"),
      error_metric("tip_angle", "rad", "phi_tip (below the horizontal) vs the reference"),
      error_metric("exit_moment", "force length", "|M_e| = B |kappa_e| (discrete clamp reaction) vs P x_tip"),
      error_metric("tip_x", "length", "tip x vs the reference"),
      error_metric("tip_y", "length", "tip y vs the reference"),
      invariant_metric("eshelby_identity", "N_in - N_out - M_e^2/(2B) (N_in from the equilibrium in l)", 2.0),
      invariant_metric("H_continuity", "H inside (= N_in) - mean of H along the arm", 2.0),
      invariant_metric("H_spread", "max |H(s) - mean| / natural scale along the arm", 2.0),
      invariant_metric("N_in_vs_S", "(N_in - S) / P, N_in = -dPi_arm/dl: the length row of the gradient",
                       std::nullopt),
      diagnostic("tension_jump", "N_in - N_out at the exit"),
      diagnostic("length_stiffness", "d2Pi*/dl2 (< 0: unstable under the dead pull)"),
      diagnostic("newton_iterations", "Newton iterations")};
  // Measured with `rodvv sweep sleeve/eshelby --levels 32,64,128,256,512,1024,2048` (2026-11-21):
  // values at N = 256 below; least-squares orders 2.000 for every metric, N_in - S <= 2.5e-15.
  const std::string why = "smooth solution, polygon with half-cell clamp: O(h^2)";
  second_order(c, "free_length", 6.3899e-06, 256, why);
  second_order(c, "tip_angle", 7.3736e-06, 256, why);
  second_order(c, "exit_moment", 7.7383e-06, 256, "clamp reaction by the discrete moment balance: O(h^2)");
  second_order(c, "tip_x", 3.8692e-06, 256, why);
  second_order(c, "tip_y", 3.5138e-06, 256, why);
  second_order(c, "eshelby_identity", 1.2990e-05, 256, "M_e is O(h^2), N_in and N_out exact: O(h^2)");
  second_order(c, "H_continuity", 1.1856e-05, 256, "H of the arm is O(h^2) from H_in");
  second_order(c, "H_spread", 1.0292e-06, 256, "H drift of a smooth discrete solution: O(h^2)");
  c.gates.push_back(upper_bound_gate("N_in_vs_S", kTolerance, GateScope::AllLevels,
                                     "the length row of grad Pi, (S - N_in) / P: <= the Newton tolerance 1e-11"));
  c.run_level = [](const Parameters& p, double level) { return run_eshelby_level(p, level); };
  return c;
}

// ---- sleeve/arm-scale ---------------------------------------------------------------------------

// The arm scale has an equilibrium with both arms outside the sleeve only for some weights, angles and
// stiffnesses (references/sleeve.hpp: f(0) < 0 < f(L - L_s)); outside it one arm is pulled into the
// sleeve, and the case refuses naming the lighter side's weight (before: every level failed in the
// solver's line search, e.g. at P2 = 0.1, alpha = 1.2, B = 10). And the load the levels resolve:
// max(P1, P2) L^2 / B <= 10 (measured: at alpha = 0.3 and P1 = P2 up to 35 passes, at 42 (B = 0.0957)
// the solver settles on another equilibrium than the reference's, orders 0; with an arm leaving the
// sleeve upwards and loaded, alpha = -0.7 and P1 L^2/B = 16, or alpha = 0.7 and P2 L^2/B = 20, its
// line search fails; every alpha in +-1.3 with either weight at 10 passes). A sleeve not inclined:
// |alpha| >= 0.01 (at alpha = 0 the problem is symmetric, the Eshelby balance's terms vanish and its
// error is round-off growing as N^2 - no order to measure; 0.01 passes with P1 = 1 and 2).
constexpr double kArmScaleMaxLoad = 10.0;
constexpr double kArmScaleMinAngle = 0.01;
void check_arm_scale_parameters(const Parameters& p) {
  const double rod_length = parameter_value(p, "rod_length"), B = parameter_value(p, "B");
  const double P1 = parameter_value(p, "P1"), P2 = parameter_value(p, "P2"), alpha = parameter_value(p, "alpha");
  require_open_interval("sleeve_length", parameter_value(p, "sleeve_length"), 0.0, rod_length);
  const double load = std::max(P1, P2) * rod_length * rod_length / B;
  if (load > kArmScaleMaxLoad)
    throw InputError(P1 >= P2 ? "P1" : "P2",
                     fmt::format("invalid parameters: max(P1, P2) L^2 / B = {} exceeds {}, the load the levels "
                                 "resolve (beyond it the solver may settle on another equilibrium branch or fail); "
                                 "lower P1, P2 or L, or raise B",
                                 format_value(load), kArmScaleMaxLoad));
  if (std::abs(alpha) < kArmScaleMinAngle)
    throw InputError("alpha", fmt::format("invalid parameter 'alpha' = {}: |alpha| must be >= {} (a level sleeve makes "
                                          "the problem symmetric: the Eshelby balance has no terms left to converge)",
                                          format_value(alpha), kArmScaleMinAngle));
  try {
    (void)ref::arm_scale_equilibrium({alpha, P1, P2, B, rod_length, parameter_value(p, "sleeve_length")});
  } catch (const ref::ArmPulledIn& error) {
    // The reference says which arm (sleeve.hpp); the user's parameters are named here.
    const bool arm2_pulled_in = error.arm() == 2;
    throw InputError(arm2_pulled_in ? "P2" : "P1",
                     fmt::format("invalid parameters: no equilibrium with both arms outside the sleeve at P1 = {}, "
                                 "P2 = {}, alpha = {}, B = {}, L = {}: arm {} would be pulled fully into the sleeve "
                                 "({}); raise {} or bring alpha towards 0",
                                 format_value(P1), format_value(P2), format_value(alpha), format_value(B),
                                 format_value(rod_length), arm2_pulled_in ? 2 : 1,
                                 arm2_pulled_in ? "P1 sin(alpha) >= P2 sin(beta2) even with l1 = 0"
                                                : "P1 sin(beta1) <= -P2 sin(alpha) even with l2 = 0",
                                 arm2_pulled_in ? "P2" : "P1"));
  }
}

LevelOutput run_arm_scale_level(const Parameters& p, double level) {
  e2d::ArmScaleProblem problem;
  problem.bending_stiffness = parameter_value(p, "B");
  problem.angle = parameter_value(p, "alpha");
  problem.weight1 = parameter_value(p, "P1");
  problem.weight2 = parameter_value(p, "P2");
  problem.rod_length = parameter_value(p, "rod_length");
  problem.sleeve_length = parameter_value(p, "sleeve_length");
  e2d::SleeveSolverOptions options;
  options.elements = element_count(level);
  options.tolerance = kTolerance;
  const e2d::ArmScaleSolution s = e2d::solve_arm_scale(problem, options);
  const ref::ArmScaleEquilibrium r = ref::arm_scale_equilibrium(
      {problem.angle, problem.weight1, problem.weight2, problem.bending_stiffness, problem.rod_length,
       problem.sleeve_length});
  const double b = problem.bending_stiffness;
  const double m1 = s.arm1.exit_moment, m2 = s.arm2.exit_moment;
  const auto h1 = invariants::planar_noether_spread(s.arm1.shape);
  const auto h2 = invariants::planar_noether_spread(s.arm2.shape);

  LevelOutput out;
  out.metrics["l1"] = error_sample(s.arm1.free_length, r.arm1.length);
  out.metrics["l2"] = error_sample(s.arm2.free_length, r.arm2.length);
  out.metrics["axial_force"] = error_sample(s.axial_force, r.axial_force);
  out.metrics["beta1"] = error_sample(s.beta1, r.arm1.tip_angle);
  out.metrics["beta2"] = error_sample(s.beta2, r.arm2.tip_angle);
  out.metrics["exit_moment_1"] = error_sample(std::abs(m1), r.arm1.exit_moment);
  out.metrics["exit_moment_2"] = error_sample(std::abs(m2), r.arm2.exit_moment);
  const double w1 = problem.weight1, w2 = problem.weight2;
  out.metrics["tip_balance"] = deviation(w1 * std::sin(s.beta1) - w2 * std::sin(s.beta2), w1 * std::abs(std::sin(s.beta1)));
  out.metrics["eshelby_balance"] = deviation((w1 + w2) * std::sin(problem.angle) - (m2 * m2 - m1 * m1) / (2.0 * b),
                                             (w1 + w2) * std::abs(std::sin(problem.angle)));
  out.metrics["H_continuity"] =
      deviation(std::max(std::abs(s.axial_force - h1.mean), std::abs(s.axial_force - h2.mean)), std::abs(s.axial_force));
  out.metrics["H_spread"] = deviation(std::max(h1.spread, h2.spread), 1.0);
  out.metrics["N1_vs_N2"] = deviation((s.axial_force - s.axial_force_arm2) / std::max(w1, w2));
  out.metrics["length_stiffness"] = {s.length_stiffness, std::nullopt, std::nullopt};
  out.metrics["newton_iterations"] = {double(s.iterations), std::nullopt, std::nullopt};

  // Shape: arm 1 reversed (tip .. exit 1), the straight part in the sleeve, arm 2 (exit 2 .. tip).
  std::vector<double> x(s.arm1.shape.x.rbegin(), s.arm1.shape.x.rend());
  std::vector<double> y(s.arm1.shape.y.rbegin(), s.arm1.shape.y.rend());
  x.insert(x.end(), s.arm2.shape.x.begin(), s.arm2.shape.x.end());
  y.insert(y.end(), s.arm2.shape.y.begin(), s.arm2.shape.y.end());
  out.series.push_back(thin_series("shape|rod", "x", "y", x, y));
  add_sleeve(out, s.arm1.shape.x.front(), s.arm1.shape.y.front(), s.arm2.shape.x.front(), s.arm2.shape.y.front(),
             0.02 * problem.rod_length);
  // Profiles, s along each arm from the sleeve centre outwards (arm 1 to the left: negative s).
  const double half = 0.5 * problem.sleeve_length;
  add_profiles(out, "arm 2", half, half, s.axial_force, s.arm2.shape);
  std::vector<double> sm{0.0, -half}, nt{s.axial_force, s.axial_force}, hm{s.axial_force, s.axial_force};
  const std::vector<double> h_arm = invariants::planar_noether_h(s.arm1.shape);
  for (std::size_t i = 0; i < s.arm1.shape.nodes(); ++i) {
    sm.push_back(-half - s.arm1.shape.s[i]);
    nt.push_back(s.arm1.shape.axial_force[i]);
    hm.push_back(h_arm[i]);
  }
  out.series.push_back(thin_series("n.t and H along s|n.t arm 1", "s", "n.t, H", sm, nt));
  out.series.push_back(thin_series("n.t and H along s|H arm 1", "s", "n.t, H", sm, hm));
  return out;
}

Case arm_scale_case() {
  Case c;
  c.info.name = "sleeve/arm-scale";
  c.info.family = "sleeve";
  c.info.group = "sleeve/arm-scale";
  c.info.title = "elastica arm scale: two weighted arms through an inclined frictionless sleeve";
  c.info.physics =
      "Planar inextensible rod through a rigid frictionless sleeve of length L_s inclined at alpha, centre at "
      "the origin; dead weights P1 (arm 1, leaving along -d) and P2 (arm 2, along +d) at the tips; "
      "l1 + l2 = L - L_s. Equilibrium: P1 sin beta1 = P2 sin beta2 = N, (P1 + P2) sin alpha = (M2^2 - M1^2)/(2B).";
  c.info.reference =
      "references/sleeve.hpp arm_scale_equilibrium (elliptic closed form per arm, root in l1; PHYSICS.md §6.2); "
      "the two balances and H continuity as identities";
  c.info.citation =
      "Bosi, Misseroni, Dal Corso & Bigoni 2014, Proc. R. Soc. A 470:20140232; PHYSICS.md §6.2";
  c.info.method = kMethod;
  c.info.parameters = {
      make_parameter("B", 1.0, 0.0, 1e6, true, false, "force length^2", "bending stiffness"),
      make_parameter("alpha", 0.3, -1.5707963267948966, 1.5707963267948966, true, true, "rad",
                     "sleeve inclination above the horizontal"),
      make_parameter("P1", 1.0, 0.0, 1e6, true, false, "force", "weight at the tip of arm 1 (lower exit)"),
      make_parameter("P2", 1.0, 0.0, 1e6, true, false, "force", "weight at the tip of arm 2 (upper exit)"),
      make_parameter("rod_length", 2.0, 0.0, 1e6, true, false, "length", "total rod length L"),
      make_parameter("sleeve_length", 0.2, 0.0, 1e6, true, false, "length", "sleeve length L_s, < L")};
  require_window(c,
                 fmt::format("sleeve_length < rod_length, max(P1, P2) rod_length^2 / B <= {:g}, |alpha| >= {:g}, and "
                             "an equilibrium with both arms outside the sleeve",
                             kArmScaleMaxLoad, kArmScaleMinAngle),
                 check_arm_scale_parameters);
  c.info.resolution = {"N", "elements per arm", ResolutionScale::Count, {32, 64, 128, 256},
                       {32, 64, 128, 256, 512, 1024, 2048}};
  c.info.metrics = {
      error_metric("l1", "length", "free length of arm 1 vs the reference"),
      error_metric("l2", "length", "free length of arm 2 vs the reference"),
      error_metric("axial_force", "force", "N = -dPi_arm1/dl1 vs the reference"),
      error_metric("beta1", "rad", "tip angle of arm 1 below the horizontal"),
      error_metric("beta2", "rad", "tip angle of arm 2 below the horizontal"),
      error_metric("exit_moment_1", "force length", "|M1| at exit 1"),
      error_metric("exit_moment_2", "force length", "|M2| at exit 2"),
      invariant_metric("tip_balance", "P1 sin beta1 - P2 sin beta2", 2.0),
      invariant_metric("eshelby_balance", "(P1 + P2) sin alpha - (M2^2 - M1^2)/(2B)", 2.0),
      invariant_metric("H_continuity", "max over arms |N - mean H of the arm|", 2.0),
      invariant_metric("H_spread", "max over arms of max |H(s) - mean| / natural scale", 2.0),
      invariant_metric("N1_vs_N2", "(N1 - N2) / max(P1, P2), N_k = -dPi_k/dl_k: the length row of the gradient in its unit", std::nullopt),
      diagnostic("length_stiffness", "d2Pi*/dl1^2"),
      diagnostic("newton_iterations", "Newton iterations")};
  const std::string why = "smooth solution, polygon with half-cell clamp: O(h^2)";
  // Measured with `rodvv sweep sleeve/arm-scale --levels 32,64,...,2048` (2026-11-21): values at
  // N = 256 below; least-squares orders 2.000 (H_spread 1.999).
  second_order(c, "l1", 2.9761e-06, 256, why);
  second_order(c, "l2", 2.9761e-06, 256, why);
  second_order(c, "axial_force", 2.2414e-06, 256, why);
  second_order(c, "beta1", 1.3978e-06, 256, why);
  second_order(c, "beta2", 3.3667e-06, 256, why);
  second_order(c, "exit_moment_1", 2.4055e-06, 256, why);
  second_order(c, "exit_moment_2", 2.3431e-06, 256, why);
  second_order(c, "tip_balance", 4.3162e-06, 256, why);
  second_order(c, "eshelby_balance", 4.0264e-06, 256, why);
  second_order(c, "H_continuity", 5.4810e-06, 256, why);
  second_order(c, "H_spread", 4.2382e-07, 256, "H drift of a smooth discrete solution: O(h^2)");
  c.gates.push_back(upper_bound_gate("N1_vs_N2", kTolerance, GateScope::AllLevels,
                                     "the length row of grad Pi, (N2 - N1) / max(P1, P2): <= the Newton tolerance 1e-11"));
  c.run_level = [](const Parameters& p, double level) { return run_arm_scale_level(p, level); };
  return c;
}

}  // namespace

void register_sleeve_cases(Registry& registry) {
  registry.add(eshelby_case());
  registry.add(arm_scale_case());
}

}  // namespace rodvv::harness

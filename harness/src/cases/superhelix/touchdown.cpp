// superhelix/touchdown: a heavy Super-Helix lands on a frictionless floor and settles there - the dynamics
// with velocity-level contact (solvers/superhelix/contact_dynamics.hpp: the dense step as a QP, the shared
// contact::solve_velocity_qp and its Lemke LCP; issue 13, class 5: the dense velocity QP had no case).
//
// The rod (EI1 = EI in the vertical plane, EI2 = 1.8 EI, GJ = 0.6 EI, weight w per length) is clamped
// horizontally at height delta above the floor, released straight at rest, falls, lands and comes to rest under
// Rayleigh damping. At rest it is a heavy cantilever lifted off a flat floor over a length l and lying on it
// beyond (references/heavy_touchdown.hpp): the clamp's moment sqrt(2 EI w delta), exact at any deflection (the
// Noether invariant H = 0 from the touchdown to the clamp); in the small-deflection limit l = (72 EI delta /
// w)^(1/4), the shape y(x), the clamp's vertical force 2 w l / 3 and so the floor's total reaction
// w (L - 2 l / 3), whose relative error (3/7) (delta / l)^2 is 4e-7 at the defaults, kept below the
// discretisation's by the window delta / l <= 2e-3.
// Metrics: the loads' moment about the clamp and the floor's reaction (gravity of the Gauss points, contact
// impulses / h), the lifted shape against y(x) in units of delta, and - at the same N - the settled state
// against the quasi-static frictionless solver (frictional_statics.hpp, mu = 0: Newton on (q, r) with a
// primal-dual active set), which solves the same discrete problem by another algorithm. Reported: the largest
// penetration over the steps, and (diagnostic) how far l lies outside the bracket the Gauss points give (the
// last one off the floor, the first on it), in element lengths: 0.5 at every default level, the discrete
// touchdown half an element before the continuum's.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "touchdown.hpp"

#include "../case_builder.hpp"
#include "superhelix_problems.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/solvers/superhelix/contact_dynamics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::harness::superhelix_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;

references::HeavyTouchdown reference(const Parameters& p) {
  return {parameter_value(p, "EI"), parameter_value(p, "w"), parameter_value(p, "delta")};
}

double lowest_frequency(const sh::RodModel& m) {  // of the cantilever: 1.8751^2 sqrt(EI1 / (rho S L^4))
  return 1.8751 * 1.8751 * std::sqrt(m.stiffness(1) / (m.line_density * std::pow(m.length, 4)));
}

// The clamp at height delta over the floor z = 0, in a frame whose tangent n0 and n1 are horizontal (bending
// about n1 moves the rod in the vertical plane of n0), the rod heading along no coordinate axis. One Gauss
// point per element: a lying element then touches the floor at one point, so the contacts are not redundant
// (contact_dynamics.hpp: with four, W is singular and Lemke's pivots grow ~20-fold).
sh::RodModel model(const Parameters& p, std::size_t elements) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), w = parameter_value(p, "w");
  const double delta = parameter_value(p, "delta"), rho_S = parameter_value(p, "rhoS");
  const double turn = 0.6;  // the rod's heading in the floor plane
  sh::RodModel m;
  m.length = L;
  m.elements = elements;
  m.stiffness = Vec3(0.6 * EI, EI, 1.8 * EI);
  m.gauss_points = 1;
  m.line_density = rho_S;
  const double r = 0.01 * L;  // a solid round section of radius L / 100: rho I = rho S r^2 (1/2, 1/4, 1/4)
  m.rotational_inertia = rho_S * r * r * Vec3(0.5, 0.25, 0.25);
  m.gravity = Vec3(0.0, 0.0, -w / rho_S);
  m.root_position = Vec3(0.3 * L, -0.2 * L, delta);
  const Vec3 along(std::cos(turn), std::sin(turn), 0.0), side(-std::sin(turn), std::cos(turn), 0.0);
  m.root_frame.col(0) = along;
  m.root_frame.col(1) = side;
  m.root_frame.col(2) = along.cross(side);  // up
  m.rayleigh_stiffness = 0.2 / lowest_frequency(m);  // a tenth of critical damping on the lowest mode
  return m;
}

sh::RigidObstacle floor_plane() { return {sh::RigidObstacle::Shape::Plane, Vec3::Zero(), Vec3::UnitZ(), 0.0, 0.0}; }

LevelOutput run(const Parameters& p, double level) { return touchdown_level(p, level, reference(p)); }

}  // namespace

LevelOutput touchdown_level(const Parameters& p, double level, const references::HeavyTouchdown& t) {
  const std::size_t n = element_count(level);
  const double L = parameter_value(p, "L");
  const sh::RodModel m = model(p, n);
  const std::vector<sh::RigidObstacle> floor{floor_plane()};
  // Steps of a fifth of the lowest period / 2 pi; at rest when a step changes q by less than 1e-12 of its
  // scale (q in units of 1 / L), measured to take 30 - 32 steps at N = 8 .. 128.
  const double h = 0.2 / lowest_frequency(m);
  constexpr std::size_t kMaxSteps = 20000;
  const auto dofs = static_cast<Eigen::Index>(sh::dof_count(m));
  sh::DynamicState state{VecX::Zero(dofs), VecX::Zero(dofs), 0.0};
  sh::ContactStepResult step;
  std::vector<double> times, heights;
  double change = 0.0;
  std::size_t steps = 0;
  double max_penetration = 0.0;
  for (; steps < kMaxSteps; ++steps) {
    step = sh::step_with_obstacles(m, state, h, floor);
    change = (step.state.q - state.q).lpNorm<Eigen::Infinity>() * L;
    state = step.state;
    max_penetration = std::max(max_penetration, step.penetration);
    times.push_back(state.time);
    heights.push_back(sh::Kinematics(m, state.q).tip_position().z() / t.delta);
    if (change <= 1e-12 * std::max(1.0, state.q.lpNorm<Eigen::Infinity>() * L)) break;
  }
  if (steps == kMaxSteps)
    throw SolverError("superhelix semi-implicit Euler step with velocity-level contact",
                      fmt::format("the rod did not come to rest in {} steps of h = {}", kMaxSteps, format_value(h)),
                      kMaxSteps, change);

  // The loads at rest: gravity at the Gauss points and the contact forces impulse / h along the normal.
  const sh::Kinematics at_rest(m, state.q);
  const auto& points = at_rest.points();
  std::vector<Vec3> contact_force(points.size(), Vec3::Zero());
  for (const auto& c : step.contacts) contact_force[c.point] += c.impulse / h * c.normal;
  const Vec3 lateral = m.root_frame.col(1);
  double moment = 0.0, reaction = 0.0, shape = 0.0, last_open = 0.0, first_closed = L;
  bool touched = false;
  const double ell = m.length / double(n);
  for (std::size_t g = 0; g < points.size(); ++g) {
    const Vec3 load = points[g].mass * m.gravity + contact_force[g];
    moment += (points[g].position - m.root_position).cross(load).dot(lateral);
    reaction += contact_force[g].z();
    const double s = double(points[g].element) * ell + points[g].sigma;
    const double x = (points[g].position - m.root_position).dot(m.root_frame.col(0));
    shape = std::max(shape, std::abs(points[g].position.z() - references::touchdown_height(t, x)) / t.delta);
    if (contact_force[g].z() > 0.0) {
      if (!touched) first_closed = s;
      touched = true;
    } else if (!touched) {
      last_open = s;
    }
  }
  const double l = references::touchdown_lifted_span(t);
  // Gravity's moment about the clamp is + w x per length about the lateral axis n1 (the rod points along n0,
  // gravity down), the floor's the opposite: their sum is the moment the clamp holds.
  LevelOutput output;
  output.metrics["clamp_moment"] = error_sample(moment, references::touchdown_clamp_moment(t));
  output.metrics["floor_reaction"] = error_sample(reaction, t.w * L - references::touchdown_clamp_force(t));
  output.metrics["lifted_shape"] = value_sample(shape, 1.0);
  output.metrics["touchdown_outside_bracket"] = diagnostic(std::max({0.0, last_open - l, l - first_closed}) / ell);

  // The same discrete problem, quasi-static: from the straight rod in one frictionless increment.
  sh::FrictionalStaticOptions options;
  options.tolerance = 1e-11;
  const auto statics = sh::solve_frictional_increment(m, floor, sh::frictional_start(m, VecX::Zero(dofs)), options);
  output.metrics["rest_vs_statics"] = value_sample(
      (state.q - statics.q).lpNorm<Eigen::Infinity>() / std::max(statics.q.lpNorm<Eigen::Infinity>(), 1.0 / L), 1.0);
  output.metrics["penetration"] = value_sample(max_penetration / t.delta, 1.0);
  output.metrics["lcp_residual"] = diagnostic(step.lcp_residual);
  output.metrics["steps_to_rest"] = diagnostic(double(steps + 1));
  output.series.push_back(thin_series("tip height / delta while the rod lands and settles", "t", "z_tip / delta",
                                      times, heights));
  return output;
}

namespace {

// The lifted length the levels resolve and the small-deflection regime: l / L in [0.25, 0.9] (a quarter of the
// rod at least lifted, a tenth at least on the floor) and delta / l <= 2e-3 (the reference's relative error
// (delta / l)^2 <= 4e-6, below the discretisation error of N = 64, 5.6e-4 at the defaults, by 100x).
Window touchdown_window() {
  return {"l / L in [0.25, 0.9] and delta / l <= 2e-3, l = (72 EI delta / w)^(1/4) (the lifted length the levels "
          "resolve; the small-deflection reference's (delta / l)^2)",
          [](const Parameters& p) {
            const references::HeavyTouchdown t = reference(p);
            const double L = parameter_value(p, "L"), l = references::touchdown_lifted_span(t);
            if (!(l >= 0.25 * L && l <= 0.9 * L))
              throw InputError("delta", fmt::format("invalid parameter 'delta' = {}: the lifted length l = (72 EI "
                                                    "delta / w)^(1/4) = {} (EI = {}, w = {}) must be in [0.25, 0.9] "
                                                    "L = [{}, {}] (L = {}: the rod must lift off and land)",
                                                    format_value(t.delta), format_value(l), format_value(t.EI),
                                                    format_value(t.w), format_value(0.25 * L), format_value(0.9 * L),
                                                    format_value(L)));
            if (!(t.delta <= 2e-3 * l))
              throw InputError("delta", fmt::format("invalid parameter 'delta' = {}: delta / l = {} must be <= 2e-3 "
                                                    "(the small-deflection reference's error (delta / l)^2)",
                                                    format_value(t.delta), format_value(t.delta / l)));
          }};
}

}  // namespace

void add_touchdown(Registry& registry) {
  // Measured at the defaults (2026-11-28) over N = 8 .. 128: orders 2.14 2.09 2.06 2.04 (moment), 2.18 2.13 2.09
  // 2.06 (reaction), 1.88 1.93 1.96 1.97 (shape; hence the levels from 16); at N = 64 6.0454e-6, 9.6105e-6,
  // 4.2660e-4. The touchdown sits at
  // an element end at every level there (l = L 5/8); elsewhere the contact set's jumps between levels make the
  // errors irregular, so the orders and bounds are checked at the defaults only.
  const double h = 1.0 / 64.0;
  const std::string why = "piecewise-constant strains and one Gauss point per element: second order, regular when "
                          "the touchdown sits at an element end at every level (the defaults: l = 5 L / 8)";
  std::vector<GateSpec> gates{
      measured_order_gate("clamp_moment", 2.0, why), measured_order_gate("floor_reaction", 2.0, why),
      measured_order_gate("lifted_shape", 2.0, why), measured_bound("clamp_moment", 6.0454e-6, h, 2.0),
      measured_bound("floor_reaction", 9.6105e-6, h, 2.0), measured_bound("lifted_shape", 4.2660e-4, h, 2.0),
      // The contacts' compliance (1e-9 of W's largest diagonal) and the statics' tolerance 1e-11: measured
      // 2.0e-10 .. 6.1e-9 over N = 8 .. 128, growing with the Delassus matrix's spread; 3x the largest.
      upper_bound_gate("rest_vs_statics", 2e-8, GateScope::AllLevels,
                       "the contact compliance 1e-9: measured <= 6.1e-9 over N = 8 .. 128, x 3"),
      // The gap is kept linearised over each step (and softened by the compliance): measured 1.3e-9 .. 1.9e-9 of
      // delta over N = 8 .. 128; 10x.
      upper_bound_gate("penetration", 2e-8, GateScope::AllLevels,
                       "linearised gaps and the contact compliance: measured <= 1.9e-9 delta over N = 8 .. 128, x 10")};
  std::vector<MetricSpec> metrics{
      error_metric("clamp_moment", "force length",
                   "moment of gravity and the floor about the clamp vs sqrt(2 EI w delta)", 2.0),
      error_metric("floor_reaction", "force", "total floor reaction vs w (L - 2 l / 3)", 2.0),
      invariant_metric("lifted_shape", "max |z(x) - y(x)| / delta over the Gauss points", 2.0),
      diagnostic_metric("touchdown_outside_bracket",
                        "distance of l outside [last Gauss point off the floor, first on it] / element length"),
      invariant_metric("rest_vs_statics", "|q_rest - q_statics|_inf / max(|q_statics|_inf, 1 / L), same N"),
      invariant_metric("penetration", "largest penetration over the steps / delta"),
      diagnostic_metric("lcp_residual", "natural-map residual of the last step's LCP"),
      diagnostic_metric("steps_to_rest", "steps until a step changes q by < 1e-12 of its scale")};
  Case c = make_case(
      "superhelix",
      {"superhelix/touchdown", "A heavy Super-Helix lands on a frictionless floor and settles (velocity-level contact)",
       "Super-Helix cantilever, EI1 = EI (vertical plane), EI2 = 1.8 EI, GJ = 0.6 EI, weight w per length, clamped "
       "horizontally at height delta over a frictionless floor; released straight at rest, it falls, lands and "
       "settles under Rayleigh damping (a tenth of critical on the lowest mode).",
       "Clamp moment sqrt(2 EI w delta), exact (Noether's H = 0 along the lifted part); small-deflection l = (72 EI "
       "delta / w)^(1/4), floor reaction w (L - 2 l / 3) and y(x) (relative error (3/7) (delta / l)^2; "
       "references/heavy_touchdown.hpp, against mpmath shooting); the quasi-static frictionless solver at the same N",
       "Timoshenko & Gere (beam on a rigid foundation); Levin et al. 2011 (velocity-level contact QP); Bertails "
       "et al. 2006",
       "Super-Helix semi-implicit Euler, dense path, with frictionless velocity-level contact at the Gauss points "
       "(convex QP in the metric M + D, dual LCP by Lemke)"},
      {make_parameter("L", 1.6, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI", 0.9, 0.0, 1e12, true, false, "force length^2",
                      "bending stiffness EI1 in the vertical plane"),
       make_parameter("w", 0.0648, 0.0, 1e12, true, false, "force / length", "weight per unit length rho S g"),
       make_parameter("rhoS", 0.4, 0.0, 1e12, true, false, "mass / length", "line density (sets the time scale)"),
       make_parameter("delta", 1e-3, 0.0, 1e6, true, false, "length", "height of the clamp above the floor")},
      element_levels("number of elements", {16, 32, 64}, {8, 16, 32, 64, 128}), std::move(metrics), std::move(gates),
      run);
  cases::require(c, touchdown_window());
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::superhelix_cases

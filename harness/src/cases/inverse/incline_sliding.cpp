// inverse/incline-sliding: the forward frictional statics (solvers/superhelix/frictional_statics.hpp) on
// the friction law's classic threshold, the forward counterpart of inverse/friction-cone. A straight
// Super-Helix lies across the fall line of an incline of angle alpha, clamped at its root with its tangent
// horizontal, every Gauss point (one per element, its midpoint) on the plane, Coulomb friction mu; gravity
// is applied in one increment from rest. The weight is the quadrature at those same points, so a force
// in each point's cone cancels it exactly iff tan alpha <= mu:
//  - below the threshold (tan alpha = (1 - m) mu) every contact sticks and the rod does not move;
//  - above it (tan alpha = (1 + m) mu) every contact slides downhill with mu r_N uphill, and the rod
//    carries the excess p = rhoS g (sin alpha - mu cos alpha) per length by bending in the plane: a
//    cantilever under a uniform load, tip deflection p L^4 / (8 EI) (Euler-Bernoulli).
// The reference is linear. Its neglected terms, relative: the dead load's geometric nonlinearity,
// O((delta / L)^2), and the turn of each point's slip off the fall line by its axial displacement,
// ~ delta / L, which puts an axial friction ~ mu w cos alpha (delta / L) on the rod (w = rhoS g) and
// changes the deflection by ~ (mu cos alpha / (sin alpha - mu cos alpha)) (p L^3 / EI) (delta / L)
// = 8 (delta / L)^2 / m (tan alpha = (1 + m) mu). The window 8 (delta / L)^2 / m <= 1e-4 keeps it 20 x
// below the finest default level's discretization error (1.95e-3 relative at N = 16). Measured: at the
// defaults (delta / L = 7.4e-5) the orders are 2.000 up to N = 64 (relative error 1.2e-4 there); at the
// window's edge (EI = 0.14: 9e-5) 1.99 .. 1.95 from N = 8 to 64; beyond it (EI = 0.02: 4.4e-3) 1.26 on
// N = 4 .. 64.
// The contact forces beside the clamp are ill-determined, not the shape: a point force at an element's
// midpoint acts on the curvatures through a triangular Toeplitz operator (symbol 1/8 + z / (1 - z)^2 in
// units of h^2) whose inverse grows like (3 + 2 sqrt 2)^k toward the clamp, so forces alternating with the
// ratio 2 sqrt 2 - 3 = -0.17 from the clamp are self-equilibrated to round-off. Measured at N = 8 below the
// threshold: r_N / (w h cos alpha) = 0.17, 1.14, 0.98, 1.004, 0.9993, ... from the clamp; at N = 64 above it
// the first contact carries nothing (63 loaded). The checks on forces are therefore counts and directions
// (which contacts slide, against what slip, inside their cones), not sizes.
// Checks:
//  - tip_deflection: the tip's downhill displacement above the threshold against p L^4 / (8 EI); order 2
//    (the load lumped at the element midpoints, the curvature constant per element) and a bound at the
//    finest level;
//  - displacement_below: max over the Gauss points of their displacement / L below the threshold: 0 up to
//    the Newton's tolerance (1e-9 relative; a rod that slips moves by ~ delta);
//  - sliding_below = 0 (no contact on its cone's boundary), sticking_above = 0 (every loaded contact
//    slides), slip_alignment (friction against the slip), cone_violation and penetration, both inclines.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../case_builder.hpp"
#include "friction_law.hpp"
#include "incline.hpp"
#include "inverse_cases.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::harness::inverse_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;

// The excess load along the fall line per unit length, p = w (sin alpha - mu cos alpha), at tan alpha = ratio mu.
double excess_load(const Parameters& p, double ratio) {
  const double mu = parameter_value(p, "mu"), alpha = std::atan(ratio * mu);
  return parameter_value(p, "rhoS") * parameter_value(p, "g") * (std::sin(alpha) - mu * std::cos(alpha));
}

// The linear cantilever's tip deflection under that load, over L.
double relative_deflection(const Parameters& p, double ratio) {
  const double L = parameter_value(p, "L");
  return excess_load(p, ratio) * L * L * L / (8.0 * parameter_value(p, "EI"));
}

struct OnIncline {
  sh::RodModel model;
  sh::FrictionalStaticResult start, rest;
  Vec3 downhill;
};

// The straight rod laid on the incline tan alpha = ratio mu, and its equilibrium once its weight is on.
OnIncline settle(const Parameters& p, std::size_t elements, double ratio) {
  const double mu = parameter_value(p, "mu");
  const Incline on = incline(std::atan(ratio * mu));
  const sh::RodModel m = rod_across_incline(p, elements, on);
  const sh::RigidObstacle plane{sh::RigidObstacle::Shape::Plane, m.root_position, on.normal, 0.0, mu};
  OnIncline out;
  out.model = m;
  out.downhill = on.downhill;
  out.start = sh::frictional_start(m, VecX::Zero(Eigen::Index(3 * elements)));
  out.rest = sh::solve_frictional_increment(m, {plane}, out.start);
  return out;
}

LevelOutput run(const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), mu = parameter_value(p, "mu"), margin = parameter_value(p, "margin");
  const std::size_t N = element_count(level);
  const OnIncline below = settle(p, N, 1.0 - margin), above = settle(p, N, 1.0 + margin);
  const FrictionLaw below_law = friction_law(below.rest.contacts, mu), above_law = friction_law(above.rest.contacts, mu);
  if (below_law.loaded == 0 || above_law.loaded == 0)
    throw SolverError("superhelix frictional statics", "the rod does not rest on the incline",
                      below.rest.iterations + above.rest.iterations,
                      std::max(below.rest.residual, above.rest.residual));
  double displacement_below = 0.0;
  for (std::size_t g = 0; g < below.rest.points.size(); ++g)
    displacement_below = std::max(displacement_below, (below.rest.points[g] - below.start.points[g]).norm() / L);
  // The tip's downhill displacement from the straight rod (whose tip is at the root + L across).
  const sh::Kinematics bent(above.model, above.rest.q), straight(above.model, above.start.q);
  const double deflection = (bent.tip_position() - straight.tip_position()).dot(above.downhill) / L;

  LevelOutput out;
  out.metrics["tip_deflection"] = error_sample(deflection, relative_deflection(p, 1.0 + margin));
  out.metrics["displacement_below"] = value_sample(displacement_below, 1.0);
  out.metrics["sliding_below"] = value_sample(double(below_law.sliding), 1.0);
  out.metrics["sticking_above"] = value_sample(double(above_law.loaded - above_law.sliding), 1.0);
  out.metrics["slip_alignment"] = value_sample(above_law.slip_alignment, 1.0);
  out.metrics["cone_violation"] = value_sample(std::max(below_law.cone_violation, above_law.cone_violation), 1.0);
  out.metrics["penetration"] = value_sample(std::max(below.rest.penetration, above.rest.penetration) / L, 1.0);
  out.metrics["loaded_contacts"] = diagnostic(double(std::min(below_law.loaded, above_law.loaded)));
  out.metrics["iterations"] = diagnostic(double(below.rest.iterations + above.rest.iterations));
  out.metrics["equilibrium_residual"] = diagnostic(std::max(below.rest.residual, above.rest.residual));
  out.metrics["contact_residual"] = diagnostic(std::max(below.rest.contact_residual, above.rest.contact_residual));
  return out;
}

}  // namespace

void add_incline_sliding(Registry& registry) {
  std::vector<MetricSpec> metrics{
      error_metric("tip_deflection", "", "tip's downhill displacement / L at tan alpha = (1 + m) mu, against p L^3 / (8 EI)",
                   2.0),
      invariant_metric("displacement_below", "max displacement of a Gauss point / L at tan alpha = (1 - m) mu"),
      invariant_metric("sliding_below", "contacts on their cone's boundary at tan alpha = (1 - m) mu"),
      invariant_metric("sticking_above", "loaded contacts not sliding at tan alpha = (1 + m) mu"),
      invariant_metric("slip_alignment", "max 1 + r_T.u_T / (|r_T| |u_T|) above: friction against the slip"),
      invariant_metric("cone_violation", "max (|r_T| - mu r_N)_+ / max r_N, both inclines"),
      invariant_metric("penetration", "max penetration of a Gauss point / L, both inclines"),
      diagnostic_metric("loaded_contacts", "contacts with r_N > 0 (the fewer of the two inclines)"),
      diagnostic_metric("iterations", "Newton iterations, both inclines"),
      diagnostic_metric("equilibrium_residual", "relative |R|_inf at the end (the larger)"),
      diagnostic_metric("contact_residual", "natural-map residual of the last contact solve (the larger)")};
  std::vector<GateSpec> gates{
      order_gate("tip_deflection", 2.0, "the load lumped at the element midpoints, the curvature constant per element"),
      // measured 2026-11-29 at the defaults: 2.32e-6, 5.80e-7, 1.45e-7 at N = 4, 8, 16 (delta / L units)
      measured_bound("tip_deflection", 1.4495e-7, 1.0 / 16.0, 2.0),
      upper_bound_gate("displacement_below", 1e-9, GateScope::AllLevels, "the rod sticks: it moves by the Newton's tolerance only"),
      upper_bound_gate("sliding_below", 0.0, GateScope::AllLevels, "every force strictly inside its cone"),
      upper_bound_gate("sticking_above", 0.0, GateScope::AllLevels, "every loaded contact slides"),
      upper_bound_gate("slip_alignment", 1e-9, GateScope::AllLevels, "the local Coulomb solver's exact sliding root"),
      upper_bound_gate("cone_violation", 1e-12, GateScope::AllLevels, "the local solver keeps r in its cone"),
      upper_bound_gate("penetration", 1e-9, GateScope::AllLevels, "gaps closed to the Newton tolerance")};
  Case c = make_case(
      "inverse",
      {"inverse/incline-sliding",
       "Forward frictional statics: a hair across an incline sticks iff tan alpha <= mu, and above it bends as a "
       "cantilever under the excess weight",
       "Straight Super-Helix lying across the fall line of an incline, clamped with a horizontal tangent, Coulomb "
       "friction mu at one Gauss point per element (the weight's quadrature points); gravity applied in one "
       "increment from rest at tan alpha = (1 - m) mu and (1 + m) mu.",
       "Below: no point moves. Above: every contact slides, and the tip deflection is p L^4 / (8 EI), p = rhoS g "
       "(sin alpha - mu cos alpha)",
       "Coulomb's sliding block; Euler-Bernoulli cantilever under a uniform load; ALGORITHMS.md §4",
       "Super-Helix quasi-static frictional contact: Newton on (q, r) with the Delassus W = H A^-1 H^T, the contact "
       "problem by a primal-dual active set, block Gauss-Seidel with the exact local Coulomb solver (De Saxce) as "
       "its fallback"},
      {make_parameter("L", 0.35, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI", 2.0, 0.0, 1e12, true, false, "force length^2", "in-plane bending stiffness (EI1 = 1.4 EI, GJ = 0.6 EI)"),
       make_parameter("rhoS", 0.07, 0.0, 1e12, true, false, "mass / length", "line density"),
       make_parameter("g", 9.81, 0.0, 1e12, true, false, "length / time^2", "gravity"),
       make_parameter("mu", 0.45, 0.1, 10.0, false, false, "", "friction coefficient"),
       make_parameter("margin", 0.1, 0.1, 0.9, false, false, "", "m: the inclines at tan alpha = (1 -+ m) mu")},
      element_levels("number of elements", {4, 8, 16}, {4, 8, 16, 32, 64}), std::move(metrics), std::move(gates), run);
  require_window(c, "8 (delta / L)^2 / m <= 1e-4, delta = p L^4 / (8 EI) above the threshold (the linear reference)",
                 [](const Parameters& p) {
                   const double margin = parameter_value(p, "margin"), delta = relative_deflection(p, 1.0 + margin);
                   const double neglected = 8.0 * delta * delta / margin;
                   if (!(neglected <= 1e-4))
                     throw InputError("EI", "invalid parameters: the rod bends too far for the linear reference: "
                                            "8 (delta / L)^2 / m = " + format_value(neglected) +
                                            " must be <= 1e-4 (delta / L = rhoS g (sin alpha - mu cos alpha) L^3 / "
                                            "(8 EI) = " + format_value(delta) + "; raise EI)");
                 });
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::inverse_cases

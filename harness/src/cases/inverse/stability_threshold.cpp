// inverse/stability-threshold: a shape that is a stable equilibrium only above a computed stiffness
// (ALGORITHMS.md §3.1: EI > lambda_max(K^-1/2 dF/dq K^-1/2) EI). The shape is Greenhill's heavy
// column, a straight Super-Helix clamped upright under its own weight (references/heavy_column.hpp):
// the inverse statics gives q0 = 0 (no generalised force on a straight vertical rod) and the
// critical stiffness factor alpha_c from the exact Hessian K - dF/dq (load_stiffness.hpp), hence the
// critical weight w L^3 / (alpha_c EI1) with EI1 < EI2 the weaker axis; it converges to
// 7.8373474... at O(h^2) (piecewise-constant strains and the Gauss quadrature of gravity).
//
// The stiffness a user would pick from it is then tried in the forward DYNAMICS (solvers/superhelix/
// dynamics.hpp, semi-implicit Euler, the O(N) path): the column at alpha = 1.05 alpha_c and at
// 0.95 alpha_c, released from a slight bow (uniform curvature 1e-4 / L about both axes) at rest, for
// t_end = 24 sqrt(L / g). The K-norm |q|_K = sqrt(q^T K q) of the scaled model over the run against
// its start:
//  - stable (1.05): the linearised motion conserves 1/2 q^T H q + 1/2 qdot^T M qdot, so |q|_K^2 stays
//    below lambda_max / lambda_min of K^-1/2 H K^-1/2 times its start; lambda_min = 1 - 1/1.05 = 0.048
//    and lambda_max <= 1 + |mu_min| / 1.05 with mu_min the most negative eigenvalue of K^-1/2 D K^-1/2
//    at alpha = 1.05 alpha_c (the gravity that stiffens the column's other modes; measured below
//    0.05): growth <= sqrt(1.05 / 0.048) = 4.7, gated at 5.
//  - unstable (0.95): the soft mode grows like exp(sigma t), sigma^2 ~ 0.053 omega_1^2 with omega_1 the
//    column's first bending frequency near the threshold, ~ 3.5^2 x 0.12 g/L: sigma t_end ~ 6.7,
//    growth ~ 800; gated at 50 (the stable bound x 10).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "../case_builder.hpp"
#include "inverse_cases.hpp"
#include "rodvv/references/heavy_column.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/inverse_statics.hpp"

namespace rodvv::harness::inverse_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;

constexpr double kAbove = 1.05, kBelow = 0.95;
constexpr double kStableGrowthBound = 5.0, kUnstableGrowthBound = 50.0;
constexpr double kSwings = 24.0;      // t_end sqrt(g / L)
constexpr double kStepsPerSwing = 500.0;

sh::RodModel column(const Parameters& p, std::size_t elements) {
  const double EI = parameter_value(p, "EI");
  sh::RodModel m;
  m.elements = elements;
  m.length = parameter_value(p, "L");
  m.stiffness = Vec3(0.6 * EI, EI, 1.9 * EI);  // buckles about n1
  m.line_density = parameter_value(p, "rhoS");
  m.rotational_inertia = sh::elliptic_section_inertia(m.line_density, 0.02 * m.length, 0.015 * m.length);
  m.root_frame = tilted_frame(0.9);
  m.root_position = Vec3(0.3, 0.1, -0.2) * m.length;
  m.gravity = -parameter_value(p, "g") * m.root_frame.col(0);  // against the clamp's tangent: upright
  return m;
}

// max over the run of |q|_K / |q(0)|_K for the column stiffened by `factor`.
double growth(const sh::RodModel& model, double factor) {
  const std::size_t n = model.elements;
  const VecX straight = VecX::Zero(Eigen::Index(3 * n));
  const sh::RodModel scaled = sh::model_at_rest_in(model, straight, factor);
  const VecX k = sh::generalised_stiffness(scaled);
  sh::DynamicState state{VecX::Zero(Eigen::Index(3 * n)), VecX::Zero(Eigen::Index(3 * n)), 0.0};
  for (std::size_t e = 0; e < n; ++e) state.q.segment<3>(Eigen::Index(3 * e)) = Vec3(0.0, 1e-4, 1e-4) / model.length;
  const auto norm = [&k](const VecX& q) { return std::sqrt(q.dot(k.cwiseProduct(q))); };
  const double start = norm(state.q);
  const double swing = std::sqrt(model.length / model.gravity.norm());
  const double h = swing / kStepsPerSwing;
  const auto steps = static_cast<std::size_t>(kSwings * kStepsPerSwing);
  double largest = 1.0;
  for (std::size_t i = 0; i < steps; ++i) {
    state = sh::step(scaled, state, h, sh::DynamicsPath::Recursive);
    largest = std::max(largest, norm(state.q) / start);
  }
  return largest;
}

LevelOutput run(const Parameters& p, double level) {
  const sh::RodModel model = column(p, element_count(level));
  const VecX straight = VecX::Zero(Eigen::Index(3 * model.elements));
  const sh::InverseStatics inverse = sh::inverse_statics(model, straight);
  const double w = model.line_density * model.gravity.norm();
  const double weight = w * std::pow(model.length, 3) / (inverse.critical_stiffness_factor * model.stiffness[1]);
  const double exact = references::heavy_column_critical_weight();
  LevelOutput out;
  out.metrics["critical_weight"] = error_sample(weight, exact);
  out.metrics["critical_weight_relative"] = value_sample(weight / exact - 1.0, 1.0);
  // |q0| L in eps of w L^3 / EI1: only the rounding of the tilted frame's vectors is left.
  out.metrics["rest_strain"] = value_sample(
      inverse.natural_strain.lpNorm<Eigen::Infinity>() * model.length * model.stiffness[1] /
          (std::numeric_limits<double>::epsilon() * w * std::pow(model.length, 3)),
      1.0);
  out.metrics["growth_above"] = diagnostic(growth(model, kAbove * inverse.critical_stiffness_factor));
  out.metrics["growth_below"] = diagnostic(growth(model, kBelow * inverse.critical_stiffness_factor));
  return out;
}

}  // namespace

void add_stability_threshold(Registry& registry) {
  const double h = 1.0 / 32.0;
  std::vector<MetricSpec> metrics{
      error_metric("critical_weight", "", "rhoS g L^3 / EI1 at the onset (from alpha_c)", 2.0, true),
      error_metric("critical_weight_relative", "", "|critical weight / 7.8373 - 1|", 2.0),
      error_metric("rest_strain", "eps w L^3/EI1", "|q0|_inf L of the straight column (0 but for rounding)", std::nullopt),
      diagnostic_metric("growth_above", "max |q|_K / |q(0)|_K of the column at 1.05 x the critical stiffness"),
      diagnostic_metric("growth_below", "max |q|_K / |q(0)|_K of the column at 0.95 x the critical stiffness")};
  std::vector<GateSpec> gates{
      order_gate("critical_weight_relative", 2.0, "piecewise-constant strains, Gauss quadrature of the weight: O(h^2)"),
      // measured 3.0212e-4 at N = 32 (4.82e-3, 1.21e-3 at N = 8, 16: order 2.00)
      measured_bound("critical_weight_relative", 3.0212e-4, h, 2.0),
      upper_bound_gate("rest_strain", 64.0, GateScope::AllLevels,
                       "a straight vertical rod has no generalised force: rounding of the tilted frame's vectors"),
      upper_bound_gate("growth_above", kStableGrowthBound, GateScope::AllLevels,
                       "energy bound sqrt(lambda_max / lambda_min) of the linearised motion (file comment)"),
      lower_bound_gate("growth_below", kUnstableGrowthBound, GateScope::AllLevels,
                       "exponential growth of the soft mode over 24 sqrt(L/g), 10 x the stable bound")};
  Case c = make_case(
      "inverse",
      {"inverse/stability-threshold",
       "The stiffness above which a shape is stable: Greenhill's heavy column from the inverse Hessian, tried in the dynamics",
       "Straight Super-Helix clamped upright (tilted frame) under its own weight; EI1 = EI < EI2 = 1.9 EI, GJ = 0.6 EI, "
       "elliptic section inertia; alpha_c = lambda_max(K^-1/2 dF/dq K^-1/2); dynamics at 1.05 and 0.95 alpha_c from a "
       "slight bow.",
       "Greenhill's heavy column: rhoS g L^3 / EI = (9/4) j_{-1/3,1}^2 = 7.8373474 (references/heavy_column.hpp)",
       "Greenhill 1881; Timoshenko & Gere 1961 §2.10; ALGORITHMS.md §3.1", 
       "Super-Helix inverse statics: exact Hessian K - dF/dq, generalised eigenvalue against K; semi-implicit Euler "
       "dynamics (O(N) articulated-body step)",
},
      {make_parameter("L", 1.3, 0.0, 1e6, true, false, "length", "column length"),
       make_parameter("EI", 0.9, 0.0, 1e12, true, false, "force length^2", "weaker bending stiffness EI1"),
       make_parameter("rhoS", 0.7, 0.0, 1e12, true, false, "mass / length", "line density"),
       make_parameter("g", 3.1, 0.0, 1e12, true, false, "length / time^2", "gravity")},
      element_levels("number of elements", {8, 16, 32}, {8, 16, 32, 64}), std::move(metrics), std::move(gates), run);
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::inverse_cases

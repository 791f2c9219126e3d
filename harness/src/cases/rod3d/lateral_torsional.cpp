// rod3d/lateral-torsional: lateral-torsional buckling of a cantilever under a dead tip load at the
// centroid (Michell 1899; Prandtl 1899; PRIOR_ART.md §4.5) on the nodal 3-D rod: the load bends the
// rod about its stiff axis, and at P_cr = gamma sqrt(EI_weak GJ) / L^2 (gamma = 4.0125993...) the
// smallest eigenvalue of the constrained Hessian at the loaded equilibrium crosses zero (the rod
// flips sideways and twists). The classical gamma neglects the in-plane prebuckling deflection
// (EI_strong -> infinity); its correction is O(EI_weak / EI_strong), so the case finds the critical
// load at two stiffness ratios r = EI_weak/EI_strong (r0 and 2 r0) and extrapolates linearly to
// r = 0 (leaving O(r0^2) = 1e-6 at the default r0 = 1e-3). Anisotropic and non-unit throughout:
// EI_weak != GJ, tilted clamp.
#include <cmath>

#include "../case_builder.hpp"
#include "buckling_threshold.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/references/twisted_rod.hpp"
#include "rodvv/solvers/rod3d/linearized.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

double stability_at(const Parameters& p, std::size_t elements, double ratio, double load) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI_weak"), GJ = parameter_value(p, "GJ");
  rod::RodModel model;
  model.elements = elements;
  model.length = L;
  model.stiffness = Vec3(GJ, EI, EI / ratio);  // weak about m1, strong about m2
  model.line_density = parameter_value(p, "rhoS");
  model.twist_inertia = 1e-2 * model.line_density * L * L;  // only the eigenvalue's sign is used
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(1.1);
  model.root.position = Vec3(0.1, 0.2, -0.3) * L;
  model.end_force = load * model.root.frame.col(1);  // bends the rod about m2, its stiff axis
  rod::StaticOptions options;
  options.tolerance = 1e-12;
  const auto equilibrium = rod::solve_static(model, rod::make_straight_state(model), options).state;
  return rod::stability_eigenvalue(model, equilibrium);
}

double critical(const Parameters& p, std::size_t elements, double ratio, double guess) {
  return critical_load([&](double load) { return stability_at(p, elements, ratio, load); }, 0.8 * guess, 1.2 * guess,
                       "lateral-torsional tip load");
}

LevelOutput run(const Parameters& p, double level) {
  const std::size_t n = element_count(level);
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI_weak"), GJ = parameter_value(p, "GJ");
  const double r0 = parameter_value(p, "stiffness_ratio");
  const double exact = ref::lateral_torsional_cantilever_critical_load({EI, GJ, L});
  const double at_r0 = critical(p, n, r0, exact), at_2r0 = critical(p, n, 2.0 * r0, exact);
  const double extrapolated = 2.0 * at_r0 - at_2r0;
  LevelOutput output;
  output.metrics["critical_load"] = error_sample(extrapolated, exact);
  output.metrics["critical_load_relative"] = {extrapolated / exact, 1.0, std::abs(extrapolated / exact - 1.0)};
  output.metrics["prebuckling_slope"] = diagnostic((at_2r0 - at_r0) / (r0 * exact));  // d(P_cr/P_classical)/dr
  return output;
}

}  // namespace

void add_lateral_torsional(Registry& registry) {
  const double h = 1.0 / 64.0;
  std::vector<GateSpec> gates{order_gate("critical_load_relative", 2.0, "vertex curvature and twist: O(h^2) (measured)"),
                              measured_bound("critical_load_relative", 1.0703e-4, h, 2.0)};
  std::vector<MetricSpec> metrics{
      error_metric("critical_load", "force", "P_cr extrapolated to EI_weak/EI_strong = 0", 2.0, true),
      error_metric("critical_load_relative", "", "|P_cr / (gamma sqrt(EI_weak GJ)/L^2) - 1|", 2.0),
      diagnostic_metric("prebuckling_slope", "d(P_cr / P_classical) / d(EI_weak/EI_strong) (the prebuckling correction)")};
  Case c = make_case(
      "rod3d",
      {"rod3d/lateral-torsional", "Lateral-torsional buckling of a cantilever: critical tip load from the linearised Hessian",
       "Cantilever (tilted clamp) with EI_strong = EI_weak / r >> EI_weak and GJ, dead tip load at the centroid bending "
       "it about the stiff axis; P_cr where the stability eigenvalue crosses zero, at r = r0 and 2 r0, extrapolated to r = 0.",
       "P_cr = gamma sqrt(EI_weak GJ) / L^2, gamma = 2 j_{-1/4,1} = 4.0125993435789 (references/twisted_rod.hpp)",
       "Michell 1899; Prandtl 1899; Timoshenko & Gere 1961; PRIOR_ART.md §4.5", kMethod, "rod-3d/lateral-torsional"},
      {make_parameter("L", 1.9, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI_weak", 0.7, 0.0, 1e12, true, false, "force length^2", "weak-axis bending stiffness (about m1)"),
       make_parameter("GJ", 1.6, 0.0, 1e12, true, false, "force length^2", "torsional stiffness"),
       make_parameter("stiffness_ratio", 1e-3, 1e-5, 1e-3, false, false, "",
                      "r0 = EI_weak / EI_strong (also 2 r0); larger r0 leaves an O(r0^2) extrapolation remainder "
                      "that the order gate sees (3e-3 fails it)"),
       make_parameter("rhoS", 0.4, 0.0, 1e12, true, false, "mass / length", "line density (mass metric of the eigenproblem)")},
      element_levels("number of edges", {16, 32, 64}, {16, 32, 64, 128}), std::move(metrics), std::move(gates), run);
  // The prebuckling rotation at P_cr is about gamma r sqrt(GJ/EI_weak): the linear extrapolation in r
  // and the bracket [0.8, 1.2] P_classical hold while it stays below 2e-3 (measured: 1.5e-3 at the
  // defaults passes; 4e-3 (EI_weak = 0.1) and 1.2e-2 (GJ = 100) fail).
  c.check_parameters = [](const Parameters& p) {
    const double r0 = parameter_value(p, "stiffness_ratio");
    const double limit = 2e-3 * std::sqrt(parameter_value(p, "EI_weak") / parameter_value(p, "GJ"));
    if (r0 > limit)
      throw InputError("stiffness_ratio", "invalid parameter 'stiffness_ratio' = " + format_value(r0) +
                                              ": must be <= 2e-3 sqrt(EI_weak / GJ) = " + format_value(limit) +
                                              " (the prebuckling rotation r0 sqrt(GJ/EI_weak) must stay below 2e-3)");
  };
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

// rod3d/helix-axial-wrench: the uniform helix held by an axial wrench (Love 1944 §§270-271;
// PHYSICS.md §7.1) on the nodal 3-D rod: clamped at s = 0 in the helix's material frame, loaded at
// the tip by the dead force n(L) and moment m(L) of the closed form, natural twist u_hat0 so that
// the twisting moment is M_t. Newton starts from a helix of 5 % smaller radius and pitch angle, so
// the case checks that the discrete equilibrium converges to THE helix, not that it stays put.
#include <algorithm>
#include <cmath>

#include "../case_builder.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

LevelOutput run(const Parameters& p, double level) {
  const ref::AxialWrenchHelix helix{parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "radius"),
                                    parameter_value(p, "pitch_angle"), parameter_value(p, "twisting_moment")};
  const double L = parameter_value(p, "L");
  const auto exact = ref::axial_wrench_helix(helix);
  const auto root = ref::axial_wrench_helix_point(helix, 0.0), tip = ref::axial_wrench_helix_point(helix, L);
  rod::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(helix.C, helix.B, helix.B);
  model.natural_strain = Vec3(exact.natural_twist, 0.0, 0.0);
  model.root.support = rod::EndSupport::Clamped;
  model.root.position = root.position;
  model.root.frame = root.frame;
  model.end_force = tip.force;    // the axial wrench as a dead tip force ...
  model.end_moment = tip.moment;  // ... and the moment m(L) it carries
  ref::AxialWrenchHelix start = helix;
  start.radius *= 0.95;
  start.pitch_angle *= 0.95;
  const auto initial = state_on_curve(model, [&](double s) {
    const auto point = ref::axial_wrench_helix_point(start, s);
    return CurvePoint{point.position, point.frame};
  });
  rod::StaticOptions options;
  options.tolerance = 1e-12;
  const auto result = rod::solve_static(model, initial, options);
  const SpatialRodSolution solution = rod::make_solution(model, result.state);

  double shape = 0.0, frame = 0.0, strain = 0.0;
  for (std::size_t i = 0; i < solution.vertex_s.size(); ++i)
    shape = std::max(shape, (solution.vertex_position[i] - ref::axial_wrench_helix_point(helix, solution.vertex_s[i]).position).norm());
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    frame = std::max(frame, (solution.frame[i] - ref::axial_wrench_helix_point(helix, solution.s[i]).frame).cwiseAbs().maxCoeff());
    strain = std::max(strain, (solution.strain_u[i] - Vec3(exact.tau, exact.kappa, 0.0)).cwiseAbs().maxCoeff());
  }
  LevelOutput output;
  output.metrics["shape_max_error"] = value_sample(shape / L, 1.0);
  output.metrics["frame_max_error"] = value_sample(frame, 1.0);  // radians
  output.metrics["strain_max_error"] = value_sample(strain / exact.darboux, 1.0);
  output.metrics["newton_iterations"] = diagnostic(double(result.iterations));
  add_noether3d_metrics(output, solution, exact.H);
  std::vector<double> x, z, xr, zr;
  for (const auto& r : solution.vertex_position) {
    x.push_back(r.x());
    z.push_back(r.z());
  }
  for (int i = 0; i <= 200; ++i) {
    const auto point = ref::axial_wrench_helix_point(helix, L * i / 200.0);
    xr.push_back(point.position.x());
    zr.push_back(point.position.z());
  }
  output.series.push_back(thin_series("helix (x, z)|computed vertices", "x", "z", x, z));
  output.series.push_back(thin_series("helix (x, z)|closed form", "x", "z", xr, zr));
  return output;
}

}  // namespace

void add_helix_axial_wrench(Registry& registry) {
  const double h = 1.0 / 64.0;
  std::vector<GateSpec> gates{
      order_gate("shape_max_error", 2.0, "chords of the helix, curvature 2 tan(phi/2)/ebar: O(h^2)"),
      order_gate("frame_max_error", 2.0, "halfway rotation of the edge frames vs the frame at the vertex: O(h^2)"),
      order_gate("strain_max_error", 2.0, "discrete curvature and twist of a uniform helix: O(h^2)"),
      order_gate("H_mean", 2.0, "H at the vertices from O(h^2) strains and edge-averaged forces"),
      // H is uniform along the discrete helix except where the clamp and the tip load end it: its
      // spread falls at fourth order (measured 3.996 over N = 16 ... 128).
      order_gate("H_spread", 4.0, "the discrete helix is uniform away from its ends: H spread O(h^4) (measured)"),
      measured_bound("shape_max_error", 1.7532e-4, h, 2.0),
      measured_bound("frame_max_error", 4.0192e-4, h, 2.0),
      measured_bound("strain_max_error", 2.7594e-4, h, 2.0),
      measured_bound("H_mean", 7.4473e-5, h, 2.0),
      measured_bound("H_spread", 7.7242e-9, h, 4.0),
      upper_bound_gate("H_form_difference", 1e-12, GateScope::AllLevels,
                       "compact and flattened H agree to round-off when m = R K (u - u_hat)")};
  std::vector<MetricSpec> metrics{
      error_metric("shape_max_error", "", "max |r_i - r_helix(s_i)| / L over the vertices", 2.0),
      error_metric("frame_max_error", "", "max |R_i - R_helix(s_i)| (entries) at the stations", 2.0),
      error_metric("strain_max_error", "", "max |u_i - (tau, kappa, 0)| / sqrt(kappa^2 + tau^2)", 2.0),
      diagnostic_metric("newton_iterations", "Newton iterations")};
  for (auto& m : noether3d_metric_specs(true, 4.0, 2.0)) metrics.push_back(m);
  registry.add(make_case(
      "rod3d",
      {"rod3d/helix-axial-wrench", "Uniform helix held by an axial wrench on the nodal 3-D rod",
       "Kirchhoff rod (bending B both axes, twisting C != B) clamped in the helix frame at s = 0, loaded at s = L by "
       "the dead force and moment of the closed form, natural twist u_hat0 = tau - M_t / C.",
       "kappa = sin^2(a)/R, tau = sin(a)cos(a)/R; n = F e_z, F = (M_t - B tau) sin(a)/R; material frame = Frenet frame "
       "(t, b, -N); H = F cos(a) + B kappa^2/2 + M_t tau - M_t^2/(2C)",
       "Love 1944 §§270-271; PHYSICS.md §7.1", kMethod, "rod-3d/helix-axial-wrench"},
      {make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness (both axes)"),
       make_parameter("C", 0.9, 0.0, 1e12, true, false, "force length^2", "twisting stiffness"),
       make_parameter("radius", 0.7, 0.0, 1e6, true, false, "length", "helix radius R"),
       make_parameter("pitch_angle", 0.6, 0.1, 1.4, false, false, "rad", "angle between tangent and axis"),
       make_parameter("twisting_moment", 0.37, -10.0, 10.0, false, false, "force length", "M_t = m.t"),
       make_parameter("L", 3.1, 0.0, 1e3, true, false, "length", "rod length")},
      element_levels("number of edges", {16, 32, 64}, {16, 32, 64, 128}), std::move(metrics),
      std::move(gates), run));
}

}  // namespace rodvv::harness::rod3d_cases

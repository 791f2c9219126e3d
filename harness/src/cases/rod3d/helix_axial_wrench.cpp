// rod3d/helix-axial-wrench: the uniform helix held by an axial wrench (Love 1944 §§270-271;
// PHYSICS.md §7.1) on the nodal 3-D rod: clamped at s = 0 in the helix's material frame, loaded at
// the tip by the dead force n(L) and moment m(L) of the closed form, natural twist u_hat0 so that
// the twisting moment is M_t. Newton starts from a helix of 1 % smaller radius and pitch angle (divided
// by the turns beyond one), so the case checks that the discrete equilibrium converges to THE helix,
// not that it stays put.
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "../case_builder.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

ref::AxialWrenchHelix helix_of(const Parameters& p) {
  return {parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "radius"),
          parameter_value(p, "pitch_angle"), parameter_value(p, "twisting_moment")};
}

Solution solve(const Parameters& p, double level) {
  const ref::AxialWrenchHelix helix = helix_of(p);
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
  const double offset = 0.01 / std::max(1.0, helix_turns(p));
  ref::AxialWrenchHelix start = helix;
  start.radius *= 1.0 - offset;
  start.pitch_angle *= 1.0 - offset;
  const auto initial = state_on_curve(model, [&](double s) {
    const auto point = ref::axial_wrench_helix_point(start, s);
    return CurvePoint{point.position, point.frame};
  });
  // Newton with its line search from the start; where that fails (measured at M_t >= 1 and the other
  // defaults, a residual stuck near 1), pseudo-transient continuation from the same start, whose first
  // steps are damped (tau = 1e3) - alone it leaves helices of more than ~1.3 turns (L = 12), which
  // Newton reaches. Either converges to THE helix or the shape gates say it did not.
  rod::StaticOptions options;
  options.tolerance = 1e-12;
  const auto result = [&] {
    try {
      return rod::solve_static(model, initial, options);
    } catch (const SolverError&) {
      options.pseudo_transient = true;
      options.initial_pseudo_time = 1e3;
      options.max_iterations = 400;
      return rod::solve_static(model, initial, options);
    }
  }();
  SpatialRodSolution solution = rod::make_solution(model, result.state);
  solution.iterations = result.iterations;
  return solution;
}

// Reads only the solution: the shape from its vertices; the frames, strains and H from its stations
// where it has them. A file from another 3-D rod solver (the same clamp: the helix's frame at s = 0,
// the closed form's dead force and moment at s = L) is measured exactly like rodvv's own.
LevelOutput measure(const Parameters& p, double, const Solution& any) {
  const auto& solution = solution_as<SpatialRodSolution>(any, "spatial_rod");
  const ref::AxialWrenchHelix helix = helix_of(p);
  const double L = parameter_value(p, "L");
  const auto exact = ref::axial_wrench_helix(helix);
  if (solution.vertex_position.size() < 2 || solution.vertex_s.size() != solution.vertex_position.size())
    throw InputError("vertices", "the helix needs at least 2 vertices, each with its s, got " +
                                     std::to_string(solution.vertex_position.size()) + " positions and " +
                                     std::to_string(solution.vertex_s.size()) + " arclengths");
  double shape = 0.0;
  for (std::size_t i = 0; i < solution.vertex_s.size(); ++i)
    shape = std::max(shape, (solution.vertex_position[i] - ref::axial_wrench_helix_point(helix, solution.vertex_s[i]).position).norm());
  LevelOutput output;
  output.metrics["shape_max_error"] = value_sample(shape / L, 1.0);
  if (!solution.s.empty()) {
    double frame = 0.0, strain = 0.0;
    for (std::size_t i = 0; i < solution.s.size(); ++i) {
      frame = std::max(frame, (solution.frame[i] - ref::axial_wrench_helix_point(helix, solution.s[i]).frame).cwiseAbs().maxCoeff());
      strain = std::max(strain, (solution.strain_u[i] - Vec3(exact.tau, exact.kappa, 0.0)).cwiseAbs().maxCoeff());
    }
    output.metrics["frame_max_error"] = value_sample(frame, 1.0);  // radians
    output.metrics["strain_max_error"] = value_sample(strain / exact.darboux, 1.0);
    add_noether3d_metrics(output, solution, exact.H);
  }
  if (solution.iterations > 0) output.metrics["newton_iterations"] = diagnostic(double(solution.iterations));
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

// The helix is posed in units of its radius (R and L scaled alike by 1e-2 or 10 pass), so three
// numbers shape it, each measured over a grid of the others' defaults (2026-11-26, levels 32 .. 128):
// - turns L sin(a) / (2 pi R) in [0.015, 1.5]: at 0.013 (L = 0.1) the errors of the finest levels
//   reach Newton's tolerance floor; at 1.8 (L = 14) and beyond neither Newton nor the pseudo-transient
//   fallback reaches the helix from the 1 % start at 32 edges;
// - the twisting moment M_t R / B in [-4.5, 5]: at -5.4 (M_t = -10) the frame order is 1.89, still
//   pre-asymptotic on these levels (1.84, 1.94, 1.98 pairwise up to N = 256); at 5.4 (M_t = 10) both
//   solves fail with levels finer than these;
// - C / B in [0.03, 100]: at 0.007 (C = 0.009) an order leaves its window, at B = 1e12 or C = 1e12 all
//   levels fail.
void require_helix_windows(Case& c) {
  require(c, helix_turns_window(0.015, 1.5, "the turns the levels resolve"));
  require_window(c, "twisting_moment x radius / B in [-4.5, 5]", [](const Parameters& p) {
    const double moment = parameter_value(p, "twisting_moment") * parameter_value(p, "radius") / parameter_value(p, "B");
    if (!(moment >= -4.5 && moment <= 5.0))
      throw InputError("twisting_moment",
                       fmt::format("invalid parameters: twisting_moment x radius / B = {} must be in [-4.5, 5], where "
                                   "the levels resolve the helix",
                                   format_value(moment)));
  });
  require(c, ratio_window("C", "B", 0.03, 100.0, "the twist-to-bending ratios the levels resolve the helix at"));
}

}  // namespace

void add_helix_axial_wrench(Registry& registry) {
  // Levels 32, 64, 128 (were 16, 32, 64: at 16 edges a helix of more than ~1.3 turns is not in Newton's
  // reach from a 1 % offset, and the H spread's order 4 was pre-asymptotic off the defaults, 3.82 .. 3.87).
  // Values measured at N = 128 (2026-11-26).
  const double h = 1.0 / 128.0;
  std::vector<GateSpec> gates{
      order_gate("shape_max_error", 2.0, "chords of the helix, curvature 2 tan(phi/2)/ebar: O(h^2)"),
      order_gate("frame_max_error", 2.0, "halfway rotation of the edge frames vs the frame at the vertex: O(h^2)"),
      order_gate("strain_max_error", 2.0, "discrete curvature and twist of a uniform helix: O(h^2)"),
      order_gate("H_mean", 2.0, "H at the vertices from O(h^2) strains and edge-averaged forces"),
      // H is uniform along the discrete helix except where the clamp and the tip load end it: its
      // spread falls at fourth order at the defaults (measured 3.996 over N = 16 ... 128), a
      // superconvergence not derived: off the defaults the same levels give 3.5 .. 3.9, or reach the
      // round-off floor (radius 1.5: 1.63), so the order is a measured gate like the bounds.
      measured_order_gate("H_spread", 4.0, "the discrete helix is uniform away from its ends: H spread O(h^4) "
                                           "(measured at the defaults)"),
      measured_bound("shape_max_error", 4.3436e-5, h, 2.0),
      measured_bound("frame_max_error", 1.0198e-4, h, 2.0),
      measured_bound("strain_max_error", 6.8394e-5, h, 2.0),
      measured_bound("H_mean", 1.8464e-5, h, 2.0),
      measured_bound("H_spread", 4.8383e-10, h, 4.0),
      upper_bound_gate("H_form_difference", 1e-12, GateScope::AllLevels,
                       "compact and flattened H agree to round-off when m = R K (u - u_hat)")};
  std::vector<MetricSpec> metrics{
      error_metric("shape_max_error", "", "max |r_i - r_helix(s_i)| / L over the vertices", 2.0),
      error_metric("frame_max_error", "", "max |R_i - R_helix(s_i)| (entries) at the stations", 2.0),
      error_metric("strain_max_error", "", "max |u_i - (tau, kappa, 0)| / sqrt(kappa^2 + tau^2)", 2.0),
      diagnostic_metric("newton_iterations", "Newton iterations")};
  for (auto& m : noether3d_metric_specs(true, 4.0, 2.0)) metrics.push_back(m);
  Case c = make_case(
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
      element_levels("number of edges", {32, 64, 128}, {32, 64, 128, 256}), std::move(metrics),
      std::move(gates), nullptr);
  split_level(c, solve, measure);
  require_helix_windows(c);
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

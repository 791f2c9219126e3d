// rod3d/heavy-cantilever: a cantilever under its own weight on the nodal 3-D rod, clamped in a tilted
// frame with EI1 != EI2 != GJ, against the planar shooting solution of the same problem (an oracle that
// shares no code with the nodal rod: RKF78 on theta' = m/EI, m' = -(r' x n), n' = rho S g). The
// distributed load makes the internal force vary along the rod, so the vertex forces the solution
// reports (the mean of the two edges' forces) carry their O(h^2) into H: with the dead tip loads of
// the other rod3d cases the edge force is constant, and a one-sided vertex force went unseen
// (tests/mutation: rod3d-solution-force-one-sided).
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "../case_builder.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/shooting.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace e2d = solvers::elastica2d;
using namespace cases;

struct HeavyCantilever {
  double L, EI, weight;  // weight = rho S g, per unit length
};
HeavyCantilever heavy_of(const Parameters& p) {
  return {parameter_value(p, "L"), parameter_value(p, "EI"), parameter_value(p, "rhoS") * parameter_value(p, "g")};
}

// The clamp: a general tilted frame and an offset root; gravity along its third director, so that the
// rod bends about the first (EI1 = EI).
const Mat3 kClampFrame = tilted_frame(-0.4);
Vec3 clamp_position(double L) { return Vec3(-0.3, 0.1, 0.5) * L; }

// The planar problem: clamped horizontally at s = 0, V(x, y) = w y per unit length (f = -w e_y).
e2d::Problem planar_problem(const HeavyCantilever& c) {
  e2d::Problem problem;
  problem.length = c.L;
  problem.bending_stiffness = [EI = c.EI](double) { return EI; };
  problem.start.support = e2d::Support::Clamped;
  problem.potential.value = [w = c.weight](double, double y) { return w * y; };
  problem.potential.gradient = [w = c.weight](double, double) { return Eigen::Vector2d(0.0, w); };
  problem.potential.hessian = [](double, double) { return Eigen::Matrix2d::Zero().eval(); };
  return problem;
}

struct ShootingTip {
  double down, along;  // tip deflection along gravity, tip position along the clamp tangent
};
// RKF78 at 1e-13 (errors ~1e-12, far below the levels' h^2), started from the arcs solution at N = 64.
ShootingTip shooting_tip(const HeavyCantilever& c) {
  const e2d::Problem problem = planar_problem(c);
  e2d::SolverOptions discrete;
  discrete.load_steps = 4;
  const auto guess = e2d::shooting_guess_from(e2d::solve_static(problem, {e2d::Scheme::Arcs, 64}, discrete), problem);
  e2d::ShootingOptions options;
  options.sample_points = 1;
  const PlanarRodSolution solution = e2d::solve_shooting(problem, options, guess);
  return {-solution.y.back(), solution.x.back()};
}

Solution solve(const Parameters& p, double level) {
  const HeavyCantilever c = heavy_of(p);
  rod::RodModel model;
  model.elements = element_count(level);
  model.length = c.L;
  model.stiffness = Vec3(0.7 * c.EI, c.EI, 2.3 * c.EI);  // (GJ, EI1, EI2)
  model.line_density = parameter_value(p, "rhoS");
  model.gravity = parameter_value(p, "g") * kClampFrame.col(2);
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = kClampFrame;
  model.root.position = clamp_position(c.L);
  rod::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-12;
  const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
  SpatialRodSolution solution = rod::make_solution(model, result.state);
  solution.iterations = result.iterations;
  return solution;
}

// Reads only the solution's vertices and stations: a file from another 3-D rod solver is measured
// like rodvv's own.
LevelOutput measure(const Parameters& p, double, const Solution& any) {
  const auto& solution = solution_as<SpatialRodSolution>(any, "spatial_rod");
  const HeavyCantilever c = heavy_of(p);
  if (solution.vertex_position.size() < 2)
    throw InputError("vertices", "the cantilever needs at least 2 vertices, got " +
                                     std::to_string(solution.vertex_position.size()));
  const ShootingTip exact = shooting_tip(c);
  const Vec3 t0 = kClampFrame.col(0), down = kClampFrame.col(2);
  const Vec3 tip = solution.vertex_position.back() - clamp_position(c.L);
  LevelOutput output;
  output.metrics["tip_w"] = error_sample(tip.dot(down), exact.down);
  output.metrics["tip_u"] = error_sample(c.L - tip.dot(t0), c.L - exact.along);
  output.metrics["tip_w"].scale = output.metrics["tip_u"].scale = c.L;
  output.metrics["out_of_plane"] = value_sample(std::abs(tip.dot(t0.cross(down))) / c.L);
  if (solution.iterations > 0) output.metrics["newton_iterations"] = diagnostic(double(solution.iterations));
  if (!solution.s.empty()) add_noether3d_metrics(output, solution, std::nullopt);
  return output;
}

}  // namespace

void add_heavy_cantilever(Registry& registry) {
  const double h = 1.0 / 128.0;
  constexpr double kTipW = 1.4009e-05, kTipU = 2.1395e-06, kHSpread = 1.3280e-05;  // errors at N = 128
  // Measured at N = 128 (default parameters, 2026-11-26); bounds C h^2 with C = 2 x measured.
  std::vector<GateSpec> gates{
      order_gate("tip_w", 2.0, "polygon curvature 2 tan(phi/2)/ebar, ghost-edge clamp, lumped weights: O(h^2)"),
      order_gate("tip_u", 2.0, "as tip_w"),
      order_gate("H_spread", 2.0, "H at the vertices with the mean of the two edges' forces: O(h^2)"),
      measured_bound("tip_w", kTipW, h, 2.0),
      measured_bound("tip_u", kTipU, h, 2.0),
      measured_bound("H_spread", kHSpread, h, 2.0),
      // Planar loading in a tilted frame: only round-off leaves the plane (mattiasson-2: ~eps N^4).
      out_of_plane_round_off_gate("planar loading: round-off drift only, ~eps N^4 (measured 0.03 eps N^4 at "
                                  "N = 128)"),
      upper_bound_gate("H_form_difference", 1e-12, GateScope::AllLevels,
                       "compact and flattened H agree to round-off when m = R K (u - u_hat)")};
  std::vector<MetricSpec> metrics{
      error_metric("tip_w", "length", "deflection of the tip along gravity vs shooting", 2.0, true),
      error_metric("tip_u", "length", "shortening of the tip along the clamp tangent vs shooting", 2.0, true),
      error_metric("out_of_plane", "", "|tip . (t0 x d)| / L", std::nullopt),
      diagnostic_metric("newton_iterations", "Newton iterations (all load steps)")};
  for (auto& m : noether3d_metric_specs(false, 2.0)) metrics.push_back(m);
  Case c = make_case(
      "rod3d",
      {"rod3d/heavy-cantilever", "Cantilever under its own weight on the nodal 3-D rod, tilted clamp",
       "Inextensible Kirchhoff rod clamped with a general tilted frame, gravity g along the clamp's third director "
       "(it bends about m1: EI1 = EI; EI2 = 2.3 EI, GJ = 0.7 EI), line density rhoS; w = rhoS g L^3 / EI.",
       "The planar heavy cantilever by shooting (RKF78 at 1e-13 on the same ODEs, an independent code); H constant "
       "along s (Noether: the uniform field's potential does not depend on s), with V = -rhoS g.r",
       "PHYSICS.md §1.2, §3.5", kMethod, "rod-3d/heavy-cantilever"},
      {make_parameter("L", 1.3, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI", 1.7, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 (EI2 = 2.3 EI, GJ = 0.7 EI)"),
       make_parameter("rhoS", 0.8, 0.0, 1e12, true, false, "mass / length", "line density"),
       make_parameter("g", 2.1, 0.0, 1e12, true, false, "length / time^2", "gravity")},
      element_levels("number of edges", {16, 32, 64, 128}, {16, 32, 64, 128, 256}), std::move(metrics),
      std::move(gates), nullptr);
  split_level(c, solve, measure);
  // The weight the levels resolve, 1e-3 <= w = rhoS g L^3 / EI <= 5 (default 2.17). Measured 2026-11-26: every gate
  // passes from w = 1e-3 to 5.48 (and at L = 1e-3 with g scaled); from 5.58 the H spread's order is below 1.9 on
  // N = 32 .. 128 (1.86 at 7.2), pre-asymptotic. Below 1e-3 the horizontal tip displacement, O(w^2), reaches the
  // Newton floor (tip_u's order 1.82 at 1e-4, none at 1e-5; 2026-11-28: L = 0.013 or EI = 1e12 with g held
  // failed, the lower end had not been enforced).
  require_window(c, "1e-3 <= rhoS g L^3 / EI <= 5 (the weight the levels resolve)", [](const Parameters& p) {
    const HeavyCantilever rod = heavy_of(p);
    const double w = rod.weight * rod.L * rod.L * rod.L / rod.EI;
    if (!(w >= 1e-3 && w <= 5.0))
      throw InputError("g", fmt::format("invalid parameters: the weight rhoS g L^3 / EI = {} must be in [1e-3, 5], "
                                        "where the levels resolve the cantilever",
                                        format_value(w)));
  });
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

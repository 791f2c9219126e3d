// elastica/manufactured/<scheme>: the method of manufactured solutions on the planar elastica (issue 13,
// class 2; references/manufactured_planar_rod.hpp). The planar solvers take their distributed load as a
// potential field V(x, y), so the shape is chosen - theta(s) with a varying curvature, EI(s) varying by +-30 %
// - with a field V (a quadratic well tilted against the rod, coupling x and y) and dead tip loads F, M, and the
// equilibrium then fixes n(s), m(s) and the natural curvature kappa_hat = theta' - m / EI that the solver is
// given. Every input of the planar statics is used at once: EI(s), kappa_hat(s), the potential's gradient and
// Hessian, the free end's dead force and couple, a clamp at a rotated angle. Metrics: the tangent angle and the
// positions at the nodes, the internal force n and the moment EI (kappa - kappa_hat) there, each the largest
// deviation over the nodes (in units of pi, L, max |n|, max |m|).
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "../case_builder.hpp"
#include "elastica_problems.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/references/manufactured_planar_rod.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::harness::elastica_cases {

namespace {

namespace e2d = solvers::elastica2d;
namespace ref = references;
using namespace cases;

// The manufactured rod at (L, EI, amplitude): theta's variation scaled by the amplitude, the field and the tip
// loads in units of EI/L^3, EI/L^2 and EI/L (1: the rod turns by about 1.5 rad and back).
ref::ManufacturedPlanarRod manufactured_rod(const Parameters& p) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), a = parameter_value(p, "amplitude");
  ref::ManufacturedPlanarRod rod;
  rod.length = L;
  rod.root_x = 0.3 * L;
  rod.root_y = -0.5 * L;
  rod.theta_root = 0.4;
  rod.theta_slope = a * 1.1;
  rod.theta_sine = -a * 0.7;
  rod.theta_cosine = a * 0.35;
  rod.stiffness = EI;
  rod.stiffness_variation = 0.3;
  rod.field_xx = 1.3 * EI / (L * L * L * L);
  rod.field_xy = -0.6 * EI / (L * L * L * L);
  rod.field_y = 2.2 * EI / (L * L * L);
  rod.tip_force_x = -0.8 * EI / (L * L);
  rod.tip_force_y = 1.7 * EI / (L * L);
  rod.tip_moment = 0.45 * EI / L;
  return rod;
}

e2d::Problem planar_problem(const ref::ManufacturedPlanarRod& rod) {
  e2d::Problem problem;
  problem.length = rod.length;
  // EI(s) and kappa_hat(s) from the reference's stations (the solver samples each at its nodes and
  // quadrature points once per solve).
  problem.bending_stiffness = [rod](double s) {
    return rod.stiffness * (1.0 + rod.stiffness_variation * std::sin(std::numbers::pi * s / rod.length));
  };
  problem.natural_curvature = [rod](double s) {
    return ref::manufactured_planar_stations(rod, {std::clamp(s, 0.0, rod.length)}).front().natural_curvature;
  };
  problem.potential.value = [rod](double x, double y) {
    return 0.5 * rod.field_xx * x * x + rod.field_xy * x * y + rod.field_y * y;
  };
  problem.potential.gradient = [rod](double x, double y) {
    return Eigen::Vector2d(rod.field_xx * x + rod.field_xy * y, rod.field_xy * x + rod.field_y);
  };
  problem.potential.hessian = [rod](double, double) {
    return (Eigen::Matrix2d() << rod.field_xx, rod.field_xy, rod.field_xy, 0.0).finished();
  };
  problem.start.support = e2d::Support::Clamped;
  problem.start.x = rod.root_x;
  problem.start.y = rod.root_y;
  problem.start.angle = rod.theta_root;
  problem.end.load = {rod.tip_force_x, rod.tip_force_y, rod.tip_moment};
  return problem;
}

Solution solve(e2d::Scheme scheme, const Parameters& p, double level) {
  e2d::SolverOptions options;
  options.load_steps = 8;
  options.tolerance = 1e-12;
  PlanarRodSolution solution =
      e2d::solve_static(planar_problem(manufactured_rod(p)), {scheme, element_count(level)}, options);
  return solution;
}

LevelOutput measure(const Parameters& p, double, const Solution& any) {
  const auto& rod = solution_as<PlanarRodSolution>(any, "planar_rod");
  if (rod.s.size() < 2 || rod.force_x.size() != rod.s.size() || rod.kappa.size() != rod.s.size())
    throw InputError("nodes", "the manufactured elastica needs at least 2 nodes with angle, curvature and force");
  const ref::ManufacturedPlanarRod exact_rod = manufactured_rod(p);
  const auto exact = ref::manufactured_planar_stations(exact_rod, rod.s);
  double theta = 0.0, position = 0.0, force = 0.0, moment = 0.0, force_size = 0.0, moment_size = 0.0;
  for (std::size_t i = 0; i < exact.size(); ++i) {
    const auto& e = exact[i];
    theta = std::max(theta, std::abs(rod.theta[i] - e.theta));
    position = std::max(position, std::hypot(rod.x[i] - e.x, rod.y[i] - e.y));
    force = std::max(force, std::hypot(rod.force_x[i] - e.force_x, rod.force_y[i] - e.force_y));
    const double m = rod.bending_stiffness[i] * (rod.kappa[i] - rod.natural_curvature[i]);
    moment = std::max(moment, std::abs(m - e.moment));
    force_size = std::max(force_size, std::hypot(e.force_x, e.force_y));
    moment_size = std::max(moment_size, std::abs(e.moment));
  }
  LevelOutput output;
  output.metrics["theta"] = value_sample(theta / std::numbers::pi, 1.0);
  output.metrics["position"] = value_sample(position / exact_rod.length, 1.0);
  output.metrics["force"] = value_sample(force / force_size, 1.0);
  output.metrics["moment"] = value_sample(moment / moment_size, 1.0);
  if (rod.iterations > 0) output.metrics["newton_iterations"] = diagnostic(double(rod.iterations));
  return output;
}

// What another solver needs to pose the problem (`rodvv problem`): the clamp, the potential's coefficients, the
// tip loads, EI(s) and the natural curvature at uniform stations, and the exact solution there.
ProblemData problem_data(const Parameters& p, std::size_t intervals) {
  const ref::ManufacturedPlanarRod rod = manufactured_rod(p);
  const std::vector<double> s = uniform_stations(rod.length, intervals);
  ProblemData data;
  data.description =
      "A planar inextensible, unshearable rod of length `length`, clamped at s = 0 at (root_x, root_y) with tangent "
      "angle theta_root; bending stiffness bending_stiffness(s) and natural curvature natural_curvature(s) per "
      "station; loaded by the potential V(x, y) = 1/2 field_xx x^2 + field_xy x y + field_y y per unit length "
      "(force density -grad V) and at s = L by the dead force (tip_force_x, tip_force_y) and moment tip_moment. The "
      "other columns are the exact solution: x, y, theta, kappa, force_x, force_y (the internal force, the action of "
      "(s, L] on [0, s]) and moment.";
  data.values = {{"length", rod.length},           {"root_x", rod.root_x},
                 {"root_y", rod.root_y},           {"theta_root", rod.theta_root},
                 {"field_xx", rod.field_xx},       {"field_xy", rod.field_xy},
                 {"field_y", rod.field_y},         {"tip_force_x", rod.tip_force_x},
                 {"tip_force_y", rod.tip_force_y}, {"tip_moment", rod.tip_moment}};
  data.columns = {"s", "bending_stiffness", "natural_curvature", "x", "y", "theta", "kappa", "force_x", "force_y",
                  "moment"};
  for (const auto& q : ref::manufactured_planar_stations(rod, s))
    data.rows.push_back({q.s, q.bending_stiffness, q.natural_curvature, q.x, q.y, q.theta, q.kappa, q.force_x,
                         q.force_y, q.moment});
  return data;
}

}  // namespace

void add_manufactured(Registry& registry) {
  for (e2d::Scheme scheme : {e2d::Scheme::Polygon, e2d::Scheme::Arcs}) {
    const std::string id(e2d::scheme_id(scheme));
    Case c = make_case(
        "elastica",
        {"elastica/manufactured/" + id, "Manufactured planar equilibrium: varying EI, natural curvature, a field, " + id,
         "Inextensible planar elastica, EI(s) = EI (1 + 0.3 sin(pi s / L)), natural curvature kappa_hat(s), a "
         "quadratic potential V(x, y) per unit length coupling x and y, clamped at a rotated angle at s = 0, dead "
         "force and couple at the free tip.",
         "The manufactured fields (references/manufactured_planar_rod.hpp: n and m by GSL rk8pd from the tip, "
         "checked against an mpmath table to 6 eps)",
         "Roache 2002 (method of manufactured solutions)",
         std::string(scheme == e2d::Scheme::Polygon ? "polygon (curvature at vertices)" : "arcs (exact circular arcs)") +
             "; Newton on the KKT system, banded LU, load stepping",
         "elastica/manufactured"},
        {make_parameter("L", 1.6, 0.0, 1e6, true, false, "length", "rod length"),
         make_parameter("EI", 0.9, 0.0, 1e12, true, false, "force length^2", "bending stiffness at s = 0"),
         // amplitude measured 2026-11-28: every gate passes on both schemes from 0.01 to 10 (the range).
         make_parameter("amplitude", 1.0, 0.0, 10.0, true, false, "", "scale of the variation of theta(s)")},
        element_levels("number of elements", {16, 32, 64, 128}, {16, 32, 64, 128, 256}),
        {invariant_metric("theta", "max |theta - theta(s)| / pi over the nodes", 2.0),
         invariant_metric("position", "max |r - r(s)| / L over the nodes", 2.0),
         invariant_metric("force", "max |n - n(s)| / max |n(s)| over the nodes", 2.0),
         invariant_metric("moment", "max |EI (kappa - kappa_hat) - m(s)| / max |m(s)| over the nodes", 2.0),
         diagnostic_metric("newton_iterations", "Newton iterations (all load steps)")},
        {}, nullptr);
    // Measured at the defaults (2026-11-28) over N = 16 .. 256: every metric at order 2.00 (pairwise 1.99 .. 2.01),
    // at N = 128: polygon theta 6.1664e-5, position 5.7898e-5, force 1.1833e-5, moment 7.2095e-5; arcs 2.4365e-5,
    // 1.6161e-5, 2.3052e-6, 8.3570e-4 (the arcs' node moment is the mean of two element curvatures).
    const bool polygon = scheme == e2d::Scheme::Polygon;
    for (const auto& [metric, measured] :
         {std::pair{"theta", polygon ? 6.1664e-5 : 2.4365e-5}, {"position", polygon ? 5.7898e-5 : 1.6161e-5},
          {"force", polygon ? 1.1833e-5 : 2.3052e-6}, {"moment", polygon ? 7.2095e-5 : 8.3570e-4}}) {
      c.gates.push_back(order_gate(metric, 2.0, "both planar schemes are second order in h = L/N"));
      c.gates.push_back(measured_bound(metric, measured, 1.0 / 128.0, 2.0));
    }
    split_level(
        c, [scheme](const Parameters& p, double level) { return solve(scheme, p, level); }, measure);
    c.problem_data = problem_data;
    registry.add(std::move(c));
  }
}

}  // namespace rodvv::harness::elastica_cases

// rod3d/bathe-bolourchi: the 45-degree bend (Bathe & Bolourchi 1979; PRIOR_ART.md §4.2): a curved
// cantilever (a 45-degree arc of radius R = 100, naturally curved) loaded at its free end by a dead
// force of 600 normal to its plane. No closed form: the verification is self-convergence (the
// difference between the tip at N and at 2N falls at second order, with a magnitude bound), and the
// validation is the converged published tip displacement of a geometrically exact beam (Kynema's
// spectral solution, (-23.6459716009047, 13.7208006040058, 53.5776450626987), with shear stiffness
// kGA = 4.16667e6 and EA = 1e7), compared through its frame-free parts: the component along the load
// (53.578) and the in-plane magnitude (27.338). Reported, not gated: this inextensible, unshearable
// rod converges to values 0.109 (0.2 %) and 0.133 below them (extrapolated from N = 16 ... 128),
// ten times the shear compliance estimate P L / kGA = 0.011. The Super-Helix, a different
// discretisation sharing no code with this one (superhelix/bathe-bolourchi), converges to the same
// tip to 2e-5 (53.46862 vs 53.46860 along the load, 27.20516 vs 27.20515 in plane, both extrapolated
// from 2N = 64, 128): the gap is between the Kirchhoff rod and Kynema's beam model (shear, extension,
// or its torsional input GJ = 8.333e5 = G I_p, used here as given), not a discretisation error.
#include <cmath>
#include <numbers>

#include "../case_builder.hpp"
#include "bathe_bolourchi.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
using namespace cases;
constexpr double kPi = std::numbers::pi;

}  // namespace

BatheBolourchiTip nodal_bathe_bolourchi_tip(double R, double EI, double P, std::size_t elements) {
  const Mat3 Q = tilted_frame(0.4);
  const double L = R * kPi / 4.0;
  // The arc in the plane of Q e_x (initial tangent) and Q e_y (towards the centre); material frame
  // (t, N, b): curvature 1/R about m2 = b.
  const auto arc = [&](double s) {
    const double a = s / R;
    CurvePoint point;
    point.position = Q * Vec3(R * std::sin(a), R * (1.0 - std::cos(a)), 0.0);
    point.frame.col(0) = Q * Vec3(std::cos(a), std::sin(a), 0.0);
    point.frame.col(1) = Q * Vec3(-std::sin(a), std::cos(a), 0.0);
    point.frame.col(2) = Q * Vec3::UnitZ();
    return point;
  };
  rod::RodModel model;
  model.elements = elements;
  model.length = L;
  model.stiffness = Vec3(EI, EI, EI);  // Kynema's input: GJ = EI1 = EI2 = 8.333e5
  model.natural_strain = Vec3(0.0, 0.0, 1.0 / R);
  model.root.support = rod::EndSupport::Clamped;
  model.root.position = arc(0.0).position;
  model.root.frame = arc(0.0).frame;
  const Vec3 load_direction = Q * Vec3::UnitZ();
  model.end_force = P * load_direction;
  rod::StaticOptions options;
  options.load_steps = 10;
  options.tolerance = 1e-11;
  const auto result = rod::solve_static(model, state_on_curve(model, arc), options);
  const auto solution = rod::make_solution(model, result.state);
  const Vec3 u = solution.vertex_position.back() - arc(L).position;
  return {u.dot(load_direction), (u - u.dot(load_direction) * load_direction).norm()};
}

Parameters bathe_bolourchi_parameters() {
  return {make_parameter("R", 100.0, 0.0, 1e6, true, false, "length", "arc radius"),
          make_parameter("EI", 833333.3333333334, 0.0, 1e15, true, false, "force length^2", "EI1 = EI2 = GJ"),
          make_parameter("P", 600.0, 0.0, 1e4, true, false, "force", "tip load normal to the plane")};
}

cases::Window bathe_bolourchi_load_window() {
  return cases::load_window("R", 0.5, 40.0,
                            "the benchmark's 7.2; beyond 40 the default levels do not reach the asymptotic range, "
                            "below 0.5 the self-convergence and the nodal oracle reach their round-off floors");
}

void add_bathe_bolourchi_metrics(LevelOutput& output, const BatheBolourchiTip& tip, const BatheBolourchiTip& finer,
                                 double R) {
  constexpr double kPublishedAlongLoad = 53.5776450626987;  // Kynema, converged
  constexpr double kPublishedInPlane = 27.338049;           // |(-23.6459716009047, 13.7208006040058)|
  output.metrics["tip_along_load_self"] = {tip.along_load, finer.along_load, std::abs(tip.along_load - finer.along_load)};
  output.metrics["tip_in_plane_self"] = {tip.in_plane, finer.in_plane, std::abs(tip.in_plane - finer.in_plane)};
  output.metrics["tip_along_load_vs_published"] = error_sample(finer.along_load, kPublishedAlongLoad);
  output.metrics["tip_in_plane_vs_published"] = error_sample(finer.in_plane, kPublishedInPlane);
  output.metrics["tip_along_load_self"].scale = output.metrics["tip_in_plane_self"].scale = R;
}

std::vector<MetricSpec> bathe_bolourchi_metric_specs() {
  return {error_metric("tip_along_load_self", "length", "|u.load(N) - u.load(2N)| (self-convergence)", 2.0),
          error_metric("tip_in_plane_self", "length", "| |u_plane(N)| - |u_plane(2N)| | (self-convergence)", 2.0),
          error_metric("tip_along_load_vs_published", "length", "u.load at 2N vs Kynema's converged 53.5776 (reported)",
                       std::nullopt),
          error_metric("tip_in_plane_vs_published", "length", "|u_plane| at 2N vs Kynema's converged 27.3380 (reported)",
                       std::nullopt)};
}

namespace {

LevelOutput run(const Parameters& p, double level) {
  const std::size_t n = element_count(level);
  const double R = parameter_value(p, "R"), EI = parameter_value(p, "EI"), P = parameter_value(p, "P");
  LevelOutput output;
  add_bathe_bolourchi_metrics(output, nodal_bathe_bolourchi_tip(R, EI, P, n), nodal_bathe_bolourchi_tip(R, EI, P, 2 * n), R);
  return output;
}

}  // namespace

void add_bathe_bolourchi(Registry& registry) {
  const double h = 1.0 / 32.0;
  const std::string self_why = "self-convergence |u(N) - u(2N)| = (3/4) C h^2 for a second-order scheme";
  std::vector<GateSpec> gates{order_gate("tip_along_load_self", 2.0, self_why),
                              order_gate("tip_in_plane_self", 2.0, self_why),
                              measured_bound("tip_along_load_self", 3.1016e-2, h, 2.0),
                              measured_bound("tip_in_plane_self", 1.7034e-2, h, 2.0)};
  Case c = make_case(
      "rod3d",
      {"rod3d/bathe-bolourchi", "Bathe-Bolourchi 45-degree bend under an out-of-plane tip load",
       "Naturally curved inextensible cantilever, 45-degree arc of radius R (tilted plane), EI1 = EI2 = GJ = EI; dead "
       "tip force P normal to the plane.",
       "Self-convergence |u(N) - u(2N)|; the converged geometrically exact beam of Kynema (with shear) reported beside it",
       "Bathe & Bolourchi 1979; Simo & Vu-Quoc 1986; PRIOR_ART.md §4.2 (Kynema's converged value)", kMethod,
       "rod-3d/bathe-bolourchi"},
      bathe_bolourchi_parameters(),
      element_levels("number of edges (the level also solves 2N)", {8, 16, 32}, {8, 16, 32, 64}),
      bathe_bolourchi_metric_specs(), std::move(gates), run);
  require(c, bathe_bolourchi_load_window());
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

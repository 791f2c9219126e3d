#include "nodal_plectoneme.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "contact_profile.hpp"
#include "knot_cases.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::knot_cases {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

namespace {

constexpr double kPi = std::numbers::pi;
const char* const kMethod = kContactStaticsMethod;

}  // namespace

NodalPly nodal_ply_of(const Parameters& p, double theta0) {
  return {parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "radius"), theta0,
          parameter_value(p, "barrier")};
}

std::vector<Parameter> nodal_ply_parameters(double C, double barrier_low, double barrier_high) {
  return {make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 = EI2"),
          make_parameter("C", C, 0.0, 1e12, true, false, "force length^2", "twisting stiffness GJ"),
          make_parameter("radius", 0.05, 0.0, 1e6, true, false, "length", "rod radius h (contact at distance 2h)"),
          make_parameter("barrier", 500.0, barrier_low, barrier_high, false, false, "",
                         "barrier stiffness k h^2 / T_ext")};
}

LevelOutput relax_nodal_plectoneme(const NodalPly& k, const PlyLayout& layout, std::size_t n) {
  const ref::PlectonemeSolution laid_law = ply_law(k.B, k.h, k.theta0);
  // The twist that holds a left-handed ply: M_t / C > 0 (the law's M_t is a right-handed ply's).
  const double T_ext = laid_law.tail_tension, twist_rate = -laid_law.ply.twisting_moment / k.C;
  const TiedRod laid = lay_plectoneme(layout, n);
  const PulledPly pulled = pull_laid_ply(laid, twist_rate, k.B, k.C, T_ext, {k.h, k.barrier * T_ext / (k.h * k.h)});

  rod::StaticOptions options;
  options.pseudo_transient = true;
  // Measured (2026-12-07): 300 to 580 iterations at N = 200 .. 800, theta = 10 .. 35 deg, C/B = 0.69 .. 3; 20 n
  // stops a ply that comes undone (C/B = 0.5 at 35 degrees) in seconds, not minutes.
  options.max_iterations = 20 * n;
  options.tolerance = 1e-9;
  const auto result = rod::solve_static(pulled.model, pulled.start, options);
  return measure_nodal_ply(pulled.model, result, k.B, k.h, T_ext, 0.5 * layout.tail_length);
}

LevelOutput measure_nodal_ply(const rod::RodModel& model, const rod::StaticResult& result, double B, double h,
                              double T_ext, double tail_station) {
  const auto solution = rod::make_solution(model, result.state);
  const double ebar = rod::rest_edge_length(model);
  const auto contacts = rod::self_contacts(model.self_contact, result.state.position, ebar);
  if (contacts.empty())
    throw SolverError(kMethod, "the ply came undone: no self-contact at equilibrium", result.iterations,
                      result.residual);

  // The tails: the station at tail_station on the root's tail.
  const std::size_t tail = station_nearest(solution, tail_station);
  const Vec3 t_tail = solution.frame[tail].col(0);
  PlyMeasurement ply;
  ply.tail_tension = solution.force_n[tail].dot(t_tail);
  ply.twisting_moment = solution.moment_m[tail].dot(t_tail);
  const auto flattened = invariants::noether3d_flattened(solution);
  for (double H : flattened) ply.H_deviation = std::max(ply.H_deviation, std::abs(H - flattened[tail]) / T_ext);

  // The middle of the ply: the root strand's segments first .. of the pairs, the outer quarters dropped.
  std::size_t lo = contacts.front().first, hi = contacts.front().first;
  for (const auto& c : contacts) lo = std::min(lo, c.first), hi = std::max(hi, c.first);
  const std::size_t from = lo + (hi - lo) / 4, to = hi - (hi - lo) / 4;
  const auto tangent = [&](std::size_t j) { return (result.state.position[j + 1] - result.state.position[j]).normalized(); };
  double R_sum = 0.0, theta_sum = 0.0, force_sum = 0.0;
  std::size_t segments = 0;
  for (std::size_t j = from; j <= to; ++j) {
    const rod::ContactPair* closest = nullptr;
    for (const auto& c : contacts)
      if (c.first == j) {
        force_sum += c.force;
        if (!closest || c.distance < closest->distance) closest = &c;
      }
    if (!closest) continue;
    R_sum += 0.5 * closest->distance;
    theta_sum += 0.5 * std::acos(std::clamp(-tangent(j).dot(tangent(closest->second)), -1.0, 1.0));
    ++segments;
  }
  if (segments < 3)
    throw SolverError(kMethod, "no uniform ply: " + std::to_string(segments) + " strand segments in contact in its middle",
                      result.iterations, result.residual);
  ply.R = R_sum / double(segments);
  ply.theta = theta_sum / double(segments);
  if (!(ply.theta < 0.25 * kPi))
    throw SolverError(kMethod, "no uniform ply: the helix angle in its middle is " + std::to_string(ply.theta * 180.0 / kPi) +
                                   " deg, beyond the ply's 45", result.iterations, result.residual);
  ply.contact_force = force_sum / (double(to - from + 1) * ebar);
  std::size_t strand_stations = 0;
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    const double vertex = solution.s[i] / ebar + 0.5;  // the station's vertex index (clamped root)
    if (vertex < double(from) + 1.0 || vertex > double(to)) continue;
    ply.strand_tension += solution.force_n[i].dot(solution.frame[i].col(0));
    ++strand_stations;
  }
  ply.strand_tension /= double(std::max<std::size_t>(strand_stations, 1));

  LevelOutput output;
  add_ply_metrics(output, ply, B, h, T_ext);
  add_noether3d_metrics(output, solution, std::nullopt);
  output.metrics["contact_pairs"] = diagnostic(double(contacts.size()));
  output.series.push_back(contact_force_series(model, contacts));
  output.metrics["iterations"] = diagnostic(double(result.iterations));
  output.metrics["equilibrium_residual"] = diagnostic(result.residual);
  return output;
}

std::vector<MetricSpec> nodal_plectoneme_metric_specs(std::optional<double> H_order) {
  std::vector<MetricSpec> metrics = ply_metric_specs();
  for (auto& spec : metrics)
    if (spec.name == "H_deviation") spec.theoretical_order = H_order;
  for (auto& spec : noether3d_metric_specs(false, std::nullopt)) metrics.push_back(std::move(spec));
  metrics.push_back(diagnostic_metric("contact_pairs", "segment pairs closer than 2h at equilibrium"));
  metrics.push_back(diagnostic_metric("iterations", "Newton iterations of the pseudo-transient relaxation"));
  metrics.push_back(diagnostic_metric("equilibrium_residual", "final scaled residual"));
  return metrics;
}

}  // namespace rodvv::harness::knot_cases

#include "trefoil_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "../case_builder.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"

namespace rodvv::harness::knot_cases {

double TrefoilKnot::lambda() const { return std::sqrt(B / T); }
double TrefoilKnot::radius() const { return looseness * lambda(); }

namespace {
double looseness_of(const Parameters& p) {
  return parameter_value(p, "radius") * std::sqrt(parameter_value(p, "T") / parameter_value(p, "B"));
}
}  // namespace

TrefoilKnot trefoil_knot(const Parameters& p, std::optional<double> looseness, std::optional<double> barrier) {
  return {parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "T"),
          looseness ? *looseness : looseness_of(p), barrier ? *barrier : parameter_value(p, "barrier")};
}

Parameter radius_parameter() {
  return make_parameter("radius", 0.05, 0.0, 1e6, true, false, "length", "rod radius h (contact at distance 2h)");
}

cases::Window looseness_window(double low, double high, std::string why) {
  return cases::group_window("radius", "the looseness radius sqrt(T / B)", looseness_of, low, high, std::move(why));
}

LoopRelations loop_relations(const SpatialRodSolution& solution, double B, double T, const std::string& method,
                             std::size_t iterations, double residual) {
  std::vector<double> tx, kappa;
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    tx.push_back(solution.frame[i].col(0).x());
    kappa.push_back(std::hypot(solution.strain_u[i][1], solution.strain_u[i][2]));
  }
  std::vector<std::size_t> turns;  // i: t.e_x changes sign between stations i and i + 1
  double perpendicular_sum = 0.0;
  for (std::size_t i = 0; i + 1 < tx.size(); ++i)
    if ((tx[i] > 0) != (tx[i + 1] > 0)) {
      const double u = tx[i] / (tx[i] - tx[i + 1]);
      const double kappa_b = kappa[i] + u * (kappa[i + 1] - kappa[i]);
      perpendicular_sum += 0.5 * B * kappa_b * kappa_b / T;
      turns.push_back(i);
    }
  if (turns.size() < 2)
    throw SolverError(method, "no loop: the tangent turns through perpendicular to the pull at " +
                                  std::to_string(turns.size()) + " stations (a tied knot's loop: 2)",
                      iterations, residual);
  std::size_t apex = turns.front() + 1;
  for (std::size_t i = turns.front() + 1; i <= turns.back(); ++i)
    if (tx[i] < tx[apex]) apex = i;
  LoopRelations relations;
  relations.perpendicular_ratio = perpendicular_sum / double(turns.size());
  relations.perpendicular_points = turns.size();
  relations.apex_ratio = B * kappa[apex] * kappa[apex] / (4.0 * T);
  return relations;
}

void add_trefoil_metrics(LevelOutput& output, const SpatialRodSolution& solution, double B, double T, double span,
                         const TrefoilSolve& solve) {
  using namespace cases;
  double deviation = 0.0;
  for (double H : invariants::noether3d_flattened(solution)) deviation = std::max(deviation, std::abs(H - T) / T);
  const LoopRelations loop = loop_relations(solution, B, T, solve.method, solve.iterations, solve.residual);
  output.metrics["H_deviation"] = value_sample(deviation, 1.0);  // in units of the tension
  output.metrics["perpendicular_ratio"] = diagnostic(loop.perpendicular_ratio);
  output.metrics["perpendicular_points"] = diagnostic(double(loop.perpendicular_points));
  output.metrics["apex_ratio"] = diagnostic(loop.apex_ratio);
  output.metrics["shortening_ratio"] = diagnostic((solution.length - span) / (4.0 * std::sqrt(B / T)));
  add_noether3d_metrics(output, solution, T);
}

std::vector<MetricSpec> trefoil_metric_specs() {
  using namespace cases;
  std::vector<MetricSpec> metrics{
      invariant_metric("H_deviation", "max_s |H(s) - T| / T through the knot, V_eff of the barrier included", 1.0)};
  for (auto& spec : noether3d_metric_specs(true, std::nullopt)) metrics.push_back(std::move(spec));
  metrics.push_back(diagnostic_metric("perpendicular_ratio",
                                      "mean of 1/2 B kappa^2 / T where t is perpendicular to the pull (loose limit: 1)"));
  metrics.push_back(diagnostic_metric("perpendicular_points", "where t.e_x changes sign (the loose loop: 2)"));
  metrics.push_back(diagnostic_metric("apex_ratio", "B kappa_apex^2 / (4 T) at the apex (loose limit: 1)"));
  metrics.push_back(diagnostic_metric("shortening_ratio", "(L - end span along the pull) / (4 sqrt(B/T)) (loose limit: 1)"));
  return metrics;
}

Parameters trefoil_parameters(std::vector<Parameter> own) {
  Parameters parameters{make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 = EI2"),
                        make_parameter("C", 0.9, 0.0, 1e12, true, false, "force length^2", "twisting stiffness GJ"),
                        make_parameter("T", 5.2, 0.0, 1e12, true, false, "force", "dead pull at the tip")};
  for (auto& parameter : own) parameters.push_back(std::move(parameter));
  return parameters;
}

}  // namespace rodvv::harness::knot_cases

#include "ply_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "../case_builder.hpp"

namespace rodvv::harness::knot_cases {

using namespace cases;

references::PlectonemeSolution ply_law(double B, double R, double theta) {
  return references::plectoneme({B, R, theta, 0.0, 0.0});
}

double theta_of_moment(double B, double R, double moment) {
  double lo = 1e-9, hi = 0.25 * std::numbers::pi - 1e-12;
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (-ply_law(B, R, mid).ply.twisting_moment < moment ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

void add_ply_metrics(LevelOutput& output, const PlyMeasurement& ply, double B, double h, double T_ext) {
  const references::PlectonemeSolution at = ply_law(B, ply.R, ply.theta);
  // The law's M_t is that of a right-handed ply; the cases' plies are left-handed (plectoneme_tying.hpp): -M_t.
  const double M_law = -at.ply.twisting_moment;
  const double theta_moment = theta_of_moment(B, ply.R, ply.twisting_moment);
  const double T_from_moment = ply_law(B, ply.R, theta_moment).tail_tension;
  constexpr double kDegree = 180.0 / std::numbers::pi;
  output.metrics["H_deviation"] = value_sample(ply.H_deviation, 1.0);  // in units of the tension
  output.metrics["tension_law"] = value_sample(T_ext / at.tail_tension - 1.0);
  output.metrics["tension_from_moment"] = value_sample(T_ext / T_from_moment - 1.0);
  output.metrics["moment_law"] = value_sample(ply.twisting_moment / M_law - 1.0);
  output.metrics["contact_force_law"] = value_sample(ply.contact_force / at.ply.contact_force - 1.0);
  output.metrics["strand_tension_law"] = value_sample(ply.strand_tension / at.ply.tension - 1.0);
  output.metrics["helix_angle"] = diagnostic(ply.theta * kDegree);
  output.metrics["helix_angle_from_moment"] = diagnostic(theta_moment * kDegree);
  output.metrics["ply_radius"] = diagnostic(ply.R / h);
  output.metrics["tail_tension"] = diagnostic(ply.tail_tension);
  output.metrics["twisting_moment"] = diagnostic(ply.twisting_moment);
}

std::vector<MetricSpec> ply_metric_specs() {
  return {
      invariant_metric("H_deviation", "max_s |H(s) - H_tail| / T_ext through the ply, V_eff of the barrier included", 1.5),
      invariant_metric("tension_law", "T_ext / T_law(R, theta) - 1 at the measured R and theta"),
      invariant_metric("tension_from_moment", "T_ext / T_law(R, theta(M_t)) - 1, theta from the measured M_t"),
      invariant_metric("moment_law", "M_t / M_t,law(R, theta) - 1 (a left-handed ply: M_t > 0)"),
      invariant_metric("contact_force_law", "p / p_law(R, theta) - 1, p the contact force per strand length"),
      invariant_metric("strand_tension_law", "n_t / n_t,law(R, theta) - 1 on the strands in the ply's middle"),
      diagnostic_metric("helix_angle", "theta in the ply's middle (degrees)"),
      diagnostic_metric("helix_angle_from_moment", "theta at which the M_t law gives the measured M_t (degrees)"),
      diagnostic_metric("ply_radius", "R / h in the ply's middle"),
      diagnostic_metric("tail_tension", "n.t on the root's tail (= the applied T_ext at equilibrium)"),
      diagnostic_metric("twisting_moment", "M_t, m.t on the root's tail")};
}

GateSpec law_envelope(const std::string& metric, const std::vector<double>& elements, const std::vector<double>& errors) {
  const double finest = elements.back();
  double at_finest = 0.0;
  for (std::size_t i = 0; i < elements.size(); ++i) at_finest = std::max(at_finest, std::abs(errors[i]) * elements[i] / finest);
  GateSpec gate = measured_bound(metric, at_finest, 1.0 / finest, 1.0);
  gate.rationale = "first-order envelope of the errors measured at the default levels, times 2";
  return gate;
}

GateSpec resolved_law(const std::string& metric) {
  return upper_bound_gate(metric, kResolvedFraction, GateScope::AllLevels,
                          "a tenth of the quantity at every level (the resolution rodvv asks beside every order, "
                          "gate.hpp kResolvedFraction)");
}

std::size_t station_nearest(const SpatialRodSolution& solution, double s) {
  std::size_t nearest = 0;
  for (std::size_t i = 0; i < solution.s.size(); ++i)
    if (std::abs(solution.s[i] - s) < std::abs(solution.s[nearest] - s)) nearest = i;
  return nearest;
}

}  // namespace rodvv::harness::knot_cases

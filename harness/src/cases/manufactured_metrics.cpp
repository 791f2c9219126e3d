#include "manufactured_metrics.hpp"

#include <algorithm>
#include <string>

#include <Eigen/Geometry>

#include "case_builder.hpp"
#include "rodvv/common/errors.hpp"

namespace rodvv::harness::cases {

namespace {

double rotation_angle(const Mat3& a, const Mat3& b) { return Eigen::AngleAxisd(a.transpose() * b).angle(); }

}  // namespace

LevelOutput measure_manufactured(const SpatialRodSolution& solution, const references::ManufacturedRod& exact) {
  if (solution.vertex_position.size() < 2 || solution.s.empty())
    throw InputError("vertices", "the manufactured rod needs vertices and stations, got " +
                                     std::to_string(solution.vertex_position.size()) + " vertices and " +
                                     std::to_string(solution.s.size()) + " stations");
  const double L = exact.length;
  const auto at_vertices = references::manufactured_stations(exact, solution.vertex_s);
  const auto at_stations = references::manufactured_stations(exact, solution.s);
  double position = 0.0, frame = 0.0, strain = 0.0, force = 0.0, moment = 0.0, force_size = 0.0, moment_size = 0.0;
  for (std::size_t i = 0; i < at_vertices.size(); ++i)
    position = std::max(position, (solution.vertex_position[i] - at_vertices[i].position).norm() / L);
  for (std::size_t k = 0; k < at_stations.size(); ++k) {
    const auto& e = at_stations[k];
    frame = std::max(frame, rotation_angle(solution.frame[k], e.frame));
    strain = std::max(strain, (solution.strain_u[k] - e.strain).norm() * L);
    force = std::max(force, (solution.force_n[k] - e.force).norm());
    moment = std::max(moment, (solution.moment_m[k] - e.moment).norm());
    force_size = std::max(force_size, e.force.norm());
    moment_size = std::max(moment_size, e.moment.norm());
  }
  LevelOutput output;
  output.metrics["position"] = value_sample(position, 1.0);
  output.metrics["frame"] = value_sample(frame, 1.0);
  output.metrics["strain"] = value_sample(strain, 1.0);
  output.metrics["force"] = value_sample(force / force_size, 1.0);
  output.metrics["moment"] = value_sample(moment / moment_size, 1.0);
  if (solution.iterations > 0) output.metrics["newton_iterations"] = diagnostic(double(solution.iterations));
  return output;
}

std::vector<MetricSpec> manufactured_metric_specs() {
  return {invariant_metric("position", "max |x_i - r(s_i)| / L over the vertices", 2.0),
          invariant_metric("frame", "max rotation angle between the station frames and R(s)", 2.0),
          invariant_metric("strain", "max |u - u(s)| L over the stations", 2.0),
          invariant_metric("force", "max |n - n(s)| / max |n(s)| over the stations", 2.0),
          invariant_metric("moment", "max |m - m(s)| / max |m(s)| over the stations", 2.0),
          diagnostic_metric("newton_iterations", "Newton iterations (all load steps)")};
}

std::vector<GateSpec> manufactured_gates(const std::vector<std::pair<std::string, double>>& measured_at_finest,
                                         double h_finest, const std::string& why_second_order) {
  std::vector<GateSpec> gates;
  for (const auto& [metric, measured] : measured_at_finest) {
    gates.push_back(order_gate(metric, 2.0, why_second_order));
    gates.push_back(measured_bound(metric, measured, h_finest, 2.0));
  }
  return gates;
}

}  // namespace rodvv::harness::cases

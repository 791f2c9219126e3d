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

ProblemData manufactured_problem_data(const references::ManufacturedRod& rod, const std::vector<double>& s) {
  ProblemData data;
  data.description =
      "A Kirchhoff rod (inextensible, unshearable) of length `length`, clamped at s = 0 at root_position_* with the "
      "frame root_n0_* .. root_n2_* (its directors in world components; n0 the tangent), stiffness_0..2 = (GJ, EI1, "
      "EI2) about (n0, n1, n2), natural strain natural_strain_0..2 (material components). Loads: the force density "
      "force_density_* and couple density couple_density_* per unit length along s (world components; the couple is "
      "0 where couple_free = 1), and at s = L the dead force tip_force_* and moment tip_moment_*. The integral of the "
      "force density over [a, b] is exactly force(a) - force(b) (force_* the internal force, the action of (s, L] on "
      "[0, s]). The other columns are the exact solution: position_*, frame n0_* .. n2_*, strain_u_0..2 (twist, "
      "kappa1, kappa2), force_*, moment_*.";
  const auto put = [&](const std::string& name, const Vec3& v, const char* axes) {
    for (int a = 0; a < 3; ++a) data.values.emplace_back(name + "_" + axes[a], v[a]);
  };
  const auto stations = references::manufactured_stations(rod, s);
  const auto tip = references::manufactured_stations(rod, {rod.length}).front();
  data.values.emplace_back("length", rod.length);
  data.values.emplace_back("couple_free", rod.couple_free ? 1.0 : 0.0);
  put("stiffness", rod.stiffness, "012");
  put("natural_strain", rod.natural_strain, "012");
  put("root_position", rod.root_position, "xyz");
  for (int d = 0; d < 3; ++d) put("root_n" + std::to_string(d), rod.root_frame.col(d), "xyz");
  put("tip_force", tip.force, "xyz");
  put("tip_moment", tip.moment, "xyz");
  data.columns = {"s"};
  const auto add_columns = [&](const std::string& name, const char* axes) {
    for (int a = 0; a < 3; ++a) data.columns.push_back(name + "_" + axes[a]);
  };
  add_columns("force_density", "xyz");
  add_columns("couple_density", "xyz");
  add_columns("position", "xyz");
  for (int d = 0; d < 3; ++d) add_columns("n" + std::to_string(d), "xyz");
  add_columns("strain_u", "012");
  add_columns("force", "xyz");
  add_columns("moment", "xyz");
  for (const auto& station : stations) {
    std::vector<double> row{station.s};
    const auto append = [&](const Vec3& v) { row.insert(row.end(), {v[0], v[1], v[2]}); };
    append(station.force_density);
    // A couple-free rod's c = -m' - t x n is zero by construction; the stations carry its round-off (~1e-15).
    append(rod.couple_free ? Vec3::Zero() : station.couple_density);
    append(station.position);
    for (int d = 0; d < 3; ++d) append(station.frame.col(d));
    append(station.strain);
    append(station.force);
    append(station.moment);
    data.rows.push_back(std::move(row));
  }
  return data;
}

}  // namespace rodvv::harness::cases

#include <array>
#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rodvv/common/errors.hpp"
#include "spatial_columns.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::solution_files {

namespace {

using nlohmann::ordered_json;

// Only arrays that are there: a solver that leaves one empty has not computed it.
void put(ordered_json& object, const char* name, const std::vector<double>& values) {
  if (!values.empty()) object[name] = values;
}

ordered_json planar_json(const PlanarRodSolution& solution) {
  ordered_json nodes;
  put(nodes, "s", solution.s);
  put(nodes, "x", solution.x);
  put(nodes, "y", solution.y);
  put(nodes, "theta", solution.theta);
  put(nodes, "kappa", solution.kappa);
  put(nodes, "force_x", solution.force_x);
  put(nodes, "force_y", solution.force_y);
  put(nodes, "axial_force", solution.axial_force);
  put(nodes, "shear_force", solution.shear_force);
  put(nodes, "bending_stiffness", solution.bending_stiffness);
  put(nodes, "natural_curvature", solution.natural_curvature);
  put(nodes, "potential", solution.potential);
  ordered_json rod;
  rod["length"] = solution.length;
  if (std::isfinite(solution.axial_stiffness)) rod["axial_stiffness"] = solution.axial_stiffness;
  if (std::isfinite(solution.shear_stiffness)) rod["shear_stiffness"] = solution.shear_stiffness;
  rod["iterations"] = solution.iterations;
  rod["residual"] = solution.residual;
  rod["nodes"] = std::move(nodes);
  return rod;
}

void put_vectors(ordered_json& object, const std::string& field, const std::array<const char*, 3>& axes,
                 const std::vector<Vec3>& values) {
  if (values.empty()) return;
  const auto names = vector_columns(field, axes);
  for (int a = 0; a < 3; ++a) {
    std::vector<double> column(values.size());
    for (std::size_t i = 0; i < values.size(); ++i) column[i] = values[i][a];
    object[names[std::size_t(a)]] = std::move(column);
  }
}

void put_frames(ordered_json& object, const std::vector<Mat3>& frames) {
  for (int d = 0; d < 3; ++d) {
    std::vector<Vec3> director(frames.size());
    for (std::size_t i = 0; i < frames.size(); ++i) director[i] = frames[i].col(d);
    put_vectors(object, kDirectors[std::size_t(d)], kWorldAxes, director);
  }
}

ordered_json spatial_json(const SpatialRodSolution& solution) {
  ordered_json vertices;
  vertices["s"] = solution.vertex_s;
  put_vectors(vertices, "position", kWorldAxes, solution.vertex_position);
  put_frames(vertices, solution.vertex_frame);
  ordered_json rod;
  rod["length"] = solution.length;
  rod["iterations"] = solution.iterations;
  rod["residual"] = solution.residual;
  rod["vertices"] = std::move(vertices);
  if (!solution.s.empty()) {
    ordered_json stations;
    stations["s"] = solution.s;
    put_vectors(stations, "position", kWorldAxes, solution.position);
    put_frames(stations, solution.frame);
    put_vectors(stations, "strain_u", kMaterialAxes, solution.strain_u);
    put_vectors(stations, "strain_v", kMaterialAxes, solution.strain_v);
    put_vectors(stations, "stiffness", kMaterialAxes, solution.stiffness);
    put_vectors(stations, "natural_strain", kMaterialAxes, solution.natural_strain);
    put_vectors(stations, "force", kWorldAxes, solution.force_n);
    put_vectors(stations, "moment", kWorldAxes, solution.moment_m);
    put(stations, "potential", solution.potential);
    put(stations, "shear_energy", solution.shear_energy);
    rod["stations"] = std::move(stations);
  }
  return rod;
}

ordered_json trajectory_json(const Trajectory& trajectory) {
  ordered_json samples;
  samples["t"] = trajectory.t;
  samples["theta"] = trajectory.theta;
  samples["theta_dot"] = trajectory.theta_dot;
  ordered_json result;
  result["steps"] = trajectory.steps;
  result["rhs_evaluations"] = trajectory.rhs_evaluations;
  result["samples"] = std::move(samples);
  return result;
}

// Long form: one row per vertex and snapshot (read_solution.cpp, read_rod_trajectory).
ordered_json rod_trajectory_json(const RodTrajectory& trajectory) {
  std::vector<double> t, s;
  std::vector<Vec3> position;
  for (std::size_t k = 0; k < trajectory.size(); ++k) {
    const RodSnapshot& snapshot = trajectory.snapshots[k];
    t.insert(t.end(), snapshot.s.size(), trajectory.t[k]);
    s.insert(s.end(), snapshot.s.begin(), snapshot.s.end());
    position.insert(position.end(), snapshot.position.begin(), snapshot.position.end());
  }
  ordered_json samples;
  samples["t"] = std::move(t);
  samples["s"] = std::move(s);
  put_vectors(samples, "position", kWorldAxes, position);
  ordered_json result;
  result["steps"] = trajectory.steps;
  result["samples"] = std::move(samples);
  return result;
}

}  // namespace

std::string format_solution(const SolutionFile& file) {
  ordered_json document;
  document["format"] = kFormatName;
  document["version"] = kFormatVersion;
  document["case"] = file.case_name;
  ordered_json parameters = ordered_json::object();
  for (const auto& [name, value] : file.parameters) parameters[name] = value;
  document["parameters"] = std::move(parameters);
  // A count (N) as a whole number, a step (dt) as it is.
  ordered_json resolution;
  if (file.level == std::floor(file.level) && std::abs(file.level) < 9007199254740992.0)
    resolution[file.resolution_name] = static_cast<long long>(file.level);
  else
    resolution[file.resolution_name] = file.level;
  document["resolution"] = std::move(resolution);
  document["solver"] = file.solver;
  if (file.cpu_seconds > 0.0) document["cpu_seconds"] = file.cpu_seconds;
  if (file.wall_seconds > 0.0) document["wall_seconds"] = file.wall_seconds;
  if (const auto* planar = std::get_if<PlanarRodSolution>(&file.solution))
    document["planar_rod"] = planar_json(*planar);
  else if (const auto* spatial = std::get_if<SpatialRodSolution>(&file.solution))
    document["spatial_rod"] = spatial_json(*spatial);
  else if (const auto* trajectory = std::get_if<Trajectory>(&file.solution))
    document["trajectory"] = trajectory_json(*trajectory);
  else
    document["rod_trajectory"] = rod_trajectory_json(std::get<RodTrajectory>(file.solution));
  return document.dump(1) + "\n";
}

void write_solution_file(const std::filesystem::path& path, const SolutionFile& file) {
  const std::string text = format_solution(file);
  std::ofstream out(path, std::ios::binary);
  if (!out) throw InputError("--write-solutions", fmt::format("cannot open '{}' for writing", path.string()));
  out << text;
  if (!out) throw InputError("--write-solutions", fmt::format("could not write '{}'", path.string()));
}

}  // namespace rodvv::solution_files

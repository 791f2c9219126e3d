#include <cmath>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "rodvv/common/errors.hpp"
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
  if (const auto* planar = std::get_if<PlanarRodSolution>(&file.solution))
    document["planar_rod"] = planar_json(*planar);
  else if (const auto* trajectory = std::get_if<Trajectory>(&file.solution))
    document["trajectory"] = trajectory_json(*trajectory);
  else
    throw InputError("solution", "the solution-file format has no spatial_rod section yet (version 1: planar_rod, "
                                 "trajectory)");
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

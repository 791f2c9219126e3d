#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "column_table.hpp"
#include "json_cursor.hpp"
#include "planar_derivation.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::solution_files {

namespace {

using json = nlohmann::ordered_json;

// Line and column of a byte offset, for JSON syntax errors.
std::string line_and_column(std::string_view text, std::size_t byte) {
  std::size_t line = 1, column = 1;
  for (std::size_t i = 0; i < byte && i < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return fmt::format("line {}, column {}", line, column);
}

// The per-node or per-sample arrays: inline under `inline_key`, or in the CSV named by `csv_key`.
ColumnTable read_columns(const JsonCursor& parent, const char* inline_key, const char* csv_key,
                         const std::filesystem::path& directory, std::initializer_list<const char*> known) {
  const bool inline_given = parent.has(inline_key), csv_given = parent.has(csv_key);
  if (inline_given == csv_given)
    parent.fail(fmt::format("expected exactly one of \"{}\" (arrays inline) and \"{}\" (a CSV file)", inline_key,
                            csv_key));
  if (inline_given) return columns_from_json(parent.field(inline_key), known);
  const JsonCursor csv = parent.field(csv_key);
  const std::filesystem::path path = directory / csv.string();
  return columns_from_csv(path, csv.path(), known);
}

std::vector<double> required(const ColumnTable& table, const char* name) {
  if (const auto* values = table.find(name)) return *values;
  throw InputError("solution", fmt::format("{}: missing the required array \"{}\"", table.where, name));
}

void require_increasing(const ColumnTable& table, const char* name, const std::vector<double>& values) {
  if (values.size() < 2)
    throw InputError("solution", fmt::format("{}: \"{}\" has {} values; at least 2 are needed", table.where, name,
                                             values.size()));
  for (std::size_t i = 1; i < values.size(); ++i)
    if (!(values[i] > values[i - 1]))
      throw InputError("solution", fmt::format("{}: \"{}\" must increase strictly, but {}[{}] = {} follows {}[{}] = {}",
                                               table.where, name, name, i, values[i], name, i - 1, values[i - 1]));
}

PlanarRodSolution read_planar(const JsonCursor& rod, const std::filesystem::path& directory, SolutionFile& file) {
  rod.expect_object({"nodes", "nodes_csv", "length", "bending_stiffness", "axial_stiffness", "shear_stiffness",
                     "iterations", "residual"});
  const ColumnTable nodes =
      read_columns(rod, "nodes", "nodes_csv", directory,
                   {"s", "x", "y", "theta", "kappa", "force_x", "force_y", "axial_force", "shear_force",
                    "bending_stiffness", "natural_curvature", "potential"});
  PlanarRodSolution solution;
  solution.method = file.solver;
  solution.s = required(nodes, "s");
  solution.x = required(nodes, "x");
  solution.y = required(nodes, "y");
  require_increasing(nodes, "s", solution.s);
  const std::size_t n = solution.s.size();
  // Arclength runs from 0 to L (planar_rod.hpp): the references are evaluated at these s.
  if (std::abs(solution.s.front()) > 1e-12 * solution.s.back())
    throw InputError("solution", fmt::format("{}: s[0] = {}: the arclength must start at 0 (the clamped or first "
                                             "end)",
                                             nodes.where, solution.s.front()));
  solution.length = solution.s.back();
  if (rod.has("length")) {
    const double length = rod.field("length").positive_number();
    // A solver's cumulative sum of element lengths may differ from its L by a few ulps per element.
    if (std::abs(length - solution.s.back()) > 1e-9 * length)
      rod.field("length").fail(fmt::format("length {} differs from the last arclength s[{}] = {}", length, n - 1,
                                           solution.s.back()));
    solution.length = length;
  }

  if (const auto* theta = nodes.find("theta")) {
    solution.theta = *theta;
  } else {
    solution.theta = tangent_angle(solution.s, solution.x, solution.y);
    file.derived.push_back("theta: atan2(y', x') by second-order differences in s");
  }
  if (const auto* kappa = nodes.find("kappa")) {
    solution.kappa = *kappa;
  } else {
    solution.kappa = derivative(solution.s, solution.theta);
    file.derived.push_back("kappa: theta' by second-order differences in s");
  }
  solution.natural_curvature = nodes.find("natural_curvature") ? *nodes.find("natural_curvature")
                                                                 : std::vector<double>(n, 0.0);
  solution.potential = nodes.find("potential") ? *nodes.find("potential") : std::vector<double>(n, 0.0);

  const bool ei_column = nodes.find("bending_stiffness") != nullptr, ei_number = rod.has("bending_stiffness");
  if (ei_column && ei_number)
    rod.fail("bending_stiffness is given twice (a number here and a column of the nodes); give one");
  if (ei_column) solution.bending_stiffness = *nodes.find("bending_stiffness");
  if (ei_number) solution.bending_stiffness.assign(n, rod.field("bending_stiffness").positive_number());
  for (std::size_t i = 0; i < solution.bending_stiffness.size(); ++i)
    if (!(solution.bending_stiffness[i] > 0.0))
      throw InputError("solution", fmt::format("{}: bending_stiffness[{}] = {}: must be > 0", nodes.where, i,
                                               solution.bending_stiffness[i]));
  if (rod.has("axial_stiffness")) solution.axial_stiffness = rod.field("axial_stiffness").positive_number();
  if (rod.has("shear_stiffness")) solution.shear_stiffness = rod.field("shear_stiffness").positive_number();

  const bool fx = nodes.find("force_x") != nullptr, fy = nodes.find("force_y") != nullptr;
  if (fx != fy) throw InputError("solution", fmt::format("{}: force_x and force_y come together; one is missing", nodes.where));
  if (fx) {
    solution.force_x = *nodes.find("force_x");
    solution.force_y = *nodes.find("force_y");
  }
  // n.t and n.N: given, or from n and the section's direction t = (cos theta, sin theta).
  const auto project = [&](const char* name, bool normal) {
    if (const auto* given = nodes.find(name)) return *given;
    if (!fx) return std::vector<double>{};
    std::vector<double> values(n);
    for (std::size_t i = 0; i < n; ++i) {
      const double c = std::cos(solution.theta[i]), s = std::sin(solution.theta[i]);
      values[i] = normal ? -solution.force_x[i] * s + solution.force_y[i] * c
                         : solution.force_x[i] * c + solution.force_y[i] * s;
    }
    file.derived.push_back(fmt::format("{}: {} from force_x, force_y and theta", name, normal ? "n.N" : "n.t"));
    return values;
  };
  solution.axial_force = project("axial_force", false);
  const bool shearable = std::isfinite(solution.shear_stiffness);
  if (shearable) solution.shear_force = project("shear_force", true);

  // H needs EI, n.t and, for a shearable rod, n.N; without them the case's H metrics are not computed.
  std::vector<std::string> lacking;
  if (solution.bending_stiffness.empty()) lacking.push_back("bending_stiffness");
  if (solution.axial_force.empty()) lacking.push_back("force_x and force_y (or axial_force)");
  if (shearable && solution.shear_force.empty()) lacking.push_back("shear_force (the rod is shearable)");
  if (!lacking.empty()) {
    file.missing.push_back(fmt::format("{}: the Noether invariant H (and its metrics) not computed",
                                       fmt::format("{}", fmt::join(lacking, ", "))));
    solution.axial_force.clear();
    solution.shear_force.clear();
  }
  if (rod.has("iterations")) solution.iterations = rod.field("iterations").count();
  if (rod.has("residual")) solution.residual = rod.field("residual").number();
  return solution;
}

Trajectory read_trajectory(const JsonCursor& trajectory, const std::filesystem::path& directory) {
  trajectory.expect_object({"samples", "samples_csv", "steps", "rhs_evaluations"});
  const ColumnTable samples = read_columns(trajectory, "samples", "samples_csv", directory, {"t", "theta", "theta_dot"});
  Trajectory result;
  result.t = required(samples, "t");
  result.theta = required(samples, "theta");
  result.theta_dot = required(samples, "theta_dot");
  require_increasing(samples, "t", result.t);
  if (trajectory.has("steps")) result.steps = trajectory.field("steps").count();
  if (trajectory.has("rhs_evaluations")) result.rhs_evaluations = trajectory.field("rhs_evaluations").count();
  return result;
}

}  // namespace

SolutionFile parse_solution(std::string_view json_text, const std::string& source,
                            const std::filesystem::path& directory) {
  json document;
  try {
    document = json::parse(json_text);
  } catch (const json::parse_error& error) {
    throw InputError("solution", fmt::format("{}: not valid JSON at {}: {}", source,
                                             line_and_column(json_text, error.byte == 0 ? 0 : error.byte - 1),
                                             error.what()));
  } catch (const json::exception& error) {  // e.g. a number beyond the range of double (1e999)
    throw InputError("solution", fmt::format("{}: not readable JSON: {}", source, error.what()));
  }
  const JsonCursor root(document, "$", source);
  root.expect_object({"format", "version", "case", "parameters", "resolution", "solver", "planar_rod", "trajectory"});
  if (root.field("format").string() != kFormatName)
    root.field("format").fail(fmt::format("expected \"{}\"", kFormatName));
  const JsonCursor version = root.field("version");
  if (version.count() != std::size_t(kFormatVersion))
    version.fail(fmt::format("format version {} is not one this rodvv reads (it reads version {})", version.value().dump(),
                             kFormatVersion));

  SolutionFile file;
  file.source = source;
  file.case_name = root.field("case").string();
  if (file.case_name.empty()) root.field("case").fail("expected a case name (rodvv list), got an empty string");
  if (root.has("parameters")) {
    const JsonCursor parameters = root.field("parameters");
    if (!parameters.value().is_object()) parameters.fail("expected an object of NAME: number");
    for (const auto& [name, value] : parameters.value().items())
      file.parameters.emplace_back(name, parameters.field(name.c_str()).number());
  }
  const JsonCursor resolution = root.field("resolution");
  if (!resolution.value().is_object() || resolution.value().size() != 1)
    resolution.fail("expected an object with one entry, the case's resolution and its value, e.g. {\"N\": 40}");
  file.resolution_name = resolution.value().begin().key();
  file.level = resolution.field(file.resolution_name.c_str()).positive_number();
  if (root.has("solver")) file.solver = root.field("solver").string();

  const bool planar = root.has("planar_rod"), trajectory = root.has("trajectory");
  if (planar == trajectory) root.fail("expected exactly one solution: \"planar_rod\" or \"trajectory\"");
  if (planar)
    file.solution = read_planar(root.field("planar_rod"), directory, file);
  else
    file.solution = read_trajectory(root.field("trajectory"), directory);
  return file;
}

SolutionFile read_solution_file(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error))
    throw InputError("--solution", fmt::format("invalid --solution '{}': not a readable file", path.string()));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("--solution", fmt::format("invalid --solution '{}': cannot open it", path.string()));
  std::ostringstream text;
  text << in.rdbuf();
  return parse_solution(text.str(), path.string(), path.parent_path());
}

}  // namespace rodvv::solution_files

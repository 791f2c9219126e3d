#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <nlohmann/json.hpp>

#include "column_table.hpp"
#include "json_cursor.hpp"
#include "planar_derivation.hpp"
#include "spatial_columns.hpp"
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
                         const std::filesystem::path& directory, const std::vector<std::string>& known) {
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

// A 3-vector field from its three columns: all three, or none (nullopt).
std::optional<std::vector<Vec3>> vectors(const ColumnTable& table, const std::string& field,
                                         const std::array<const char*, 3>& axes) {
  const auto names = vector_columns(field, axes);
  const std::vector<double>* columns[3] = {table.find(names[0]), table.find(names[1]), table.find(names[2])};
  const int present = (columns[0] != nullptr) + (columns[1] != nullptr) + (columns[2] != nullptr);
  if (present == 0) return std::nullopt;
  if (present != 3)
    throw InputError("solution", fmt::format("{}: {}, {} and {} come together; {} of them given", table.where, names[0],
                                             names[1], names[2], present));
  std::vector<Vec3> values(table.rows());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = Vec3((*columns[0])[i], (*columns[1])[i], (*columns[2])[i]);
  return values;
}

// The frames R = [n0 n1 n2] from the nine director columns: all nine, or none.
std::optional<std::vector<Mat3>> frames(const ColumnTable& table) {
  std::array<std::optional<std::vector<Vec3>>, 3> directors;
  for (std::size_t d = 0; d < 3; ++d) directors[d] = vectors(table, kDirectors[d], kWorldAxes);
  const int present = bool(directors[0]) + bool(directors[1]) + bool(directors[2]);
  if (present == 0) return std::nullopt;
  if (present != 3)
    throw InputError("solution", fmt::format("{}: a frame needs the three directors n0, n1, n2 (n0_x .. n2_z); {} of "
                                             "them given",
                                             table.where, present));
  std::vector<Mat3> result(table.rows());
  for (std::size_t i = 0; i < result.size(); ++i)
    for (int d = 0; d < 3; ++d) result[i].col(d) = (*directors[std::size_t(d)])[i];
  return result;
}

std::vector<std::string> spatial_known(bool stations) {
  std::vector<std::string> names{"s"};
  const auto add = [&](const std::string& field, const std::array<const char*, 3>& axes) {
    for (auto& name : vector_columns(field, axes)) names.push_back(name);
  };
  add("position", kWorldAxes);
  for (auto& name : frame_columns()) names.push_back(name);
  if (stations) {
    for (const char* field : {"strain_u", "strain_v", "stiffness", "natural_strain"}) add(field, kMaterialAxes);
    add("force", kWorldAxes);
    add("moment", kWorldAxes);
    names.push_back("potential");
    names.push_back("shear_energy");
  }
  return names;
}

std::vector<Vec3> required_vectors(const ColumnTable& table, const std::string& field,
                                   const std::array<const char*, 3>& axes) {
  if (auto values = vectors(table, field, axes)) return *values;
  const auto names = vector_columns(field, axes);
  throw InputError("solution", fmt::format("{}: missing the required arrays {}, {}, {}", table.where, names[0],
                                           names[1], names[2]));
}

void require_arclength(const ColumnTable& table, const std::vector<double>& s) {
  require_increasing(table, "s", s);
  if (std::abs(s.front()) > 1e-12 * s.back())
    throw InputError("solution", fmt::format("{}: s[0] = {}: the arclength must start at 0", table.where, s.front()));
}

SpatialRodSolution read_spatial(const JsonCursor& rod, const std::filesystem::path& directory, SolutionFile& file) {
  rod.expect_object({"vertices", "vertices_csv", "stations", "stations_csv", "length", "iterations", "residual"});
  SpatialRodSolution solution;
  solution.method = file.solver;
  const ColumnTable vertices = read_columns(rod, "vertices", "vertices_csv", directory, spatial_known(false));
  solution.vertex_s = required(vertices, "s");
  require_arclength(vertices, solution.vertex_s);
  solution.vertex_position = required_vectors(vertices, "position", kWorldAxes);
  if (auto vertex_frames = frames(vertices)) solution.vertex_frame = std::move(*vertex_frames);
  solution.length = solution.vertex_s.back();
  if (rod.has("length")) solution.length = rod.field("length").positive_number();

  if (!rod.has("stations") && !rod.has("stations_csv")) {
    file.missing.push_back("stations (frames, strains, stiffness, n, m): the Noether invariant H not computed");
  } else {
    // The fields H reads (PHYSICS.md §1.1): all of them, so that a partial file is refused, not half-used.
    const ColumnTable stations = read_columns(rod, "stations", "stations_csv", directory, spatial_known(true));
    const std::size_t n = stations.rows();
    solution.s = required(stations, "s");
    require_increasing(stations, "s", solution.s);
    solution.position = required_vectors(stations, "position", kWorldAxes);
    auto station_frames = frames(stations);
    if (!station_frames)
      throw InputError("solution", fmt::format("{}: missing the frames n0_x .. n2_z", stations.where));
    solution.frame = std::move(*station_frames);
    solution.strain_u = required_vectors(stations, "strain_u", kMaterialAxes);
    solution.stiffness = required_vectors(stations, "stiffness", kMaterialAxes);
    solution.force_n = required_vectors(stations, "force", kWorldAxes);
    solution.moment_m = required_vectors(stations, "moment", kWorldAxes);
    if (auto v = vectors(stations, "strain_v", kMaterialAxes)) {
      solution.strain_v = std::move(*v);
    } else {
      solution.strain_v.assign(n, Vec3::UnitX());
      file.derived.push_back("strain_v: (1, 0, 0), an inextensible unshearable (Kirchhoff) rod");
    }
    if (auto natural = vectors(stations, "natural_strain", kMaterialAxes))
      solution.natural_strain = std::move(*natural);
    else
      solution.natural_strain.assign(n, Vec3::Zero());
    solution.potential = stations.find("potential") ? *stations.find("potential") : std::vector<double>(n, 0.0);
    if (const auto* shear = stations.find("shear_energy")) solution.shear_energy = *shear;
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

// A 3-D rod's trajectory in long form: one row per vertex and time, the rows of one snapshot together
// (equal t, s increasing from 0), the snapshots in increasing t.
RodTrajectory read_rod_trajectory(const JsonCursor& trajectory, const std::filesystem::path& directory,
                                  const SolutionFile& file) {
  trajectory.expect_object({"samples", "samples_csv", "steps"});
  std::vector<std::string> known{"t", "s"};
  for (auto& name : vector_columns("position", kWorldAxes)) known.push_back(name);
  const ColumnTable samples = read_columns(trajectory, "samples", "samples_csv", directory, known);
  const std::vector<double> t = required(samples, "t"), s = required(samples, "s");
  const std::vector<Vec3> position = required_vectors(samples, "position", kWorldAxes);
  RodTrajectory result;
  result.method = file.solver;
  for (std::size_t row = 0; row < t.size();) {
    std::size_t end = row;
    while (end < t.size() && t[end] == t[row]) ++end;
    if (!result.t.empty() && !(t[row] > result.t.back()))
      throw InputError("solution", fmt::format("{}: row {}: t = {} follows the snapshot at t = {}; the snapshots must "
                                               "come in strictly increasing t, each one's rows together",
                                               samples.where, row, t[row], result.t.back()));
    RodSnapshot snapshot;
    snapshot.s.assign(s.begin() + std::ptrdiff_t(row), s.begin() + std::ptrdiff_t(end));
    snapshot.position.assign(position.begin() + std::ptrdiff_t(row), position.begin() + std::ptrdiff_t(end));
    if (snapshot.s.size() < 2)
      throw InputError("solution", fmt::format("{}: rows {} .. {}: the snapshot at t = {} has {} vertex; at least 2 "
                                               "are needed",
                                               samples.where, row, end - 1, t[row], snapshot.s.size()));
    for (std::size_t i = 1; i < snapshot.s.size(); ++i)
      if (!(snapshot.s[i] > snapshot.s[i - 1]))
        throw InputError("solution", fmt::format("{}: row {}: s = {} follows s = {} in the snapshot at t = {}; s must "
                                                 "increase strictly along a snapshot",
                                                 samples.where, row + i, snapshot.s[i], snapshot.s[i - 1], t[row]));
    if (std::abs(snapshot.s.front()) > 1e-12 * snapshot.s.back())
      throw InputError("solution", fmt::format("{}: row {}: s = {}: the arclength of the snapshot at t = {} must start "
                                               "at 0 (the clamped end)",
                                               samples.where, row, snapshot.s.front(), t[row]));
    result.t.push_back(t[row]);
    result.snapshots.push_back(std::move(snapshot));
    row = end;
  }
  if (result.t.empty()) throw InputError("solution", fmt::format("{}: no samples", samples.where));
  if (trajectory.has("steps")) result.steps = trajectory.field("steps").count();
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
  root.expect_object(
      {"format", "version", "case", "parameters", "resolution", "solver", "cpu_seconds", "wall_seconds", "planar_rod",
       "spatial_rod", "trajectory", "rod_trajectory"});
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
  for (auto [key, target] : {std::pair{"cpu_seconds", &file.cpu_seconds}, std::pair{"wall_seconds", &file.wall_seconds}})
    if (root.has(key)) {
      *target = root.field(key).number();
      if (*target < 0.0) root.field(key).fail("expected a time >= 0");
    }

  const int kinds =
      root.has("planar_rod") + root.has("spatial_rod") + root.has("trajectory") + root.has("rod_trajectory");
  if (kinds != 1)
    root.fail("expected exactly one solution: \"planar_rod\", \"spatial_rod\", \"trajectory\" or \"rod_trajectory\"");
  if (root.has("planar_rod"))
    file.solution = read_planar(root.field("planar_rod"), directory, file);
  else if (root.has("spatial_rod"))
    file.solution = read_spatial(root.field("spatial_rod"), directory, file);
  else if (root.has("trajectory"))
    file.solution = read_trajectory(root.field("trajectory"), directory);
  else
    file.solution = read_rod_trajectory(root.field("rod_trajectory"), directory, file);
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

// `rodvv check`: another solver's solution files through a case's metrics, orders and gates.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstdio>

#include "commands.hpp"
#include "gate_table.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/check.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::apps {

namespace {

using harness::Case;

std::vector<const Case*> checking_cases() {
  std::vector<const Case*> cases;
  for (const Case& c : harness::default_registry().cases())
    if (c.checks_solutions()) cases.push_back(&c);
  return cases;
}

// A case by its exact name, or by its group (elastica/mattiasson-2 for its polygon and arcs cases,
// which measure the same problem): the first case of the group that checks solutions.
const Case& resolve_case(const std::string& name) {
  const auto& registry = harness::default_registry();
  if (const Case* c = registry.find(name)) {
    if (c->checks_solutions()) return *c;
  } else {
    for (const Case* candidate : checking_cases())
      if (candidate->info.group == name) return *candidate;
  }
  std::vector<std::string> groups;
  for (const Case* c : checking_cases())
    if (std::find(groups.begin(), groups.end(), c->info.group) == groups.end()) groups.push_back(c->info.group);
  throw InputError("case", fmt::format("case '{}' {}; the cases that check solution files are (by group): {}", name,
                                       registry.find(name) ? "does not check solution files" : "is unknown",
                                       fmt::join(groups, ", ")));
}

// --max-error METRIC=VALUE
harness::GateSpec parse_bound(const Case& c, const std::string& assignment) {
  const auto equals = assignment.find('=');
  if (equals == std::string::npos || equals == 0)
    throw InputError("--max-error", fmt::format("invalid --max-error '{}': expected METRIC=VALUE", assignment));
  const std::string value_text = assignment.substr(equals + 1);
  double value = 0.0;
  try {
    std::size_t used = 0;
    value = std::stod(value_text, &used);
    if (used != value_text.size()) throw std::invalid_argument("trailing characters");
  } catch (const std::exception&) {
    throw InputError("--max-error", fmt::format("invalid --max-error '{}': VALUE must be a number", assignment));
  }
  return harness::user_bound(c, assignment.substr(0, equals), value);
}

}  // namespace

int check_command(const CheckOptions& options) {
  if (options.list) {
    std::vector<std::string> groups;
    for (const Case* c : checking_cases()) {
      if (std::find(groups.begin(), groups.end(), c->info.group) != groups.end()) continue;
      groups.push_back(c->info.group);
      std::vector<std::string> parameters;
      for (const auto& parameter : c->info.parameters) parameters.push_back(parameter.name);
      fmt::print("{:<32} resolution {}; parameters {}\n", c->info.group, c->info.resolution.name,
                 fmt::join(parameters, ", "));
    }
    return kPass;
  }
  if (options.solutions.empty())
    throw InputError("--solution", "no solution files: `rodvv check [CASE] --solution FILE [FILE ...]`");
  check_outputs(options.json_path, options.csv_path);
  // A case named on the command line is resolved before any file is read: a wrong one costs nothing.
  const Case* named = options.case_name ? &resolve_case(*options.case_name) : nullptr;

  std::vector<solution_files::SolutionFile> files;
  for (const auto& path : options.solutions) files.push_back(solution_files::read_solution_file(path));
  const std::string case_name = options.case_name.value_or(files.front().case_name);
  for (const auto& file : files)
    if (file.case_name != case_name)
      throw InputError("case", fmt::format("{} is a solution of '{}', not of '{}': one case per check",
                                           file.source, file.case_name, case_name));
  const Case& c = named ? *named : resolve_case(case_name);

  // Parameters: the case's defaults with each file's values; every file must pose the same problem.
  harness::Parameters parameters = c.info.parameters;
  for (const auto& file : files) {
    if (file.resolution_name != c.info.resolution.name)
      throw InputError("resolution", fmt::format("{}: resolution \"{}\", but case '{}' is resolved by \"{}\" ({})",
                                                 file.source, file.resolution_name, c.info.name,
                                                 c.info.resolution.name, c.info.resolution.description));
    for (const auto& [name, value] : file.parameters) {
      try {
        harness::set_parameter(parameters, name, value);
      } catch (const InputError& error) {
        throw InputError(error.parameter(), fmt::format("{}: {}", file.source, error.what()));
      }
    }
  }
  for (const auto& file : files)
    for (const auto& parameter : parameters) {
      const auto given = std::find_if(file.parameters.begin(), file.parameters.end(),
                                      [&](const auto& entry) { return entry.first == parameter.name; });
      const double value = given == file.parameters.end() ? harness::parameter_value(c.info.parameters, parameter.name)
                                                          : given->second;
      if (value != parameter.value)
        throw InputError(parameter.name, fmt::format("the files pose different problems: {} = {} in {}, {} elsewhere",
                                                     parameter.name, format_value(value), file.source,
                                                     format_value(parameter.value)));
    }

  std::vector<harness::GateSpec> bounds;
  for (const auto& assignment : options.max_errors) bounds.push_back(parse_bound(c, assignment));
  std::vector<harness::LevelSolution> solutions;
  for (auto& file : files) {
    for (const auto& note : file.derived) fmt::print(stderr, "{}: derived {}\n", file.source, note);
    for (const auto& note : file.missing) fmt::print(stderr, "{}: missing {}\n", file.source, note);
    solutions.push_back({file.source, file.level, std::move(file.solution), file.solver, file.cpu_seconds,
                         file.wall_seconds});
  }
  auto result = harness::check_solutions(c, parameters, std::move(solutions), bounds, options.order);
  // Its own name in reports, beside (not in place of) rodvv's runs of the same case.
  result.info.name = "check/" + case_name;
  result.info.family = "check";
  result.info.group = result.info.name;
  std::vector<harness::SweepResult> results{std::move(result)};
  fmt::print("{}\n{}", render_level_table(results.front()), render_gate_table(results));
  const int code = exit_code(results);
  write_results(std::move(results), options.json_path, options.csv_path);
  return code;
}

}  // namespace rodvv::apps

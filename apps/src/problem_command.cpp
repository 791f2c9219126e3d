// `rodvv problem`: the data that poses a case's problem to another solver (the manufactured loads;
// harness/problem_data.hpp), written as JSON for the user's solver to read.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/registry.hpp"

namespace rodvv::apps {

namespace {

// The largest station count written: 10^6 intervals are ~100 MB of JSON for a 3-D case.
constexpr std::size_t kMaxIntervals = 1000000;

std::vector<std::string> cases_with_problem_data() {
  std::vector<std::string> names;
  for (const harness::Case& c : harness::default_registry().cases())
    if (c.problem_data) names.push_back(c.info.name);
  return names;
}

}  // namespace

int problem_command(const ProblemOptions& options) {
  const harness::Case* c = harness::default_registry().find(options.case_name);
  if (!c)
    throw InputError("case", fmt::format("unknown case '{}': `rodvv problem` takes one exact case name (`rodvv list`)",
                                         options.case_name));
  if (!c->problem_data)
    throw InputError("case", fmt::format("case '{}' has no problem data to write: its parameters and description pose "
                                         "it (`rodvv list -v {}`); the cases with data: {}",
                                         c->info.name, c->info.name, fmt::join(cases_with_problem_data(), ", ")));
  if (!(options.intervals >= 1 && options.intervals <= kMaxIntervals))
    throw InputError("--stations", fmt::format("invalid --stations {}: the number of intervals must be in [1, {}]",
                                               options.intervals, kMaxIntervals));
  const harness::Parameters parameters = case_parameters(*c, options.assignments);

  const harness::ProblemData data = c->problem_data(parameters, options.intervals);
  nlohmann::ordered_json document;
  document["format"] = "rodvv-problem";
  document["version"] = 1;
  document["case"] = c->info.name;
  nlohmann::ordered_json parameter_values = nlohmann::ordered_json::object();
  for (const auto& parameter : parameters) parameter_values[parameter.name] = parameter.value;
  document["parameters"] = std::move(parameter_values);
  document["description"] = data.description;
  nlohmann::ordered_json values = nlohmann::ordered_json::object();
  for (const auto& [name, value] : data.values) values[name] = value;
  document["values"] = std::move(values);
  nlohmann::ordered_json stations = nlohmann::ordered_json::object();
  for (std::size_t j = 0; j < data.columns.size(); ++j) {
    std::vector<double> column(data.rows.size());
    for (std::size_t i = 0; i < data.rows.size(); ++i) column[i] = data.rows[i][j];
    stations[data.columns[j]] = std::move(column);
  }
  document["stations"] = std::move(stations);

  std::ofstream out(options.out, std::ios::binary);
  if (!out) throw InputError("--out", fmt::format("invalid --out '{}': cannot open it for writing", options.out));
  out << document.dump(1) << "\n";
  if (!out) throw InputError("--out", fmt::format("could not write '{}'", options.out));
  fmt::print("wrote {}: case {}, {} stations, {} values, columns {}\n", options.out, c->info.name, data.rows.size(),
             data.values.size(), fmt::join(data.columns, " "));
  return kPass;
}

}  // namespace rodvv::apps

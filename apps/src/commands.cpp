#include "commands.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

#include "gate_table.hpp"
#include "progress.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/golden.hpp"
#include "rodvv/harness/parallel_sweeps.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"
#include "rodvv/reports/csv.hpp"
#include "rodvv/reports/golden_file.hpp"
#include "rodvv/reports/json_io.hpp"
#include "rodvv/reports/provenance.hpp"
#include "rodvv/reports/report_document.hpp"
#include "rodvv/reports/report_writer.hpp"
#include "rodvv/solution_files/solution_file.hpp"

namespace rodvv::apps {

namespace {

using harness::Case;
using harness::SweepResult;

// -j: at least 1, at most 1024; unset, the core count (hardware_concurrency, 1 if unknown).
std::size_t worker_count(const CommonOptions& common) {
  if (!common.jobs) return std::max(1u, std::thread::hardware_concurrency());
  if (*common.jobs < 1 || *common.jobs > 1024)
    throw InputError("--jobs", fmt::format("invalid --jobs {}: must be a whole number in [1, 1024]", *common.jobs));
  return std::size_t(*common.jobs);
}

// The goldens of the regression gates: --goldens (must exist), else the source tree's file when
// there is one (a note on stderr otherwise: an installed rodvv has none).
std::optional<harness::Goldens> load_goldens(const CommonOptions& common) {
  if (common.goldens) {
    if (!std::filesystem::is_regular_file(*common.goldens))
      throw InputError("--goldens", fmt::format("invalid --goldens '{}': no such file", *common.goldens));
    return reports::read_goldens(*common.goldens);
  }
  if (!std::filesystem::is_regular_file(RODVV_DEFAULT_GOLDENS)) {
    fmt::print(stderr, "rodvv: note: no goldens file at {}: regression gates not evaluated\n", RODVV_DEFAULT_GOLDENS);
    return std::nullopt;
  }
  return reports::read_goldens(RODVV_DEFAULT_GOLDENS);
}

// Runs each case at its default (or extended, or given) levels with the --set overrides applied, on
// -j worker threads, and adds its regression gate (unless regression_gates is false: bless).
// All parameters of all cases are validated before the first level runs, so bad input costs nothing.
std::vector<SweepResult> run_cases(const std::vector<const Case*>& cases, const CommonOptions& common,
                                   const std::vector<double>* levels_override, bool regression_gates = true) {
  if (!(common.level_budget > 0.0 && common.level_budget <= 1e6))
    throw InputError("--level-budget", fmt::format("invalid --level-budget {}: must be a number of seconds in (0, 1e6]",
                                                   format_value(common.level_budget)));
  const std::size_t workers = worker_count(common);
  const std::optional<harness::Goldens> goldens = regression_gates ? load_goldens(common) : std::nullopt;
  std::vector<harness::SweepJob> jobs;
  for (const Case* c : cases) {
    harness::Parameters p = case_parameters(*c, common.assignments);
    const auto levels = levels_override ? std::span<const double>(*levels_override)
                                        : harness::sweep_levels(*c, common.extended);
    harness::validate_levels(*c, levels);
    jobs.push_back({c, std::move(p), std::vector<double>(levels.begin(), levels.end())});
  }
  ProgressReporter progress(cases.size(), common.verbose);
  const harness::CaseAmendment regression = [&](std::size_t i, SweepResult& result) {
    harness::add_regression_gate(*cases[i], result, *goldens);
  };
  return harness::run_sweeps(
      jobs, workers, common.level_budget, progress.level_callback(),
      [&progress](const SweepResult& result) { progress.case_finished(result); },
      goldens ? regression : harness::CaseAmendment{});
}

reports::ValidationReport make_report(std::vector<SweepResult> results) {
  reports::ValidationReport report;
  report.provenance = reports::collect_provenance();
  report.cases = std::move(results);
  return report;
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out) throw InputError("output", fmt::format("cannot open '{}' for writing", path));
  out << text;
  if (!out) throw InputError("output", fmt::format("could not write '{}'", path));
}

void write_outputs(const reports::ValidationReport& report, const std::optional<std::string>& json_path,
                   const std::optional<std::string>& csv_path) {
  if (json_path) {
    reports::write_report_file(*json_path, report);
    fmt::print(stderr, "wrote {}\n", *json_path);
  }
  if (csv_path) {
    write_text(*csv_path, reports::render_csv(report));
    fmt::print(stderr, "wrote {}\n", *csv_path);
  }
}

}  // namespace

harness::Parameters case_parameters(const harness::Case& c, const std::vector<std::string>& assignments) {
  harness::Parameters p = c.info.parameters;
  for (const auto& assignment : assignments) {
    try {
      harness::apply_assignment(p, assignment);
    } catch (const InputError& error) {
      throw InputError(error.parameter(), fmt::format("case '{}': {}", c.info.name, error.what()));
    }
  }
  if (c.check_parameters) c.check_parameters(p);
  return p;
}

// A case in which no gate was evaluated (all of them skipped, e.g. measured bounds at user
// parameters) has shown nothing: it is not a pass. Said on stderr, exit 1.
int exit_code(const std::vector<SweepResult>& results) {
  std::vector<std::string> without_evidence;
  // A regression gate says only that nothing changed: evidence is a verification gate.
  for (const auto& result : results)
    if (std::none_of(result.gates.begin(), result.gates.end(),
                     [](const auto& gate) { return gate.kind != harness::GateKind::Regression; }))
      without_evidence.push_back(result.info.name);
  for (const auto& name : without_evidence)
    fmt::print(stderr, "rodvv: no evidence: no gate of '{}' was evaluated at these parameters and levels; "
                       "that is not a pass\n",
               name);
  if (!without_evidence.empty()) return kGateFailed;
  for (const auto& result : results)
    if (!result.passed()) return kGateFailed;
  return kPass;
}

namespace {

// Output paths are checked before any case runs, not after minutes of work: not empty, not a
// directory, in a directory that exists; and the JSON and CSV files are not the same file.
void check_output_path(const char* option, const std::optional<std::string>& path) {
  if (!path) return;
  if (path->empty()) throw InputError(option, fmt::format("invalid {} '': an output file path is required", option));
  const std::filesystem::path p(*path);
  std::error_code error;
  if (std::filesystem::is_directory(p, error))
    throw InputError(option, fmt::format("invalid {} '{}': is a directory, not a file", option, *path));
  const auto parent = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
  if (!std::filesystem::is_directory(parent, error))
    throw InputError(option, fmt::format("invalid {} '{}': directory '{}' does not exist", option, *path,
                                         parent.string()));
}
}  // namespace

void check_outputs(const std::optional<std::string>& json_path, const std::optional<std::string>& csv_path) {
  check_output_path("--json", json_path);
  check_output_path("--csv", csv_path);
  std::error_code error;
  if (json_path && csv_path &&
      std::filesystem::weakly_canonical(*json_path, error) == std::filesystem::weakly_canonical(*csv_path, error))
    throw InputError("--csv", fmt::format("invalid --csv '{}': the same file as --json (the CSV would overwrite "
                                          "the JSON)",
                                          *csv_path));
}

void write_results(std::vector<SweepResult> results, const std::optional<std::string>& json_path,
                   const std::optional<std::string>& csv_path) {
  write_outputs(make_report(std::move(results)), json_path, csv_path);
}

namespace {

// DIR/<case name with '/' -> '_'>_<resolution><level>.json, in the format `rodvv check` reads.
void write_level_solution(const std::filesystem::path& directory, const Case& c, const harness::Parameters& parameters,
                          double level, const Solution& solution) {
  solution_files::SolutionFile file;
  file.case_name = c.info.name;
  for (const auto& parameter : parameters) file.parameters.emplace_back(parameter.name, parameter.value);
  file.resolution_name = c.info.resolution.name;
  file.level = level;
  file.solver = "rodvv: " + c.info.method;
  file.solution = solution;
  std::string stem = c.info.name;
  std::replace(stem.begin(), stem.end(), '/', '_');
  const auto path = directory / fmt::format("{}_{}{:g}.json", stem, c.info.resolution.name, level);
  solution_files::write_solution_file(path, file);
}

// --shard I/K (1 <= I <= K): the selected cases whose position in the registry's order is I - 1
// modulo K. Round robin, not contiguous blocks, so that each shard gets a share of every family
// (the families differ in cost by orders of magnitude); the K shards partition the selection.
std::vector<const Case*> shard_of(const std::vector<const Case*>& cases, const std::string& shard) {
  const auto bad = [&](const std::string& why) {
    return InputError("--shard", fmt::format("invalid --shard '{}': {}", shard, why));
  };
  const auto slash = shard.find('/');
  if (slash == std::string::npos) throw bad("expected I/K, two whole numbers with 1 <= I <= K");
  const auto whole = [&](const std::string& text) -> long {
    if (text.empty() || text.size() > 6 || text.find_first_not_of("0123456789") != std::string::npos)
      throw bad("expected I/K, two whole numbers with 1 <= I <= K <= 999999");
    return std::stol(text);
  };
  const long index = whole(shard.substr(0, slash)), count = whole(shard.substr(slash + 1));
  if (count < 1 || index < 1 || index > count) throw bad("expected 1 <= I <= K");
  std::vector<const Case*> slice;
  for (std::size_t i = 0; i < cases.size(); ++i)
    if (long(i % std::size_t(count)) == index - 1) slice.push_back(cases[i]);
  if (slice.empty())
    throw bad(fmt::format("it selects no case: the selection has {} cases, fewer than K", cases.size()));
  return slice;
}

}  // namespace

int list_command(const std::vector<std::string>& patterns, bool verbose) {
  const auto cases = harness::default_registry().select(patterns);
  for (const Case* c : cases) {
    const auto& info = c->info;
    fmt::print("{:<48} {}\n", info.name, info.title);
    if (!verbose) continue;
    std::string levels;
    for (double level : info.resolution.default_levels) levels += fmt::format(" {:g}", level);
    fmt::print("    resolution {}:{}\n", info.resolution.name, levels);
    for (const auto& parameter : info.parameters)
      fmt::print("    --set {}={:g}  {}; {}\n", parameter.name, parameter.value, harness::describe_allowed(parameter),
                 parameter.description);
    for (const auto& window : info.parameter_windows) fmt::print("    requires: {}\n", window);
    for (const auto& gate : c->gates) fmt::print("    gate: {}\n", gate.name);
  }
  fmt::print(stderr, "{} cases\n", cases.size());
  return kPass;
}

int run_command(const RunOptions& options) {
  check_outputs(options.json_path, options.csv_path);
  auto cases = harness::default_registry().select(options.common.cases);
  if (options.shard) cases = shard_of(cases, *options.shard);
  auto results = run_cases(cases, options.common, nullptr);
  fmt::print("{}", render_gate_table(results));
  const int code = exit_code(results);
  write_outputs(make_report(std::move(results)), options.json_path, options.csv_path);
  return code;
}

int sweep_command(const SweepOptions& options) {
  const Case* c = harness::default_registry().find(options.common.cases.front());
  if (!c)
    throw InputError("case", fmt::format("unknown case '{}': `rodvv sweep` takes one exact case name "
                                         "(`rodvv list` shows them)",
                                         options.common.cases.front()));
  check_outputs(options.json_path, options.csv_path);
  Case writing;  // the case with each level's solution written out on the way
  if (options.write_solutions) {
    if (!c->checks_solutions())
      throw InputError("--write-solutions",
                       fmt::format("invalid --write-solutions: case '{}' does not split its levels into a solver run "
                                   "and measurements, so it has no solution to write (`rodvv check --list` names "
                                   "the cases that do)",
                                   c->info.name));
    std::error_code error;
    if (!std::filesystem::is_directory(*options.write_solutions, error))
      throw InputError("--write-solutions", fmt::format("invalid --write-solutions '{}': not a directory",
                                                        *options.write_solutions));
    writing = *c;
    writing.run_level = [c, directory = std::filesystem::path(*options.write_solutions)](
                            const harness::Parameters& parameters, double level) {
      const Solution solution = c->solve(parameters, level);
      write_level_solution(directory, *c, parameters, level, solution);
      return c->measure(parameters, level, solution);
    };
    c = &writing;
  }
  auto results = run_cases({c}, options.common, &options.levels);
  fmt::print("{}\n{}", render_level_table(results.front()), render_gate_table(results));
  const int code = exit_code(results);
  write_outputs(make_report(std::move(results)), options.json_path, options.csv_path);
  return code;
}

int report_command(const ReportOptions& options) {
  reports::ValidationReport report;
  if (options.from_dir) {
    if (!options.common.assignments.empty() || !options.common.cases.empty() || options.common.extended)
      throw InputError("--from", "invalid --from with --set, --extended or case names: `report --from` merges results "
                                 "already computed, so those options would have no effect; run the cases with "
                                 "`rodvv run --json` instead");
    std::error_code ignored;
    if (std::filesystem::weakly_canonical(*options.from_dir, ignored) ==
        std::filesystem::weakly_canonical(options.out_dir, ignored))
      throw InputError("--out", fmt::format("--out '{}' is the --from directory: the merged "
                                            "results.json would be read back as a part next time; "
                                            "choose another output directory",
                                            options.out_dir));
    report = reports::merge_reports(reports::read_reports_from_directory(*options.from_dir));
    fmt::print(stderr, "merged {} cases from {}\n", report.cases.size(), *options.from_dir);
  } else {
    const auto cases = harness::default_registry().select(options.common.cases);
    report = make_report(run_cases(cases, options.common, nullptr));
  }
  reports::WriteOptions write_options;
  write_options.make_plots = options.plots;
  const auto written = reports::write_report_directory(report, options.out_dir, write_options);
  if (!written.plots_ok) fmt::print(stderr, "warning: {}\n", written.plots_message);
  fmt::print("{}", render_gate_table(report.cases));
  fmt::print("report: {}\n", (std::filesystem::path(options.out_dir) / "index.html").string());
  return exit_code(report.cases);
}

int bless_command(const CommonOptions& options) {
  const std::filesystem::path path(options.goldens ? *options.goldens : std::string(RODVV_DEFAULT_GOLDENS));
  harness::Goldens goldens;
  if (std::filesystem::exists(path)) goldens = reports::read_goldens(path);
  else if (options.goldens)
    throw InputError("--goldens", fmt::format("invalid --goldens '{}': no such file (bless updates an existing file; "
                                              "without --goldens it writes the source tree's)",
                                              *options.goldens));
  const auto cases = harness::default_registry().select(options.cases);
  auto results = run_cases(cases, options, nullptr, false);
  std::size_t unchanged = 0, changed = 0, added = 0, refused = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto& result = results[i];
    const std::string& name = cases[i]->info.name;
    if (!result.passed()) {
      fmt::print("{:<48} NOT BLESSED: fails its verification gates (fix it, or bless what passes)\n", name);
      ++refused;
      continue;
    }
    harness::GoldenCase now = harness::golden_of(result);
    const auto old = goldens.find(name);
    if (old == goldens.end()) {
      fmt::print("{:<48} new\n", name);
      ++added;
    } else {
      auto changes = harness::compare_goldens(old->second, now);
      std::erase_if(changes, [](const harness::GoldenChange& c) { return c.deviation == 0.0; });
      bool levels_moved = old->second.levels.size() != now.levels.size();
      for (std::size_t l = 0; !levels_moved && l < now.levels.size(); ++l)
        levels_moved = old->second.levels[l].level != now.levels[l].level;
      if (changes.empty() && !levels_moved) {
        ++unchanged;
      } else {
        ++changed;
        fmt::print("{:<48} changed{}\n", name, levels_moved ? " (levels differ)" : "");
        std::sort(changes.begin(), changes.end(),
                  [](const auto& a, const auto& b) { return a.deviation > b.deviation; });
        const auto show = [](std::optional<double> v) { return v ? fmt::format("{:.10g}", *v) : std::string("-"); };
        for (std::size_t k = 0; k < changes.size() && k < 5; ++k)
          fmt::print("    {} = {:g} {}: value {} -> {}, error {} -> {} ({:.3g} x tolerance)\n",
                     cases[i]->info.resolution.name, changes[k].level, changes[k].metric, show(changes[k].old_value),
                     show(changes[k].new_value), show(changes[k].old_error), show(changes[k].new_error),
                     changes[k].deviation);
        if (changes.size() > 5) fmt::print("    ... and {} more values\n", changes.size() - 5);
      }
    }
    goldens[name] = std::move(now);
  }
  std::size_t removed = 0;
  if (options.cases.empty()) {  // blessing every case: goldens of cases that no longer exist go
    for (auto it = goldens.begin(); it != goldens.end();) {
      const bool known = std::any_of(cases.begin(), cases.end(), [&](const Case* c) { return c->info.name == it->first; });
      if (known) {
        ++it;
      } else {
        fmt::print("{:<48} removed (no such case)\n", it->first);
        it = goldens.erase(it);
        ++removed;
      }
    }
  }
  reports::write_goldens(path, goldens);
  fmt::print(stderr, "bless: {} unchanged, {} changed, {} new, {} removed, {} not blessed; wrote {}\n", unchanged,
             changed, added, removed, refused, path.string());
  return refused ? kGateFailed : kPass;
}

}  // namespace rodvv::apps

#include "commands.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "gate_table.hpp"
#include "progress.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"
#include "rodvv/reports/csv.hpp"
#include "rodvv/reports/json_io.hpp"
#include "rodvv/reports/provenance.hpp"
#include "rodvv/reports/report_document.hpp"
#include "rodvv/reports/report_writer.hpp"

namespace rodvv::apps {

namespace {

using harness::Case;
using harness::SweepResult;

// Runs each case at its default (or extended, or given) levels with the --set overrides applied.
// All parameters of all cases are validated before the first level runs, so bad input costs nothing.
std::vector<SweepResult> run_cases(const std::vector<const Case*>& cases, const CommonOptions& common,
                                   const std::vector<double>* levels_override) {
  std::vector<harness::Parameters> parameters;
  for (const Case* c : cases) {
    harness::Parameters p = c->info.parameters;
    for (const auto& assignment : common.assignments) {
      try {
        harness::apply_assignment(p, assignment);
      } catch (const InputError& error) {
        throw InputError(error.parameter(), fmt::format("case '{}': {}", c->info.name, error.what()));
      }
    }
    if (c->check_parameters) c->check_parameters(p);
    harness::validate_levels(*c, levels_override ? std::span<const double>(*levels_override)
                                                 : harness::sweep_levels(*c, common.extended));
    parameters.push_back(std::move(p));
  }
  ProgressReporter progress(cases.size(), common.verbose);
  std::vector<SweepResult> results;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const auto levels = levels_override ? std::span<const double>(*levels_override)
                                        : harness::sweep_levels(*cases[i], common.extended);
    results.push_back(harness::run_sweep(*cases[i], parameters[i], levels, progress.level_callback()));
    progress.case_finished(results.back());
  }
  return results;
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

int exit_code(const std::vector<SweepResult>& results) {
  for (const auto& result : results)
    if (!result.passed()) return kGateFailed;
  return kPass;
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
      fmt::print("    --set {}={:g}  in {} {}\n", parameter.name, parameter.value,
                 harness::describe_range(parameter), parameter.description);
    for (const auto& gate : c->gates) fmt::print("    gate: {}\n", gate.name);
  }
  fmt::print(stderr, "{} cases\n", cases.size());
  return kPass;
}

int run_command(const RunOptions& options) {
  const auto cases = harness::default_registry().select(options.common.cases);
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
  auto results = run_cases({c}, options.common, &options.levels);
  fmt::print("{}\n{}", render_level_table(results.front()), render_gate_table(results));
  const int code = exit_code(results);
  write_outputs(make_report(std::move(results)), options.json_path, options.csv_path);
  return code;
}

int report_command(const ReportOptions& options) {
  reports::ValidationReport report;
  if (options.from_dir) {
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

}  // namespace rodvv::apps

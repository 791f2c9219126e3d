// rodvv: run verification cases of slender-structure solvers against exact references and
// conservation laws, gate their convergence, and write the validation report.
#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <cstdio>
#include <exception>
#include <string>

#include "commands.hpp"
#include "rodvv/common/errors.hpp"

namespace {

constexpr const char* kDescription =
    "rodvv - verification and validation of slender-structure solvers.\n"
    "Runs each case at increasing resolution against closed-form references and invariants,\n"
    "fits observed orders, evaluates pass/fail gates and writes a validation report.\n"
    "Exit codes: 0 all gates passed, 1 a gate failed, 2 bad input, 3 internal error.";

void add_common(CLI::App* command, rodvv::apps::CommonOptions& common, bool cases_positional) {
  if (cases_positional)
    command->add_option("cases", common.cases,
                        "case names, family or group prefixes (pendulum, pendulum/rotation) or "
                        "globs ('*/rk4'); default: all");
  command->add_option("--set", common.assignments,
                      "override a case parameter, NAME=VALUE (validated against its range); repeatable");
  command->add_flag("-v,--verbose", common.verbose, "progress per level on stderr");
  command->add_option("--level-budget", common.level_budget,
                      "wall-clock seconds one level may take (default 300); past it the level fails, naming the "
                      "budget, and the run goes on");
  command->add_option("-j,--jobs", common.jobs,
                      "levels run at once on worker threads, in [1, 1024] (default: the core count); the results "
                      "are those of -j 1, only the times differ");
  command->add_option("--goldens", common.goldens,
                      "the regression gates' goldens file (default: the source tree's tests/goldens/default-levels.json, "
                      "skipped with a note if absent); written by `rodvv bless`");
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rodvv::apps;
  CLI::App app{kDescription, "rodvv"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rodvv 0.1.0");

  std::vector<std::string> list_patterns;
  bool list_verbose = false;
  auto* list = app.add_subcommand("list", "list the cases (with -v: levels, parameters, gates)");
  list->add_option("cases", list_patterns, "names, prefixes or globs to filter by");
  list->add_flag("-v,--verbose", list_verbose, "show levels, parameters and gates");

  RunOptions run_options;
  auto* run = app.add_subcommand("run", "run cases at their default levels and print the gate table "
                                        "(the CI gate)");
  add_common(run, run_options.common, true);
  run->add_flag("--extended", run_options.common.extended, "use the larger (extended) sweeps");
  run->add_option("--json", run_options.json_path, "also write the results as JSON (mergeable)");
  run->add_option("--csv", run_options.csv_path, "also write the results as CSV");
  run->add_option("--shard", run_options.shard,
                  "I/K: run only the I-th of K deterministic slices of the selected cases (round robin; "
                  "the K shards partition them; merge their --json files with `report --from`)");

  SweepOptions sweep_options;
  sweep_options.common.cases.resize(1);
  auto* sweep = app.add_subcommand("sweep", "run one case at the given levels and print every level");
  sweep->add_option("case", sweep_options.common.cases.front(), "exact case name")->required();
  add_common(sweep, sweep_options.common, false);
  sweep->add_option("--levels", sweep_options.levels,
                    "levels coarse to fine, comma separated (dt or tol decreasing, N increasing)")
      ->delimiter(',')
      ->check(CLI::Validator(
          [](std::string& level) {
            return level.empty() ? std::string("an empty level (levels are numbers, comma separated, e.g. 16,32,64)")
                                 : std::string();
          },
          "LEVEL"))
      ->required();
  sweep->add_option("--json", sweep_options.json_path, "also write the results as JSON");
  sweep->add_option("--csv", sweep_options.csv_path, "also write the results as CSV");
  sweep->add_option("--write-solutions", sweep_options.write_solutions,
                    "write each level's solution into this directory, in the format `rodvv check` reads");

  CheckOptions check_options;
  auto* check = app.add_subcommand("check", "check solution files written by any solver against a case: the "
                                            "same metrics, orders and gates as a sweep (README: \"Checking your "
                                            "own solver\")");
  check->add_option("case", check_options.case_name,
                    "the case or its group (default: the one the files name); `rodvv check --list`");
  check->add_option("--solution", check_options.solutions, "solution files, one per resolution level")
      ->expected(1, -1);
  check->add_option("--max-error", check_options.max_errors,
                    "METRIC=VALUE: the metric's error at the finest level must be <= VALUE; repeatable");
  check->add_option("--order", check_options.order,
                    "the order of convergence the solver should show (default: the case's theoretical order)");
  check->add_option("--json", check_options.json_path, "also write the results as JSON (mergeable)");
  check->add_option("--csv", check_options.csv_path, "also write the results as CSV");
  check->add_flag("--list", check_options.list, "list the cases that check solution files");

  ReportOptions report_options;
  auto* report = app.add_subcommand("report", "run every case (or merge results) and write the "
                                              "validation report: results.json, results.csv, "
                                              "report.md, index.html with plots, junit.xml");
  add_common(report, report_options.common, true);
  report->add_flag("--extended", report_options.common.extended, "use the larger (extended) sweeps");
  report->add_option("--out", report_options.out_dir, "output directory (default rodvv-report/)");
  report->add_option("--from", report_options.from_dir,
                     "merge the JSON files in this directory (from `rodvv run --json`) instead of running");
  report->add_flag("!--no-plots", report_options.plots, "skip the matplotlib plots");

  ProblemOptions problem_options;
  auto* problem = app.add_subcommand("problem", "write the data that poses a case's problem to another solver (the "
                                                "manufactured loads, the clamp, the tip loads, the exact solution) as "
                                                "JSON at uniform stations");
  problem->add_option("case", problem_options.case_name, "exact case name")->required();
  problem->add_option("--set", problem_options.assignments,
                      "override a case parameter, NAME=VALUE (validated against its range); repeatable");
  problem->add_option("--stations", problem_options.intervals, "uniform intervals along the rod (default 100)");
  problem->add_option("--out", problem_options.out, "the JSON file to write")->required();

  CommonOptions bless_options;
  auto* bless = app.add_subcommand("bless", "run cases at their default levels and parameters and write their metrics "
                                            "as the goldens of the regression gates, printing what moved");
  bless->add_option("cases", bless_options.cases, "case names, family or group prefixes or globs; default: all");
  bless->add_flag("-v,--verbose", bless_options.verbose, "progress per level on stderr");
  bless->add_option("-j,--jobs", bless_options.jobs, "levels run at once, in [1, 1024] (default: the core count)");
  bless->add_option("--goldens", bless_options.goldens,
                    "the goldens file to update (default: the source tree's tests/goldens/default-levels.json)");

  // An unknown first word is named (CLI11 would only say that a subcommand is required).
  if (argc >= 2 && argv[1][0] != '-') {
    const std::string word = argv[1];
    if (word != "list" && word != "run" && word != "sweep" && word != "report" && word != "check" && word != "bless" &&
        word != "problem") {
      fmt::print(stderr, "rodvv: error: unknown command '{}': expected list, run, sweep, report, check, problem or bless "
                         "(rodvv --help)\n",
                 word);
      return kBadInput;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int code = app.exit(error);
    return code == 0 ? kPass : kBadInput;
  }

  try {
    if (*list) return list_command(list_patterns, list_verbose);
    if (*run) return run_command(run_options);
    if (*sweep) return sweep_command(sweep_options);
    if (*report) return report_command(report_options);
    if (*check) return check_command(check_options);
    if (*problem) return problem_command(problem_options);
    if (*bless) return bless_command(bless_options);
  } catch (const rodvv::InputError& error) {
    fmt::print(stderr, "rodvv: error: {}\n", error.what());
    return kBadInput;
  } catch (const rodvv::SolverError& error) {
    fmt::print(stderr, "rodvv: numerical failure: {}\n", error.what());
    return kGateFailed;
  } catch (const std::exception& error) {
    fmt::print(stderr, "rodvv: internal error: {}\n", error.what());
    return kInternalError;
  }
  return kBadInput;
}

#pragma once
// The subcommands of `rodvv`. Each returns the process exit code:
//   0 every gate passed, 1 a gate (or a level) failed, 2 bad input, 3 internal error.
#include <optional>
#include <string>
#include <vector>

#include "rodvv/harness/sweep.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::apps {

enum ExitCode : int { kPass = 0, kGateFailed = 1, kBadInput = 2, kInternalError = 3 };

struct CommonOptions {
  std::vector<std::string> cases;        // names, family/group prefixes or globs; empty = all
  std::vector<std::string> assignments;  // --set NAME=VALUE
  bool extended = false;                 // larger sweeps
  bool verbose = false;                  // per-level progress
  double level_budget = harness::kDefaultLevelBudgetSeconds;  // --level-budget: seconds per level
  std::optional<int> jobs;  // -j: levels run at once; unset: the machine's core count
  std::optional<std::string> goldens;  // --goldens: the regression gates' file; unset: the source tree's
};

struct RunOptions {
  CommonOptions common;
  std::optional<std::string> json_path;
  std::optional<std::string> csv_path;
  std::optional<std::string> shard;  // "I/K": the I-th of K deterministic slices of the selected cases
};

struct SweepOptions {
  CommonOptions common;  // exactly one case
  std::vector<double> levels;
  std::optional<std::string> write_solutions;  // a directory: one solution file per level
  std::optional<std::string> json_path;
  std::optional<std::string> csv_path;
};

struct ReportOptions {
  CommonOptions common;
  std::string out_dir = "rodvv-report";
  std::optional<std::string> from_dir;  // merge results.json files instead of running
  bool plots = true;
};

struct CheckOptions {
  std::optional<std::string> case_name;  // a case or its group; default: the one the files name
  std::vector<std::string> solutions;    // solution files, one per level
  std::vector<std::string> max_errors;   // METRIC=VALUE: user bounds at the finest level
  std::optional<double> order;           // the order the solver should show (default: the case's)
  std::optional<std::string> json_path;
  std::optional<std::string> csv_path;
  bool list = false;  // list the cases that check solution files
};

int list_command(const std::vector<std::string>& patterns, bool verbose);
int run_command(const RunOptions& options);
int sweep_command(const SweepOptions& options);
int report_command(const ReportOptions& options);
int check_command(const CheckOptions& options);

struct ProblemOptions {
  std::string case_name;                 // exact
  std::vector<std::string> assignments;  // --set NAME=VALUE
  std::size_t intervals = 100;           // --stations: uniform intervals, intervals + 1 stations
  std::string out;                       // the JSON file written
};
int problem_command(const ProblemOptions& options);

// A case's parameters: its defaults with the --set assignments applied (InputError naming the case and the
// parameter), then its windows checked.
harness::Parameters case_parameters(const harness::Case& c, const std::vector<std::string>& assignments);
int bless_command(const CommonOptions& options);

// Shared by the commands: exit code of finished results (no evidence is not a pass), and the
// --json / --csv outputs.
int exit_code(const std::vector<harness::SweepResult>& results);
void check_outputs(const std::optional<std::string>& json_path, const std::optional<std::string>& csv_path);
void write_results(std::vector<harness::SweepResult> results, const std::optional<std::string>& json_path,
                   const std::optional<std::string>& csv_path);

}  // namespace rodvv::apps

#pragma once
// The subcommands of `rodvv`. Each returns the process exit code:
//   0 every gate passed, 1 a gate (or a level) failed, 2 bad input, 3 internal error.
#include <optional>
#include <string>
#include <vector>

namespace rodvv::apps {

enum ExitCode : int { kPass = 0, kGateFailed = 1, kBadInput = 2, kInternalError = 3 };

struct CommonOptions {
  std::vector<std::string> cases;        // names, family/group prefixes or globs; empty = all
  std::vector<std::string> assignments;  // --set NAME=VALUE
  bool extended = false;                 // larger sweeps
  bool verbose = false;                  // per-level progress
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
  std::optional<std::string> json_path;
  std::optional<std::string> csv_path;
};

struct ReportOptions {
  CommonOptions common;
  std::string out_dir = "rodvv-report";
  std::optional<std::string> from_dir;  // merge results.json files instead of running
  bool plots = true;
};

int list_command(const std::vector<std::string>& patterns, bool verbose);
int run_command(const RunOptions& options);
int sweep_command(const SweepOptions& options);
int report_command(const ReportOptions& options);

}  // namespace rodvv::apps

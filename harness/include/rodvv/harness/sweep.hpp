#pragma once
// The sweep runner: runs a case at each level (coarse -> fine), times each level, collects the
// metrics, fits orders, applies Richardson/GCI to extrapolable metrics and evaluates the gates.
#include <cstddef>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "rodvv/harness/case.hpp"

namespace rodvv::harness {

struct SweepProgress {
  std::string case_name;
  std::string resolution_name;
  std::size_t level_index = 0;  // 0-based
  std::size_t level_count = 0;
  double level = 0.0;
  double seconds = 0.0;  // wall time of that level
  bool failed = false;
};
using ProgressCallback = std::function<void(const SweepProgress&)>;

// Checks that levels are finite, positive, integral for count resolutions, strictly refining
// (h decreasing), no finer than the case honours (finest_level_honoured) and at least fit_levels
// many when the case gates an order. Throws InputError.
void validate_levels(const Case& c, std::span<const double> levels);

// The finest level a case honours: resolution.finest_honoured if set, else four times finer (in h)
// than its finest default or extended level - a sweep one or two refinements past what the case
// was measured on, not the 1e6 elements that end in a bad_alloc or a run of hours.
double finest_level_honoured(const Resolution& resolution);

// The wall-clock budget of one level (rodvv --level-budget): the solvers' loops check it
// (common/time_budget.hpp) and stop past it with a SolverError naming it, a level failure, so no
// input hangs a run. 300 s: 7x the slowest level of the extended sweep (the plectoneme, ~40 s).
inline constexpr double kDefaultLevelBudgetSeconds = 300.0;

// Runs the sweep. InputError from parameters or levels propagates (nothing is run); a SolverError
// at a level is recorded as that level's failure and the sweep goes on, and so is running out of
// memory (std::bad_alloc), named as such: never an internal error. Each level runs under a
// TimeBudget of level_budget_seconds.
SweepResult run_sweep(const Case& c, const Parameters& parameters, std::span<const double> levels,
                      const ProgressCallback& progress = {},
                      double level_budget_seconds = kDefaultLevelBudgetSeconds);

// The two halves of run_sweep, for runners that schedule levels themselves (parallel_sweeps.hpp):
// one level, timed (wall and the thread's CPU time) under its budget, a SolverError or bad_alloc
// recorded as its failure; and the analyses and gates over the finished levels (wall_seconds left
// for the caller to set).
LevelResult run_level(const Case& c, const Parameters& parameters, double level, double level_budget_seconds);
SweepResult finish_sweep(const Case& c, const Parameters& parameters, std::vector<LevelResult> levels);

// Orders (and Richardson/GCI for extrapolable metrics) of a case's metrics over finished levels.
std::vector<MetricAnalysis> analyse_levels(const Case& c, const std::vector<LevelResult>& levels);

// Default levels, or the extended ones when asked (falling back to the defaults if a case has none).
std::span<const double> sweep_levels(const Case& c, bool extended);

}  // namespace rodvv::harness

#pragma once
// Sweeps of many cases on a pool of worker threads (rodvv run/report -j N). The unit of work is one
// level of one case, not a whole case: a few cases (the plectoneme's three levels) hold most of the
// run's time, and their levels are independent solves. Results are exactly those of run_sweep one
// case after another: every level is computed by the same code from the same inputs, whatever the
// thread, and gathered in case and level order (only the times differ).
//
// Callbacks are serialised (never two at once): on_level as each level finishes (in completion
// order), on_case in case order, as soon as a case and every case before it are complete.
#include <cstddef>
#include <functional>
#include <span>
#include <vector>

#include "rodvv/harness/sweep.hpp"

namespace rodvv::harness {

struct SweepJob {
  const Case* c = nullptr;
  Parameters parameters;
  std::vector<double> levels;
};

using CaseCallback = std::function<void(const SweepResult&)>;
// Applied to each finished case (its index in jobs) before on_case sees it: e.g. its regression
// gate (golden.hpp).
using CaseAmendment = std::function<void(std::size_t job, SweepResult&)>;

// Validates every job's levels and parameters first (InputError before anything runs). An
// InputError thrown inside a level that names an input of its case (run_level) stops the workers
// taking new levels and is rethrown, the first in job order. `workers` >= 1 (1: this thread only).
// A case's wall_seconds is the sum of its levels' wall times (its levels may overlap in time).
std::vector<SweepResult> run_sweeps(std::span<const SweepJob> jobs, std::size_t workers,
                                    double level_budget_seconds = kDefaultLevelBudgetSeconds,
                                    const ProgressCallback& on_level = {}, const CaseCallback& on_case = {},
                                    const CaseAmendment& amend = {});

}  // namespace rodvv::harness

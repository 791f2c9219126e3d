#include "rodvv/common/time_budget.hpp"

#include <algorithm>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv {
namespace {
using Clock = std::chrono::steady_clock;
thread_local std::optional<Clock::time_point> deadline;
thread_local double budget_seconds = 0.0;
}  // namespace

TimeBudget::TimeBudget(double seconds) : previous_deadline_(deadline), previous_seconds_(budget_seconds) {
  require_positive("level_budget", seconds);
  const auto mine = Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                       std::min(seconds, 1e9)));  // 30 years: no overflow of the clock
  if (!deadline || mine < *deadline) {
    deadline = mine;
    budget_seconds = seconds;
  }
}

TimeBudget::~TimeBudget() {
  deadline = previous_deadline_;
  budget_seconds = previous_seconds_;
}

void check_time_budget(std::string_view method, std::size_t iterations, double residual) {
  if (deadline && Clock::now() > *deadline)
    throw SolverError(std::string(method),
                      "exceeded its time budget of " + format_value(budget_seconds) +
                          " s per level (rodvv --level-budget)",
                      iterations, residual);
}

}  // namespace rodvv

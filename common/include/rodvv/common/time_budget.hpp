#pragma once
// A wall-clock budget for one piece of work on this thread (a sweep level), checked cooperatively by
// the solvers' iteration loops (Newton iterations, time steps): past the deadline the loop throws a
// SolverError naming the budget, which the sweep records as a level failure (exit 1), so that no
// input makes a run hang (issue 14, class 3). Nothing is interrupted from outside.
#include <chrono>
#include <cstddef>
#include <optional>
#include <string_view>

namespace rodvv {

// Sets this thread's deadline to now + seconds for its lifetime (nested budgets: the earlier
// deadline wins) and restores the previous one. seconds must be > 0 (InputError "level_budget").
class TimeBudget {
 public:
  explicit TimeBudget(double seconds);
  ~TimeBudget();
  TimeBudget(const TimeBudget&) = delete;
  TimeBudget& operator=(const TimeBudget&) = delete;

 private:
  std::optional<std::chrono::steady_clock::time_point> previous_deadline_;
  double previous_seconds_ = 0.0;
};

// Throws SolverError(method, "exceeded its time budget of ... s", iterations, residual) when this
// thread has a deadline and it has passed; free otherwise (one clock read, no allocation: it is
// called on every Newton iteration and time step).
void check_time_budget(std::string_view method, std::size_t iterations, double residual);

}  // namespace rodvv

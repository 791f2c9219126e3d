#include "rodvv/harness/parallel_sweeps.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "rodvv/common/errors.hpp"

namespace rodvv::harness {

std::vector<SweepResult> run_sweeps(std::span<const SweepJob> jobs, std::size_t workers, double level_budget_seconds,
                                    const ProgressCallback& on_level, const CaseCallback& on_case,
                                    const CaseAmendment& amend) {
  if (workers < 1) throw InputError("jobs", "invalid number of jobs 0: must be at least 1");
  for (const SweepJob& job : jobs) {
    validate_levels(*job.c, job.levels);
    if (job.c->check_parameters) job.c->check_parameters(job.parameters);
  }

  // Levels in case order, coarse to fine: the order of a serial run.
  struct Task {
    std::size_t job, level;
  };
  std::vector<Task> tasks;
  std::vector<std::vector<std::optional<LevelResult>>> finished(jobs.size());
  std::vector<std::size_t> remaining(jobs.size());
  for (std::size_t j = 0; j < jobs.size(); ++j) {
    for (std::size_t l = 0; l < jobs[j].levels.size(); ++l) tasks.push_back({j, l});
    finished[j].resize(jobs[j].levels.size());
    remaining[j] = jobs[j].levels.size();
  }
  std::vector<std::optional<SweepResult>> results(jobs.size());
  std::vector<std::exception_ptr> errors(jobs.size());
  std::atomic<std::size_t> next_task{0};
  std::atomic<bool> stop{false};
  std::mutex mutex;  // guards finished, remaining, results, errors, next_report and the callbacks
  std::size_t next_report = 0;

  const auto work = [&] {
    while (!stop.load()) {
      const std::size_t t = next_task.fetch_add(1);
      if (t >= tasks.size()) return;
      const Task task = tasks[t];
      const SweepJob& job = jobs[task.job];
      try {
        LevelResult level = run_level(*job.c, job.parameters, job.levels[task.level], level_budget_seconds);
        const std::lock_guard lock(mutex);
        if (on_level)
          on_level({job.c->info.name, job.c->info.resolution.name, task.level, job.levels.size(), level.level,
                    level.wall_seconds, level.failure.has_value()});
        finished[task.job][task.level] = std::move(level);
        if (--remaining[task.job] != 0) continue;
        std::vector<LevelResult> levels;
        double wall = 0.0;
        for (auto& l : finished[task.job]) {
          wall += l->wall_seconds;
          levels.push_back(std::move(*l));
        }
        results[task.job] = finish_sweep(*job.c, job.parameters, std::move(levels));
        results[task.job]->wall_seconds = wall;
        if (amend) amend(task.job, *results[task.job]);
        for (; next_report < jobs.size() && results[next_report]; ++next_report)
          if (on_case) on_case(*results[next_report]);
      } catch (...) {
        const std::lock_guard lock(mutex);
        if (!errors[task.job]) errors[task.job] = std::current_exception();
        stop = true;
      }
    }
  };

  {
    std::vector<std::jthread> pool;
    for (std::size_t w = 1; w < workers && w < tasks.size(); ++w) pool.emplace_back(work);
    work();
  }  // joined here
  for (const auto& error : errors)
    if (error) std::rethrow_exception(error);
  std::vector<SweepResult> out;
  out.reserve(results.size());
  for (auto& r : results) out.push_back(std::move(*r));
  return out;
}

}  // namespace rodvv::harness

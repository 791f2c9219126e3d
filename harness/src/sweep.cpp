#include "rodvv/harness/sweep.hpp"

#include <chrono>
#include <ctime>
#include <time.h>
#include <cmath>
#include <limits>
#include <new>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/convergence.hpp"

namespace rodvv::harness {

namespace {

// An InputError naming this is the user's: a parameter of the case, its resolution, its levels.
bool names_input_of(const Case& c, const std::string& name) {
  if (name == c.info.resolution.name || name == "levels") return true;
  for (const auto& parameter : c.info.parameters)
    if (parameter.name == name) return true;
  return false;
}

// CPU time of the calling thread: a level runs on one thread, so this is its own CPU time even
// when other levels run beside it (std::clock counts the whole process).
double thread_cpu_seconds() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

bool gates_an_order(const Case& c) {
  for (const auto& gate : c.gates)
    if (gate.kind == GateKind::Order) return true;
  return false;
}

}  // namespace

std::vector<MetricAnalysis> analyse_levels(const Case& c, const std::vector<LevelResult>& levels) {
  return analyse_metrics(c.info.metrics, levels, c.fit_levels,
                         c.info.resolution.scale != ResolutionScale::Parameter);
}

std::span<const double> sweep_levels(const Case& c, bool extended) {
  if (extended && !c.info.resolution.extended_levels.empty()) return c.info.resolution.extended_levels;
  return c.info.resolution.default_levels;
}

double finest_level_honoured(const Resolution& resolution) {
  if (resolution.finest_honoured > 0.0) return resolution.finest_honoured;
  double finest_h = std::numeric_limits<double>::infinity();
  for (const auto* levels : {&resolution.default_levels, &resolution.extended_levels})
    for (double level : *levels) finest_h = std::min(finest_h, resolution.h(level));
  if (!std::isfinite(finest_h)) return resolution.increasing() ? 1e9 : 0.0;
  return resolution.increasing() ? 4.0 / finest_h : finest_h / 4.0;
}

void validate_levels(const Case& c, std::span<const double> levels) {
  const Resolution& resolution = c.info.resolution;
  if (levels.empty()) throw InputError("levels", "case '" + c.info.name + "': no levels given");
  const double finest = finest_level_honoured(resolution);
  const bool count = resolution.scale == ResolutionScale::Count, increasing = resolution.increasing();
  for (double level : levels) {
    require_positive(resolution.name, level);
    if (count && level != std::floor(level))
      throw InputError(resolution.name, "invalid level " + resolution.name + " = " +
                                            format_value(level) + ": must be a whole number >= 1");
    if (increasing ? level > finest : level < finest)
      throw InputError(resolution.name,
                       "invalid level " + resolution.name + " = " + format_value(level) + ": case '" + c.info.name +
                           "' honours " + resolution.name + (increasing ? " <= " : " >= ") + format_value(finest) +
                           " on this machine class (" +
                           (resolution.finest_honoured > 0.0 ? "declared by the case"
                                                             : "four times finer than its finest extended level") +
                           "); finer levels would exhaust time or memory");
  }
  for (std::size_t i = 1; i < levels.size(); ++i)
    if (!(resolution.h(levels[i]) < resolution.h(levels[i - 1])))
      throw InputError("levels", "case '" + c.info.name + "': levels must refine strictly from " +
                                     "coarse to fine (" + resolution.name + " " +
                                     (resolution.increasing() ? "increasing" : "decreasing") +
                                     "), but " + format_value(levels[i - 1]) + " is followed by " +
                                     format_value(levels[i]));
  if (gates_an_order(c) && levels.size() < c.fit_levels)
    throw InputError("levels", "case '" + c.info.name + "' gates an observed order, which needs at least " +
                                   std::to_string(c.fit_levels) + " levels; got " +
                                   std::to_string(levels.size()));
}

void require_window(Case& c, std::string statement, ParameterCheck check) {
  c.info.parameter_windows.push_back(std::move(statement));
  c.check_parameters = [earlier = std::move(c.check_parameters), check = std::move(check)](const Parameters& p) {
    if (earlier) earlier(p);
    check(p);
  };
}

void split_level(Case& c, SolveLevel solve, MeasureSolution measure) {
  c.run_level = [solve, measure](const Parameters& parameters, double level) {
    return measure(parameters, level, solve(parameters, level));
  };
  c.solve = std::move(solve);
  c.measure = std::move(measure);
}

LevelResult run_level(const Case& c, const Parameters& parameters, double level_value,
                      double level_budget_seconds) {
  using Clock = std::chrono::steady_clock;
  LevelResult level;
  level.level = level_value;
  level.h = c.info.resolution.h(level_value);
  const auto start = Clock::now();
  const double cpu_start = thread_cpu_seconds();
  try {
    const TimeBudget budget(level_budget_seconds);
    LevelOutput output = c.run_level(parameters, level_value);
    level.metrics = std::move(output.metrics);
    level.series = std::move(output.series);
  } catch (const SolverError& error) {
    level.failure = error.what();
  } catch (const InputError& error) {
    // Naming one of the case's parameters (or its resolution), it is the user's input: exit 2. Naming
    // anything else, it is an input the case built for a solver from the results of another (a rest
    // shape that does not hold its target, a state that is not at rest): a numerical failure of
    // this level, not bad input (issue 13: a defect in the inverse statics ended a run with exit 2).
    if (names_input_of(c, error.parameter())) throw;
    level.failure = "internal input refused at " + c.info.resolution.name + " = " + format_value(level_value) +
                    " (not a parameter of the case): " + error.what();
  } catch (const std::bad_alloc&) {
    level.failure = "out of memory at " + c.info.resolution.name + " = " + format_value(level_value) +
                    " (std::bad_alloc)";
  }
  level.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  level.cpu_seconds = thread_cpu_seconds() - cpu_start;
  return level;
}

SweepResult finish_sweep(const Case& c, const Parameters& parameters, std::vector<LevelResult> levels) {
  SweepResult result;
  result.info = c.info;
  result.info.parameters = parameters;
  result.levels = std::move(levels);
  result.analyses = analyse_levels(c, result.levels);
  // A measured bound holds at the default parameters; changing a unit scale alone keeps it.
  const bool at_defaults = at_default_parameters(c.info, parameters, true);
  for (const GateSpec& gate : c.gates) {
    if (gate.measured && !at_defaults)
      result.skipped_gates.push_back(gate.name + ": bound measured at the default parameters");
    else
      result.gates.push_back(evaluate_gate(gate, result));
  }
  return result;
}

SweepResult run_sweep(const Case& c, const Parameters& parameters, std::span<const double> levels,
                      const ProgressCallback& progress, double level_budget_seconds) {
  validate_levels(c, levels);
  if (c.check_parameters) c.check_parameters(parameters);
  const auto sweep_start = std::chrono::steady_clock::now();
  std::vector<LevelResult> results;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    results.push_back(run_level(c, parameters, levels[i], level_budget_seconds));
    if (progress)
      progress({c.info.name, c.info.resolution.name, i, levels.size(), results.back().level,
                results.back().wall_seconds, results.back().failure.has_value()});
  }
  SweepResult result = finish_sweep(c, parameters, std::move(results));
  result.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - sweep_start).count();
  return result;
}

}  // namespace rodvv::harness

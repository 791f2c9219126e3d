#pragma once
// A verification case: a problem with a known answer, a solver, the metrics compared at each
// resolution level, and the gates that decide pass/fail (ARCHITECTURE.md, "Data flow").
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/solution.hpp"
#include "rodvv/harness/case_info.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/harness/problem_data.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

// What one level produces: its metrics, and curves for plots.
struct LevelOutput {
  std::map<std::string, MetricSample> metrics;
  std::vector<Series> series;
};

// Runs the solver at one resolution level with the given parameters. Throws InputError for
// parameters the solver rejects and SolverError for numerical failure.
using LevelRunner = std::function<LevelOutput(const Parameters& parameters, double level)>;

// Cross-parameter validation beyond each parameter's own range (e.g. v0 > 2 omega); throws
// InputError. Called before any level runs.
using ParameterCheck = std::function<void(const Parameters& parameters)>;

// A level split in two, for the cases that can check solutions written by other solvers
// (`rodvv check`): the solver run, and the measurements of its solution against the reference.
// measure reads only the Solution (and the parameters and level that posed it), never a solver's
// internals, so a file written by anyone gives the same metrics as rodvv's own run.
using SolveLevel = std::function<Solution(const Parameters& parameters, double level)>;
using MeasureSolution =
    std::function<LevelOutput(const Parameters& parameters, double level, const Solution& solution)>;

struct Case {
  CaseInfo info;  // info.parameters holds the defaults
  std::vector<GateSpec> gates;
  std::size_t fit_levels = 3;  // least-squares order over the last fit_levels levels (>= 3)
  // For metrics at round-off (in units of eps, or at a floor set by the problem's conditioning): the
  // regression gate's absolute tolerance on value and error (golden.hpp), derived where it is set. Their
  // bits follow the CPU: glibc's libm picks its FMA code paths at run time, and the last bits of sin,
  // exp, pow move the round-off such a metric measures.
  std::map<std::string, double> golden_absolute;
  ParameterCheck check_parameters;
  LevelRunner run_level;
  // Set together by split_level, in the cases that can check solution files.
  SolveLevel solve;
  MeasureSolution measure;
  bool checks_solutions() const { return bool(solve) && bool(measure); }
  // The data another solver needs to pose the problem (manufactured loads; `rodvv problem`); empty when
  // the case's parameters and text pose it.
  ProblemDataAt problem_data;
};

// The alternative of a Solution that a case measures; InputError naming both kinds otherwise.
template <class Kind>
const Kind& solution_as(const Solution& solution, const char* expected_kind);

// Adds a window on a combination of parameters: its statement to info.parameter_windows (so that
// `list -v` promises no more than a run accepts) and its check to check_parameters, after any
// earlier one. The check throws InputError beyond the window.
void require_window(Case& c, std::string statement, ParameterCheck check);

// Makes a case check solution files: sets solve, measure, and run_level = measure(solve(...)).
void split_level(Case& c, SolveLevel solve, MeasureSolution measure);

template <class Kind>
const Kind& solution_as(const Solution& solution, const char* expected_kind) {
  if (const Kind* found = std::get_if<Kind>(&solution)) return *found;
  throw InputError("solution", std::string("this case measures a ") + expected_kind + " solution; got a " +
                                   solution_kind(solution));
}

}  // namespace rodvv::harness

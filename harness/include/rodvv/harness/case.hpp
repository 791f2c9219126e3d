#pragma once
// A verification case: a problem with a known answer, a solver, the metrics compared at each
// resolution level, and the gates that decide pass/fail (ARCHITECTURE.md, "Data flow").
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "rodvv/harness/case_info.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/parameters.hpp"
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

struct Case {
  CaseInfo info;  // info.parameters holds the defaults
  std::vector<GateSpec> gates;
  std::size_t fit_levels = 3;  // least-squares order over the last fit_levels levels (>= 3)
  ParameterCheck check_parameters;
  LevelRunner run_level;
};

}  // namespace rodvv::harness

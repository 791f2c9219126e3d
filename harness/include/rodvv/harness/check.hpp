#pragma once
// `rodvv check`: a case's metrics, orders and gates computed on solutions that another solver
// wrote, one solution per resolution level, exactly as a sweep computes them on rodvv's own.
//
// Which gates apply to another solver: the case's ORDER gates (the order a consistent scheme of the
// case's theoretical order shows) and the bounds the user states (`--max-error METRIC=VALUE`, on the
// finest level). The case's own bound gates are constants measured on, or exactness properties
// of, rodvv's solver; they are skipped and the result says so. An order gate needs fit_levels
// solutions; with fewer it is skipped, and so is a gate on a metric that the solutions do not allow
// (the reader says which fields were missing).
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "rodvv/common/solution.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

struct LevelSolution {
  std::string source;  // where it came from (a file name), for messages
  double level = 0.0;  // the resolution it was computed at, in the case's resolution (N, dt)
  Solution solution;
  std::string solver;  // who computed it (free text from the file)
  double cpu_seconds = 0.0;  // its cost, as the file states it (0: not stated)
  double wall_seconds = 0.0;
};

// Throws InputError: a case that cannot check solutions, no solutions, levels that do not refine
// strictly, a solution of the wrong kind (planar for a trajectory case), or a user bound on a metric
// the case does not have. A solution the case's measurements reject (too few nodes, inconsistent
// arrays) is an InputError naming its source.
// stated_order: the order of the user's scheme (--order); the order gates then use the window
// around it instead of around the case's theoretical order (a first-order scheme checked against a
// problem that rodvv solves at second order).
SweepResult check_solutions(const Case& c, const Parameters& parameters, std::vector<LevelSolution> solutions,
                            std::span<const GateSpec> user_bounds, std::optional<double> stated_order = std::nullopt);

// An upper bound on a metric's gated value at the finest level, stated by the user.
GateSpec user_bound(const Case& c, const std::string& metric, double bound);

}  // namespace rodvv::harness

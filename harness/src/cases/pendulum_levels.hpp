#pragma once
// Default sweep levels and measured gate bounds of the pendulum cases. The levels are chosen in the
// asymptotic range of each method (errors well above round-off, below the pre-asymptotic regime),
// measured first with `rodvv sweep CASE --levels ...` over a wide range, then fixed here.
#include <string>
#include <string_view>
#include <vector>

namespace rodvv::harness {

struct LevelPlan {
  std::vector<double> levels;           // default: coarse -> fine, factor 2
  std::vector<double> extended_levels;  // `--extended`: two more refinements
  double error_bound = 0.0;             // theta_max_error at the finest default level
  double period_bound = 0.0;            // |period - 4K/omega| at the finest default level
  double tolerance_ratio_bound = 0.0;   // adaptive: theta_max_error / tol at every level
  double tolerance_order = 1.0;         // adaptive: slope of log error vs log tol
  std::string order_metric = "state_max_error";  // the metric whose order is gated
  std::string rationale;                // how the bounds were derived, and any exception
};

// motion: "libration-30", ..., or "long-time-energy"; method: a solvers::pendulum method id.
LevelPlan pendulum_level_plan(std::string_view motion, std::string_view method);

}  // namespace rodvv::harness

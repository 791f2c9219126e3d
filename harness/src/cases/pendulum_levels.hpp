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
  // Measured bounds C h^p: state_max_error <= error_constant h^error_order and
  // |period - 4K/omega| <= period_constant h^period_order (constant 0: no bound gate).
  double error_constant = 0.0;
  double error_order = 0.0;
  double period_constant = 0.0;
  double period_order = 0.0;
  double tolerance_ratio_bound = 0.0;   // adaptive: theta_max_error / tol at every level
  double tolerance_order = 1.0;         // adaptive: slope of log error vs log tol
  std::string order_metric = "state_max_error";  // the metric whose order is gated
  std::string rationale;                // how the bounds were derived
  std::string note;                     // why this case departs from the usual gates, if it does
};

// motion: "libration-30", ..., or "long-time-energy"; method: a solvers::pendulum method id with
// its theoretical order.
LevelPlan pendulum_level_plan(std::string_view motion, std::string_view method, int method_order);

}  // namespace rodvv::harness

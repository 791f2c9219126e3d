#include "pendulum_levels.hpp"

#include <stdexcept>
#include <string>

namespace rodvv::harness {

namespace {

std::vector<double> halvings(double coarsest, int count) {
  std::vector<double> levels;
  for (int i = 0; i < count; ++i) levels.push_back(coarsest / double(1 << i));
  return levels;
}

}  // namespace

LevelPlan pendulum_level_plan(std::string_view motion, std::string_view method) {
  // PROVISIONAL: to be replaced by measured levels and bounds.
  LevelPlan plan;
  double coarsest = 0.02;
  if (method == "explicit-euler" || method == "symplectic-euler") coarsest = 4e-3;
  if (method == "stormer-verlet") coarsest = 0.04;
  if (method == "rk4" || method == "rkn4-mclachlan") coarsest = 0.2;
  if (method == "dopri5") coarsest = 1e-6;
  if (motion == "long-time-energy") coarsest = 0.1;
  const double ratio = method == "dopri5" ? 10.0 : 2.0;
  for (int i = 0; i < 6; ++i) {
    double level = coarsest;
    for (int j = 0; j < i; ++j) level /= ratio;
    (i < 4 ? plan.levels : plan.extended_levels).push_back(level);
  }
  (void)halvings;
  plan.error_bound = 1.0;
  plan.period_bound = 1.0;
  plan.tolerance_ratio_bound = 100.0;
  plan.growth_bound = method == "explicit-euler" || method == "rk4" ? 10.0 : 2.0;
  plan.rationale = "provisional";
  return plan;
}

}  // namespace rodvv::harness

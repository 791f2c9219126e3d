#pragma once
// Pass/fail gates of a case (ARCHITECTURE.md, convention 7).
//  - Order: the least-squares observed order of a metric's error lies in the two-sided window
//    [p - 0.1, p + 0.5] around the theoretical order p (MOOSE's mms style): an order well above
//    theory is a failure too, since it means the test is not measuring what it claims.
//  - UpperBound / LowerBound: the gated value of a metric (its error where it has one, else its
//    computed value) at the finest level, or at every level, lies below / above a bound.
// Each gate evaluates to a GateResult with a one-line reason saying what was measured against what.
#include <limits>
#include <string>
#include <vector>

#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

inline constexpr double kOrderWindowBelow = 0.1;
inline constexpr double kOrderWindowAbove = 0.5;

struct GateSpec {
  std::string name;
  GateKind kind = GateKind::Order;
  std::string metric;
  double lower = -std::numeric_limits<double>::infinity();  // window [lower, upper]; a bound gate uses one side
  double upper = std::numeric_limits<double>::infinity();
  GateScope scope = GateScope::FinestLevel;  // bound gates only
  std::string rationale;  // where the bound comes from (theory, a measured floor times a factor)
};

GateSpec order_gate(std::string metric, double theoretical_order, std::string rationale);
GateSpec upper_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);
GateSpec lower_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);

// The value a bound gate compares: the error where the sample has one, else the computed value.
double gated_value(const MetricSample& sample);

// Evaluates a gate on a finished sweep (levels and analyses filled in).
GateResult evaluate_gate(const GateSpec& gate, const SweepResult& sweep);

}  // namespace rodvv::harness

#pragma once
// Pass/fail gates of a case (ARCHITECTURE.md, convention 7).
//  - Order: the least-squares observed order of a metric's error lies in the two-sided window
//    [p - 0.1, p + 0.5] around the theoretical order p (MOOSE's mms style): an order well above
//    theory is a failure too, since it means the test is not measuring what it claims.
//  - UpperBound / LowerBound: the gated value of a metric (its error where it has one, else its
//    computed value) at the finest level, or at every level, lies below / above a bound. A bound
//    with bound_order p != 0 is C h^p (C = `upper`), so it follows the level it is checked at (p < 0:
//    a quantity allowed to grow under refinement, such as round-off, C N^|p| for h = 1/N).
//    A bound measured at a case's default parameters (`measured`) does not apply to other
//    parameters: the sweep skips it there and records that it did.
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
  double bound_order = 0.0;  // bound gates: 0 = constant bound, p != 0 = bound x h^p
  bool measured = false;     // the bound was measured at the case's default parameters
  std::string rationale;  // where the bound comes from (theory, a measured floor times a factor)
};

GateSpec order_gate(std::string metric, double theoretical_order, std::string rationale);
GateSpec upper_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);
GateSpec lower_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);
// value <= constant * h^order: a measured error constant times the theoretical power of h.
GateSpec scaled_upper_bound_gate(std::string metric, double constant, double order, GateScope scope,
                                 std::string rationale);

// The value a bound gate compares: the error where the sample has one, else the computed value.
double gated_value(const MetricSample& sample);

// Evaluates a gate on a finished sweep (levels and analyses filled in).
GateResult evaluate_gate(const GateSpec& gate, const SweepResult& sweep);

}  // namespace rodvv::harness

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
//  - A relative bound (`relative`) gates error / size, size = the sample's stated scale, else
//    |reference| (metric_size). Every order gate gets one, the resolution gate (resolution_gate): the
//    finest level's error is at most kResolvedFraction of the quantity's size. An order says the
//    error shrinks like h^p; only beside a magnitude does it say the levels resolve the solution
//    (issue 14: errors of 1e7 rad that shrank exactly as dt^2 passed an order gate). This magnitude
//    holds at any parameters, where bounds measured at the defaults are skipped.
// Each gate evaluates to a GateResult with a one-line reason saying what was measured against what.
#include <limits>
#include <string>
#include <vector>

#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

inline constexpr double kOrderWindowBelow = 0.1;
inline constexpr double kOrderWindowAbove = 0.5;
// The asymptotic range the resolution gate asks of the finest level: an error under a tenth of the
// quantity. Beyond it e = C h^p (1 + O(h)) is no longer an expansion one can fit (ASME V&V 20's
// asymptotic-range condition, stated as a size). Measured at the defaults of every case: <= 0.084.
inline constexpr double kResolvedFraction = 0.1;

struct GateSpec {
  std::string name;
  GateKind kind = GateKind::Order;
  std::string metric;
  double lower = -std::numeric_limits<double>::infinity();  // window [lower, upper]; a bound gate uses one side
  double upper = std::numeric_limits<double>::infinity();
  GateScope scope = GateScope::FinestLevel;  // bound gates only
  double bound_order = 0.0;  // bound gates: 0 = constant bound, p != 0 = bound x h^p
  bool measured = false;     // the bound was measured at the case's default parameters
  bool relative = false;     // bound gates: on error / metric_size(sample), not on the error
  std::string rationale;  // where the bound comes from (theory, a measured floor times a factor)
};

GateSpec order_gate(std::string metric, double theoretical_order, std::string rationale);
// For an error that mixes two orders (an O(h) and an O(h^2) part whose weights move with the
// parameters): the window [low - 0.1, high + 0.5] around the orders the theory brackets.
GateSpec order_range_gate(std::string metric, double low_order, double high_order, std::string rationale);
GateSpec upper_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);
GateSpec lower_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale);
// value <= constant * h^order: a measured error constant times the theoretical power of h.
GateSpec scaled_upper_bound_gate(std::string metric, double constant, double order, GateScope scope,
                                 std::string rationale);

// value / size <= kResolvedFraction at the finest level, for a metric with an order gate.
GateSpec resolution_gate(std::string metric);
// Appends a resolution gate for each metric that has an order gate and none yet (Registry::add).
void add_resolution_gates(std::vector<GateSpec>& gates);

// The value a bound gate compares: the error where the sample has one, else the computed value.
double gated_value(const MetricSample& sample);
// The stated scale, else |reference|, when positive and finite; nothing when the sample has no size.
std::optional<double> metric_size(const MetricSample& sample);

// Evaluates a gate on a finished sweep (levels and analyses filled in).
GateResult evaluate_gate(const GateSpec& gate, const SweepResult& sweep);

}  // namespace rodvv::harness

#include "rodvv/harness/gate.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <fmt/format.h>

namespace rodvv::harness {

GateSpec order_gate(std::string metric, double theoretical_order, std::string rationale) {
  GateSpec gate;
  gate.name = fmt::format("order of {} = {:g}", metric, theoretical_order);
  gate.kind = GateKind::Order;
  gate.metric = std::move(metric);
  gate.lower = theoretical_order - kOrderWindowBelow;
  gate.upper = theoretical_order + kOrderWindowAbove;
  gate.rationale = std::move(rationale);
  return gate;
}

GateSpec order_range_gate(std::string metric, double low_order, double high_order, std::string rationale) {
  GateSpec gate = order_gate(std::move(metric), low_order, std::move(rationale));
  gate.name = fmt::format("order of {} in [{:g}, {:g}]", gate.metric, low_order, high_order);
  gate.upper = high_order + kOrderWindowAbove;
  return gate;
}

namespace {
const char* scope_words(GateScope scope) {
  return scope == GateScope::AllLevels ? "at every level" : "at the finest level";
}
}  // namespace

namespace {
GateSpec bound_gate(GateKind kind, std::string metric, double bound, GateScope scope,
                    std::string rationale) {
  const bool upper = kind == GateKind::UpperBound;
  GateSpec gate;
  gate.name = fmt::format("{} {} {:.3g} {}", metric, upper ? "<=" : ">=", bound, scope_words(scope));
  gate.kind = kind;
  gate.metric = std::move(metric);
  (upper ? gate.upper : gate.lower) = bound;
  gate.scope = scope;
  gate.rationale = std::move(rationale);
  return gate;
}
}  // namespace

GateSpec upper_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale) {
  return bound_gate(GateKind::UpperBound, std::move(metric), bound, scope, std::move(rationale));
}

GateSpec lower_bound_gate(std::string metric, double bound, GateScope scope, std::string rationale) {
  return bound_gate(GateKind::LowerBound, std::move(metric), bound, scope, std::move(rationale));
}

GateSpec scaled_upper_bound_gate(std::string metric, double constant, double order, GateScope scope,
                                 std::string rationale) {
  GateSpec gate = upper_bound_gate(std::move(metric), constant, scope, std::move(rationale));
  gate.name = fmt::format("{} <= {:.3g} h^{:g} {}", gate.metric, constant, order, scope_words(scope));
  gate.bound_order = order;
  return gate;
}

GateSpec resolution_gate(std::string metric) {
  GateSpec gate = upper_bound_gate(std::move(metric), kResolvedFraction, GateScope::FinestLevel,
                                   "asymptotic range: an observed order is evidence only where the error is small "
                                   "beside the quantity (gate.hpp, kResolvedFraction)");
  gate.name = fmt::format("{} resolved: error <= {:g} x its size at the finest level", gate.metric,
                          kResolvedFraction);
  gate.relative = true;
  return gate;
}

void add_resolution_gates(std::vector<GateSpec>& gates) {
  std::vector<std::string> ordered, resolved;
  for (const GateSpec& gate : gates) {
    if (gate.kind == GateKind::Order) ordered.push_back(gate.metric);
    if (gate.relative) resolved.push_back(gate.metric);
  }
  for (const std::string& metric : ordered)
    if (std::find(resolved.begin(), resolved.end(), metric) == resolved.end()) {
      gates.push_back(resolution_gate(metric));
      resolved.push_back(metric);
    }
}

double gated_value(const MetricSample& sample) { return sample.error ? *sample.error : sample.computed; }

std::optional<double> metric_size(const MetricSample& sample) {
  const double size = sample.scale ? *sample.scale : sample.reference ? std::abs(*sample.reference) : 0.0;
  if (size > 0.0 && std::isfinite(size)) return size;
  return std::nullopt;
}

namespace {

GateResult start(const GateSpec& gate) {
  GateResult result;
  result.name = gate.name;
  result.kind = gate.kind;
  result.metric = gate.metric;
  result.rationale = gate.rationale;
  if (std::isfinite(gate.lower)) result.lower = gate.lower;
  if (std::isfinite(gate.upper)) result.upper = gate.upper;
  return result;
}

GateResult evaluate_order(const GateSpec& gate, const SweepResult& sweep) {
  GateResult result = start(gate);
  const MetricAnalysis* analysis = nullptr;
  for (const auto& candidate : sweep.analyses)
    if (candidate.metric == gate.metric) analysis = &candidate;
  if (!analysis) {
    result.reason = fmt::format("no convergence analysis for metric '{}'", gate.metric);
    return result;
  }
  if (!analysis->order.least_squares) {
    result.reason = fmt::format(
        "least-squares order of '{}' unavailable: needs {} levels with positive finite errors",
        gate.metric, std::max<std::size_t>(analysis->order.levels_used, 3));
    return result;
  }
  const double order = *analysis->order.least_squares;
  result.measured = order;
  result.passed = order >= gate.lower && order <= gate.upper;
  result.reason = fmt::format("observed order {:.3f} (R^2 {:.4f}, last {} levels) {} [{:g}, {:g}]",
                              order, analysis->order.r_squared.value_or(0.0),
                              analysis->order.levels_used, result.passed ? "in" : "outside",
                              gate.lower, gate.upper);
  return result;
}

GateResult evaluate_bound(const GateSpec& gate, const SweepResult& sweep) {
  GateResult result = start(gate);
  const bool upper = gate.kind == GateKind::UpperBound;
  const double constant = upper ? gate.upper : gate.lower;
  const auto bound_at = [&](const LevelResult& level) {
    return gate.bound_order != 0.0 ? constant * std::pow(level.h, gate.bound_order) : constant;
  };
  if (sweep.levels.empty()) {
    result.reason = "no levels were run";
    return result;
  }
  const std::size_t first = gate.scope == GateScope::AllLevels ? 0 : sweep.levels.size() - 1;
  // The worst level decides: the largest value relative to its bound for an upper bound, the
  // smallest for a lower one.
  std::optional<double> worst;
  double worst_level = 0.0, worst_bound = 0.0, worst_margin = 0.0;
  for (std::size_t i = first; i < sweep.levels.size(); ++i) {
    const LevelResult& level = sweep.levels[i];
    const auto found = level.metrics.find(gate.metric);
    if (level.failure || found == level.metrics.end()) {
      result.reason = fmt::format("metric '{}' missing at level {:g}{}", gate.metric, level.level,
                                  level.failure ? " (the level failed: " + *level.failure + ")" : "");
      return result;
    }
    double value = gated_value(found->second);
    if (gate.relative) {
      const std::optional<double> size = metric_size(found->second);
      if (!size) {
        result.reason = fmt::format("metric '{}' has no size at level {:g}: its reference is 0 or absent and the case "
                                    "states no scale, so its relative error is unknown",
                                    gate.metric, level.level);
        return result;
      }
      value = std::abs(value) / *size;
    }
    if (!std::isfinite(value)) {
      result.measured.reset();
      result.reason = fmt::format("metric '{}' is not finite at level {:g}", gate.metric, level.level);
      return result;
    }
    const double bound = bound_at(level);
    const double margin = upper ? value / bound : bound / value;  // > 1 violates
    if (!worst || margin > worst_margin) {
      worst = value;
      worst_level = level.level;
      worst_bound = bound;
      worst_margin = margin;
    }
  }
  result.measured = *worst;
  if (gate.bound_order != 0.0) (upper ? result.upper : result.lower) = worst_bound;
  result.passed = upper ? *worst <= worst_bound : *worst >= worst_bound;
  result.reason = fmt::format("{} {:.3e} at {} = {:g} {} {} {:.3e}",
                              gate.relative ? "relative error"
                              : gate.scope == GateScope::AllLevels ? "worst value" : "value",
                              *worst,
                              sweep.info.resolution.name, worst_level,
                              result.passed ? "within" : "violates", upper ? "<=" : ">=", worst_bound);
  return result;
}

}  // namespace

GateResult evaluate_gate(const GateSpec& gate, const SweepResult& sweep) {
  if (gate.kind == GateKind::Regression)
    throw std::logic_error("evaluate_gate: regression gates come from the goldens (golden.hpp), not from a GateSpec");
  return gate.kind == GateKind::Order ? evaluate_order(gate, sweep) : evaluate_bound(gate, sweep);
}

}  // namespace rodvv::harness

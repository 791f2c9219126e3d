#include "rodvv/harness/golden.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

namespace rodvv::harness {

namespace {

double magnitude(const GoldenSample& s) {
  double m = std::abs(s.computed);
  if (s.reference) m = std::max(m, std::abs(*s.reference));
  if (s.scale) m = std::max(m, std::abs(*s.scale));
  return m;
}

// |a - b| over its tolerance; a value present on one side only, or not finite where the other is,
// is an unbounded change.
double deviation(std::optional<double> a, std::optional<double> b, double tolerance) {
  if (!a && !b) return 0.0;
  if (!a || !b) return std::numeric_limits<double>::infinity();
  if (!std::isfinite(*a) || !std::isfinite(*b))
    return (std::isnan(*a) && std::isnan(*b)) || *a == *b ? 0.0 : std::numeric_limits<double>::infinity();
  const double d = std::abs(*a - *b);
  if (d == 0.0) return 0.0;
  return tolerance > 0.0 ? d / tolerance : std::numeric_limits<double>::infinity();
}

const GoldenLevel* find_level(const GoldenCase& golden, double level) {
  for (const auto& l : golden.levels)
    if (l.level == level) return &l;
  return nullptr;
}

}  // namespace

GoldenCase golden_of(const SweepResult& result) {
  GoldenCase golden;
  for (const auto& level : result.levels) {
    GoldenLevel g;
    g.level = level.level;
    g.failed = level.failure.has_value();
    for (const auto& [name, sample] : level.metrics) {
      const MetricSpec* spec = find_metric_spec(result.info, name);
      if (spec && spec->kind == MetricKind::Diagnostic) continue;
      g.metrics[name] = {sample.computed, sample.reference, sample.error, sample.scale};
    }
    golden.levels.push_back(std::move(g));
  }
  return golden;
}

std::vector<GoldenChange> compare_goldens(const GoldenCase& golden, const GoldenCase& now,
                                          const GoldenTolerance& tolerance) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  std::vector<GoldenChange> changes;
  for (const auto& level : now.levels) {
    const GoldenLevel* old = find_level(golden, level.level);
    if (!old) continue;
    if (old->failed != level.failed) {
      changes.push_back({level.level, level.failed ? "(level now fails)" : "(level no longer fails)", {}, {}, {}, {},
                         kInf});
      continue;
    }
    for (const auto& [name, sample] : old->metrics) {
      const auto it = level.metrics.find(name);
      if (it == level.metrics.end()) {
        changes.push_back({level.level, name + " (metric gone)", sample.computed, {}, sample.error, {}, kInf});
        continue;
      }
      const GoldenSample& s = it->second;
      const double m = magnitude(sample);
      const auto absolute = tolerance.absolute.find(name);
      const double value_tolerance =
          tolerance.value_relative * m + (absolute == tolerance.absolute.end() ? 0.0 : absolute->second);
      double d = deviation(sample.computed, s.computed, value_tolerance);
      if (sample.error || s.error) {
        const double error_tolerance =
            tolerance.error_relative * (sample.error ? std::abs(*sample.error) : 0.0) + value_tolerance;
        d = std::max(d, deviation(sample.error, s.error, error_tolerance));
      }
      changes.push_back({level.level, name, sample.computed, s.computed, sample.error, s.error, d});
    }
    for (const auto& [name, sample] : level.metrics)
      if (!old->metrics.count(name))
        changes.push_back({level.level, name + " (metric new)", {}, sample.computed, {}, sample.error, kInf});
  }
  return changes;
}

std::optional<GateResult> regression_gate(const Case& c, const SweepResult& result, const Goldens& goldens,
                                          std::string* why_not, const GoldenTolerance& tolerance) {
  const auto skip = [&](std::string why) -> std::optional<GateResult> {
    if (why_not) *why_not = std::move(why);
    return std::nullopt;
  };
  const auto found = goldens.find(c.info.name);
  if (found == goldens.end()) return skip("no golden values for this case (rodvv bless writes them)");
  // Unit scales too: the goldens hold numbers in the case's units.
  if (!at_default_parameters(c.info, result.info.parameters, false)) return skip("goldens hold the default parameters");
  GoldenTolerance with_round_off = tolerance;
  with_round_off.absolute.insert(c.golden_absolute.begin(), c.golden_absolute.end());
  const auto changes = compare_goldens(found->second, golden_of(result), with_round_off);
  std::size_t levels = 0;
  for (const auto& level : result.levels) levels += find_level(found->second, level.level) ? 1 : 0;
  if (levels == 0) return skip("no level in common with the goldens");

  GateResult gate;
  gate.name = "regression: metrics match their goldens";
  gate.kind = GateKind::Regression;
  gate.metric = "(all)";
  gate.upper = 1.0;
  const GoldenChange* worst = nullptr;
  for (const auto& change : changes)
    if (!worst || change.deviation > worst->deviation) worst = &change;
  gate.measured = worst ? worst->deviation : 0.0;
  gate.passed = !worst || worst->deviation <= 1.0;
  const auto number = [](std::optional<double> v) { return v ? fmt::format("{:.17g}", *v) : std::string("none"); };
  if (!worst || worst->deviation == 0.0) {
    gate.reason = fmt::format("{} values at {} levels identical to the goldens", changes.size(), levels);
  } else {
    gate.reason = fmt::format("{} values at {} levels; largest change {} at {} = {:g}: value {} -> {}, error {} -> {} "
                              "({:.3g} x its tolerance)",
                              changes.size(), levels, worst->metric, c.info.resolution.name, worst->level,
                              number(worst->old_value), number(worst->new_value), number(worst->old_error),
                              number(worst->new_error), worst->deviation);
  }
  gate.rationale = fmt::format("runs are bit-identical; tolerance {:g} of a value's magnitude, and {:g} of its "
                               "error besides (golden.hpp); goldens written by rodvv bless",
                               tolerance.value_relative, tolerance.error_relative);
  return gate;
}

void add_regression_gate(const Case& c, SweepResult& result, const Goldens& goldens,
                         const GoldenTolerance& tolerance) {
  std::string why_not;
  if (auto gate = regression_gate(c, result, goldens, &why_not, tolerance))
    result.gates.push_back(std::move(*gate));
  else
    result.skipped_gates.push_back("regression: " + why_not);
}

}  // namespace rodvv::harness

#include "rodvv/harness/convergence.hpp"

#include <cmath>
#include <optional>
#include <string>
#include <utility>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/order_fit.hpp"
#include "rodvv/harness/richardson.hpp"

namespace rodvv::harness {

namespace {

std::optional<double> computed_value(const LevelResult& level, const std::string& metric) {
  const auto found = level.metrics.find(metric);
  if (level.failure || found == level.metrics.end()) return std::nullopt;
  return found->second.computed;
}

// Richardson/GCI on the three finest levels, or the reason it was not applied.
void extrapolate(const std::string& metric, const std::vector<LevelResult>& levels, MetricAnalysis& analysis) {
  const std::size_t n = levels.size();
  if (n < 3) {
    analysis.richardson_note = "fewer than three levels";
    return;
  }
  const auto fine = computed_value(levels[n - 1], metric), medium = computed_value(levels[n - 2], metric),
             coarse = computed_value(levels[n - 3], metric);
  if (!fine || !medium || !coarse) {
    analysis.richardson_note = "a level of the finest three is missing the metric";
    return;
  }
  std::string why_not;
  analysis.richardson =
      richardson_gci({levels[n - 1].h, levels[n - 2].h, levels[n - 3].h, *fine, *medium, *coarse}, &why_not);
  if (!analysis.richardson) analysis.richardson_note = why_not;
}

}  // namespace

std::vector<MetricAnalysis> analyse_metrics(const std::vector<MetricSpec>& metrics,
                                            const std::vector<LevelResult>& levels, std::size_t fit_levels,
                                            bool fit_orders) {
  std::vector<MetricAnalysis> analyses;
  std::vector<double> h;
  for (const auto& level : levels) h.push_back(level.h);
  for (const MetricSpec& metric : metrics) {
    if (metric.kind == MetricKind::Diagnostic) continue;
    MetricAnalysis analysis;
    analysis.metric = metric.name;
    if (!fit_orders) {
      analyses.push_back(std::move(analysis));
      continue;
    }
    std::vector<std::optional<double>> errors;
    for (const auto& level : levels) {
      const auto found = level.metrics.find(metric.name);
      errors.push_back(level.failure || found == level.metrics.end() ? std::nullopt : found->second.error);
    }
    analysis.order = fit_order(h, errors, fit_levels);
    if (metric.extrapolate) extrapolate(metric.name, levels, analysis);
    analyses.push_back(std::move(analysis));
  }
  return analyses;
}

SweepResult evaluate_convergence(CaseInfo info, std::vector<LevelResult> levels, std::vector<GateSpec> gates,
                                 std::size_t fit_levels) {
  if (levels.empty()) throw InputError("levels", "invalid parameter 'levels': no levels given (at least one)");
  require_at_least("fit_levels", fit_levels, 2);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    const double h = levels[i].h;
    if (!(std::isfinite(h) && h > 0.0) || (i > 0 && !(h < levels[i - 1].h)))
      throw InputError("levels", "invalid parameter 'levels': level " + std::to_string(i) + " has h = " +
                                     format_value(h) + "; each h must be finite, > 0 and below the previous "
                                     "level's (levels coarse to fine)");
  }
  for (const GateSpec& gate : gates) {
    if (gate.kind == GateKind::Regression)
      throw InputError("gates", "invalid parameter 'gates': gate '" + gate.name +
                                    "' is a regression gate, which compares with stored goldens (golden.hpp), not "
                                    "evaluated here");
    if (gate.kind == GateKind::Order && info.resolution.scale == ResolutionScale::Parameter)
      throw InputError("gates", "invalid parameter 'gates': gate '" + gate.name + "' gates an order, but the levels of " +
                                    info.name + " are a parameter study (" + info.resolution.name +
                                    "), not a mesh: no order is fitted");
    if (!find_metric_spec(info, gate.metric))
      throw InputError("gates", "invalid parameter 'gates': gate '" + gate.name + "' is on metric '" + gate.metric +
                                    "', which info.metrics does not declare");
  }
  add_resolution_gates(gates);
  SweepResult result;
  result.info = std::move(info);
  result.levels = std::move(levels);
  result.analyses = analyse_metrics(result.info.metrics, result.levels, fit_levels,
                                    result.info.resolution.scale != ResolutionScale::Parameter);
  for (const GateSpec& gate : gates) result.gates.push_back(evaluate_gate(gate, result));
  return result;
}

}  // namespace rodvv::harness

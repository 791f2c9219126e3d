#pragma once
// A convergence study analysed and gated on its own: the part of a sweep that needs no rodvv case.
// For a project that runs its own solver at several resolutions and computes its own errors, and
// wants rodvv's order fits, Richardson/GCI estimates and gates in its tests (installed as the library
// rodvv::gates; tests/install/consumer shows the use). A case's sweep (sweep.hpp) goes through
// analyse_metrics and the same evaluate_gate, so a consumer's verdict is the verdict `rodvv run` would
// give on the same numbers.
//
// The levels are given coarse to fine, each with its h (> 0, strictly decreasing) and its metrics by
// name; a metric absent at a level, or a level with a failure, is a missing point (the order fit
// leaves it out, a bound gate on it fails). Order gates get their resolution gate (gate.hpp) as in a
// case, so an order never passes without a magnitude beside it.
#include <cstddef>
#include <vector>

#include "rodvv/harness/case_info.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

// One MetricAnalysis per non-diagnostic metric of `metrics`: the observed order of its error over the
// levels (least squares over the last fit_levels, order_fit.hpp) and, for a metric with `extrapolate`,
// Richardson/GCI on its computed value at the three finest levels (richardson.hpp). With fit_orders
// false (a parameter study, ResolutionScale::Parameter: its levels are no mesh) neither: the analyses
// name the metrics only.
std::vector<MetricAnalysis> analyse_metrics(const std::vector<MetricSpec>& metrics,
                                            const std::vector<LevelResult>& levels, std::size_t fit_levels = 3,
                                            bool fit_orders = true);

// The analyses and every gate evaluated: a SweepResult a report writer can take as it is. `info` names
// the study and declares its metrics (info.metrics) and resolution; its parameters are not checked.
// InputError: no levels, an h not finite and > 0 or not decreasing, fit_levels < 2, a gate on a metric
// that info.metrics does not declare, a regression gate (it needs stored goldens, golden.hpp), an order
// gate on a parameter study (ResolutionScale::Parameter: no order is fitted there).
SweepResult evaluate_convergence(CaseInfo info, std::vector<LevelResult> levels, std::vector<GateSpec> gates,
                                 std::size_t fit_levels = 3);

}  // namespace rodvv::harness

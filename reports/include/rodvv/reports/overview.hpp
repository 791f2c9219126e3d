#pragma once
// The report's first screen: "is everything right, and where is it weakest". Every evaluated gate
// gets a margin, its distance from failing, so that failures and the closest calls can be listed
// first and drawn in one overview figure across all cases.
//
// Margins (positive when the gate passes, negative when it fails, zero on the edge):
// - bound gates (UpperBound, LowerBound): decades of headroom, log10(upper / measured) or
//   log10(measured / lower), when bound and measured value are positive (errors, drifts, ratios);
//   otherwise the distance relative to the bound's magnitude, (upper - measured) / |upper| (a signed
//   bound has no decades). A measured zero under a positive upper bound has unbounded headroom
//   (kUnboundedMargin). A zero bound is a sign gate ("wall force <= 0"): it passes or fails and
//   has no margin.
// - order gates: the distance in order units to the nearer end of the accepted window
//   min(measured - lower, upper - measured).
// Units differ between the two kinds; the overview figure draws them in separate panels.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "rodvv/harness/sweep_result.hpp"
#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

inline constexpr double kUnboundedMargin = 1e300;

struct GateMargin {
  std::size_t case_index = 0;  // into ValidationReport::cases
  std::size_t gate_index = 0;  // into SweepResult::gates
  harness::GateKind kind = harness::GateKind::Order;
  bool passed = false;
  bool measured = false;  // the gate has a finite measured value
  std::optional<double> margin;
  bool in_decades = false;  // bound gates: log10 ratio (else the relative distance)
  // Order gates: the theoretical order the window was built around (gate.hpp).
  std::optional<double> theoretical_order;
};

// One entry per gate, in report order; `margin` is nullopt for sign gates and for gates without a
// measured value (a failed level left nothing to measure: the gate failed).
std::vector<GateMargin> gate_margins(const ValidationReport& report);

// The margin of one gate (see above); nullopt when it has no measured value, no bound or is a
// sign gate.
std::optional<double> gate_margin(const harness::GateResult& gate);

// "0.42 decades", "0.05 in order", "unbounded", "sign gate", "not measured".
std::string margin_text(const GateMargin& margin);

// Failed gates (most negative margin first, sign gates last), then the `closest` passing gates of
// smallest margin (sign gates have none and are never among them).
// Ties keep report order, so the list is deterministic.
std::vector<GateMargin> needs_attention(const std::vector<GateMargin>& margins, std::size_t closest);

// The attributes by which the page's filters select everything that belongs to a case (its
// section, table-of-contents entry, overview points, attention rows): class "filterable" plus
// data-family, data-status (pass | fail), data-skipped (1 when gates were skipped), data-name.
std::string case_filter_attributes(const harness::SweepResult& result);

// The overview figure as inline SVG: observed against theoretical order for order gates (the
// diagonal is "as predicted", the window's edges as error bars), and the headroom of bound gates in
// decades per family (the closest calls sit near the zero line); regression gates are not drawn
// (they say whether a result changed, not how near it is to wrong). Each point links to its case
// (case_ids[i] is the element id of case i) and carries data-family / data-status attributes for
// the page's filters, and a <title> tooltip naming case, gate, measured value and bounds.
std::string overview_svg(const ValidationReport& report, const std::vector<GateMargin>& margins,
                         const std::vector<std::string>& case_ids);

}  // namespace rodvv::reports

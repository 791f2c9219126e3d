#include "rodvv/reports/overview.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "rodvv/harness/gate.hpp"
#include "rodvv/reports/markup_escape.hpp"
#include "rodvv/reports/number_format.hpp"
#include "rodvv/reports/report_tables.hpp"

namespace rodvv::reports {

namespace {

// A margin and its unit: decades (log10 of a ratio) or not (order units, relative distance).
struct Headroom {
  double value;
  bool in_decades;
};

// Signed distance of `measured` inside the bound: decades when both are positive, else relative to
// the bound's magnitude; none for a zero bound (a sign gate).
std::optional<Headroom> bound_headroom(double inside_minus_outside_sign, double bound, double measured) {
  if (bound == 0.0) return std::nullopt;  // a sign gate: passes or fails, no scale to measure against
  if (bound > 0.0 && measured > 0.0) return Headroom{inside_minus_outside_sign * std::log10(bound / measured), true};
  if (bound > 0.0 && measured == 0.0 && inside_minus_outside_sign > 0.0) return Headroom{kUnboundedMargin, true};
  return Headroom{inside_minus_outside_sign * (bound - measured) / std::abs(bound), false};
}

std::optional<Headroom> headroom_of(const harness::GateResult& gate) {
  if (!gate.measured || !std::isfinite(*gate.measured)) return std::nullopt;
  const double m = *gate.measured;
  if (gate.kind == harness::GateKind::Order) {
    if (!gate.lower && !gate.upper) return std::nullopt;
    double margin = kUnboundedMargin;
    if (gate.lower) margin = std::min(margin, m - *gate.lower);
    if (gate.upper) margin = std::min(margin, *gate.upper - m);
    return Headroom{margin, false};
  }
  // Bound gates: the one bound of their kind, or the tighter of both when a window is given.
  std::optional<Headroom> tightest;
  for (const auto& [bound, sign] : {std::pair{gate.upper, +1.0}, std::pair{gate.lower, -1.0}}) {
    if (!bound) continue;
    const auto headroom = bound_headroom(sign, *bound, m);
    if (!headroom) return std::nullopt;
    if (!tightest || headroom->value < tightest->value) tightest = headroom;
  }
  return tightest;
}

}  // namespace

std::optional<double> gate_margin(const harness::GateResult& gate) {
  if (const auto headroom = headroom_of(gate)) return headroom->value;
  return std::nullopt;
}

std::string case_filter_attributes(const harness::SweepResult& result) {
  return " data-family=\"" + escape_xml_attribute(result.info.family) + "\" data-status=\"" +
         (result.passed() ? "pass" : "fail") + "\" data-skipped=\"" + (result.skipped_gates.empty() ? "0" : "1") +
         "\" data-name=\"" + escape_xml_attribute(result.info.name) + "\"";
}

std::vector<GateMargin> gate_margins(const ValidationReport& report) {
  std::vector<GateMargin> margins;
  for (std::size_t c = 0; c < report.cases.size(); ++c) {
    const auto& result = report.cases[c];
    for (std::size_t g = 0; g < result.gates.size(); ++g) {
      const auto& gate = result.gates[g];
      GateMargin entry;
      entry.case_index = c;
      entry.gate_index = g;
      entry.kind = gate.kind;
      entry.passed = gate.passed;
      entry.measured = gate.measured && std::isfinite(*gate.measured);
      if (const auto headroom = headroom_of(gate)) {
        entry.margin = headroom->value;
        entry.in_decades = headroom->in_decades;
      }
      // order_gate and order_range_gate (gate.hpp) open the window kOrderWindowBelow under the
      // (lowest) theoretical order; the metric's declared order can differ from a gate's.
      if (gate.kind == harness::GateKind::Order && gate.lower)
        entry.theoretical_order = *gate.lower + harness::kOrderWindowBelow;
      margins.push_back(entry);
    }
  }
  return margins;
}

std::string margin_text(const GateMargin& m) {
  if (!m.measured) return "not measured";
  if (!m.margin) return "sign gate";
  if (*m.margin >= kUnboundedMargin) return "unbounded";
  std::string out = format_general(*m.margin, 3);
  out.append(m.kind == harness::GateKind::Order ? " in order" : m.in_decades ? " decades" : " relative");
  return out;
}

std::vector<GateMargin> needs_attention(const std::vector<GateMargin>& margins, std::size_t closest) {
  std::vector<GateMargin> failed, passed;
  for (const auto& m : margins) {
    if (!m.passed)
      failed.push_back(m);
    else if (m.margin)
      passed.push_back(m);
  }
  // Sign gates (no margin) after every measured one.
  const auto by_margin = [](const GateMargin& a, const GateMargin& b) {
    return a.margin.value_or(kUnboundedMargin) < b.margin.value_or(kUnboundedMargin);
  };
  std::stable_sort(failed.begin(), failed.end(), by_margin);
  std::stable_sort(passed.begin(), passed.end(), by_margin);
  if (passed.size() > closest) passed.resize(closest);
  failed.insert(failed.end(), passed.begin(), passed.end());
  return failed;
}

namespace {

// Plot geometry (SVG user units; the figure scales to the page width).
constexpr double kWidth = 1000.0, kHeight = 360.0;
constexpr double kTop = 40.0, kBottom = 300.0;             // both panels' plot area, y
constexpr double kOrderLeft = 70.0, kOrderRight = 430.0;   // panel 1, x
constexpr double kBoundLeft = 620.0, kBoundRight = 980.0;  // panel 2, x
constexpr double kDecadesMin = -2.0, kDecadesMax = 10.0;   // panel 2's axis: beyond it, drawn at the edge

std::string num(double v) { return format_fixed(v, 1); }

const char* status_of(bool passed) { return passed ? "pass" : "fail"; }


// One point: a link to its case with the filter attributes, a tooltip, a circle.
void append_point(std::string& out, const ValidationReport& report, const GateMargin& m,
                  const std::vector<std::string>& case_ids, double x, double y, bool clipped) {
  const auto& result = report.cases[m.case_index];
  const auto& gate = result.gates[m.gate_index];
  out += "<a class=\"filterable point\" href=\"#" + escape_xml_attribute(case_ids[m.case_index]) + "\"" +
         case_filter_attributes(result) + ">";
  std::string tooltip = result.info.name;
  tooltip.append(" \u00b7 ").append(gate.name).append(": measured ").append(gate_number(gate.kind, gate.measured));
  tooltip.append(", accepted ").append(gate_window(gate)).append(", margin ").append(margin_text(m));
  out += "<title>" + escape_xml(tooltip) + "</title>";
  out += "<circle cx=\"" + num(x) + "\" cy=\"" + num(y) + "\" r=\"4.5\" class=\"" + status_of(m.passed) +
         (clipped ? " clipped" : "") + "\"/></a>\n";
}

void append_text(std::string& out, double x, double y, const std::string& anchor, const std::string& text,
                 const std::string& extra = "") {
  out += "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" text-anchor=\"" + anchor + "\"" + extra + ">" +
         escape_xml(text) + "</text>\n";
}

void append_line(std::string& out, double x1, double y1, double x2, double y2, const char* cls) {
  out += "<line x1=\"" + num(x1) + "\" y1=\"" + num(y1) + "\" x2=\"" + num(x2) + "\" y2=\"" + num(y2) +
         "\" class=\"" + cls + "\"/>\n";
}

// Panel 1: observed order (y) against theoretical order (x), both on [0, top].
void append_order_panel(std::string& out, const ValidationReport& report, const std::vector<GateMargin>& margins,
                        const std::vector<std::string>& case_ids) {
  double top = 4.0;
  for (const auto& m : margins)
    if (m.kind == harness::GateKind::Order && m.theoretical_order) top = std::max(top, *m.theoretical_order + 1.0);
  top = std::ceil(top);
  const auto px = [&](double p) { return kOrderLeft + (kOrderRight - kOrderLeft) * p / top; };
  const auto py = [&](double p) { return kBottom - (kBottom - kTop) * p / top; };
  append_text(out, 0.5 * (kOrderLeft + kOrderRight), kTop - 16, "middle", "Order gates: observed vs theoretical order",
              " class=\"heading\"");
  for (int p = 0; p <= static_cast<int>(top); ++p) {
    append_line(out, px(p), kTop, px(p), kBottom, "grid");
    append_line(out, kOrderLeft, py(p), kOrderRight, py(p), "grid");
    append_text(out, px(p), kBottom + 16, "middle", std::to_string(p));
    append_text(out, kOrderLeft - 8, py(p) + 4, "end", std::to_string(p));
  }
  append_line(out, px(0), py(0), px(top), py(top), "diagonal");
  append_text(out, 0.5 * (kOrderLeft + kOrderRight), kBottom + 36, "middle", "theoretical order");
  out += "<text transform=\"translate(" + num(kOrderLeft - 40) + " " + num(0.5 * (kTop + kBottom)) +
         ") rotate(-90)\" text-anchor=\"middle\">observed order</text>\n";
  std::map<double, int> seen;  // points per theoretical order: spread sideways so none hides another
  for (const auto& m : margins) {
    if (m.kind != harness::GateKind::Order || !m.theoretical_order || !m.margin) continue;
    const auto& gate = report.cases[m.case_index].gates[m.gate_index];
    const int k = seen[*m.theoretical_order]++;
    const double x = px(*m.theoretical_order + 0.035 * ((k % 9) - 4));
    if (gate.lower && gate.upper)
      append_line(out, x, py(std::clamp(*gate.lower, 0.0, top)), x, py(std::clamp(*gate.upper, 0.0, top)), "window");
    const double observed = std::clamp(*gate.measured, 0.0, top);
    append_point(out, report, m, case_ids, x, py(observed), observed != *gate.measured);
  }
}

// Regression gates (golden.hpp) say whether anything changed, not how close a result is to being
// wrong: they stay out of the figure (the attention table lists them when they fail or moved).
bool in_bound_panel(const GateMargin& m) {
  return m.margin && m.kind != harness::GateKind::Order && m.kind != harness::GateKind::Regression;
}

// Panel 2: headroom of bound gates in decades, one row per family.
void append_bound_panel(std::string& out, const ValidationReport& report, const std::vector<GateMargin>& margins,
                        const std::vector<std::string>& case_ids) {
  std::vector<std::string> families;
  for (const auto& m : margins) {
    if (!in_bound_panel(m)) continue;
    const auto& family = report.cases[m.case_index].info.family;
    if (std::find(families.begin(), families.end(), family) == families.end()) families.push_back(family);
  }
  const auto px = [&](double d) {
    return kBoundLeft + (kBoundRight - kBoundLeft) * (d - kDecadesMin) / (kDecadesMax - kDecadesMin);
  };
  const double row = families.empty() ? 0.0 : (kBottom - kTop) / static_cast<double>(families.size());
  append_text(out, 0.5 * (kBoundLeft + kBoundRight), kTop - 16, "middle",
              "Bound gates: headroom (decades below the bound)", " class=\"heading\"");
  out += "<rect x=\"" + num(px(kDecadesMin)) + "\" y=\"" + num(kTop) + "\" width=\"" +
         num(px(0.0) - px(kDecadesMin)) + "\" height=\"" + num(kBottom - kTop) + "\" class=\"failzone\"/>\n";
  for (int d = static_cast<int>(kDecadesMin); d <= static_cast<int>(kDecadesMax); d += 2) {
    append_line(out, px(d), kTop, px(d), kBottom, d == 0 ? "zero" : "grid");
    append_text(out, px(d), kBottom + 16, "middle", std::to_string(d));
  }
  append_text(out, 0.5 * (kBoundLeft + kBoundRight), kBottom + 36, "middle",
              "margin: log10(bound / measured); left of 0 fails");
  for (std::size_t f = 0; f < families.size(); ++f) {
    append_line(out, kBoundLeft, kTop + row * static_cast<double>(f + 1), kBoundRight,
                kTop + row * static_cast<double>(f + 1), "grid");
    append_text(out, kBoundLeft - 8, kTop + row * (static_cast<double>(f) + 0.5) + 4, "end",
                families[f].empty() ? "(no family)" : families[f]);
  }
  std::map<std::string, int> seen;
  for (const auto& m : margins) {
    if (!in_bound_panel(m)) continue;
    const auto& family = report.cases[m.case_index].info.family;
    const auto f = static_cast<double>(std::find(families.begin(), families.end(), family) - families.begin());
    const int k = seen[family]++;
    const double y = kTop + row * (f + 0.5 + 0.13 * ((k % 7) - 3));
    const double x = std::clamp(*m.margin, kDecadesMin, kDecadesMax);
    append_point(out, report, m, case_ids, px(x), y, x != *m.margin);
  }
}

}  // namespace

std::string overview_svg(const ValidationReport& report, const std::vector<GateMargin>& margins,
                         const std::vector<std::string>& case_ids) {
  std::string out;
  out += "<svg id=\"overview-figure\" class=\"overview\" viewBox=\"0 0 " + num(kWidth) + " " + num(kHeight) +
         "\" role=\"img\" aria-label=\"Overview: observed against theoretical order of every order gate, and the "
         "headroom of every bound gate\" xmlns=\"http://www.w3.org/2000/svg\">\n";
  append_order_panel(out, report, margins, case_ids);
  append_bound_panel(out, report, margins, case_ids);
  out += "</svg>\n";
  return out;
}

}  // namespace rodvv::reports

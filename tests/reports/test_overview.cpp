// The report's first screen (overview.hpp): gate margins in decades and order units, the order of
// "needs attention" (failures, then closest calls), the overview figure's points and the page's
// filter attributes. The page's behaviour in a browser: test_report_browser.py.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "rodvv/reports/html.hpp"
#include "rodvv/reports/overview.hpp"
#include "rodvv/reports/plot_manifest.hpp"
#include "rodvv/reports/report_tables.hpp"

namespace {

using namespace rodvv;
using namespace rodvv::reports;
using harness::GateKind;

constexpr double kEps = 2.220446049250313e-16;

harness::GateResult gate(std::string name, GateKind kind, bool passed, std::optional<double> measured,
                         std::optional<double> lower, std::optional<double> upper) {
  return {std::move(name), kind, "m", passed, measured, lower, upper, "", ""};
}

harness::SweepResult make_case(std::string name, std::string family, std::vector<harness::GateResult> gates) {
  harness::SweepResult r;
  r.info.name = std::move(name);
  r.info.family = std::move(family);
  r.gates = std::move(gates);
  return r;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + what.size())) ++n;
  return n;
}

TEST(ReportsOverview, BoundMarginsAreDecadesOfHeadroom) {
  // 1e-8 under a bound of 1e-6: two decades; above it: minus one.
  EXPECT_NEAR(*gate_margin(gate("u", GateKind::UpperBound, true, 1e-8, {}, 1e-6)), 2.0, 8 * kEps);
  EXPECT_NEAR(*gate_margin(gate("u", GateKind::UpperBound, false, 1e-5, {}, 1e-6)), -1.0, 8 * kEps);
  // A lower bound: log10(measured / lower).
  EXPECT_NEAR(*gate_margin(gate("l", GateKind::LowerBound, true, 50.0, 0.5, {})), 2.0, 8 * kEps);
  // Both bounds: the tighter side.
  EXPECT_NEAR(*gate_margin(gate("w", GateKind::UpperBound, true, 2.0, 1.0, 1000.0)), std::log10(2.0), 8 * kEps);
  // Exactly zero under a positive bound: unbounded headroom.
  EXPECT_EQ(*gate_margin(gate("z", GateKind::UpperBound, true, 0.0, {}, 1e-9)), kUnboundedMargin);
  // A negative bound has no decades: the distance relative to the bound, (-1 - (-3)) / 1 = 2.
  EXPECT_NEAR(*gate_margin(gate("n", GateKind::UpperBound, true, -3.0, {}, -1.0)), 2.0, 8 * kEps);
  // Sign gates (bound 0) and unmeasured gates have no margin.
  EXPECT_FALSE(gate_margin(gate("s", GateKind::UpperBound, true, -1.0, {}, 0.0)));
  EXPECT_FALSE(gate_margin(gate("s", GateKind::LowerBound, true, 3.0, 0.0, {})));
  EXPECT_FALSE(gate_margin(gate("x", GateKind::UpperBound, false, std::nullopt, {}, 1.0)));
}

TEST(ReportsOverview, OrderMarginsAreDistancesToTheWindowInOrderUnits) {
  EXPECT_NEAR(*gate_margin(gate("o", GateKind::Order, true, 2.02, 1.9, 2.5)), 0.12, 64 * kEps);
  EXPECT_NEAR(*gate_margin(gate("o", GateKind::Order, true, 2.45, 1.9, 2.5)), 0.05, 64 * kEps);
  EXPECT_NEAR(*gate_margin(gate("o", GateKind::Order, false, 1.7, 1.9, 2.5)), -0.2, 64 * kEps);
  EXPECT_NEAR(*gate_margin(gate("o", GateKind::Order, true, 3.0, 1.9, std::nullopt)), 1.1, 64 * kEps);
  EXPECT_FALSE(gate_margin(gate("o", GateKind::Order, true, std::nan(""), 1.9, 2.5)));
}

ValidationReport attention_report() {
  ValidationReport report;
  report.cases.push_back(make_case("fam-a/one", "fam-a",
                                   {gate("far", GateKind::UpperBound, true, 1e-9, {}, 1e-3),
                                    gate("close", GateKind::UpperBound, true, 0.9e-3, {}, 1e-3),
                                    gate("sign", GateKind::UpperBound, true, -1.0, {}, 0.0)}));
  report.cases.push_back(make_case("fam-b/two", "fam-b",
                                   {gate("order", GateKind::Order, true, 1.95, 1.9, 2.5),
                                    gate("bad order", GateKind::Order, false, 1.2, 1.9, 2.5),
                                    gate("worse", GateKind::UpperBound, false, 1.0, {}, 1e-3),
                                    gate("unmeasured", GateKind::UpperBound, false, std::nullopt, {}, 1.0)}));
  return report;
}

TEST(ReportsOverview, NeedsAttentionListsFailuresThenTheClosestCalls) {
  const ValidationReport report = attention_report();
  const auto margins = gate_margins(report);
  ASSERT_EQ(margins.size(), 7u);  // every gate, measured or not
  const auto rows = needs_attention(margins, 2);
  std::vector<std::string> names;
  for (const auto& m : rows) names.push_back(report.cases[m.case_index].gates[m.gate_index].name);
  // Failures by margin (-3 decades, -0.7 in order, unmeasured last), then the two closest passes
  // (0.0458 decades, 0.05 in order); the far gate and the sign gate are not listed.
  EXPECT_EQ(names, (std::vector<std::string>{"worse", "bad order", "unmeasured", "close", "order"}));
  const Table table = attention_table(report, rows);
  ASSERT_EQ(table.rows.size(), 5u);
  EXPECT_EQ(table.rows[0][5].text, "-3 decades");
  EXPECT_EQ(table.rows[2][5].text, "not measured");
  EXPECT_EQ(table.rows[4][5].text, "0.05 in order");
  EXPECT_EQ(table.rows[0][6].style, CellStyle::Fail);
  EXPECT_EQ(table.rows[4][6].style, CellStyle::Pass);
  // The theoretical order is the one the window was built around (lower + 0.1).
  EXPECT_NEAR(*margins[3].theoretical_order, 2.0, 64 * kEps);
}

TEST(ReportsOverview, FigureHasOnePointPerGateWithAMarginLinkedToItsCase) {
  ValidationReport report = attention_report();
  report.cases[0].info.name = "fam-a/\"quoted\" & <odd>";
  const auto margins = gate_margins(report);
  const std::string svg = overview_svg(report, margins, {"case-a", "case-b"});
  // 5 gates have a margin (not the sign gate, not the unmeasured one).
  EXPECT_EQ(count(svg, "<circle"), 5u);
  EXPECT_EQ(count(svg, "href=\"#case-a\""), 2u);
  EXPECT_EQ(count(svg, "href=\"#case-b\""), 3u);
  // Filter attributes come from the case: the failing case's points are marked fail.
  EXPECT_EQ(count(svg, "data-family=\"fam-b\" data-status=\"fail\""), 3u);
  EXPECT_EQ(count(svg, "data-family=\"fam-a\" data-status=\"pass\""), 2u);
  // Failing gates are red; a point beyond the axis (-3 decades: the axis starts at -2) is drawn at
  // its edge, outlined.
  EXPECT_EQ(count(svg, "r=\"4.5\" class=\"fail"), 2u);
  EXPECT_EQ(count(svg, "class=\"fail clipped\""), 1u);
  EXPECT_EQ(count(svg, "clipped"), 1u);
  EXPECT_NE(svg.find("fam-a/&quot;quoted&quot; &amp; &lt;odd&gt;"), std::string::npos);
  EXPECT_EQ(svg.find("<odd>"), std::string::npos);
  // A regression gate (golden.hpp) is not drawn.
  ValidationReport with_regression = report;
  with_regression.cases[0].gates.push_back(gate("regression", GateKind::Regression, true, 0.0, {}, 1.0));
  EXPECT_EQ(count(overview_svg(with_regression, gate_margins(with_regression), {"case-a", "case-b"}), "<circle"), 5u);
  // Unbounded headroom too, at the right edge.
  report.cases[0].gates[0].measured = 0.0;
  EXPECT_EQ(count(overview_svg(report, gate_margins(report), {"case-a", "case-b"}), "pass clipped"), 1u);
}

TEST(ReportsOverview, PageHasFiltersAndTheOverviewBeforeTheContents) {
  const ValidationReport report = attention_report();
  const std::string html = render_html(report, PlotManifest{});
  const auto glance = html.find("id=\"at-a-glance\"");
  ASSERT_NE(glance, std::string::npos);
  EXPECT_LT(html.find("id=\"filters\""), glance);
  EXPECT_LT(glance, html.find("<h2>Contents</h2>"));
  EXPECT_NE(html.find("id=\"overview-figure\""), std::string::npos);
  EXPECT_NE(html.find("<option value=\"fam-b\">fam-b</option>"), std::string::npos);
  EXPECT_NE(html.find("failed (1)"), std::string::npos);
  // Each case's section, contents entry, points and attention rows carry its filter attributes.
  EXPECT_EQ(count(html, "<section class=\"case filterable\""), 2u);
  EXPECT_EQ(count(html, "<li class=\"filterable\""), 2u);
  EXPECT_EQ(count(html, "<tr class=\"filterable\""), 6u);  // 3 failed gates + the 3 passing ones
  EXPECT_EQ(count(html, "Failed gates (3)"), 1u);
}

}  // namespace

#pragma once
// The tables of a report as plain, unescaped text cells, built once and rendered by both
// markdown.cpp and html.cpp, so the two formats always show the same numbers.
#include <optional>
#include <string>
#include <vector>

#include "rodvv/reports/overview.hpp"
#include "rodvv/reports/report_document.hpp"

namespace rodvv::reports {

enum class CellStyle { Text, Number, Pass, Fail };

struct TableCell {
  std::string text;
  CellStyle style = CellStyle::Text;
};

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<TableCell>> rows;
  bool empty() const { return rows.empty(); }
};

// The content of one case section, in display order.
struct CaseTables {
  Table metrics;     // declared metrics: name, kind, unit, theoretical order, description
  Table parameters;  // name, value, unit, allowed range, description
  Table levels;      // per level: resolution, h, per metric computed/reference/error, wall time
  Table orders;      // per analysed metric: pairwise orders, least-squares order, R^2, levels used
  Table richardson;  // Richardson/GCI, only rows of metrics where it was applied (may be empty)
  std::vector<std::string> richardson_notes;  // "metric: why Richardson was not applied"
  Table gates;       // gate, kind, metric, measured, window, status, reason, rationale
  std::vector<std::string> skipped_gates;  // "gate: why it was not evaluated"
};

CaseTables case_tables(const harness::SweepResult& result);

Table summary_table(const ValidationReport& report);  // case, title, levels, gates, status
Table provenance_table(const ValidationReport& report);
// One row per entry of needs_attention(...) (overview.hpp), in its order: case, gate, kind,
// measured, accepted window, margin (decades for bound gates, order units for order gates), status.
Table attention_table(const ValidationReport& report, const std::vector<GateMargin>& rows);
// Every skipped gate: case, "gate: why it was not evaluated".
Table skipped_gates_table(const ValidationReport& report);

const char* status_text(bool passed);  // "PASS" / "FAIL"

// A gate's numbers as every table shows them: orders with 2 decimals, bounds on errors and
// invariants in scientific notation; the window "[a, b]", ">= a" or "<= b".
std::string gate_number(harness::GateKind kind, const std::optional<double>& value);
std::string gate_window(const harness::GateResult& gate);

}  // namespace rodvv::reports

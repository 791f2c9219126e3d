#include "rodvv/reports/markdown.hpp"

#include "rodvv/reports/markup_escape.hpp"
#include "rodvv/reports/report_tables.hpp"

namespace rodvv::reports {

namespace {

std::string cell_text(const TableCell& cell) {
  if (cell.text.empty()) return " ";
  std::string text = escape_markdown(cell.text);
  return cell.style == CellStyle::Fail ? "**" + text + "**" : text;
}

// GitHub-flavoured pipe table; numeric columns right-aligned (judged by the first row).
void append_table(std::string& out, const Table& table) {
  out += '|';
  for (const auto& h : table.header) out += ' ' + (h.empty() ? std::string(" ") : escape_markdown(h)) + " |";
  out += "\n|";
  for (std::size_t c = 0; c < table.header.size(); ++c) {
    const bool numeric = !table.rows.empty() && c < table.rows.front().size() &&
                         table.rows.front()[c].style == CellStyle::Number;
    out += numeric ? "---:|" : "---|";
  }
  out += '\n';
  for (const auto& row : table.rows) {
    out += '|';
    for (const auto& cell : row) out += ' ' + cell_text(cell) + " |";
    out += '\n';
  }
  out += '\n';
}

void append_section(std::string& out, const std::string& heading, const Table& table) {
  if (table.empty()) return;
  out += "##### " + heading + "\n\n";
  append_table(out, table);
}

void append_field(std::string& out, const char* label, const std::string& value) {
  if (value.empty()) return;
  out += std::string("- **") + label + ":** " + escape_markdown(value) + '\n';
}

void append_case(std::string& out, const harness::SweepResult& result) {
  const auto& info = result.info;
  out += "#### " + escape_markdown(info.name) + " \u2014 " +
         (result.passed() ? "PASS" : "**FAIL**") + "\n\n";
  if (!info.title.empty()) out.append("*").append(escape_markdown(info.title)).append("*\n\n");
  append_field(out, "Physics", info.physics);
  append_field(out, "Reference", info.reference);
  append_field(out, "Citation", info.citation);
  append_field(out, "Method", info.method);
  if (!info.resolution.name.empty())
    append_field(out, "Resolution",
                 info.resolution.name + " (" + harness::to_string(info.resolution.scale) + ")" +
                     (info.resolution.description.empty() ? "" : ": " + info.resolution.description));
  out += '\n';

  const CaseTables t = case_tables(result);
  append_section(out, "Metrics", t.metrics);
  append_section(out, "Parameters", t.parameters);
  append_section(out, "Levels", t.levels);
  append_section(out, "Observed order", t.orders);
  append_section(out, "Richardson extrapolation and GCI", t.richardson);
  if (!t.richardson_notes.empty()) {
    if (t.richardson.empty()) out += "##### Richardson extrapolation and GCI\n\n";
    for (const auto& note : t.richardson_notes) out += "- " + escape_markdown(note) + '\n';
    out += '\n';
  }
  append_section(out, "Gates", t.gates);
  if (!t.skipped_gates.empty()) {
    out += "Skipped gates (not evaluated):\n\n";
    for (const auto& s : t.skipped_gates) out += "- " + escape_markdown(s) + '\n';
    out += '\n';
  }
}

}  // namespace

std::string render_markdown(const ValidationReport& report) {
  const ReportTotals sum = totals(report);
  std::string out = "# rodvv validation report\n\n";
  out += std::string("**Status: ") + status_text(report.passed()) + "** \u2014 " +
         std::to_string(sum.cases_passed) + " of " + std::to_string(sum.cases) +
         " cases passed, " + std::to_string(sum.gates_passed) + " of " +
         std::to_string(sum.gates) + " gates passed" +
         (sum.gates_skipped ? " (" + std::to_string(sum.gates_skipped) + " skipped)" : "") + ", " +
         std::to_string(sum.levels_failed) +
         " of " + std::to_string(sum.levels) + " levels failed.\n\n";
  // Where it is weakest (overview.hpp): failed gates, then the closest calls; skipped gates.
  const auto attention = needs_attention(gate_margins(report), 12);
  out += "## Needs attention\n\nFailed gates, then the passing gates closest to their bounds (margin: decades "
         "below a bound, or order units inside an order window).\n\n";
  append_table(out, attention_table(report, attention));
  if (const Table skipped = skipped_gates_table(report); !skipped.empty()) {
    out += "Skipped gates (not evaluated):\n\n";
    append_table(out, skipped);
  }
  out += "## Provenance\n\n";
  append_table(out, provenance_table(report));
  out += "## Summary\n\n";
  append_table(out, summary_table(report));

  std::string family;
  bool first = true;
  for (const auto& group : group_cases(report)) {
    if (first || group.family != family) {
      out += "## " + escape_markdown(group.family.empty() ? "(no family)" : group.family) + "\n\n";
      family = group.family;
      first = false;
    }
    out += "### " + escape_markdown(group.group.empty() ? "(ungrouped)" : group.group) + "\n\n";
    for (const std::size_t i : group.cases) append_case(out, report.cases[i]);
  }
  return out;
}

}  // namespace rodvv::reports

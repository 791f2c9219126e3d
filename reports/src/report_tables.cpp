#include "rodvv/reports/report_tables.hpp"

#include <cmath>

#include "rodvv/reports/number_format.hpp"

namespace rodvv::reports {

namespace {

TableCell text(std::string value) { return {std::move(value), CellStyle::Text}; }
TableCell num(std::string value) { return {std::move(value), CellStyle::Number}; }
TableCell status(bool passed) {
  return {status_text(passed), passed ? CellStyle::Pass : CellStyle::Fail};
}

// Parameter bounds may be infinite (an unbounded side): shown as the infinity sign, not "n/a".
std::string bound(double value) {
  if (std::isinf(value)) return value > 0 ? "\u221E" : "\u2212\u221E";
  return format_shortest(value);
}

std::string range(const harness::Parameter& p) {
  return std::string(p.min_open ? "(" : "[") + bound(p.min) + ", " + bound(p.max) +
         (p.max_open ? ")" : "]");
}

}  // namespace

std::string gate_number(harness::GateKind kind, const std::optional<double>& value) {
  return kind == harness::GateKind::Order ? format_order(value) : format_error(value);
}

// Built by appending: GCC 12 gives a false -Wrestrict for `"literal" + std::string&&`
// (GCC bug 105651).
std::string gate_window(const harness::GateResult& g) {
  std::string out;
  if (g.lower && g.upper) {
    out.append("[").append(gate_number(g.kind, g.lower)).append(", ");
    out.append(gate_number(g.kind, g.upper)).append("]");
  } else if (g.lower) {
    out.append("\u2265 ").append(gate_number(g.kind, g.lower));
  } else if (g.upper) {
    out.append("\u2264 ").append(gate_number(g.kind, g.upper));
  } else {
    out = kNotAvailable;
  }
  return out;
}

namespace {

std::string pairwise(const std::vector<double>& orders) {
  std::string out;
  for (const double p : orders) out += (out.empty() ? "" : ", ") + format_order(p);
  return out.empty() ? kNotAvailable : out;
}

}  // namespace

const char* status_text(bool passed) { return passed ? "PASS" : "FAIL"; }

CaseTables case_tables(const harness::SweepResult& result) {
  const auto& info = result.info;
  CaseTables t;

  t.metrics.header = {"metric", "kind", "unit", "theoretical order", "extrapolate", "description"};
  for (const auto& m : info.metrics)
    t.metrics.rows.push_back({text(m.name), text(harness::to_string(m.kind)), text(m.unit),
                              num(m.theoretical_order ? format_order(m.theoretical_order) : ""),
                              text(m.extrapolate ? "yes" : "no"), text(m.description)});

  t.parameters.header = {"parameter", "value", "unit", "allowed range", "description"};
  for (const auto& p : info.parameters)
    t.parameters.rows.push_back({text(p.name), num(format_shortest(p.value)), text(p.unit),
                                 text(range(p)), text(p.description)});

  // Levels: only the columns some level fills (reference and error are often absent).
  const auto names = ordered_metric_names(result);
  struct Column {
    std::string metric;
    int which;  // 0 computed, 1 reference, 2 error
  };
  std::vector<Column> columns;
  bool any_failure = false;
  for (const auto& level : result.levels) any_failure = any_failure || level.failure.has_value();
  for (const auto& name : names) {
    bool any_reference = false, any_error = false;
    for (const auto& level : result.levels) {
      const auto it = level.metrics.find(name);
      if (it == level.metrics.end()) continue;
      any_reference = any_reference || it->second.reference.has_value();
      any_error = any_error || it->second.error.has_value();
    }
    columns.push_back({name, 0});
    if (any_reference) columns.push_back({name, 1});
    if (any_error) columns.push_back({name, 2});
  }
  const std::string level_name = info.resolution.name.empty() ? "level" : info.resolution.name;
  t.levels.header = {level_name, "h"};
  for (const auto& c : columns)
    t.levels.header.push_back(c.metric + (c.which == 0 ? " computed" : c.which == 1 ? " reference"
                                                                                    : " error"));
  t.levels.header.push_back("wall time");
  t.levels.header.push_back("CPU time");
  if (any_failure) t.levels.header.push_back("failure");
  for (const auto& level : result.levels) {
    std::vector<TableCell> row = {num(format_shortest(level.level)),
                                  num(format_general(level.h, 4))};
    for (const auto& c : columns) {
      const auto it = level.metrics.find(c.metric);
      if (it == level.metrics.end()) {
        row.push_back(num(kNotAvailable));
        continue;
      }
      const auto& s = it->second;
      row.push_back(num(c.which == 0   ? format_value(s.computed)
                        : c.which == 1 ? format_value(s.reference)
                                       : format_error(s.error)));
    }
    row.push_back(num(format_seconds(level.wall_seconds)));
    row.push_back(num(format_seconds(level.cpu_seconds)));
    if (any_failure)
      row.push_back(level.failure ? TableCell{*level.failure, CellStyle::Fail} : text(""));
    t.levels.rows.push_back(std::move(row));
  }

  t.orders.header = {"metric", "theoretical", "pairwise orders", "least-squares order", "R\u00B2",
                     "levels used"};
  // A parameter study has no orders (case_info.hpp: ResolutionScale::Parameter): no table.
  for (const auto& a : result.analyses) {
    if (info.resolution.scale == harness::ResolutionScale::Parameter) break;
    const auto* spec = find_metric_spec(info, a.metric);
    t.orders.rows.push_back(
        {text(a.metric), num(spec && spec->theoretical_order ? format_order(spec->theoretical_order)
                                                             : kNotAvailable),
         num(pairwise(a.order.pairwise)), num(format_order(a.order.least_squares)),
         num(format_fixed(a.order.r_squared, 4)), num(std::to_string(a.order.levels_used))});
  }

  t.richardson.header = {"metric", "refinement ratio", "observed order", "extrapolated",
                         "GCI fine", "GCI coarse", "asymptotic ratio"};
  for (const auto& a : result.analyses) {
    if (a.richardson) {
      const auto& r = *a.richardson;
      t.richardson.rows.push_back(
          {text(a.metric), num(format_general(r.refinement_ratio, 4)),
           num(format_order(r.observed_order)), num(format_general(r.extrapolated, 10)),
           num(format_error(r.gci_fine)), num(format_error(r.gci_coarse)),
           num(format_fixed(r.asymptotic_ratio, 3))});
    }
    if (a.richardson_note) t.richardson_notes.push_back(a.metric + ": " + *a.richardson_note);
  }

  t.gates.header = {"gate", "kind", "metric", "measured", "window", "status", "reason",
                    "rationale"};
  for (const auto& g : result.gates)
    t.gates.rows.push_back({text(g.name), text(harness::to_string(g.kind)), text(g.metric),
                            num(gate_number(g.kind, g.measured)), num(gate_window(g)), status(g.passed),
                            text(g.reason), text(g.rationale)});
  t.skipped_gates = result.skipped_gates;
  return t;
}

Table summary_table(const ValidationReport& report) {
  Table t;
  t.header = {"case", "title", "levels", "gates passed", "wall time", "status"};
  for (const auto& result : report.cases) {
    std::size_t failed_levels = 0, gates_passed = 0;
    for (const auto& level : result.levels) failed_levels += level.failure ? 1 : 0;
    for (const auto& gate : result.gates) gates_passed += gate.passed ? 1 : 0;
    std::string levels = std::to_string(result.levels.size());
    std::string gates = std::to_string(gates_passed) + "/" + std::to_string(result.gates.size());
    if (!result.skipped_gates.empty())
      gates += " (" + std::to_string(result.skipped_gates.size()) + " skipped)";
    if (failed_levels > 0) levels += " (" + std::to_string(failed_levels) + " failed)";
    t.rows.push_back({text(result.info.name), text(result.info.title), num(levels),
                      num(gates),
                      num(format_seconds(result.wall_seconds)), status(result.passed())});
  }
  return t;
}

Table provenance_table(const ValidationReport& report) {
  const auto& p = report.provenance;
  Table t;
  t.header = {"item", "value"};
  t.rows = {{text("rodvv version"), text(p.rodvv_version)},
            {text("git commit"), text(p.git_commit)},
            {text("compiler"), text(p.compiler_id + " " + p.compiler_version)},
            {text("build type"), text(p.build_type)},
            {text("compile flags"), text(p.compile_flags.empty() ? "(none)" : p.compile_flags)},
            {text("CPU"), text(p.cpu_model)},
            {text("host cores"), text(std::to_string(p.host_cores))},
            {text("date (UTC)"), text(p.date_utc)}};
  if (!report.merged_from.empty()) {
    std::string sources;
    for (const auto& s : report.merged_from) sources += (sources.empty() ? "" : ", ") + s;
    t.rows.push_back({text("merged from"), text(sources)});
  }
  return t;
}

Table attention_table(const ValidationReport& report, const std::vector<GateMargin>& rows) {
  Table t;
  t.header = {"case", "gate", "kind", "measured", "accepted", "margin", "status"};
  for (const auto& m : rows) {
    const auto& result = report.cases[m.case_index];
    const auto& gate = result.gates[m.gate_index];
    t.rows.push_back({text(result.info.name), text(gate.name), text(harness::to_string(gate.kind)),
                      num(gate_number(gate.kind, gate.measured)), num(gate_window(gate)), num(margin_text(m)),
                      status(m.passed)});
  }
  return t;
}

Table skipped_gates_table(const ValidationReport& report) {
  Table t;
  t.header = {"case", "skipped gate"};
  for (const auto& result : report.cases)
    for (const auto& why : result.skipped_gates) t.rows.push_back({text(result.info.name), text(why)});
  return t;
}

}  // namespace rodvv::reports

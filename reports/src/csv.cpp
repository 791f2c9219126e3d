#include "rodvv/reports/csv.hpp"

#include <cmath>
#include <optional>

#include "rodvv/reports/number_format.hpp"

namespace rodvv::reports {

namespace {

// RFC 4180: a field holding a comma, quote or line break is quoted, inner quotes doubled.
std::string csv_field(std::string_view field) {
  if (field.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(field);
  std::string out = "\"";
  for (const char ch : field) {
    if (ch == '"') out += '"';
    out += ch;
  }
  out += '"';
  return out;
}

std::string cell(double value) { return std::isfinite(value) ? format_shortest(value) : ""; }
std::string cell(const std::optional<double>& value) { return value ? cell(*value) : ""; }

}  // namespace

std::string render_csv(const ValidationReport& report) {
  std::string out = "case,family,level,h,metric,kind,computed,reference,error,wall_seconds\n";
  for (const auto& result : report.cases) {
    const auto names = ordered_metric_names(result);
    for (const auto& level : result.levels) {
      for (const auto& name : names) {
        const auto it = level.metrics.find(name);
        if (it == level.metrics.end()) continue;
        const auto* spec = find_metric_spec(result.info, name);
        const auto& sample = it->second;
        out += csv_field(result.info.name) + ',' + csv_field(result.info.family) + ',' +
               cell(level.level) + ',' + cell(level.h) + ',' + csv_field(name) + ',' +
               (spec ? harness::to_string(spec->kind) : "") + ',' + cell(sample.computed) + ',' +
               cell(sample.reference) + ',' + cell(sample.error) + ',' + cell(level.wall_seconds) +
               '\n';
      }
    }
  }
  return out;
}

}  // namespace rodvv::reports

#pragma once
// The validation report as data: provenance plus the results of every case. Serialised by
// json_io.hpp to results.json (the canonical format); every other output is rendered from it.
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/harness/sweep_result.hpp"
#include "rodvv/reports/provenance.hpp"

namespace rodvv::reports {

// Bumped whenever results.json changes incompatibly; a reader refuses other versions.
inline constexpr int kSchemaVersion = 1;

struct ValidationReport {
  int schema_version = kSchemaVersion;
  Provenance provenance;
  // Sources combined by merge_reports (file paths), in merge order; empty for a single run.
  std::vector<std::string> merged_from;
  std::vector<harness::SweepResult> cases;
  // Where this report was read from (set by read_report_file), used to name the inputs of a
  // merge in error messages. Not serialised.
  std::string source;

  // Every gate of every case passed and no level failed.
  bool passed() const;
};

// Totals for summary lines and badges.
struct ReportTotals {
  std::size_t cases = 0;
  std::size_t cases_passed = 0;
  std::size_t gates = 0;
  std::size_t gates_passed = 0;
  std::size_t gates_skipped = 0;  // SweepResult::skipped_gates (not evaluated, not failed)
  std::size_t levels = 0;
  std::size_t levels_failed = 0;
};

ReportTotals totals(const ValidationReport& report);

// Cases of one CaseInfo.family and .group, shown together (one report section, overlay plots).
struct CaseGroup {
  std::string family;
  std::string group;                // may be empty: cases that belong to no group
  std::vector<std::size_t> cases;   // indices into ValidationReport::cases, in report order
};

// Families in order of first appearance, groups likewise within each family.
std::vector<CaseGroup> group_cases(const ValidationReport& report);

// A case's metric names in display order: those declared in CaseInfo.metrics first (the case
// author's order), then any others found in its levels, alphabetically.
std::vector<std::string> ordered_metric_names(const harness::SweepResult& result);

// The MetricSpec of `name` in the case (harness/case_info.hpp).
using harness::find_metric_spec;

}  // namespace rodvv::reports

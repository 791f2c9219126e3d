#include "rodvv/reports/report_document.hpp"

#include <algorithm>
#include <set>

namespace rodvv::reports {

bool ValidationReport::passed() const {
  return std::all_of(cases.begin(), cases.end(), [](const auto& c) { return c.passed(); });
}

ReportTotals totals(const ValidationReport& report) {
  ReportTotals t;
  for (const auto& result : report.cases) {
    ++t.cases;
    if (result.passed()) ++t.cases_passed;
    for (const auto& gate : result.gates) {
      ++t.gates;
      if (gate.passed) ++t.gates_passed;
    }
    t.gates_skipped += result.skipped_gates.size();
    for (const auto& level : result.levels) {
      ++t.levels;
      if (level.failure) ++t.levels_failed;
    }
  }
  return t;
}

std::vector<CaseGroup> group_cases(const ValidationReport& report) {
  std::vector<CaseGroup> groups;
  std::vector<std::string> families;  // first-appearance order
  for (const auto& result : report.cases)
    if (std::find(families.begin(), families.end(), result.info.family) == families.end())
      families.push_back(result.info.family);
  for (const auto& family : families) {
    const std::size_t first = groups.size();
    for (std::size_t i = 0; i < report.cases.size(); ++i) {
      const auto& info = report.cases[i].info;
      if (info.family != family) continue;
      auto it = std::find_if(groups.begin() + static_cast<std::ptrdiff_t>(first), groups.end(),
                             [&](const CaseGroup& g) { return g.group == info.group; });
      if (it == groups.end()) {
        groups.push_back({family, info.group, {}});
        it = groups.end() - 1;
      }
      it->cases.push_back(i);
    }
  }
  return groups;
}

std::vector<std::string> ordered_metric_names(const harness::SweepResult& result) {
  std::vector<std::string> names;
  std::set<std::string> declared;
  for (const auto& spec : result.info.metrics)
    if (declared.insert(spec.name).second) names.push_back(spec.name);
  std::set<std::string> extra;  // sorted
  for (const auto& level : result.levels)
    for (const auto& [name, sample] : level.metrics)
      if (!declared.count(name)) extra.insert(name);
  names.insert(names.end(), extra.begin(), extra.end());
  return names;
}

}  // namespace rodvv::reports

#include "rodvv/reports/junit.hpp"

#include <cmath>

#include <fmt/format.h>

#include "rodvv/reports/markup_escape.hpp"
#include "rodvv/reports/number_format.hpp"

namespace rodvv::reports {

namespace {

std::string seconds(double value) {
  return fmt::format("{:.6f}", std::isfinite(value) && value > 0 ? value : 0.0);
}

std::string attr(std::string_view text) { return escape_xml_attribute(text); }

}  // namespace

std::string render_junit(const ValidationReport& report) {
  std::string suites;
  std::size_t all_tests = 0, all_failures = 0, all_skipped = 0;
  double all_time = 0.0;
  for (const auto& result : report.cases) {
    const std::string& name = result.info.name;
    std::size_t failed_levels = 0, failed_gates = 0;
    for (const auto& level : result.levels) failed_levels += level.failure ? 1 : 0;
    for (const auto& gate : result.gates) failed_gates += gate.passed ? 0 : 1;
    const std::size_t skipped = result.skipped_gates.size();
    const std::size_t tests = result.gates.size() + failed_levels + skipped;
    const std::size_t failures = failed_gates + failed_levels;
    // The gates are evaluated on the whole sweep; its time is shared out evenly among them.
    const double per_gate =
        result.gates.empty() ? 0.0 : result.wall_seconds / static_cast<double>(result.gates.size());
    all_tests += tests;
    all_skipped += skipped;
    all_failures += failures;
    if (std::isfinite(result.wall_seconds) && result.wall_seconds > 0) all_time += result.wall_seconds;

    suites += "  <testsuite name=\"" + attr(name) + "\" tests=\"" + std::to_string(tests) +
              "\" failures=\"" + std::to_string(failures) + "\" errors=\"0\" skipped=\"" + std::to_string(skipped) + "\" time=\"" +
              seconds(result.wall_seconds) + "\" timestamp=\"" +
              attr(report.provenance.date_utc) + "\">\n";
    for (const auto& gate : result.gates) {
      suites += "    <testcase classname=\"" + attr(name) + "\" name=\"" + attr(gate.name) +
                "\" time=\"" + seconds(per_gate) + "\"";
      if (gate.passed) {
        suites += "/>\n";
        continue;
      }
      suites += ">\n      <failure message=\"" + attr(gate.reason) + "\" type=\"" +
                attr(harness::to_string(gate.kind)) + "\">" +
                escape_xml("metric: " + gate.metric + "\nmeasured: " + (gate.measured ? format_shortest(*gate.measured) : kNotAvailable) +
                           "\nlower: " + (gate.lower ? format_shortest(*gate.lower) : kNotAvailable) +
                           "\nupper: " + (gate.upper ? format_shortest(*gate.upper) : kNotAvailable) +
                           "\nreason: " + gate.reason + "\nrationale: " + gate.rationale) +
                "</failure>\n    </testcase>\n";
    }
    for (const auto& level : result.levels) {
      if (!level.failure) continue;
      suites += "    <testcase classname=\"" + attr(name) + "\" name=\"" +
                attr("level " + result.info.resolution.name +
                     (result.info.resolution.name.empty() ? "" : "=") +
                     format_shortest(level.level)) +
                "\" time=\"" + seconds(level.wall_seconds) + "\">\n      <failure message=\"" +
                attr(*level.failure) + "\" type=\"level-failure\">" + escape_xml(*level.failure) +
                "</failure>\n    </testcase>\n";
    }
    // A skipped gate reads "name: reason" (harness/sweep.cpp).
    for (const auto& text : result.skipped_gates) {
      const auto colon = text.find(": ");
      const std::string gate = colon == std::string::npos ? text : text.substr(0, colon);
      suites += "    <testcase classname=\"" + attr(name) + "\" name=\"" + attr(gate) +
                "\" time=\"0.000000\">\n      <skipped message=\"" + attr(text) +
                "\"/>\n    </testcase>\n";
    }
    suites += "  </testsuite>\n";
  }
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites name=\"rodvv\" tests=\"" +
         std::to_string(all_tests) + "\" failures=\"" + std::to_string(all_failures) +
         "\" errors=\"0\" skipped=\"" + std::to_string(all_skipped) + "\" time=\"" + seconds(all_time) + "\">\n" + suites + "</testsuites>\n";
}

}  // namespace rodvv::reports

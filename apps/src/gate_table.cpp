#include "gate_table.hpp"

#include <fmt/format.h>

#include <cmath>

namespace rodvv::apps {

namespace {
std::string number(const std::optional<double>& value, const char* format = "{:.3g}") {
  if (!value || !std::isfinite(*value)) return "n/a";
  return fmt::format(fmt::runtime(format), *value);
}
}  // namespace

std::string render_gate_table(const std::vector<harness::SweepResult>& results) {
  std::string out = fmt::format("{:<46} {:<52} {:>10}  {:<22} {}\n", "CASE", "GATE", "MEASURED",
                                "WINDOW", "RESULT");
  std::size_t gates = 0, failed = 0, failed_cases = 0;
  for (const auto& result : results) {
    for (const auto& gate : result.gates) {
      ++gates;
      failed += gate.passed ? 0 : 1;
      const std::string window = fmt::format("[{}, {}]", number(gate.lower), number(gate.upper));
      out += fmt::format("{:<46} {:<52} {:>10}  {:<22} {}\n", result.info.name, gate.name,
                         number(gate.measured), window, gate.passed ? "PASS" : "FAIL");
      if (!gate.passed) out += fmt::format("    reason: {}\n", gate.reason);
    }
    for (const auto& skipped : result.skipped_gates)
      out += fmt::format("{:<46} skipped: {}\n", result.info.name, skipped);
    for (const auto& level : result.levels)
      if (level.failure)
        out += fmt::format("{:<46} level {}={:g} failed: {}\n", result.info.name,
                           result.info.resolution.name, level.level, *level.failure);
    failed_cases += result.passed() ? 0 : 1;
  }
  out += fmt::format("\n{} cases, {} gates: {} passed, {} failed; {} cases failed\n", results.size(),
                     gates, gates - failed, failed, failed_cases);
  return out;
}

std::string render_level_table(const harness::SweepResult& result) {
  std::string out = fmt::format("{} ({} levels)\n{:>12}", result.info.name, result.levels.size(),
                                result.info.resolution.name);
  for (const auto& metric : result.info.metrics) out += fmt::format(" {:>22}", metric.name);
  out += fmt::format(" {:>10} {:>10}\n", "wall [s]", "cpu [s]");
  for (const auto& level : result.levels) {
    out += fmt::format("{:>12.5g}", level.level);
    for (const auto& metric : result.info.metrics) {
      const auto found = level.metrics.find(metric.name);
      if (found == level.metrics.end()) {
        out += fmt::format(" {:>22}", level.failure ? "failed" : "n/a");
        continue;
      }
      const auto& sample = found->second;
      out += fmt::format(" {:>22}", sample.error ? fmt::format("err {:.4e}", *sample.error)
                                                  : fmt::format("{:.6g}", sample.computed));
    }
    out += fmt::format(" {:>10.4f} {:>10.4f}\n", level.wall_seconds, level.cpu_seconds);
  }
  // The values behind the errors at the finest level that ran: what the solver computed and what it
  // was compared with, to 15 digits.
  for (auto level = result.levels.rbegin(); level != result.levels.rend(); ++level) {
    if (level->failure) continue;
    out += fmt::format("  values at {} = {:g}:\n", result.info.resolution.name, level->level);
    for (const auto& metric : result.info.metrics) {
      const auto found = level->metrics.find(metric.name);
      if (found == level->metrics.end()) continue;
      const auto& sample = found->second;
      out += sample.reference ? fmt::format("    {:<24} computed {:<24.15g} reference {:.15g}\n", metric.name,
                                            sample.computed, *sample.reference)
                              : fmt::format("    {:<24} computed {:.15g}\n", metric.name, sample.computed);
    }
    break;
  }
  if (result.info.resolution.scale == harness::ResolutionScale::Parameter)
    return out + fmt::format("  no orders: the levels ({}) are a parameter study, not a mesh\n",
                             result.info.resolution.name);
  for (const auto& analysis : result.analyses) {
    std::string pairwise;
    for (double p : analysis.order.pairwise) pairwise += (std::isfinite(p) ? fmt::format(" {:.3f}", p) : " n/a");
    out += fmt::format("  order of {:<22} pairwise:{}  least squares {} (R^2 {})\n", analysis.metric,
                       pairwise, number(analysis.order.least_squares, "{:.3f}"),
                       number(analysis.order.r_squared, "{:.5f}"));
    if (analysis.richardson)
      out += fmt::format("  richardson {:<20} extrapolated {:.15g}, p {:.3f}, GCI_fine {:.3e}, "
                         "asymptotic ratio {:.4f}\n",
                         analysis.metric, analysis.richardson->extrapolated,
                         analysis.richardson->observed_order, analysis.richardson->gci_fine,
                         analysis.richardson->asymptotic_ratio);
  }
  return out;
}

}  // namespace rodvv::apps

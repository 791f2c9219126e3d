#include "progress.hpp"

#include <fmt/format.h>

#include <cstdio>

namespace rodvv::apps {

harness::ProgressCallback ProgressReporter::level_callback() const {
  if (!verbose_) return {};
  return [](const harness::SweepProgress& p) {
    fmt::print(stderr, "    {} {}={:g} ({}/{}) {:.3f} s{}\n", p.case_name, p.resolution_name, p.level,
               p.level_index + 1, p.level_count, p.seconds, p.failed ? " FAILED" : "");
  };
}

void ProgressReporter::case_finished(const harness::SweepResult& result) {
  ++cases_done_;
  std::size_t passed = 0;
  for (const auto& gate : result.gates) passed += gate.passed ? 1 : 0;
  const int width = static_cast<int>(fmt::formatted_size("{}", case_count_));
  fmt::print(stderr, "[{:>{}}/{}] {:<48} {} ({}/{} gates, {} levels, {:.2f} s)\n", cases_done_, width,
             case_count_, result.info.name,
             result.gates.empty() ? "NO EVIDENCE" : result.passed() ? "pass" : "FAIL", passed,
             result.gates.size(), result.levels.size(), result.wall_seconds);
  std::fflush(stderr);
}

}  // namespace rodvv::apps

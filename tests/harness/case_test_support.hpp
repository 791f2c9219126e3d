#pragma once
// Helpers shared by the per-family case tests: look a case up, run it at its default levels, list
// failing gates, and make a GoogleTest-safe name from a case name.
#include <cctype>
#include <stdexcept>
#include <string>
#include <vector>

#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"

namespace rodvv::testing {

inline std::vector<std::string> case_names_of_family(const std::string& family) {
  std::vector<std::string> names;
  for (const auto& c : harness::default_registry().cases())
    if (c.info.family == family) names.push_back(c.info.name);
  return names;
}

inline const harness::Case& named_case(const std::string& name) {
  const harness::Case* c = harness::default_registry().find(name);
  if (!c) throw std::logic_error("no case " + name);
  return *c;
}

inline harness::SweepResult run_at_default_levels(const harness::Case& c) {
  return harness::run_sweep(c, c.info.parameters, c.info.resolution.default_levels);
}

inline std::string failing_gates(const harness::SweepResult& result) {
  std::string text;
  for (const auto& gate : result.gates)
    if (!gate.passed) text += "\n  " + gate.name + ": " + gate.reason;
  for (const auto& level : result.levels)
    if (level.failure) text += "\n  level failed: " + *level.failure;
  return text;
}

// "pendulum/libration-90/rk4" -> "pendulumXlibrationX90Xrk4" (GoogleTest names are alphanumeric).
inline std::string test_name_of_case(const std::string& case_name) {
  std::string name;
  for (char ch : case_name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : 'X';
  return name;
}

}  // namespace rodvv::testing

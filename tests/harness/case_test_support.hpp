#pragma once
// Helpers shared by the per-family case tests: look a case up, run it at its default levels, list
// failing gates, and make a GoogleTest-safe name from a case name.
#include <gtest/gtest.h>

#include <cctype>
#include <stdexcept>
#include <string>
#include <utility>
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

// A case whose parameters `scales` are unit scales (case_info.hpp: Parameter::unit_scale) gives the
// same errors at other values of them: run at the defaults and with `scales` set, the second run passes
// with every gate evaluated (none skipped), and every metric error agrees with the first's within
// relative * |error| + absolute.
inline void expect_results_free_of_units(const harness::Case& c,
                                         const std::vector<std::pair<std::string, double>>& scales,
                                         double relative, double absolute) {
  harness::Parameters other = c.info.parameters;
  for (const auto& [name, value] : scales) {
    ASSERT_NE(harness::parameter_value(c.info.parameters, name), 1.0) << c.info.name << ": " << name << " at unity";
    harness::set_parameter(other, name, value);
  }
  const auto at_default = run_at_default_levels(c);
  const auto at_other = harness::run_sweep(c, other, c.info.resolution.default_levels);
  EXPECT_TRUE(at_other.passed()) << c.info.name << failing_gates(at_other);
  EXPECT_TRUE(at_other.skipped_gates.empty()) << c.info.name;
  EXPECT_EQ(at_other.gates.size(), at_default.gates.size()) << c.info.name;
  ASSERT_EQ(at_other.levels.size(), at_default.levels.size());
  for (std::size_t i = 0; i < at_other.levels.size(); ++i)
    for (const auto& [metric, sample] : at_default.levels[i].metrics) {
      if (!sample.error) continue;
      const double a = *sample.error, b = *at_other.levels[i].metrics.at(metric).error;
      EXPECT_NEAR(b, a, relative * a + absolute) << c.info.name << " " << metric << " at level " << i;
    }
}

// "pendulum/libration-90/rk4" -> "pendulumXlibrationX90Xrk4" (GoogleTest names are alphanumeric).
inline std::string test_name_of_case(const std::string& case_name) {
  std::string name;
  for (char ch : case_name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : 'X';
  return name;
}

}  // namespace rodvv::testing

#pragma once
// Helpers shared by the per-family case tests: look a case up, run it at its default levels, gate a
// variant on levels already solved, list failing gates, and make a GoogleTest-safe name from a case name.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/sweep.hpp"

// Under the sanitizers (the asan preset, where a 3-D case's sweep takes minutes) a test is skipped whose solves
// run code the sanitizers already see: a gate's teeth on a case's default sweep that another test runs there,
// the same solves at other parameter values, or a case's whole default sweep (a family's PassesAtDefaultLevels),
// whose code EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics runs there at the coarsest level. The sanitizers
// check the code a solve runs, which those repeats and finer levels do not change; what the skipped test checks
// (a verdict, the numbers) is checked by the release preset, where it runs (and where every case's default
// sweep is also its own CTest test). Tests of code no other sanitized test runs are never skipped.
#if defined(__SANITIZE_ADDRESS__)
#define RODVV_RELEASE_PRESET_ONLY(why) GTEST_SKIP() << "release preset only (its solves run under the sanitizers in " \
                                                    << why << ")"
#else
#define RODVV_RELEASE_PRESET_ONLY(why) static_cast<void>(0)
#endif

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

// A gate's teeth without solving the levels again: the levels of `ran` (a sweep of the case `c` was copied
// from, at c's parameters), each level's metrics edited by `edit` if given (a tripled error, a reference off
// by 1 %), analysed and gated as `c` (its gates, its metrics) by finish_sweep, the second half of run_sweep.
// The same verdict as run_at_default_levels(c) with c.run_level the original followed by `edit`, at a
// fraction of the cost (the sweeps of the 3-D cases are minutes under the sanitizers).
using MetricEdit = std::function<void(const harness::Parameters&, std::map<std::string, harness::MetricSample>&)>;
inline harness::SweepResult regated(const harness::Case& c, const harness::SweepResult& ran, const MetricEdit& edit = {}) {
  std::vector<harness::LevelResult> levels = ran.levels;
  if (edit)
    for (auto& level : levels) edit(c.info.parameters, level.metrics);
  return harness::finish_sweep(c, c.info.parameters, std::move(levels));
}

// The case's gates replaced by one order gate on `metric` at each of the wrong `claims`: each fails on the levels
// of `ran` (a sweep of c at its defaults), which are not solved again.
inline void expect_wrong_order_claims_fail(const harness::Case& c, const harness::SweepResult& ran,
                                           const std::string& metric, std::initializer_list<double> claims = {4.0, 1.0}) {
  for (const double claimed : claims) {
    harness::Case wrong = c;
    wrong.gates = {harness::order_gate(metric, claimed, "wrong claim")};
    EXPECT_FALSE(regated(wrong, ran).passed()) << c.info.name << ": " << metric << " claimed at order " << claimed;
  }
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

// The factor on a value of `unit` (a parameter's unit text: "force length^2", "mass / length", "1/time^2", "rad",
// "" ...) when the units of length, mass and time are changed so that a length is `length` times its old value,
// a mass `mass` times and a time `time` times: force = mass length / time^2. Throws std::invalid_argument
// naming an unknown unit word.
inline double unit_factor(const std::string& unit, double length, double mass, double time) {
  double factor = 1.0;
  bool denominator = false;
  std::string word;
  const auto apply = [&](std::string token) {
    if (token.empty()) return;
    int power = 1;
    if (const auto caret = token.find('^'); caret != std::string::npos) {
      power = std::stoi(token.substr(caret + 1));
      token = token.substr(0, caret);
    }
    double base = 1.0;
    if (token == "length") base = length;
    else if (token == "mass") base = mass;
    else if (token == "time") base = time;
    else if (token == "force") base = mass * length / (time * time);
    else if (token == "energy") base = mass * length * length / (time * time);
    else if (token != "1" && token != "rad" && token != "deg" && token != "degrees")
      throw std::invalid_argument("unit_factor: unknown unit word '" + token + "' in '" + unit + "'");
    factor *= std::pow(base, denominator ? -power : power);
  };
  for (char ch : unit) {
    if (ch == ' ' || ch == '/') {
      apply(word);
      word.clear();
      if (ch == '/') denominator = true;
    } else {
      word += ch;
    }
  }
  apply(word);
  return factor;
}

// The same physical problem in other units (every real parameter times its unit_factor; whole numbers such as N
// are counts); the resolution (dt / tau, N, ...) is left as it is, so a case whose levels are dimensionless runs
// the same discrete problem.
inline harness::Parameters in_other_units(const harness::Parameters& parameters, double length, double mass,
                                          double time) {
  harness::Parameters other = parameters;
  for (auto& p : other)
    if (p.kind == harness::ParameterKind::Real) p.value *= unit_factor(p.unit, length, mass, time);
  return other;
}

// Runs a case at its coarsest default level in its own units and in other units, and compares each metric's
// error (its value where it has no reference: what the gates see) with the default's times expected_factor(name)
// (nullopt: not compared), within relative * max(|expected|, floor * factor). Metrics in `round_off` are skipped.
inline void expect_metrics_in_other_units(const harness::Case& c, double length, double mass, double time,
                                          double relative, double floor, const std::vector<std::string>& round_off,
                                          const std::function<std::optional<double>(const std::string&)>& expected_factor) {
  const harness::Parameters other = in_other_units(c.info.parameters, length, mass, time);
  if (c.check_parameters) c.check_parameters(other);  // windows on dimensionless groups: the same verdict
  const double level = c.info.resolution.default_levels.front();
  const harness::LevelOutput at_default = c.run_level(c.info.parameters, level);
  const harness::LevelOutput at_other = c.run_level(other, level);
  ASSERT_FALSE(at_default.metrics.empty()) << c.info.name;
  for (const auto& [metric, sample] : at_default.metrics) {
    if (std::find(round_off.begin(), round_off.end(), metric) != round_off.end()) continue;
    const std::optional<double> factor = expected_factor(metric);
    if (!factor) continue;
    const auto& other_sample = at_other.metrics.at(metric);
    const double a = *factor * (sample.error ? *sample.error : sample.computed);
    const double b = other_sample.error ? *other_sample.error : other_sample.computed;
    EXPECT_NEAR(b, a, relative * std::max(std::abs(a), floor * *factor)) << c.info.name << " " << metric;
  }
}

// A case posed in other units reports the same metrics (its errors are dimensionless, in the case's own
// units); floor: the size below which a value is round-off, e.g. 1e-10 for metrics that are 0 in exact
// arithmetic; metrics in `round_off` (measured in eps) are not compared.
inline void expect_metrics_free_of_units(const harness::Case& c, double length, double mass, double time,
                                         double relative, double floor,
                                         const std::vector<std::string>& round_off = {}) {
  expect_metrics_in_other_units(c, length, mass, time, relative, floor, round_off,
                                [](const std::string&) { return std::optional<double>(1.0); });
}

// For cases whose metrics carry physical units (MetricSpec::unit, e.g. "length", "mass length/time", "energy"):
// posed in other units, each metric is the default's times its unit's factor. Metrics without a MetricSpec
// and those in `round_off` are not compared.
inline void expect_metrics_scale_with_units(const harness::Case& c, double length, double mass, double time,
                                            double relative, double floor,
                                            const std::vector<std::string>& round_off = {}) {
  expect_metrics_in_other_units(c, length, mass, time, relative, floor, round_off,
                                [&](const std::string& metric) -> std::optional<double> {
                                  for (const auto& spec : c.info.metrics)
                                    if (spec.name == metric) return unit_factor(spec.unit, length, mass, time);
                                  return std::nullopt;
                                });
}

// "pendulum/libration-90/rk4" -> "pendulumXlibrationX90Xrk4" (GoogleTest names are alphanumeric).
inline std::string test_name_of_case(const std::string& case_name) {
  std::string name;
  for (char ch : case_name) name += std::isalnum(static_cast<unsigned char>(ch)) ? ch : 'X';
  return name;
}

}  // namespace rodvv::testing

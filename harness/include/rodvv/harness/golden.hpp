#pragma once
// Regression gates (issue 13, class 6): a case's metrics at its default levels against stored
// "golden" values. Verification gates ask "is it right?" with bounds of a few times the measured
// error constant, so a change of that constant by 10 % passes them; runs are bit-identical (run to
// run, -j 1 to -j N), so a regression gate can ask "did it change?" with tolerances near round-off,
// in the manner of MOOSE's CSVDiff (per-value relative and absolute tolerances). `rodvv bless`
// rewrites the goldens and prints what moved.
//
// Compared: every non-diagnostic metric (kind Error or Invariant; iteration counts and other
// diagnostics may move with the build) at every level whose value is also in the goldens, and
// whether the level failed. Tolerances, with m = max(|golden value|, |reference|, scale):
//   value:  |v - v_golden| <= value_relative m            (1e-9: compiler and libm variation)
//   error:  |e - e_golden| <= error_relative |e_golden| + value_relative m
//           (1e-6: a change of the error constant by 1e-5 is seen; the second term is the
//           round-off of an error far below the value it is the error of)
//   plus, for a metric at round-off, the absolute tolerance its case states (Case::golden_absolute):
//   round-off is not the same bits on every CPU (case.hpp).
// The gate's measured value is the largest deviation over its tolerance (<= 1 passes).
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rodvv/harness/case.hpp"
#include "rodvv/harness/sweep_result.hpp"

namespace rodvv::harness {

struct GoldenSample {
  double computed = 0.0;
  std::optional<double> reference;
  std::optional<double> error;
  std::optional<double> scale;
};

struct GoldenLevel {
  double level = 0.0;
  bool failed = false;
  std::map<std::string, GoldenSample> metrics;  // non-diagnostic metrics only
};

struct GoldenCase {
  std::vector<GoldenLevel> levels;
};

using Goldens = std::map<std::string, GoldenCase>;  // by case name

struct GoldenTolerance {
  double value_relative = 1e-9;
  double error_relative = 1e-6;
  // Per metric, an absolute tolerance added to both (Case::golden_absolute: metrics at round-off).
  std::map<std::string, double> absolute;
};

// The goldens of a finished sweep (diagnostic metrics left out).
GoldenCase golden_of(const SweepResult& result);

// One difference between two goldens of a case, for `rodvv bless` and the gate's reason.
struct GoldenChange {
  double level = 0.0;
  std::string metric;  // "(level failed)" for a change of the failure state, "(level added)" ...
  std::optional<double> old_value, new_value;
  std::optional<double> old_error, new_error;
  double deviation = 0.0;  // over its tolerance (> 1: outside it); infinite for a changed failure state
};

// Every compared value of `now` against `golden` at the levels both hold, with its deviation.
std::vector<GoldenChange> compare_goldens(const GoldenCase& golden, const GoldenCase& now,
                                          const GoldenTolerance& tolerance = {});

// The regression gate of a case run at `defaults` parameters and levels, or nothing with the reason
// in *why_not (no golden for the case, parameters not at their defaults, no level in common).
std::optional<GateResult> regression_gate(const Case& c, const SweepResult& result, const Goldens& goldens,
                                          std::string* why_not, const GoldenTolerance& tolerance = {});

// Appends the case's regression gate to result.gates, or the reason it was skipped to
// result.skipped_gates ("regression: ...").
void add_regression_gate(const Case& c, SweepResult& result, const Goldens& goldens,
                         const GoldenTolerance& tolerance = {});

}  // namespace rodvv::harness

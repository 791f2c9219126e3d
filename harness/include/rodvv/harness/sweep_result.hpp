#pragma once
// The result of running one case over its levels: the data model that reports/ serialises to
// results.json (the canonical format) and renders to CSV, Markdown, HTML and JUnit XML.
// Absent values are std::nullopt (written as null), never NaN.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "rodvv/harness/case_info.hpp"

namespace rodvv::harness {

struct MetricSample {
  double computed = 0.0;
  std::optional<double> reference;  // exact value, when one exists
  std::optional<double> error;      // the quantity whose convergence is fitted and gated
  // The quantity's natural size in the error's units, where |reference| is not it: a reference that
  // is 0 or may vanish, or an error already relative or in units of a problem scale (then 1).
  // The error's relative size is error / scale, else error / |reference| (gate.hpp, metric_size).
  std::optional<double> scale = std::nullopt;
};

// A curve attached to a level for plotting (energy vs time, theta vs t, ...), thinned to a few
// hundred points.
struct Series {
  std::string name;
  std::string x_label;
  std::string y_label;
  std::vector<double> x;
  std::vector<double> y;
};

struct LevelResult {
  double level = 0.0;   // the resolution as given (dt, N, tol)
  double h = 0.0;       // mesh size used for the fits
  double wall_seconds = 0.0;
  // CPU time of the thread that ran the level (a level runs on one thread, also under `-j N`): the
  // cost measure of a work-precision comparison, less disturbed than wall time on a shared machine.
  double cpu_seconds = 0.0;
  std::map<std::string, MetricSample> metrics;
  std::vector<Series> series;
  std::optional<std::string> failure;  // a SolverError at this level: the message
};

struct OrderFit {
  // p_i = log(e_i / e_{i+1}) / log(h_i / h_{i+1}) between levels i and i+1; NaN where either error
  // is missing or zero (the one place a NaN is kept, to keep indices aligned; written as null).
  std::vector<double> pairwise;
  std::optional<double> least_squares;    // slope of log e vs log h over the last levels_used levels
  std::optional<double> r_squared;
  std::size_t levels_used = 0;
};

// Richardson extrapolation and the Grid Convergence Index on the three finest levels
// (Roache 1994, J. Fluids Eng. 116:405; Celik et al. 2008, J. Fluids Eng. 130:078001).
struct RichardsonResult {
  double refinement_ratio = 0.0;  // r = h_coarse / h_fine (of the finest pair)
  double observed_order = 0.0;
  double extrapolated = 0.0;
  double gci_fine = 0.0;          // relative, with safety factor Fs = 1.25
  double gci_coarse = 0.0;
  double asymptotic_ratio = 0.0;  // GCI_coarse / (r^p GCI_fine); ~1 in the asymptotic range
};

struct MetricAnalysis {
  std::string metric;
  OrderFit order;
  std::optional<RichardsonResult> richardson;
  std::optional<std::string> richardson_note;  // why Richardson was not applied
};

// Order: least-squares order of a metric's error in [lower, upper] (two-sided, MOOSE mms style).
// UpperBound / LowerBound: a metric's value (its error, or its computed value for invariants and
// diagnostics) at the finest level or at every level lies below / above a bound.
// Regression: a case's metrics against its stored goldens (golden.hpp), measured = the largest deviation
// over its tolerance, upper = 1.
enum class GateKind { Order, UpperBound, LowerBound, Regression };
enum class GateScope { FinestLevel, AllLevels };

struct GateResult {
  std::string name;
  GateKind kind = GateKind::Order;
  std::string metric;
  bool passed = false;
  std::optional<double> measured;
  std::optional<double> lower;
  std::optional<double> upper;
  std::string reason;     // one line: what was measured against what
  std::string rationale;  // where the bound comes from
};

struct SweepResult {
  CaseInfo info;
  std::vector<LevelResult> levels;
  std::vector<MetricAnalysis> analyses;
  std::vector<GateResult> gates;
  // Gates not evaluated, with the reason: bounds measured at the default parameters, when the
  // sweep ran at other parameters (`--set`).
  std::vector<std::string> skipped_gates;
  double wall_seconds = 0.0;

  bool passed() const {
    for (const auto& gate : gates)
      if (!gate.passed) return false;
    for (const auto& level : levels)
      if (level.failure) return false;
    return true;
  }
};

const char* to_string(MetricKind kind);
const char* to_string(GateKind kind);
const char* to_string(ResolutionScale scale);

}  // namespace rodvv::harness

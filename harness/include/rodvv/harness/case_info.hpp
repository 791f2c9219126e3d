#pragma once
// What a case is, as data: the description that travels with its results into every report.
#include <optional>
#include <string>
#include <vector>

namespace rodvv::harness {

// A named scalar parameter of a case with its allowed range, settable with `--set NAME=VALUE`.
// What values a parameter takes: any real in its range, a whole number in it (a count), or 0/1 (a
// switch). --set refuses the others with the allowed form instead of rounding them silently.
enum class ParameterKind { Real, Integer, Boolean };

struct Parameter {
  std::string name;
  double value = 0.0;
  double min = 0.0;  // allowed range; open or closed at each end
  double max = 0.0;
  bool min_open = false;
  bool max_open = false;
  std::string unit;
  std::string description;
  ParameterKind kind = ParameterKind::Real;
  // A unit of the problem (the pendulum's omega): the case's levels and metrics are in units built
  // from it, so its results do not depend on it (up to round-off) and bounds measured at the
  // default parameters still hold when only unit scales are changed (sweep.cpp).
  bool unit_scale = false;
};

// The resolution parameter of a sweep. A StepSize level is the mesh size h itself (dt, a
// tolerance); a Count level is a number of elements N with h = 1 / N. Orders are fitted in h.
// A Parameter level is not a resolution but a physical parameter the case studies (a helix angle): its
// levels increase (h = 1 / level orders them only), no order is fitted or may be gated, and the report
// draws the metrics over the level itself.
enum class ResolutionScale { StepSize, Count, Parameter };

struct Resolution {
  std::string name;  // "dt", "N", "tol"
  std::string description;
  ResolutionScale scale = ResolutionScale::StepSize;
  std::vector<double> default_levels;   // coarse -> fine; sized so `rodvv run` stays fast
  std::vector<double> extended_levels;  // a larger sweep behind `--extended`
  // The finest level the case honours on this machine class (2 cores, a few GB): the largest N, or
  // the smallest step. 0: four times finer than its finest default or extended level (sweep.hpp:
  // finest_level_honoured). A level beyond it is refused as bad input, before any work.
  double finest_honoured = 0.0;

  double h(double level) const { return scale == ResolutionScale::StepSize ? level : 1.0 / level; }
  // Whether the levels grow from coarse to fine (a count, a parameter) or shrink (a step size).
  bool increasing() const { return scale != ResolutionScale::StepSize; }
};

// Error: |computed - reference|, a convergence quantity. Invariant: a conservation measure whose
// ideal value is the reference. Diagnostic: reported, not compared (iterations, step counts).
enum class MetricKind { Error, Invariant, Diagnostic };

struct MetricSpec {
  std::string name;
  MetricKind kind = MetricKind::Error;
  std::string unit;
  std::string description;
  bool extrapolate = false;  // Richardson/GCI on the computed value (a smooth solution functional)
  std::optional<double> theoretical_order;  // expected order of `error` in h (plots, order gates)
};

struct CaseInfo {
  std::string name;     // "pendulum/libration-90/stormer-verlet"
  std::string family;   // "pendulum"
  std::string group;    // cases compared side by side in one report section and overlay plot,
                        // e.g. "pendulum/long-time-energy" (symplectic vs non-symplectic)
  std::string title;    // one line for tables
  std::string physics;  // what is solved, in words and equations
  std::string reference;  // the closed form or invariant compared against
  std::string citation;   // where the reference comes from
  std::string method;     // the solver and its theoretical order
  std::vector<Parameter> parameters;
  // Windows on combinations of parameters that a run requires beyond each one's own range ("C / B
  // in [0.03, 100]"): listed by `rodvv list -v`, enforced by Case::check_parameters (exit 2).
  std::vector<std::string> parameter_windows;
  Resolution resolution;
  std::vector<MetricSpec> metrics;
};

// The MetricSpec of `name` in the case, or nullptr when the case does not declare it.
const MetricSpec* find_metric_spec(const CaseInfo& info, const std::string& name);

// Whether `parameters` hold the case's defaults (same names, same values). With unit_scales_free a
// parameter marked unit_scale may differ: a case posed in its own units gives the same results.
bool at_default_parameters(const CaseInfo& info, const std::vector<Parameter>& parameters, bool unit_scales_free);

}  // namespace rodvv::harness

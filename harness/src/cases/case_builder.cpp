#include "case_builder.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>
#include <fmt/format.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/invariants/noether3d.hpp"

namespace rodvv::harness::cases {

namespace {
// "in [low, high]", or ">= low" for an open top.
std::string interval_text(double low, double high) {
  return std::isinf(high) ? fmt::format(">= {:g}", low) : fmt::format("in [{:g}, {:g}]", low, high);
}
}  // namespace

bool inside(double v, double low, double high) {
  constexpr double kSlack = 4.0 * std::numeric_limits<double>::epsilon();
  return v >= low - kSlack * std::abs(low) && v <= high + kSlack * std::abs(high);
}

void require(Case& c, Window window) { require_window(c, std::move(window.statement), std::move(window.check)); }

Window ratio_window(std::string numerator, std::string denominator, double low, double high, std::string why) {
  std::string statement = fmt::format("{} / {} {} ({})", numerator, denominator, interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double ratio = parameter_value(p, numerator) / parameter_value(p, denominator);
            if (!inside(ratio, low, high))
              throw InputError(numerator, fmt::format("invalid parameters: {} / {} = {} must be {} ({})", numerator,
                                                      denominator, format_value(ratio), interval_text(low, high), why));
          }};
}

Window load_window(std::string length, double low, double high, std::string why) {
  std::string statement = fmt::format("P {}^2 / EI {} ({})", length, interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double arm = parameter_value(p, length), EI = parameter_value(p, "EI"), P = parameter_value(p, "P");
            const double load = P * arm * arm / EI;
            if (!inside(load, low, high))
              throw InputError("P", fmt::format("invalid parameter 'P' = {}: the load P {}^2 / EI = {} ({} = {}, EI = "
                                                "{}) must be {} ({})",
                                                format_value(P), length, format_value(load), length, format_value(arm),
                                                format_value(EI), interval_text(low, high), why));
          }};
}

Window weight_window(double low, double high, std::string why) {
  std::string statement = fmt::format("w L^3 / EI {} ({})", interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double w = parameter_value(p, "w"), L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
            const double weight = w * L * L * L / EI;
            if (!inside(weight, low, high))
              throw InputError("w", fmt::format("invalid parameter 'w' = {}: the weight w L^3 / EI = {} (L = {}, EI = {}) "
                                                "must be {} ({})",
                                                format_value(w), format_value(weight), format_value(L),
                                                format_value(EI), interval_text(low, high), why));
          }};
}

double helix_turns(const Parameters& p) {
  return parameter_value(p, "L") * std::sin(parameter_value(p, "pitch_angle")) /
         (2.0 * std::numbers::pi * parameter_value(p, "radius"));
}

Window helix_turns_window(double low, double high, std::string why) {
  std::string statement =
      fmt::format("helix turns L sin(pitch_angle) / (2 pi radius) {} ({})", interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double turns = helix_turns(p);
            if (!inside(turns, low, high))
              throw InputError("L", fmt::format("invalid parameters: the helix makes L sin(pitch_angle) / (2 pi radius) "
                                                "= {} turns, which must be {} ({})",
                                                format_value(turns), interval_text(low, high), why));
          }};
}

Parameters section_parameters(double rhoS, const Vec3& stiffness) {
  return {make_parameter("rhoS", rhoS, 0.0, 1e12, true, false, "mass/length", "line density"),
          make_parameter("GJ", stiffness.x(), 0.0, 1e12, true, false, "force length^2", "twisting stiffness"),
          make_parameter("EI1", stiffness.y(), 0.0, 1e12, true, false, "force length^2",
                         "bending stiffness about the first material axis"),
          make_parameter("EI2", stiffness.z(), 0.0, 1e12, true, false, "force length^2",
                         "bending stiffness about the second material axis")};
}

double bending_time(const Parameters& p, const std::string& stiffness) {
  const double L = parameter_value(p, "L");
  return L * L * std::sqrt(parameter_value(p, "rhoS") / parameter_value(p, stiffness));
}

Window swing_window(double max_swing) {
  std::string statement = fmt::format("t_end sqrt(g / L) <= {:g} (the swing the time levels resolve)", max_swing);
  return {statement, [=](const Parameters& p) {
            const double L = parameter_value(p, "L");
            const double swing = parameter_value(p, "t_end") * std::sqrt(parameter_value(p, "g") / L);
            if (!(swing <= max_swing))
              throw InputError("t_end", fmt::format("invalid parameters: t_end sqrt(g / L) = {} (L = {}) must be <= "
                                                    "{:g}, the swing the levels resolve",
                                                    format_value(swing), format_value(L), max_swing));
          }};
}

Window horizon_window(std::string stiffness, double low, double high, std::string why) {
  std::string statement = fmt::format("t_end / tau {}, tau = L^2 sqrt(rhoS / {}) ({})", interval_text(low, high),
                                      stiffness, why);
  return {statement, [=](const Parameters& p) {
            const double tau = bending_time(p, stiffness), t_end = parameter_value(p, "t_end");
            if (!inside(t_end / tau, low, high))
              throw InputError("t_end", fmt::format("invalid parameter 't_end' = {}: t_end / tau = {} (tau = L^2 sqrt("
                                                    "rhoS / {}) = {}) must be {} ({})",
                                                    format_value(t_end), format_value(t_end / tau), stiffness,
                                                    format_value(tau), interval_text(low, high), why));
          }};
}

Window gravity_window(std::string stiffness, double low, double high, std::string why) {
  std::string statement = fmt::format("g rhoS L^3 / {} {} ({})", stiffness, interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double g = parameter_value(p, "g"), L = parameter_value(p, "L");
            const double weight = g * parameter_value(p, "rhoS") * L * L * L / parameter_value(p, stiffness);
            if (!inside(weight, low, high))
              throw InputError("g", fmt::format("invalid parameter 'g' = {}: g rhoS L^3 / {} = {} must be {} ({})",
                                                format_value(g), stiffness, format_value(weight),
                                                interval_text(low, high), why));
          }};
}

Window group_window(std::string parameter, std::string group, std::function<double(const Parameters&)> value,
                    double low, double high, std::string why) {
  std::string statement = fmt::format("{} {} ({})", group, interval_text(low, high), why);
  return {statement, [=](const Parameters& p) {
            const double v = value(p);
            if (!inside(v, low, high))
              throw InputError(parameter, fmt::format("invalid parameter '{}' = {}: {} = {} must be {} ({})", parameter,
                                                      format_value(parameter_value(p, parameter)), group,
                                                      format_value(v), interval_text(low, high), why));
          }};
}

MetricSample error_sample(double computed, double reference) { return {computed, reference, std::abs(computed - reference)}; }
MetricSample value_sample(double value) { return {value, 0.0, std::abs(value), std::nullopt}; }
MetricSample value_sample(double value, double size) { return {value, 0.0, std::abs(value), size}; }
MetricSample diagnostic(double value) { return {value, std::nullopt, std::nullopt}; }

MetricSpec error_metric(std::string name, std::string unit, std::string description, std::optional<double> order,
                        bool extrapolate) {
  return {std::move(name), MetricKind::Error, std::move(unit), std::move(description), extrapolate, order};
}
MetricSpec invariant_metric(std::string name, std::string description, std::optional<double> order) {
  return {std::move(name), MetricKind::Invariant, "", std::move(description), false, order};
}
MetricSpec diagnostic_metric(std::string name, std::string description) {
  return {std::move(name), MetricKind::Diagnostic, "", std::move(description), false, std::nullopt};
}

Mat3 tilted_frame(double angle) {
  return Eigen::AngleAxisd(angle, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
}

Resolution element_levels(std::string description, std::vector<double> levels, std::vector<double> extended) {
  return {"N", std::move(description), ResolutionScale::Count, std::move(levels), std::move(extended)};
}

std::size_t element_count(double level) { return static_cast<std::size_t>(std::llround(level)); }

GateSpec measured_bound(const std::string& metric, double at_finest, double h_finest, double order) {
  GateSpec gate = scaled_upper_bound_gate(metric, 2.0 * at_finest / std::pow(h_finest, order), order,
                                          GateScope::FinestLevel,
                                          fmt::format("C = 2 x the value measured at the finest default level / h^{:g}", order));
  gate.measured = true;
  return gate;
}

GateSpec measured_order_gate(const std::string& metric, double order, std::string rationale) {
  GateSpec gate = order_gate(metric, order, std::move(rationale));
  gate.measured = true;
  return gate;
}

Case make_case(std::string family, CaseText text, Parameters parameters, Resolution resolution,
               std::vector<MetricSpec> metrics, std::vector<GateSpec> gates, LevelRunner runner) {
  Case c;
  c.info.name = std::move(text.name);
  c.info.family = std::move(family);
  c.info.group = text.group.empty() ? c.info.name : std::move(text.group);
  c.info.title = std::move(text.title);
  c.info.physics = std::move(text.physics);
  c.info.reference = std::move(text.reference);
  c.info.citation = std::move(text.citation);
  c.info.method = std::move(text.method);
  c.info.parameters = std::move(parameters);
  c.info.resolution = std::move(resolution);
  c.info.metrics = std::move(metrics);
  c.gates = std::move(gates);
  c.run_level = std::move(runner);
  return c;
}

void add_noether3d_metrics(LevelOutput& output, const SpatialRodSolution& solution, std::optional<double> exact) {
  const auto summary = invariants::noether3d_summary(solution);
  const double scale = std::max(summary.scale, 1e-300);
  output.metrics["H_spread"] = value_sample(summary.spread / scale, 1.0);  // in units of the term scale
  output.metrics["H_form_difference"] = value_sample(summary.form_difference / scale, 1.0);
  if (exact)
    output.metrics["H_mean"] = {summary.mean, *exact, std::abs(summary.mean - *exact) / std::max(std::abs(*exact), scale),
                                1.0};  // a relative error: size 1
  output.series.push_back(thin_series("H(s)|compact", "s", "H", solution.s, invariants::noether3d_compact(solution)));
  output.series.push_back(thin_series("H(s)|flattened", "s", "H", solution.s, invariants::noether3d_flattened(solution)));
}

std::vector<MetricSpec> noether3d_metric_specs(bool exact, std::optional<double> spread_order,
                                               std::optional<double> mean_order) {
  std::vector<MetricSpec> specs{
      invariant_metric("H_spread", "max |H(s) - mean H| / term scale at the stations", spread_order),
      invariant_metric("H_form_difference", "max |H_compact - H_flattened| / term scale (round-off)")};
  if (exact)
    specs.push_back(error_metric("H_mean", "force", "|mean H - closed form| / max(|H|, term scale)", mean_order));
  return specs;
}

}  // namespace rodvv::harness::cases

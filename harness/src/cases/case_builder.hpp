#pragma once
// The one case builder of the families that live one problem per file under
// harness/src/cases/<family>/ (ARCHITECTURE.md, convention 12): metric samples and specs, element
// levels, measured bounds, the Case itself, and the 3-D Noether metrics every 3-D rod case reports.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/harness/case.hpp"
#include "rodvv/harness/parameters.hpp"

namespace rodvv::harness::cases {

// Samples: an error against a reference; a value whose ideal is 0 (gated on |value|); a diagnostic.
MetricSample error_sample(double computed, double reference);
MetricSample value_sample(double value);
// The same, with the quantity's natural size (MetricSample::scale): 1 for a value already in units
// of a problem scale (shape / L, H spread / term scale).
MetricSample value_sample(double value, double size);
MetricSample diagnostic(double value);

MetricSpec error_metric(std::string name, std::string unit, std::string description, std::optional<double> order,
                        bool extrapolate = false);
MetricSpec invariant_metric(std::string name, std::string description, std::optional<double> order = std::nullopt);
MetricSpec diagnostic_metric(std::string name, std::string description);

// A general rotation (about the axis (0.3, -0.5, 0.8)), so that no 3-D case lives in coordinate planes.
Mat3 tilted_frame(double angle);

// A sweep over the element count N (h = 1 / N).
Resolution element_levels(std::string description, std::vector<double> levels, std::vector<double> extended);
std::size_t element_count(double level);

// value <= C h^order with C = 2 x the value measured at the finest default level (h_finest): a
// regression of the error constant by more than 2x turns red; skipped at non-default parameters.
GateSpec measured_bound(const std::string& metric, double at_finest, double h_finest, double order);
// An order seen at the default parameters but not derived (a superconvergence): checked there,
// skipped elsewhere like a measured bound.
GateSpec measured_order_gate(const std::string& metric, double order, std::string rationale);

// A window on a combination of parameters (case.hpp, require_window): the statement `list -v`
// prints and the check a run applies, made from the same numbers.
struct Window {
  std::string statement;
  ParameterCheck check;
};
void require(Case& c, Window window);

// A stiffness ratio numerator / denominator (C / B, GJ / B, ...) in [low, high] (high may be
// infinite): the ratios at which a case's levels were measured to resolve its problem (the scales
// alone cancel in a problem posed in its own units). InputError naming the numerator otherwise, with
// `why` said beyond the ends.
Window ratio_window(std::string numerator, std::string denominator, double low, double high, std::string why);

// The load a case's levels resolve, P length^2 / EI in [low, high] (a window measured per case, with
// the reason beyond its ends in `why`); InputError naming P otherwise. `length` names the parameter
// that sets the lever arm (L, R).
Window load_window(std::string length, double low, double high, std::string why);

// The weight a case's levels resolve, w L^3 / EI in [low, high] (w: weight per unit length, from the
// parameters w, L and EI; measured per case, with the reason beyond its ends in `why`); InputError
// naming w otherwise.
Window weight_window(double low, double high, std::string why);

// v in [low, high] up to the rounding of a group computed from typed values (4 eps relative): a user who types a
// window's end (GJ = 0.01 with EI1 = 0.05, GJ / EI1 = 0.19999999999999998) is inside it. NaN is outside.
bool inside(double v, double low, double high);

// A rod's line density rhoS and stiffnesses GJ, EI1, EI2 (stiffness = (GJ, EI1, EI2)) as parameters, each in
// (0, 1e12].
Parameters section_parameters(double rhoS, const Vec3& stiffness);

// Dynamic cases in the user's units: the rod's bending time tau = L^2 sqrt(rhoS / EI) from the parameters L,
// rhoS and the named bending stiffness. Their time levels are dt / tau and their start rates are given in
// units of tau, so that the resolution and the measured windows do not depend on the scales.
double bending_time(const Parameters& p, const std::string& stiffness);

// The swing t_end sqrt(g / L) a dynamic case's time levels resolve, at most max_swing (measured per case);
// InputError naming t_end otherwise.
Window swing_window(double max_swing);
// The horizon t_end / tau in [low, high] (tau from bending_time); InputError naming t_end otherwise.
Window horizon_window(std::string stiffness, double low, double high, std::string why);
// The gravity g rhoS L^3 / EI in [low, high]; InputError naming g otherwise.
Window gravity_window(std::string stiffness, double low, double high, std::string why);
// Any dimensionless group of the parameters (its formula in `group`, e.g. "rhoI0 / (rhoS L^2)") in [low, high];
// InputError naming `parameter` otherwise.
Window group_window(std::string parameter, std::string group, std::function<double(const Parameters&)> value,
                    double low, double high, std::string why);

// The turns L sin(pitch_angle) / (2 pi radius) of a uniform helix, from the parameters L, radius and
// pitch_angle (the helix cases of both 3-D rods).
double helix_turns(const Parameters& p);
// The helix turns in [low, high]; InputError naming L otherwise, with `why` said beyond the ends.
Window helix_turns_window(double low, double high, std::string why);

struct CaseText {
  std::string name, title, physics, reference, citation, method;
  std::string group = {};  // cases compared side by side (report overlays); empty: the case's own name
};
Case make_case(std::string family, CaseText text, Parameters parameters, Resolution resolution,
               std::vector<MetricSpec> metrics, std::vector<GateSpec> gates, LevelRunner runner);

// The 3-D Noether invariant of a solution (invariants/noether3d.hpp): H_spread (max |H - mean| /
// term scale), H_form_difference (compact vs flattened / term scale) and, with a closed form,
// H_mean (|mean - exact| / max(|exact|, term scale)); plus the H(s) series of both forms.
void add_noether3d_metrics(LevelOutput& output, const SpatialRodSolution& solution, std::optional<double> exact);
std::vector<MetricSpec> noether3d_metric_specs(bool exact, std::optional<double> spread_order,
                                               std::optional<double> mean_order = std::nullopt);

}  // namespace rodvv::harness::cases

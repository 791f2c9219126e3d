// rod3d/modes: small oscillations of a straight cantilever on the nodal 3-D rod - the first two
// bending frequencies in each principal plane (EI1 != EI2, a tilted clamp) and the first two
// torsional frequencies (GJ, rho I0 unrelated to the bending data) against their closed forms
// (solvers/rod3d/linearized.hpp: K v = omega^2 M v on the inextensibility constraints' null space).
//
// Discretisation error, derived where it can be: torsion is a chain of springs GJ/ebar between the
// edges' angles with masses rho I0 ebar, the clamped edge centred on the support and the last edge's
// centre ebar/2 from the free end, so its modes are exactly sin(k s) at the edge centres with
// k L = (2n - 1) pi / 2 and omega = (2/ebar) sqrt(GJ/rho I0) sin(k ebar/2): the relative error is
// -(k ebar)^2/24 + O(ebar^4), second order (gated to round-off as "torsion_discrete"). Bending:
// lumped masses, curvature at the vertices, ghost-edge clamp; measured second order, from below.
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../case_builder.hpp"
#include "rod3d_cases.hpp"
#include "rod3d_support.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/solvers/rod3d/linearized.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;
constexpr double kPi = std::numbers::pi;

// A mode belongs to a family when all but this fraction of its kinetic norm lies there. The families
// decouple exactly on a straight uniform rod; the tilted frame mixes them at round-off (measured
// <= 1e-12 off-family content up to N = 128 at the default parameters).
constexpr double kPurity = 1e-6;

// The eigensolver's round-off on the lowest frequency is eps (omega_max / omega_min)^2 (a backward
// error eps |A|_2 on each eigenvalue), with omega_max^2 the top of the discrete spectrum: bending
// ~16 EI / (rho S ebar^4), torsion ~4 GJ / (rho I0 ebar^2), and omega_min the lowest closed-form
// frequency. At the finest default level (N = 64) it must stay below 1e-6 of omega_min^2 (defaults:
// 8.8e-9), or no level can measure an O(h^2) error of ~1e-5: parameters that spread the families
// further (EI1 = 1e12: 0.55; rho I0 = 1e12; L = 1e6, where bending and torsion scale apart as 1/L^2
// and 1/L) are refused, naming what sets each end.
constexpr double kFinestDefaultEdges = 64.0;
constexpr double kMaxEigenRoundOff = 1e-6;

void check_frequency_spread(const Parameters& p) {
  const double L = parameter_value(p, "L"), GJ = parameter_value(p, "GJ"), EI1 = parameter_value(p, "EI1"),
               EI2 = parameter_value(p, "EI2"), rhoS = parameter_value(p, "rhoS"), rhoI0 = parameter_value(p, "rhoI0");
  const double ebar = L / kFinestDefaultEdges, beta1 = 1.87510406871196;
  const double top_bending = 16.0 * std::max(EI1, EI2) / (rhoS * std::pow(ebar, 4)), top_twist = 4.0 * GJ / (rhoI0 * ebar * ebar);
  const double low_bending = std::pow(beta1, 4) * std::min(EI1, EI2) / (rhoS * std::pow(L, 4));
  const double low_twist = std::pow(kPi / (2.0 * L), 2) * GJ / rhoI0;
  const double spread = std::max(top_bending, top_twist) / std::min(low_bending, low_twist);
  const double round_off = std::numeric_limits<double>::epsilon() * spread;
  if (!(round_off <= kMaxEigenRoundOff))
    throw InputError(top_bending >= top_twist ? (EI1 >= EI2 ? "EI1" : "EI2") : "GJ",
                     fmt::format("invalid parameters: the frequencies spread over (omega_max / omega_min)^2 = {} at N = "
                                 "{} (omega_max from {}, omega_min from {}), so the eigensolver's round-off on the lowest "
                                 "frequency, eps x that = {}, exceeds {}; bring EI1, EI2, GJ, rhoS, rhoI0 and L closer "
                                 "to each other's scales",
                                 format_value(spread), kFinestDefaultEdges,
                                 top_bending >= top_twist ? "bending (EI / rhoS)" : "torsion (GJ / rhoI0)",
                                 low_bending <= low_twist ? "bending" : "torsion", format_value(round_off),
                                 format_value(kMaxEigenRoundOff)));
}

LevelOutput run(const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), GJ = parameter_value(p, "GJ"), EI1 = parameter_value(p, "EI1"),
               EI2 = parameter_value(p, "EI2"), rhoS = parameter_value(p, "rhoS"), rhoI0 = parameter_value(p, "rhoI0");
  rod::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(GJ, EI1, EI2);
  model.line_density = rhoS;
  model.twist_inertia = rhoI0;
  model.root.support = rod::EndSupport::Clamped;
  model.root.frame = tilted_frame(0.7);
  model.root.position = Vec3(0.2, 0.4, -0.1) * L;
  const auto modes = rod::linear_modes(model, rod::make_straight_state(model));

  // Families: bending about m1 moves the rod along m2 (EI1), about m2 along m1 (EI2); torsion turns
  // the sections. frame columns: (t, m1, m2).
  std::vector<double> family[3];  // EI1, EI2, torsion
  double mixing = 0.0;
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k) {
    if (family[0].size() >= 2 && family[1].size() >= 2 && family[2].size() >= 2) break;
    const auto c = rod::modal_content(model, modes.shapes.col(k), model.root.frame);
    const double part[3] = {c.translation[2], c.translation[1], c.rotation};
    const int f = int(std::max_element(part, part + 3) - part);
    if (part[f] < 1.0 - kPurity)
      throw SolverError("rod3d linear modes", fmt::format("mode {} (omega = {:.6g}) mixes bending and torsion (largest "
                                                          "family share {:.6g}): near-degenerate frequencies of "
                                                          "different families; change EI1, EI2, GJ or rho I0",
                                                          k + 1, modes.frequencies[k], part[f]),
                        0, 1.0 - part[f]);
    mixing = std::max(mixing, 1.0 - part[f]);
    if (family[f].size() < 2) family[f].push_back(modes.frequencies[k]);
  }
  for (const auto& f : family)
    if (f.size() < 2)
      throw InputError("N", fmt::format("invalid parameter 'N' = {}: too few edges for two modes of each family",
                                        model.elements));

  LevelOutput output;
  const auto relative = [](double computed, double exact) {
    return MetricSample{computed, exact, std::abs(computed - exact) / exact, 1.0};  // a relative error: size 1
  };
  const double ell = rod::rest_edge_length(model), c_twist = std::sqrt(GJ / rhoI0);
  // The eigensolver's round-off: a backward error of eps |A|_2 = eps omega_max^2 on each omega^2.
  const double round_off = std::numeric_limits<double>::epsilon() * modes.omega_squared.cwiseAbs().maxCoeff();
  double discrete_twist = 0.0, discrete_twist_relative = 0.0;
  for (std::size_t n = 1; n <= 2; ++n) {
    output.metrics[fmt::format("omega{}_EI1", n)] = relative(family[0][n - 1], ref::cantilever_frequency(n, EI1, rhoS, L));
    output.metrics[fmt::format("omega{}_EI2", n)] = relative(family[1][n - 1], ref::cantilever_frequency(n, EI2, rhoS, L));
    const double k = double(2 * n - 1) * kPi / (2.0 * L);
    output.metrics[fmt::format("omega{}_twist", n)] = relative(family[2][n - 1], k * c_twist);
    const double discrete = 2.0 / ell * c_twist * std::sin(0.5 * k * ell);
    const double omega = family[2][n - 1];
    discrete_twist = std::max(discrete_twist, std::abs(omega * omega - discrete * discrete) / round_off);
    discrete_twist_relative = std::max(discrete_twist_relative, std::abs(omega - discrete) / discrete);
  }
  output.metrics["torsion_discrete"] = value_sample(discrete_twist);
  output.metrics["torsion_discrete_relative"] = diagnostic(discrete_twist_relative);
  output.metrics["mode_mixing"] = diagnostic(mixing);
  double excess = -1.0;  // the largest (omega - exact) / exact: lumped masses put the frequencies below
  for (const auto& [name, sample] : output.metrics)
    if (name.rfind("omega", 0) == 0) excess = std::max(excess, (sample.computed - *sample.reference) / *sample.reference);
  output.metrics["max_relative_excess"] = diagnostic(excess);
  return output;
}

}  // namespace

void add_modes(Registry& registry) {
  const double h = 1.0 / 64.0;
  std::vector<GateSpec> gates;
  std::vector<MetricSpec> metrics;
  // Relative errors measured at N = 64 (default parameters); bounds C h^2 with C = 2 x measured.
  const struct {
    const char* name;
    double measured;
    const char* what;
  } rows[] = {{"omega1_EI1", 3.917e-5, "first bending frequency about m1 (EI1)"},
              {"omega2_EI1", 4.723e-4, "second bending frequency about m1 (EI1)"},
              {"omega1_EI2", 3.917e-5, "first bending frequency about m2 (EI2)"},
              {"omega2_EI2", 4.723e-4, "second bending frequency about m2 (EI2)"},
              {"omega1_twist", 2.550e-5, "first torsional frequency"},
              {"omega2_twist", 2.295e-4, "second torsional frequency"}};
  for (const auto& row : rows) {
    metrics.push_back(error_metric(row.name, "", fmt::format("relative error of the {}", row.what), 2.0, true));
    const bool twist = std::string(row.name).find("twist") != std::string::npos;
    gates.push_back(order_gate(row.name, 2.0,
                               twist ? "spring-mass chain with the free end at a cell face: -(k ebar)^2/24, O(h^2)"
                                     : "lumped masses, vertex curvature, ghost-edge clamp: O(h^2) (measured 2.02)"));
    gates.push_back(measured_bound(row.name, row.measured, h, 2.0));
  }
  metrics.push_back(invariant_metric("torsion_discrete",
                                     "max |omega_twist^2 - omega_d^2| / (eps omega_max^2), omega_d = (2/ebar) sqrt(GJ/rho I0) "
                                     "sin(k ebar/2) the discrete closed form: in units of the eigensolver's round-off"));
  metrics.push_back(diagnostic_metric("torsion_discrete_relative", "max |omega_twist - omega_d| / omega_d"));
  metrics.push_back(diagnostic_metric("mode_mixing", "largest off-family share of a classified mode's kinetic norm"));
  metrics.push_back(diagnostic_metric("max_relative_excess", "max (omega - exact)/exact over the six (< 0: below)"));
  // The discrete torsional spectrum is known in closed form: what is left is the eigensolver's
  // round-off, a backward error of a modest multiple of eps |A|_2 on each eigenvalue (|A|_2 =
  // omega_max^2 = the top bending eigenvalue, ~ 16 EI2/(rho S ebar^4)). Measured <= 0.108 of it
  // (N = 8 .. 256); bound 1. (The same round-off, eps omega_max^2 / omega^2 ~ N^4 eps, reaches
  // 1e-6 relative on omega_1 at N = 256: the bending errors are clean up to N = 128.)
  gates.push_back(upper_bound_gate("torsion_discrete", 1.0, GateScope::AllLevels,
                                   "the discrete torsional frequencies in closed form, to the eigensolver's round-off "
                                   "eps omega_max^2"));
  Case c = make_case(
      "rod3d",
      {"rod3d/modes", "bending and torsional frequencies of a straight cantilever, tilted clamp",
       "Straight inextensible cantilever clamped with a general tilted frame, EI1 != EI2 != GJ, no load; small "
       "oscillations K v = omega^2 M v on the null space of the constraint Jacobian, lumped masses rho S ebar "
       "(half at the tip) and twist inertia rho I0 ebar; modes sorted into families by their kinetic norm.",
       "Euler-Bernoulli cantilever omega_n = (beta_n L)^2 sqrt(EI/(rho S L^4)), 1 + cos(beta L) cosh(beta L) = 0, in "
       "each plane; torsion omega_n = (2n - 1) pi / (2L) sqrt(GJ/(rho I0))",
       "Rayleigh, Theory of Sound; Meirovitch, Fundamentals of Vibrations; ALGORITHMS.md §5",
       "discrete elastic rod linearised about its equilibrium (solvers/rod3d/linearized.hpp): the exact (forward-mode jet) "
       "static Jacobian restricted to the free dofs, projected on the null space of the inextensibility constraints "
       "in the mass metric (column-pivoted QR), dense symmetric eigensolver",
       "rod-3d/modes"},
      {make_parameter("L", 1.3, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("GJ", 0.55, 0.0, 1e12, true, false, "force length^2", "twisting stiffness"),
       make_parameter("EI1", 1.7, 0.0, 1e12, true, false, "force length^2", "bending stiffness about m1"),
       make_parameter("EI2", 3.1, 0.0, 1e12, true, false, "force length^2", "bending stiffness about m2"),
       make_parameter("rhoS", 0.8, 0.0, 1e12, true, false, "mass/length", "line density"),
       make_parameter("rhoI0", 0.07, 0.0, 1e12, true, false, "mass length", "polar mass moment per unit length")},
      element_levels("number of edges", {8, 16, 32, 64}, {8, 16, 32, 64, 128}), std::move(metrics), std::move(gates),
      run);
  require_window(c, fmt::format("eps (omega_max / omega_min)^2 <= {:g} at N = {:g} (EI1, EI2, GJ, rhoS, rhoI0 and L on "
                                "comparable scales)", kMaxEigenRoundOff, kFinestDefaultEdges),
                 check_frequency_spread);
  // torsion_discrete is round-off, whose bits follow the CPU (case.hpp, golden_absolute): 0.069 at N = 64 on one CPU,
  // 0.0062 on another. The goldens hold it to 0.25 (2 x the largest measured, 0.108), below the gate's 1.
  c.golden_absolute["torsion_discrete"] = 0.25;
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

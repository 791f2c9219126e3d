// The Super-Helix family (ALGORITHMS.md §1, PHYSICS.md §1.1, §3.5, §7.1): the 3-D reduced-coordinate
// rod of solvers/superhelix against the closed forms of references/rod3d and references/elastica,
// and the 3-D Noether invariant of invariants/noether3d.
//
//   superhelix/roll-up               dead end moment 2 pi EI / L about a cross-section axis: a
//                                    circle, exact for any N (round-off gates)
//   superhelix/helix-axial-wrench    uniform helix held by an axial wrench, with natural twist:
//                                    exact for any N, H = closed form at every station
//   superhelix/mattiasson-2          the planar Mattiasson cantilever solved in 3-D (rotated clamp):
//                                    second order to the elliptic reference
//   superhelix/clothoid-mattiasson-2 the same on the super-clothoid rod (ALGORITHMS.md §2): fourth
//                                    order (measured)
//   superhelix/heavy-cantilever      naturally curved and twisted cantilever under gravity: H(s)
//                                    constant to the scheme's order, both H forms agree
//   superhelix/clothoid-heavy-cantilever  the same on the super-clothoid rod: H at the nodes O(h^2),
//                                    at the Gauss stations O(h^3) (asymptotic), both forms agree,
//                                    tip at fourth order vs the extrapolated Super-Helix
//   superhelix/modes                 linearised frequencies of a straight cantilever from the full 3N
//                                    eigenproblem, sorted by strain component: bending in both planes
//                                    (EI1 != EI2) vs Euler-Bernoulli, torsion vs (2n - 1) pi/(2L)
//                                    sqrt(GJ/rho I0) and vs its discrete closed form; from above, O(N^-2)
//   superhelix/energy-decay          undamped 3-D swing and twist (rotational inertia, gyroscopic
//                                    terms) under semi-implicit Euler: monotone energy loss of first
//                                    order in h; dense and recursive steps agree
//   superhelix/curl-at-rest          a curl (q = q0) without loads stays exactly at rest
//   superhelix/accelerated-root      a root accelerating at a under gravity g moves the rod as a fixed
//                                    root under g - a (equivalence principle); with a rotating root the
//                                    dense and the linear-time steps agree
//
// Comparison groups: roll-up, helix-axial-wrench, mattiasson-2 (and clothoid-mattiasson-2) and modes
// share the group rod-3d/<problem> with the nodal rod3d case of the same problem, with the same metric
// names where the normalised quantity is the same.
//
// The solver never sees the reference: loads, supports and natural strains are the problem's data.
// The helix case starts Newton from a 10 % perturbation of the helix (the axial-wrench equilibrium
// is not unique; the case checks that the discrete equilibrium IS the helix, not branch selection).
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "case_builder.hpp"
#include "superhelix/superhelix_problems.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/references/elastica.hpp"
#include "rodvv/references/rod3d.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_solution.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::harness {

namespace superhelix_cases {
const char* const kMethod =
    "Super-Helix (Bertails et al. 2006): piecewise-constant twist and curvatures, closed-form helical "
    "elements (singularity-free exponential form); statics by Newton (exact Jacobian, "
    "line search, load stepping); Gauss-Legendre mass quadrature (4 points per element) of the translational "
    "and rotational inertia of the cross-sections";
}  // namespace superhelix_cases

namespace {

namespace ref = rodvv::references;
namespace sh = rodvv::solvers::superhelix;
constexpr double kPi = std::numbers::pi;
constexpr double kEps = 2.220446049250313e-16;

using superhelix_cases::kMethod;

// The shared case builder (case_builder.hpp): samples, metric specs, measured bounds, the tilted
// clamp frame and the 3-D Noether metrics.
using cases::add_noether3d_metrics;
using cases::diagnostic;
using cases::diagnostic_metric;
using cases::element_count;
using cases::error_metric;
using cases::error_sample;
using cases::helix_turns;
using cases::invariant_metric;
using cases::measured_bound;
using cases::noether3d_metric_specs;
using cases::tilted_frame;
using cases::value_sample;

Parameter length_parameter(double value) {
  return make_parameter("L", value, 0.0, 1e6, true, false, "length", "rod length");
}
// Units (issue 13, class 3). The roll-up, cantilever and curl cases run at L = 1.7 and EI = 2.3, not 1,
// so that a solver mixing up L, EI or their powers is wrong by O(1), and report lengths over L (and H
// relative to its scale): their results do not depend on L and EI, which are unit scales (case_info.hpp:
// Parameter::unit_scale), so their measured bounds (measured at L = EI = 1) hold at any L and EI.
constexpr double kDefaultLength = 1.7;
constexpr double kDefaultStiffness = 2.3;
Parameter unit_length_parameter() {
  Parameter p = length_parameter(kDefaultLength);
  p.unit_scale = true;
  return p;
}
// unit_scale false: a case whose load is physical (superhelix/heavy-cantilever's weight w).
Parameter stiffness_parameter(bool unit_scale = true) {
  Parameter p = make_parameter("EI", kDefaultStiffness, 0.0, 1e12, true, false, "force length^2",
                               "bending stiffness (both axes)");
  p.unit_scale = unit_scale;
  return p;
}

Case make_case(std::string name, std::string title, std::string physics, std::string reference,
               std::string citation, Parameters parameters, Resolution resolution,
               std::vector<MetricSpec> metrics, std::vector<GateSpec> gates, LevelRunner runner) {
  return cases::make_case("superhelix",
                          {std::move(name), std::move(title), std::move(physics), std::move(reference),
                           std::move(citation), kMethod},
                          std::move(parameters), std::move(resolution), std::move(metrics), std::move(gates),
                          std::move(runner));
}

// Cases of the same problem as a nodal rod3d case share its comparison group (the report overlays
// them); their metrics carry the nodal case's names where the normalised quantity is the same.
Case in_group(Case c, std::string group) {
  c.info.group = std::move(group);
  return c;
}

Resolution elements(std::vector<double> levels, std::vector<double> extended) {
  return {"N", "number of helical elements", ResolutionScale::Count, std::move(levels), std::move(extended)};
}

// ---- roll-up -------------------------------------------------------------------------------------

LevelOutput run_roll_up(const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
  const double turns = parameter_value(p, "turns"), beta = parameter_value(p, "axis_angle_deg") * kPi / 180.0;
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(0.7 * EI, EI, EI);
  model.root_frame = tilted_frame(0.9);
  model.root_position = Vec3(0.2, -0.1, 0.4) * L;  // scaled with L: the problem is self-similar in L
  const Vec3 axis = std::cos(beta) * model.root_frame.col(1) + std::sin(beta) * model.root_frame.col(2);
  const double M = turns * 2.0 * kPi * EI / L;
  model.end_moment = M * axis;
  sh::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-14;  // an exact case: iterate to the round-off floor
  const auto result = sh::solve_static(model, options);
  const SpatialRodSolution solution = sh::make_solution(model, result.q);

  ref::EndMomentRollUp rod;
  rod.L = L;
  rod.EI = EI;
  rod.M = M;
  rod.root_position = model.root_position;
  rod.tangent = model.root_frame.col(0);
  rod.axis = axis;
  double shape = 0.0;
  for (std::size_t i = 0; i < solution.vertex_s.size(); ++i)
    shape = std::max(shape, (solution.vertex_position[i] - ref::end_moment_roll_up_point(rod, solution.vertex_s[i]).position).norm());
  LevelOutput output;
  output.metrics["shape_max_error"] = value_sample(shape / L, 1.0);
  // |r(L) - r(0)| / L against the closed form's (0 for a full turn): the nodal rod3d/roll-up's metric
  output.metrics["tip_gap"] = error_sample((solution.vertex_position.back() - model.root_position).norm() / L,
                                           (ref::end_moment_roll_up_point(rod, L).position - model.root_position).norm() / L);
  output.metrics["tip_gap"].scale = 1.0;  // in units of L (the closed form's gap is 0 for a full turn)
  output.metrics["newton_iterations"] = diagnostic(double(result.iterations));
  add_noether3d_metrics(output, solution, ref::end_moment_roll_up_invariant(rod));
  return output;
}

// ---- helix under an axial wrench -----------------------------------------------------------------

// The helix is exact for any N, so its errors are round-off: Newton stops where the residual is at its
// tolerance, 1e-14 of the residual scale max(K_max |q|, K_max / L, |F_ext|) (newton.cpp), or, when the line
// search stalls at the floor, up to 1e3 times that: 1e-11, 4.5e4 eps. A relative residual r is an error
// of the order of r times the problem's conditioning: the stiffness ratio max(B/C, C/B) (a moment residual
// is a strain error over the softer stiffness), 1 + |M_t| R / B (the twisting moment against the bending
// moments), 1 / (2 pi turns) when the helix is short (the scale's K_max / L term is then larger than
// K_max |u| by 1 / (L |u|)), and the turns beyond one (frame and position errors accumulate along the
// rod). The gate: every error <= 1e5 of these eps units (twice the floor rule's 4.5e4); measured over 300
// random parameter sets in the window below (2026-11-26): <= 4.4e3 (at the defaults 2 .. 8), while a
// Newton that reaches another equilibrium than the helix gives >= 1e11. The former fixed 1e-12 failed at
// C/B = 2.9e-3 or 150, at 9 turns, at tiny turns with C/B = 100. Window: the turns, stiffness ratio and
// twisting moment in which Newton from the 0.1 % start reaches THE helix: turns in [1e-3, 2], C/B in
// [0.03, 100] (at 0.015, 1.8e-4 .. 1.3e-3 it reached another equilibrium or failed), |M_t| R/B <= 10
// (33 .. 98 failed). Inside it, 1 of 300 random sets still fails, rightly: at N = 4 Newton settles on
// another equilibrium of the 4-element rod (strain error 0.045; B = 13.6, C = 19.6, R = 21.2, pitch
// 1.235, L = 100.3, M_t = -1.51), which the gate reports.
constexpr const char* kHelixRoundOffMetrics[] = {"shape_max_error", "frame_max_error", "strain_max_error",
                                                 "H_spread",        "H_mean",          "H_form_difference"};
constexpr double kHelixRoundOffUnits = 1e5;
double helix_round_off_unit(const Parameters& p) {
  const double B = parameter_value(p, "B"), C = parameter_value(p, "C"), turns = helix_turns(p);
  const double moment = std::abs(parameter_value(p, "twisting_moment")) * parameter_value(p, "radius") / B;
  return std::max({1.0, B / C, C / B}) * (1.0 + moment) * std::max({1.0, turns, 1.0 / (2.0 * kPi * turns)});
}
void require_helix_round_off_window(Case& c) {
  cases::require(c, cases::helix_turns_window(1e-3, 2.0, "beyond, Newton from its start may reach another "
                                                         "equilibrium than the helix"));
  require_window(c, "|twisting_moment| x radius / B <= 10", [](const Parameters& p) {
    const double moment = parameter_value(p, "twisting_moment") * parameter_value(p, "radius") / parameter_value(p, "B");
    if (!(std::abs(moment) <= 10.0))
      throw InputError("twisting_moment", fmt::format("invalid parameters: |twisting_moment| x radius / B = {} must "
                                                      "be <= 10",
                                                      format_value(std::abs(moment))));
  });
  cases::require(c, cases::ratio_window("C", "B", 0.03, 100.0, "the twist-to-bending ratios Newton reaches the helix at"));
}

LevelOutput run_helix(const Parameters& p, double level) {
  const ref::AxialWrenchHelix helix{parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "radius"),
                                    parameter_value(p, "pitch_angle"), parameter_value(p, "twisting_moment")};
  const double L = parameter_value(p, "L");
  const auto exact = ref::axial_wrench_helix(helix);
  const auto root = ref::axial_wrench_helix_point(helix, 0.0), tip = ref::axial_wrench_helix_point(helix, L);
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(helix.C, helix.B, helix.B);
  model.natural_strain = Vec3(exact.natural_twist, 0.0, 0.0);
  model.root_position = root.position;
  model.root_frame = root.frame;
  model.end_force = tip.force;   // the axial wrench, applied as a dead end force ...
  model.end_moment = tip.moment;  // ... and the end moment m(L) that it carries
  sh::StaticOptions options;
  options.tolerance = 1e-14;  // an exact case: iterate to the round-off floor
  options.initial_q = VecX::Zero(static_cast<Eigen::Index>(3 * model.elements));
  // Newton starts 0.1 % off the exact strains, divided by the helix's turns beyond one (it must iterate
  // to THE helix: 3 to 9 steps). From 10 % it left its basin on longer or tighter helices (L = 13, 14,
  // 20; radius 0.3; M_t = 100: line search failed at N = 8) although the helix is the equilibrium there;
  // from 1 % it reached another equilibrium of N = 4 elements (strain error 0.03) in 2 of 300 random
  // parameter sets with less than one turn, from 0.1 % in 1 of 300 (check_helix_round_off_window).
  const double offset = 0.001 / std::max(1.0, helix_turns(p));
  for (std::size_t e = 0; e < model.elements; ++e)
    options.initial_q.segment<3>(3 * e) = (1.0 - offset) * Vec3(exact.tau, exact.kappa, 0.0);
  const auto result = sh::solve_static(model, options);
  const SpatialRodSolution solution = sh::make_solution(model, result.q);
  double shape = 0.0, frame = 0.0, strain = 0.0;
  for (std::size_t i = 0; i < solution.vertex_s.size(); ++i) {
    const auto point = ref::axial_wrench_helix_point(helix, solution.vertex_s[i]);
    shape = std::max(shape, (solution.vertex_position[i] - point.position).norm());
    frame = std::max(frame, (solution.vertex_frame[i] - point.frame).cwiseAbs().maxCoeff());
  }
  for (const auto& u : solution.strain_u) strain = std::max(strain, (u - Vec3(exact.tau, exact.kappa, 0.0)).cwiseAbs().maxCoeff());
  LevelOutput output;
  output.metrics["shape_max_error"] = value_sample(shape / L, 1.0);
  output.metrics["frame_max_error"] = value_sample(frame, 1.0);  // radians
  output.metrics["strain_max_error"] = value_sample(strain / exact.darboux, 1.0);
  output.metrics["newton_iterations"] = diagnostic(double(result.iterations));
  add_noether3d_metrics(output, solution, exact.H);
  // The helix is exact for any N: every error is round-off, in units of eps times the problem's
  // conditioning (check_helix_round_off_window).
  const double unit = kEps * helix_round_off_unit(p);
  double worst = 0.0;
  for (const char* name : kHelixRoundOffMetrics) worst = std::max(worst, gated_value(output.metrics.at(name)) / unit);
  output.metrics["roundoff_units"] = value_sample(worst);
  std::vector<double> x, y, xr, yr;
  for (std::size_t i = 0; i < solution.vertex_s.size(); ++i) {
    x.push_back(solution.vertex_position[i].x());
    y.push_back(solution.vertex_position[i].z());
  }
  for (int i = 0; i <= 200; ++i) {
    const auto point = ref::axial_wrench_helix_point(helix, L * i / 200.0);
    xr.push_back(point.position.x());
    yr.push_back(point.position.z());
  }
  output.series.push_back(thin_series("helix (x, z)|computed vertices", "x", "z", x, y));
  output.series.push_back(thin_series("helix (x, z)|closed form", "x", "z", xr, yr));
  return output;
}

// ---- Mattiasson cantilever in 3-D ------------------------------------------------------------

// The rotated-clamp cantilever shared by the Super-Helix and super-clothoid cases: clamp tangent
// horizontal but rotated about the vertical by 30 deg, cross-section rolled by 40 deg, so the load
// -P e_z bends the rod in a vertical plane that is no coordinate plane of the material frame (both
// bending strains and the twist are unknowns).
struct RotatedClampCantilever {
  sh::RodModel model;
  sh::StaticOptions options;
  ref::CantileverTip tip;  // closed form (planar Mattiasson)
};

RotatedClampCantilever rotated_clamp_cantilever(const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), alpha = parameter_value(p, "alpha");
  const ref::TipLoadedCantilever cantilever{L, EI, alpha * EI / (L * L)};
  const Mat3 yaw = Eigen::AngleAxisd(kPi / 6, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 roll = Eigen::AngleAxisd(40.0 * kPi / 180.0, Vec3::UnitX()).toRotationMatrix();
  RotatedClampCantilever problem{{}, {}, ref::cantilever_tip(cantilever)};
  problem.model.elements = element_count(level);
  problem.model.length = L;
  problem.model.stiffness = Vec3(0.8 * EI, EI, EI);
  problem.model.root_frame = yaw * roll;
  problem.model.end_force = Vec3(0.0, 0.0, -cantilever.P);
  problem.options.load_steps = alpha > 3.0 ? 4 : 2;
  return problem;
}

// Tip displacements and rotation in the loading plane against the closed form, and the
// out-of-plane drift, from the tip position and frame of either rod.
LevelOutput rotated_clamp_tip_metrics(const RotatedClampCantilever& problem, const Vec3& tip_position,
                                      const Mat3& tip_frame, std::size_t iterations) {
  const double L = problem.model.length;
  const Vec3 t0 = problem.model.root_frame.col(0);
  const Vec3 r = tip_position - problem.model.root_position;
  const Vec3 t = tip_frame.col(0);
  LevelOutput output;
  output.metrics["tip_w"] = error_sample(-r.z() / L, problem.tip.w / L);
  output.metrics["tip_u"] = error_sample((L - r.dot(t0)) / L, problem.tip.u / L);
  output.metrics["tip_phi"] = error_sample(std::atan2(-t.z(), t.dot(t0)), problem.tip.phi_L);
  output.metrics["out_of_plane"] = value_sample(std::abs(r.dot(Vec3::UnitZ().cross(t0))) / L);
  output.metrics["newton_iterations"] = diagnostic(double(iterations));
  return output;
}

LevelOutput run_mattiasson(const Parameters& p, double level) {
  const auto problem = rotated_clamp_cantilever(p, level);
  const auto result = sh::solve_static(problem.model, problem.options);
  const sh::Kinematics kin(problem.model, result.q);
  return rotated_clamp_tip_metrics(problem, kin.tip_position(), kin.tip_frame(), result.iterations);
}

// ---- Mattiasson cantilever in 3-D, super-clothoid ------------------------------------------------

// The same problem on the super-clothoid rod: continuous, piecewise-affine strains
// (ALGORITHMS.md §2), q = nodal strains.
LevelOutput run_clothoid_mattiasson(const Parameters& p, double level) {
  const auto problem = rotated_clamp_cantilever(p, level);
  const auto result = sh::solve_clothoid_static(problem.model, problem.options);
  const sh::ClothoidKinematics kin(problem.model, result.q, false);
  return rotated_clamp_tip_metrics(problem, kin.tip_position(), kin.tip_frame(), result.iterations);
}

// ---- heavy cantilever: H(s) ----------------------------------------------------------------------

// The heavy cantilever shared by the Super-Helix and super-clothoid cases, under its weight w (= rho S g)
// per unit length.
sh::RodModel heavy_cantilever_model(const Parameters& p, double level, double w) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(0.6 * EI, EI, 1.4 * EI);
  model.natural_strain = Vec3(0.8, 1.2, -0.5) / L;
  model.root_frame = tilted_frame(0.4);
  model.line_density = 1.0;
  model.gravity = Vec3(0.0, 0.0, -w);
  return model;
}

// The heavy cantilever's weight parameter w L^3 / EI (w = rho S g per unit length).
double heavy_weight_parameter(const Parameters& p) {
  const double L = parameter_value(p, "L");
  return parameter_value(p, "w") * L * L * L / parameter_value(p, "EI");
}

LevelOutput run_heavy(const Parameters& p, double level) {
  const sh::RodModel model = heavy_cantilever_model(p, level, parameter_value(p, "w"));
  sh::StaticOptions options;
  options.load_steps = 2;
  const auto result = sh::solve_static(model, options);
  const SpatialRodSolution solution = sh::make_solution(model, result.q);
  LevelOutput output;
  add_noether3d_metrics(output, solution, std::nullopt);
  output.metrics["newton_iterations"] = diagnostic(double(result.iterations));
  output.metrics["tip_z"] = diagnostic(solution.vertex_position.back().z() / model.length);
  return output;
}

// ---- heavy cantilever on the super-clothoid rod: H(s) and the tip ---------------------------------

// Tip of the heavy cantilever (root at the origin): the Super-Helix (second order, an independent rod
// model) at N = 128, 256, 512 (tolerance 1e-14), extrapolated twice (h^2 then h^4 Richardson). At
// weight = 3 the stored result (per unit L; the last correction 5e-13, 2026-11-21); at other weights
// computed live (~0.15 s). The super-clothoid at N = 64, its finest default level, agrees to 4.7e-10
// (its O(h^4) error), 1e3 times the reference's.
const Vec3 kHeavyTipAtWeight3(0.65485121488338932, 0.21774040484668871, -0.57684254917621921);

Vec3 heavy_tip_reference(const Parameters& p) {
  const double L = parameter_value(p, "L");
  if (std::abs(heavy_weight_parameter(p) - 3.0) <= 3e-13) return L * kHeavyTipAtWeight3;
  Vec3 tips[3];
  for (int i = 0; i < 3; ++i) {
    const sh::RodModel model = heavy_cantilever_model(p, 128.0 * (1 << i), parameter_value(p, "w"));
    sh::StaticOptions options;
    options.load_steps = 2;
    options.tolerance = 1e-14;
    tips[i] = sh::Kinematics(model, sh::solve_static(model, options).q).tip_position();
  }
  const Vec3 coarse = (4.0 * tips[1] - tips[0]) / 3.0, fine = (4.0 * tips[2] - tips[1]) / 3.0;
  return (16.0 * fine - coarse) / 15.0;
}

LevelOutput run_clothoid_heavy(const Parameters& p, double level) {
  const sh::RodModel model = heavy_cantilever_model(p, level, parameter_value(p, "w"));
  const auto result = sh::solve_clothoid_static(model, sh::StaticOptions{});
  // H sampled at the nodes (the degrees of freedom): the nodal strains are the L2 projection of the
  // moment, O(h^2) pointwise; at the Gauss stations (the solution struct's default) the strain
  // superconverges and H is O(h^3) asymptotically (clothoid_solution.hpp).
  const SpatialRodSolution nodes = sh::make_clothoid_solution(model, result.q, sh::ClothoidStations::Nodes);
  const SpatialRodSolution gauss = sh::make_clothoid_solution(model, result.q, sh::ClothoidStations::Gauss);
  LevelOutput output;
  add_noether3d_metrics(output, nodes, std::nullopt);
  const auto at_gauss = invariants::noether3d_summary(gauss);
  output.metrics["H_spread_gauss"] = value_sample(at_gauss.spread / std::max(at_gauss.scale, 1e-300));
  auto& forms = output.metrics["H_form_difference"];
  forms = value_sample(std::max(*forms.error, at_gauss.form_difference / std::max(at_gauss.scale, 1e-300)));
  const auto at_midpoints =
      invariants::noether3d_summary(sh::make_clothoid_solution(model, result.q, sh::ClothoidStations::Midpoints));
  output.metrics["H_spread_midpoints"] = diagnostic(at_midpoints.spread / std::max(at_midpoints.scale, 1e-300));
  output.series.push_back(thin_series("H(s)|compact, Gauss stations", "s", "H", gauss.s, invariants::noether3d_compact(gauss)));
  const Vec3 reference = heavy_tip_reference(p);
  const Vec3 tip = nodes.vertex_position.back() - model.root_position;
  output.metrics["tip_error"] = {tip.norm(), reference.norm(), (tip - reference).norm() / model.length, 1.0};  // in L
  const char* component[3] = {"tip_x", "tip_y", "tip_z"};
  for (int i = 0; i < 3; ++i) output.metrics[component[i]] = error_sample(tip[i] / model.length, reference[i] / model.length);
  output.metrics["newton_iterations"] = diagnostic(double(result.iterations));
  return output;
}

// ---- linearised frequencies ----------------------------------------------------------------------

// A mode belongs to a family (twist, kappa1, kappa2 coordinates) when all but this fraction of its
// kinetic norm lies there. The families decouple exactly on the straight rod; the tilted clamp mixes
// them at round-off only.
constexpr double kModePurity = 1e-6;
constexpr std::size_t kBendingModes = 3, kTwistModes = 2;

// Small oscillations of the straight, tilted cantilever (the data of rod3d/modes): every mode of the
// full 3N eigenproblem (sh::straight_rod_modes), sorted into bending about n1 (kappa1, EI1), bending
// about n2 (kappa2, EI2) and torsion (twist) by where its eigenvector lives. Rotary inertia of the
// bending (rho I1 = rho I2) is 0 so that the reference is Euler-Bernoulli in each plane; rho I0 > 0
// carries the torsion. The twist part is a linear finite element bar with consistent mass (the angle
// is continuous and piecewise linear, its kinetic energy integrated exactly by the 4-point Gauss rule),
// whose clamped-free modes are sin(k s) at the nodes with the continuous k = (2n - 1) pi / (2L) and
// omega_d^2 = (6 c^2 / ell^2) (1 - cos k ell) / (2 + cos k ell), c^2 = GJ / rho I0: relative error
// (k ell)^2 / 24 + O(ell^4), from above (gated to round-off as torsion_discrete_relative).
// The eigensolver's relative error on a mode, eps (omega_k / omega_min)^2 (straight_rod_modes), must stay
// far below the smallest discretisation error the sweep measures at the finest default level (the first
// torsional mode, relative (k ell)^2 / 24 = 2.5e-5 at N = 64) for the orders to mean anything: at most
// 1 % of it. Closed forms give omega_min (the lowest of the three families) and the highest mode the
// case classifies (the third bending mode of the stiffer plane or the second torsional mode). Defaults:
// 1.2e-13. GJ, EI1, EI2, rhoS or rhoI0 = 1e12 put it at 3e-3 .. 1.4 (before: twist orders 1.8, or
// every level failed on a mode lost to round-off).
constexpr double kMaxModeRoundOff = 2.5e-7;
void check_mode_spread(const Parameters& p) {
  const double L = parameter_value(p, "L"), GJ = parameter_value(p, "GJ"), EI1 = parameter_value(p, "EI1"),
               EI2 = parameter_value(p, "EI2"), rhoS = parameter_value(p, "rhoS"), rhoI0 = parameter_value(p, "rhoI0");
  const double twist_speed = std::sqrt(GJ / rhoI0);
  const double twist_low = kPi / (2.0 * L) * twist_speed, twist_high = 3.0 * twist_low;
  const double bending_low = ref::cantilever_frequency(1, std::min(EI1, EI2), rhoS, L);
  const double bending_high = ref::cantilever_frequency(kBendingModes, std::max(EI1, EI2), rhoS, L);
  const double low = std::min(twist_low, bending_low), high = std::max(twist_high, bending_high);
  const double round_off = kEps * (high / low) * (high / low);
  if (!(round_off <= kMaxModeRoundOff))
    throw InputError(twist_high >= bending_high ? "GJ" : (EI1 >= EI2 ? "EI1" : "EI2"),
                     fmt::format("invalid parameters: the modes the case measures spread over (omega_high / "
                                 "omega_min)^2 = {} (omega_high from {}, omega_min from {}), so the eigensolver's "
                                 "round-off on them, eps x that = {}, exceeds {} (1 % of the finest level's smallest "
                                 "discretisation error); bring EI1, EI2, GJ, rhoS, rhoI0 and L closer to each other's "
                                 "scales",
                                 format_value((high / low) * (high / low)),
                                 twist_high >= bending_high ? "torsion (GJ / rhoI0)" : "bending (EI / rhoS)",
                                 twist_low <= bending_low ? "torsion" : "bending", format_value(round_off),
                                 format_value(kMaxModeRoundOff)));
}

LevelOutput run_modes(const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), GJ = parameter_value(p, "GJ"), EI1 = parameter_value(p, "EI1"),
               EI2 = parameter_value(p, "EI2"), rhoS = parameter_value(p, "rhoS"), rhoI0 = parameter_value(p, "rhoI0");
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = L;
  model.stiffness = Vec3(GJ, EI1, EI2);
  model.line_density = rhoS;
  model.rotational_inertia = Vec3(rhoI0, 0.0, 0.0);
  model.root_frame = tilted_frame(0.7);
  model.root_position = Vec3(0.2, 0.4, -0.1) * L;
  const sh::StraightRodModes modes = sh::straight_rod_modes(model);

  // family 0: torsion (twist), 1: bending about n1 (kappa1, EI1), 2: about n2 (kappa2, EI2)
  const std::size_t wanted[3] = {kTwistModes, kBendingModes, kBendingModes};
  std::vector<double> family[3];
  double mixing = 0.0;
  for (Eigen::Index k = 0; k < modes.frequencies.size(); ++k) {
    if (family[0].size() >= wanted[0] && family[1].size() >= wanted[1] && family[2].size() >= wanted[2]) break;
    Eigen::Index f = 0;
    const double share = modes.component_share.col(k).maxCoeff(&f);
    if (share < 1.0 - kModePurity)
      throw SolverError("superhelix modes",
                        fmt::format("mode {} (omega = {:.6g}) lives in no single strain component (largest share {:.6g}): "
                                    "near-degenerate frequencies of different families; change EI1, EI2, GJ or rho I0",
                                    k + 1, modes.frequencies[k], share),
                        0, 1.0 - share);
    mixing = std::max(mixing, 1.0 - share);
    if (family[f].size() < wanted[f]) family[f].push_back(modes.frequencies[k]);
  }
  for (int f = 0; f < 3; ++f)
    if (family[f].size() < wanted[f])
      throw InputError("N", fmt::format("invalid parameter 'N' = {}: too few elements for {} modes of each bending "
                                        "plane and {} torsional modes", model.elements, kBendingModes, kTwistModes));

  LevelOutput output;
  double smallest_excess = 1.0;
  const auto relative = [&](const std::string& name, double computed, double exact) {
    const double excess = (computed - exact) / exact;
    output.metrics[name] = {computed, exact, std::abs(excess), 1.0};  // a relative error: size 1
    smallest_excess = std::min(smallest_excess, excess);
  };
  for (std::size_t n = 1; n <= kBendingModes; ++n) {
    relative(fmt::format("omega{}_EI1", n), family[1][n - 1], ref::cantilever_frequency(n, EI1, rhoS, L));
    relative(fmt::format("omega{}_EI2", n), family[2][n - 1], ref::cantilever_frequency(n, EI2, rhoS, L));
  }
  const double ell = sh::element_length(model), c_twist = std::sqrt(GJ / rhoI0);
  // The round-off a torsional frequency can carry: the eigensolver works on 1/omega^2, so its backward
  // error eps / omega_min^2 is a relative error eps (omega_k / omega_min)^2 on omega_k^2 (large when
  // the twist is much stiffer than the bending, as for long rods: omega_twist / omega_bend ~ L); the
  // assembly of M adds ~ N^2 eps (measured 1.2e-15 at N = 8, 4.9e-14 at 64, 2.5e-13 at 128).
  const double omega_min = modes.frequencies.minCoeff();
  const auto round_off = [&](double omega) {
    return kEps * (double(model.elements * model.elements) + std::pow(omega / omega_min, 2));
  };
  double discrete_twist = 0.0, discrete_twist_roundoff = 0.0;
  for (std::size_t n = 1; n <= kTwistModes; ++n) {
    const double k = double(2 * n - 1) * kPi / (2.0 * L), omega = family[0][n - 1];
    relative(fmt::format("omega{}_twist", n), omega, k * c_twist);
    const double discrete_squared =
        6.0 * c_twist * c_twist / (ell * ell) * (1.0 - std::cos(k * ell)) / (2.0 + std::cos(k * ell));
    const double error = std::abs(omega / std::sqrt(discrete_squared) - 1.0);
    discrete_twist = std::max(discrete_twist, error);
    discrete_twist_roundoff = std::max(discrete_twist_roundoff, error / round_off(omega));
  }
  // Rayleigh-Ritz: every discrete frequency lies above the continuous one.
  output.metrics["min_relative_excess"] = diagnostic(smallest_excess);
  output.metrics["torsion_discrete_relative"] = diagnostic(discrete_twist);
  output.metrics["torsion_discrete_roundoff"] = value_sample(discrete_twist_roundoff);
  output.metrics["mode_mixing"] = diagnostic(mixing);
  // The kappa1 block alone (sh::bending_frequencies, the restricted eigenproblem) vs the EI1 family of
  // the full one: the same modes, up to the round-off of the two reductions.
  const VecX restricted = sh::bending_frequencies(model, kBendingModes);
  // The same round-off model as for the torsion above (when the bending is much stiffer than the
  // twist, as for short rods, omega_bend / omega_min is large).
  double paths = 0.0, paths_roundoff = 0.0;
  for (std::size_t n = 0; n < kBendingModes; ++n) {
    const double difference = std::abs(restricted[static_cast<Eigen::Index>(n)] / family[1][n] - 1.0);
    paths = std::max(paths, difference);
    paths_roundoff = std::max(paths_roundoff, difference / round_off(family[1][n]));
  }
  output.metrics["restricted_vs_full"] = diagnostic(paths);
  output.metrics["restricted_vs_full_roundoff"] = value_sample(paths_roundoff);
  return output;
}

// ---- dynamics: energy decay, dense vs recursive ---------------------------------------------------

// A genuinely 3-D release: a twisted, curved rod (natural strains (0.5, 0, 1.2)/L) with anisotropic
// stiffness GJ != EI1 != EI2 and a solid elliptic section (semi-axes L/7 along n1, 0.6 L/7 along n2:
// rho I0 = rho I1 + rho I2, rho I1 != rho I2), clamped in a tilted frame, under gravity along a
// direction in none of the rod's planes, started from its natural shape with strain rates in all
// three components (twist, kappa1, kappa2): it swings and twists out of plane.
// J_scale multiplies the rotational inertia (0: the translational-only Super-Helix, whose twist is
// nearly massless: it gains energy at some steps, test FreeMotionWithoutRotationalInertiaGainsEnergy).
sh::RodModel energy_model(const Parameters& p) {
  return superhelix_cases::energy_release_model(element_count(parameter_value(p, "N")), p,
                                                parameter_value(p, "J_scale"));
}

// The level is dt / tau; the step is t_end / round(t_end / dt), so that every level ends at t_end.
LevelOutput run_energy(const Parameters& p, double dt_over_tau) {
  const double t_end = parameter_value(p, "t_end");
  const sh::RodModel model = energy_model(p);
  const auto steps = static_cast<std::size_t>(
      std::max(1.0, std::round(t_end / (dt_over_tau * cases::bending_time(p, "EI1")))));
  const double dt = t_end / double(steps);
  const auto dofs = static_cast<Eigen::Index>(3 * model.elements);
  sh::DynamicState state{sh::natural_strain_vector(model), VecX::Zero(dofs), 0.0};
  const Vec3 rates = superhelix_cases::energy_release_rates(p);
  for (std::size_t e = 0; e < model.elements; ++e) state.qdot.segment<3>(static_cast<Eigen::Index>(3 * e)) = rates;
  const VecX stiffness = sh::generalised_stiffness(model);
  const double e0 = sh::total_energy(model, state);
  superhelix_cases::EnergyLedger ledger(e0);
  double worst_residual = 0.0, worst_forward = 0.0;
  double rotational_share = 0.0;
  for (std::size_t i = 0; i < steps; ++i) {
    const VecX dense = sh::velocity_change(model, state, dt, sh::DynamicsPath::Dense);
    const VecX fast = sh::velocity_change(model, state, dt, sh::DynamicsPath::Recursive);
    // Same linear system (M + D) dv = b: the recursive dv's relative residual in the dense system
    // (backward error, independent of the conditioning), and the forward relative difference
    // (bounded by cond(M + D) eps; M is positive definite with the rotational inertia).
    const sh::Kinematics kinematics(model, state.q);
    MatX system = sh::mass_matrix(model, kinematics);
    system.diagonal() += (dt * dt + dt * model.rayleigh_stiffness) * stiffness;
    worst_residual = std::max(worst_residual, (system * (dense - fast)).norm() / (system * dense).norm());
    worst_forward = std::max(worst_forward, (dense - fast).lpNorm<Eigen::Infinity>() /
                                                std::max(dense.lpNorm<Eigen::Infinity>(), 1e-300));
    const double kinetic = sh::kinetic_energy(model, kinematics, state.qdot);
    if (kinetic > 0.0)
      rotational_share = std::max(rotational_share, sh::rotational_kinetic_energy(model, kinematics, state.qdot) / kinetic);
    // The step itself is the production step (its recursive dv is `fast` again, recomputed).
    state = sh::step(model, state, dt, sh::DynamicsPath::Recursive);
    ledger.record(state.time, sh::total_energy(model, state));
  }
  LevelOutput output;
  // The exact flow conserves E: the loss E(0) - E(t_end) is the error, O(h) for this scheme.
  ledger.add_to(output);
  output.metrics["dense_vs_recursive"] = value_sample(worst_residual);
  output.metrics["dense_vs_recursive_forward"] = diagnostic(worst_forward);
  output.metrics["rotational_kinetic_share"] = diagnostic(rotational_share);
  return output;
}

// The rod's stiffnesses and line density from the parameters (GJ != EI1 != EI2).
void set_section(sh::RodModel& model, const Parameters& p) {
  model.line_density = parameter_value(p, "rhoS");
  model.stiffness = Vec3(parameter_value(p, "GJ"), parameter_value(p, "EI1"), parameter_value(p, "EI2"));
}

// 100 steps of 0.01 tau (tau = L^2 sqrt(rhoS / EI1)): at rest every force vanishes, whatever the step.
LevelOutput run_curl(const Parameters& p, double level) {
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = parameter_value(p, "L");
  set_section(model, p);
  model.natural_strain = Vec3(2.0, 5.0, -3.0) / model.length;  // a tight curl
  model.root_frame = tilted_frame(1.1);
  sh::DynamicState state{sh::natural_strain_vector(model), VecX::Zero(static_cast<Eigen::Index>(3 * model.elements)), 0.0};
  const VecX q0 = state.q;
  const double dt = 0.01 * cases::bending_time(p, "EI1");
  for (int i = 0; i < 100; ++i) {
    state = sh::step(model, state, dt, i % 2 ? sh::DynamicsPath::Dense : sh::DynamicsPath::Recursive);
  }
  LevelOutput output;
  output.metrics["max_drift"] = value_sample((state.q - q0).lpNorm<Eigen::Infinity>() + state.qdot.lpNorm<Eigen::Infinity>());
  return output;
}

// A curved, damped rod under gravity, released from a bent, moving state: 100 steps of h = 1e-3.
// (1) Root accelerating at a (no rotation) under g vs a fixed root under g - a, both linear-time:
//     the root enters the bias only through m (zeta + a - g), so the two agree to the rounding of
//     that sum, accumulated over the steps. (2) Root accelerating and spinning up about a tilted
//     axis: dense vs linear-time dv at every step.
LevelOutput run_accelerated_root(const Parameters& p, double level) {
  sh::RodModel model;
  model.elements = element_count(level);
  model.length = parameter_value(p, "L");
  set_section(model, p);
  model.natural_strain = Vec3(0.5, -1.0, 2.0) / model.length;
  // the rotational inertia of a solid elliptic section (semi-axes 0.02, 0.012) of this density
  model.rotational_inertia = sh::elliptic_section_inertia(model.line_density, 0.02, 0.012);
  model.gravity = Vec3(0.0, 0.0, -parameter_value(p, "g"));
  model.rayleigh_stiffness = 0.01;
  model.root_frame = tilted_frame(0.4);
  const Vec3 a(1.5, -0.7, 3.0);
  const auto n = static_cast<Eigen::Index>(sh::dof_count(model));
  const sh::DynamicState start{sh::natural_strain_vector(model) + VecX::Constant(n, 0.3), VecX::LinSpaced(n, -0.5, 0.5), 0.0};
  constexpr int kSteps = 100;
  constexpr double h = 1e-3;

  sh::RodModel equivalent = model;
  equivalent.gravity = model.gravity - a;
  const sh::RootMotion accelerating = sh::uniformly_accelerated_root(model, Vec3::Zero(), a);
  sh::DynamicState moving = start, fixed = start;
  double equivalence = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    moving = sh::step(model, moving, h, sh::DynamicsPath::Recursive, accelerating);
    fixed = sh::step(equivalent, fixed, h, sh::DynamicsPath::Recursive);
    equivalence = std::max(equivalence, (moving.q - fixed.q).lpNorm<Eigen::Infinity>() /
                                            std::max(1.0, fixed.q.lpNorm<Eigen::Infinity>()));
  }

  const sh::RootMotion spinning =
      sh::uniformly_accelerated_root(model, Vec3(0.2, 0.0, 0.0), a, Vec3(1.0, 1.0, 2.0).normalized(), 1.0, 5.0);
  sh::DynamicState state = start;
  const VecX damping = (h * h + h * model.rayleigh_stiffness) * sh::generalised_stiffness(model);
  double paths = 0.0, forward = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const VecX dense = sh::velocity_change(model, state, h, sh::DynamicsPath::Dense, spinning);
    const VecX fast = sh::velocity_change(model, state, h, sh::DynamicsPath::Recursive, spinning);
    // As in superhelix/energy-decay: the relative residual of the recursive dv in the dense system
    // (M + D) dv = b (M at the root pose of this step), free of the growth of cond(M + D) with N
    // that the forward difference shows (1.8e-12 at N = 32 with this section, 1.1e-12 at N = 64
    // without rotational inertia; the residual: <= 7e-14 for N = 4 .. 64).
    const sh::RootState root = spinning.state_at(model, state.time);
    sh::RodModel posed = model;
    posed.root_position = root.position;
    posed.root_frame = root.frame;
    MatX system = sh::mass_matrix(posed, sh::Kinematics(posed, state.q));
    system.diagonal() += damping;
    paths = std::max(paths, (system * (dense - fast)).norm() / (system * dense).norm());
    forward = std::max(forward, (dense - fast).lpNorm<Eigen::Infinity>() / dense.lpNorm<Eigen::Infinity>());
    state = sh::step(model, state, h, sh::DynamicsPath::Recursive, spinning);  // the production step
  }
  LevelOutput output;
  output.metrics["equivalence_difference"] = value_sample(equivalence);
  output.metrics["dense_vs_recursive"] = value_sample(paths);
  output.metrics["dense_vs_recursive_forward"] = diagnostic(forward);
  output.metrics["tip_z_moving"] = diagnostic(sh::Kinematics(model, state.q).tip_position().z());
  return output;
}

}  // namespace

sh::RodModel superhelix_cases::energy_release_model(std::size_t elements, const Parameters& p, double J_scale) {
  sh::RodModel model;
  model.elements = elements;
  model.length = parameter_value(p, "L");
  model.line_density = parameter_value(p, "rhoS");
  model.stiffness = Vec3(parameter_value(p, "GJ"), parameter_value(p, "EI1"), parameter_value(p, "EI2"));
  model.rotational_inertia =
      J_scale * sh::elliptic_section_inertia(model.line_density, model.length / 7.0, 0.6 * model.length / 7.0);
  model.natural_strain = Vec3(0.5, 0.0, 1.2) / model.length;
  model.root_frame = cases::tilted_frame(0.7);
  model.gravity = parameter_value(p, "g") * Vec3(0.2, -0.3, -1.0).normalized();
  return model;
}

Vec3 superhelix_cases::energy_release_rates(const Parameters& p) {
  return Vec3(1.25, 0.85, -0.6) / (parameter_value(p, "L") * cases::bending_time(p, "EI1"));
}

void superhelix_cases::require_energy_release_windows(Case& c, double max_swing, double max_horizon) {
  // Measured 2026-11-28 with the default levels, one ratio at a time (superhelix/energy-decay; the super-clothoid
  // at the ends: orders 0.92 .. 0.97): the loss's order 0.949 at GJ / EI1 = 0.1, 0.921 at 3, 0.906 at 4, 0.89 at
  // 5 (the torsion's omega dt grows); 0.96 at EI2 / EI1 = 0.1, 0.921 at 10, 0.912 at 20, 0.893 at 40.
  cases::require(c, cases::ratio_window("GJ", "EI1", 0.1, 3.0, "where the time levels resolve the release"));
  cases::require(c, cases::ratio_window("EI2", "EI1", 0.1, 10.0, "where the time levels resolve the release"));
  // g = 100 at the defaults (g rhoS L^3 / EI1 = 206), measured before the scales were parameters.
  cases::require(c, cases::gravity_window("EI1", 0.0, 206.0, "measured with the default levels"));
  cases::require(c, cases::horizon_window("EI1", 0.01, max_horizon, "the levels' first-order regime"));
  cases::require(c, cases::swing_window(max_swing));
}

Parameters superhelix_cases::energy_release_parameters() {
  Parameters p{length_parameter(0.7)};
  for (auto& q : cases::section_parameters(0.3, Vec3(0.03, 0.05, 0.08))) p.push_back(q);
  p.push_back(make_parameter("g", 2.0, 0.0, 1e6, true, false, "length/time^2", "gravity"));
  p.push_back(make_parameter("t_end", 0.25, 0.0, 1e6, true, false, "time", "horizon"));
  return p;
}

void superhelix_cases::EnergyLedger::record(double time, double energy) {
  scale_ = std::max(scale_, std::abs(energy));
  worst_increase_ = std::max(worst_increase_, energy - energy_);
  energy_ = energy;
  t_.push_back(time);
  loss_.push_back(e0_ - energy_);
}

void superhelix_cases::EnergyLedger::add_to(LevelOutput& output) const {
  output.metrics["energy_loss"] = cases::value_sample((e0_ - energy_) / scale_, 1.0);
  output.metrics["max_energy_increase"] = cases::diagnostic(worst_increase_ / scale_);
  output.series.push_back(thin_series("energy loss E(0) - E(t)", "t", "E(0) - E(t)", t_, loss_));
}

void register_superhelix_cases(Registry& registry) {
  // Round-off bound for the exact cases: N chained closed-form elements, each a few eps of L, plus
  // Newton's round-off floor (|r| / K ~ N eps): 1e-12 covers 64 N eps for N <= 64 (helix: measured
  // <= 1.1e-15 for N = 1 .. 16; roll-up see below).
  constexpr double kRoundOff = 1e-12;
  const std::string exact_why = "uniform strains are represented exactly: round-off only (64 N eps, N <= 64)";
  {
    std::vector<GateSpec> gates{
        // N = 1 (one element turning by 2 pi) stops at Newton's round-off floor: when the line search
        // stalls there, newton.cpp accepts a residual up to 1e3 x the tolerance (1e-14 here), i.e. a
        // relative curvature error up to 1e-11, which moves the tip of a full turn by 2 pi times that
        // (relative to L) and H = M^2 / 2EI by twice that. Bounds 2 pi 1e-11 = 6.3e-11 (shape, tip gap)
        // and 2e-11 (H). Measured at N = 1: shape 1.1e-14 (L = 1), 1.1e-12 (3), 5.2e-12 (7), 7.9e-12
        // (99), 2.9e-12 (1e3); H 3.5e-12 (L = 7); N = 2 .. 16 stay <= 4e-16 at every L. (The bounds were
        // 2e-12, 3 x the value at the default L alone, and failed at L = 7 and 1e3: issue 14, class 5.)
        upper_bound_gate("shape_max_error", 6.3e-11, GateScope::AllLevels, exact_why + "; Newton floor at N = 1"),
        upper_bound_gate("tip_gap", 6.3e-11, GateScope::AllLevels,
                         "the tip gap is the closed form's (the full circle closes): " + exact_why),
        upper_bound_gate("H_spread", kRoundOff, GateScope::AllLevels, "H = M^2/(2EI) at every station: " + exact_why),
        upper_bound_gate("H_form_difference", kRoundOff, GateScope::AllLevels, "compact = flattened to round-off"),
        upper_bound_gate("H_mean", 2e-11, GateScope::AllLevels, exact_why + "; Newton floor at N = 1")};
    registry.add(in_group(make_case(
        "superhelix/roll-up", "3-D cantilever rolled into a full circle by a dead end moment",
        "Kirchhoff rod clamped with a tilted frame; dead end moment M = 2 pi EI / L about an axis in the "
        "cross-section (isotropic bending, GJ = 0.7 EI): a circle of radius EI/M.",
        "r(s) = r0 + (EI/M) sin(Ms/EI) t0 + (EI/M)(1 - cos(Ms/EI)) a x t0; H = M^2/(2EI)",
        "Exact circle under a pure end moment (Euler); ALGORITHMS.md §1.7; PHYSICS.md §3.4",
        {unit_length_parameter(), stiffness_parameter(),
         make_parameter("turns", 1.0, 0.0, 1.0, true, false, "", "M L / (2 pi EI)"),
         make_parameter("axis_angle_deg", 30.0, -180.0, 180.0, false, false, "deg",
                        "moment axis in the cross-section, from n1 towards n2")},
        elements({1, 2, 4, 8, 16}, {1, 2, 4, 8, 16, 32, 64}),
        {{"shape_max_error", MetricKind::Error, "", "max |r_i - r_exact(s_i)| / L over vertices", false, std::nullopt},
         {"tip_gap", MetricKind::Error, "", "|r(L) - r(0)| / L vs the closed form (0: a full turn closes)", false,
          std::nullopt},
         noether3d_metric_specs(true, std::nullopt)[0], noether3d_metric_specs(true, std::nullopt)[1],
         noether3d_metric_specs(true, std::nullopt)[2], diagnostic_metric("newton_iterations", "Newton iterations")},
        gates, run_roll_up), "rod-3d/roll-up"));
  }
  {
    std::vector<GateSpec> gates{upper_bound_gate(
        "roundoff_units", kHelixRoundOffUnits, GateScope::AllLevels,
        "uniform strains are represented exactly: shape, frame, strains, H (mean, spread, compact = flattened) to "
        "round-off; per unit eps max(1, B/C, C/B) (1 + |M_t| R/B) max(1, turns, 1/(2 pi turns)), at most twice "
        "Newton's floor rule (1e-11 = 4.5e4 units; measured <= 4.4e3)")};
    auto metrics = std::vector<MetricSpec>{
        {"shape_max_error", MetricKind::Error, "", "max |r_i - r_helix(s_i)| / L over vertices", false, std::nullopt},
        {"frame_max_error", MetricKind::Error, "", "max |R_i - R_helix(s_i)| (entries)", false, std::nullopt},
        {"strain_max_error", MetricKind::Error, "", "max |q_Q - (tau, kappa, 0)| / |u|", false, std::nullopt},
        diagnostic_metric("newton_iterations", "Newton iterations"),
        invariant_metric("roundoff_units", "max of the six errors (shape, frame, strain, H spread, H mean, H forms) "
                                           "/ (eps max(1, B/C, C/B) (1 + |M_t| R/B) max(1, turns, 1/(2 pi turns)))")};
    for (auto& m : noether3d_metric_specs(true, std::nullopt)) metrics.push_back(m);
    Case c = in_group(make_case(
        "superhelix/helix-axial-wrench", "uniform helix held by an axial wrench, with natural twist",
        "Kirchhoff rod (isotropic bending B, twist C, natural twist u_hat0 = tau - M_t/C) clamped in the "
        "helix frame at s = 0, loaded at s = L by the dead force F e_z and the end moment m(L) = B kappa b "
        "+ M_t t: the uniform helix of radius R and pitch angle alpha is an exact equilibrium.",
        "kappa = sin^2(a)/R, tau = sin(a)cos(a)/R, F = (M_t - B tau) sin(a)/R, M = B sin^3(a)/R + M_t cos(a); "
        "H = F cos(a) + B kappa^2/2 + M_t tau - M_t^2/(2C)",
        "Love 1944 §§270-271; PHYSICS.md §7.1 (40-digit mpmath check in tests/data/rod3d_reference.csv)",
        {length_parameter(3.0), make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness"),
         make_parameter("C", 0.9, 0.0, 1e12, true, false, "force length^2", "twisting stiffness"),
         make_parameter("radius", 0.7, 0.0, 1e6, true, false, "length", "helix radius"),
         make_parameter("pitch_angle", 0.6, 0.0, kPi / 2, true, true, "rad", "angle between tangent and axis"),
         make_parameter("twisting_moment", 0.37, -1e6, 1e6, false, false, "force length", "M_t = m.t")},
        elements({1, 2, 4, 8, 16}, {1, 2, 4, 8, 16, 32, 64}), metrics, gates, run_helix),
        "rod-3d/helix-axial-wrench");
    require_helix_round_off_window(c);
    registry.add(std::move(c));
  }
  {
    const std::vector<double> levels{8, 16, 32};
    const double hf = 1.0 / levels.back();
    std::vector<GateSpec> gates{order_gate("tip_w", 2.0, "midpoint-consistent piecewise-constant strains: second order"),
                                order_gate("tip_u", 2.0, "second order"), order_gate("tip_phi", 2.0, "second order"),
                                // measured at N = 32 (rodvv sweep, 2026-11-21): orders 2.000 over N = 8 .. 64
                                measured_bound("tip_w", 9.024e-5, hf, 2.0), measured_bound("tip_u", 4.492e-5, hf, 2.0),
                                measured_bound("tip_phi", 4.933e-5, hf, 2.0),
                                upper_bound_gate("out_of_plane", kRoundOff, GateScope::AllLevels,
                                                 "a planar load keeps the rod in its plane: round-off")};
    registry.add(in_group(make_case(
        "superhelix/mattiasson-2", "Mattiasson cantilever (P L^2/EI = 2) solved in 3-D",
        "Super-Helix cantilever clamped horizontally (tangent yawed by 30 deg, cross-section rolled by 40 deg, "
        "GJ = 0.8 EI) under a vertical dead tip load P: a planar elastica computed with all three strains.",
        "sqrt(alpha) = K(k) - F(psi0, k); tip displacements by incomplete elliptic integrals (planar reference)",
        "Bisshopp & Drucker 1945; Mattiasson 1981, IJNME 17:145-153; PHYSICS.md §3.5",
        {unit_length_parameter(), stiffness_parameter(),
         make_parameter("alpha", 2.0, 0.0, 20.0, true, false, "", "load parameter P L^2 / EI")},
        elements(levels, {8, 16, 32, 64, 128}),
        {error_metric("tip_w", "L", "vertical tip deflection / L", 2.0, true),
         error_metric("tip_u", "L", "horizontal tip displacement along the clamp tangent / L", 2.0, true),
         error_metric("tip_phi", "rad", "tip rotation below the horizontal", 2.0, true),
         {"out_of_plane", MetricKind::Error, "", "tip distance from the load plane / L", false, std::nullopt},
         diagnostic_metric("newton_iterations", "Newton iterations")},
        gates, run_mattiasson), "rod-3d/mattiasson-2"));
  }
  {
    const std::vector<double> levels{8, 16, 32};
    std::vector<GateSpec> gates{
        order_gate("tip_w", 4.0, "continuous piecewise-affine strains: the tip superconverges at fourth order (measured)"),
        order_gate("tip_u", 4.0, "fourth order (measured)"), order_gate("tip_phi", 4.0, "fourth order (measured)"),
        // measured at N = 32 (rodvv sweep, 2026-11-28, exact-Jacobian Newton): least-squares orders 4.020, 3.988,
        // 4.008 over N = 8 .. 32; 4.002, 3.998, 4.001 over N = 4 .. 128 (errors down to 1.3e-12 at N = 128)
        measured_bound("tip_w", 6.1655e-10, 1.0 / levels.back(), 4.0),
        measured_bound("tip_u", 3.2279e-10, 1.0 / levels.back(), 4.0),
        measured_bound("tip_phi", 7.6571e-10, 1.0 / levels.back(), 4.0),
        upper_bound_gate("out_of_plane", kRoundOff, GateScope::AllLevels,
                         "a planar load keeps the rod in its plane: round-off")};
    Case c = make_case(
        "superhelix/clothoid-mattiasson-2", "Mattiasson cantilever (P L^2/EI = 2) on the super-clothoid rod",
        "Super-clothoid cantilever (continuous, piecewise-affine twist and curvatures) clamped horizontally "
        "(tangent yawed by 30 deg, cross-section rolled by 40 deg, GJ = 0.8 EI) under a vertical dead tip load P.",
        "sqrt(alpha) = K(k) - F(psi0, k); tip displacements by incomplete elliptic integrals (planar reference)",
        "Bisshopp & Drucker 1945; Mattiasson 1981, IJNME 17:145-153; Casati & Bertails-Descoubes 2013; PHYSICS.md §3.5",
        // The loads its levels (N = 8 .. 32, as the Super-Helix's) fit order 4 at: alpha in [0.1, 4.5] (measured
        // 2026-11-28: below 0.1 the errors reach round-off at N = 8 (1e-14 at alpha = 0.05, orders -0.6 .. 3.7);
        // above 4.5 tip_u's error changes sign on the levels (order 3.89 at 5, 2.52 at 12, 4.91 at 16)).
        {unit_length_parameter(), stiffness_parameter(),
         make_parameter("alpha", 2.0, 0.1, 4.5, false, false, "", "load parameter P L^2 / EI")},
        elements(levels, {8, 16, 32, 64, 128}),
        {error_metric("tip_w", "L", "vertical tip deflection / L", 4.0, true),
         error_metric("tip_u", "L", "horizontal tip displacement along the clamp tangent / L", 4.0, true),
         error_metric("tip_phi", "rad", "tip rotation below the horizontal", 4.0, true),
         {"out_of_plane", MetricKind::Error, "", "tip distance from the load plane / L", false, std::nullopt},
         diagnostic_metric("newton_iterations", "Newton iterations")},
        gates, run_clothoid_mattiasson);
    c.info.group = "rod-3d/mattiasson-2";
    c.info.method =
        "Super-clothoid (Casati & Bertails-Descoubes 2013; ALGORITHMS.md §2): nodal twist and curvatures, affine per "
        "element; frame and centreline by the adaptive power series, its derivatives by forward-mode "
        "differentiation of the series; statics by the Super-Helix Newton on the exact Jacobian (line search, load "
        "stepping)";
    registry.add(std::move(c));
  }
  {
    const std::vector<double> levels{8, 16, 32};
    std::vector<GateSpec> gates{
        order_gate("H_spread", 2.0, "H(s) at element midpoints: second order (PHYSICS.md §1.4)"),
        measured_bound("H_spread", 1.4517e-4, 1.0 / levels.back(), 2.0),  // at N = 32 (w L^3/EI = 2.99); order 1.99 over N = 8 .. 64
        upper_bound_gate("H_form_difference", kRoundOff, GateScope::AllLevels, "compact = flattened to round-off (64 eps x terms)")};
    Case c = make_case(
        "superhelix/heavy-cantilever", "naturally curved and twisted cantilever under its own weight: H(s)",
        "Super-Helix cantilever (GJ = 0.6 EI, EI2 = 1.4 EI) with natural strains (0.8, 1.2, -0.5)/L, tilted clamp, "
        "under its weight w = rho S g per unit length: the Lagrangian has no explicit s, so H is conserved.",
        "H = n.v + m.u - W - V constant along s (V = -rho S g.r), compact and flattened forms equal",
        "Maddocks & Dichmann 1994, J. Elasticity 34:83; PHYSICS.md §1.1; seed slides 002",
        // w = 1.4 at L = 1.7, EI = 2.3: w L^3 / EI = 2.99. L and EI are not unit scales here: with w
        // held, they change the weight parameter.
        {length_parameter(kDefaultLength), stiffness_parameter(false),
         make_parameter("w", 1.4, 0.0, 1e12, true, false, "force/length", "weight per unit length rho S g")},
        elements(levels, {8, 16, 32, 64, 128}),
        [] {
          auto specs = noether3d_metric_specs(false, 2.0);
          specs.push_back(diagnostic_metric("newton_iterations", "Newton iterations"));
          specs.push_back(diagnostic_metric("tip_z", "tip height / L"));
          return specs;
        }(),
        gates, run_heavy);
    // w L^3 / EI in [0.22, 40] (measured 2026-11-28 on the default levels): the H spread's order is 1.90 at 0.22,
    // 1.97 at 2, 1.91 at 40 and 1.89 at 50; below 0.22 it dips to 1.87 .. 1.89 (0.05 .. 0.2, pre-asymptotic) and
    // below 1e-3 the two H forms differ by more than the round-off gate (their terms shrink with the weight:
    // 1.7e-12 at 5e-4). The window was [0, 40] (its lower part not measured).
    cases::require(c, cases::weight_window(0.22, 40.0, "where the default levels fit the H spread's order 2"));
    registry.add(std::move(c));
  }
  {
    // Measured (rodvv sweep, 2026-11-21) at N = 2, 4, 8, 16, 32, 64:
    //   H_spread (nodes)  2.16e-2 3.99e-3 1.05e-3 2.80e-4 7.27e-5 1.86e-5: pairwise orders 2.44 1.92 1.91 1.94 1.97
    //   H_spread_gauss    9.42e-3 9.88e-4 2.79e-4 5.36e-5 8.12e-6 1.11e-6: 3.25 1.83 2.38 2.72 2.87 (-> 3)
    //   H_spread_midpoints 1.12e-2 3.41e-3 7.57e-4 1.68e-4 3.99e-5 9.74e-6: 1.72 2.17 2.17 2.08 2.04
    //   tip_error         5.64e-4 3.18e-5 1.95e-6 1.21e-7 7.54e-9 4.71e-10: 4.15 4.03 4.01 4.00 4.00
    //   H_form_difference <= 8e-16 at every level
    // Default levels N = 16, 32, 64 (2026-11-28, on the exact-Jacobian Newton; they were 2, 4, 8 on central
    // differences): one step finer than the Super-Helix's 8 .. 32 because the nodal H spread reaches its order 2
    // from below (1.956 over 16 .. 64, 1.91 .. 1.97 pairwise from N = 8); tip_error 4.003.
    const std::vector<double> levels{16, 32, 64};
    const double hf = 1.0 / levels.back();
    std::vector<GateSpec> gates{
        order_gate("H_spread", 2.0, "H at the nodes: the nodal strains are the L2 projection of the moment, O(h^2) "
                                    "(least-squares order 1.956 over N = 16 .. 64)"),
        measured_bound("H_spread", 1.8580e-5, hf, 2.0),
        measured_bound("H_spread_gauss", 1.1114e-6, hf, 3.0),
        upper_bound_gate("H_form_difference", kRoundOff, GateScope::AllLevels,
                         "compact = flattened to round-off (64 eps x terms), nodes and Gauss stations"),
        order_gate("tip_error", 4.0, "continuous piecewise-affine strains: the tip converges at fourth order"),
        measured_bound("tip_error", 4.7055e-10, hf, 4.0)};
    Case c = make_case(
        "superhelix/clothoid-heavy-cantilever", "heavy cantilever on the super-clothoid rod: H(s) and the tip",
        "The naturally curved and twisted heavy cantilever of superhelix/heavy-cantilever (GJ = 0.6 EI, EI2 = 1.4 EI, "
        "natural strains (0.8, 1.2, -0.5)/L, tilted clamp, weight w = rho S g per unit length, w L^3 / EI = 3 at the "
        "defaults) on the super-clothoid rod (continuous, piecewise-affine strains): the Lagrangian has no explicit "
        "s, so H is conserved.",
        "H = n.v + m.u - W - V constant along s (V = -rho S g.r), compact and flattened forms equal; tip: the "
        "Super-Helix at N = 128, 256, 512 extrapolated (h^2, h^4), error ~1e-12 (stored at w L^3 / EI = 3, live "
        "otherwise)",
        "Maddocks & Dichmann 1994, J. Elasticity 34:83; Casati & Bertails-Descoubes 2013; PHYSICS.md §1.1, §1.4",
        {length_parameter(kDefaultLength), stiffness_parameter(false),
         make_parameter("w", 3.0 * kDefaultStiffness / std::pow(kDefaultLength, 3), 0.0, 1e12, true, false,
                        "force/length", "weight per unit length rho S g")},
        elements(levels, {16, 32, 64, 128, 256}),
        {invariant_metric("H_spread", "max |H(s) - mean H| / term scale at the N + 1 nodes", 2.0),
         invariant_metric("H_spread_gauss", "the same at the 2 Gauss points per element (asymptotically O(h^3))"),
         invariant_metric("H_form_difference", "max |H_compact - H_flattened| / term scale (round-off)"),
         diagnostic_metric("H_spread_midpoints", "the same at the element midpoints (O(h^2))"),
         error_metric("tip_error", "length", "|r(L) - r_ref(L)| / L vs the extrapolated Super-Helix", 4.0),
         error_metric("tip_x", "L", "(tip x - root x) / L", 4.0), error_metric("tip_y", "L", "(tip y - root y) / L", 4.0),
         error_metric("tip_z", "L", "(tip z - root z) / L", 4.0),
         diagnostic_metric("newton_iterations", "Newton iterations")},
        gates, run_clothoid_heavy);
    // The weights its levels fit the H spread's order 2 at (measured 2026-11-28 on N = 16, 32, 64): 1.93 at
    // w L^3 / EI = 0.01, 1.96 at 3, 2.03 at 10, 1.96 at 30, 1.88 at 40 (refused). Below 0.01 H's terms shrink
    // with the weight and the two H forms differ by ~3.6e-15 / (w L^3 / EI) of their scale (3.6e-13 at 0.01,
    // 1.1e-12 at 0.003: past the round-off gate; at L = 0.017 with w held, 1.8e-9 and the tip's order 3.7).
    cases::require(c, cases::weight_window(0.01, 30.0, "where the default levels fit the H spread's order 2 and "
                                                       "the H forms agree to round-off"));
    c.info.method =
        "Super-clothoid (Casati & Bertails-Descoubes 2013; ALGORITHMS.md §2): nodal twist and curvatures, affine per "
        "element, series frame and centreline; statics by the shared Newton; the solution struct of "
        "solvers/superhelix/clothoid_solution (m from the constitutive law, n from force balance with the dead loads)";
    registry.add(std::move(c));
  }
  {
    // Measured (rodvv sweep, default parameters, N = 8 ... 256): every relative error converges from
    // above at order 2.000 (least squares over N = 64 ... 256; pairwise 2.00 - 2.06 from N = 8), e.g.
    // omega1_EI1 3.034e-3 7.570e-4 1.892e-4 4.728e-5 1.182e-5 2.955e-6, omega1_twist 1.607e-3 4.016e-4
    // 1.004e-4 2.510e-5 6.275e-6 1.569e-6 (= (k ell)^2/24); the relative errors of the EI1 and the EI2
    // family are equal (the discrete problem scales with EI); torsion_discrete_relative <= 8.9e-13,
    // restricted_vs_full <= 5.8e-15, mode_mixing 0. Bounds C h^2 with C = 2 x the value at N = 64.
    const std::vector<double> levels{8, 16, 32, 64};
    const double hf = 1.0 / levels.back();
    const struct {
      const char* name;
      double measured;  // relative error at N = 64
      const char* what;
    } rows[] = {{"omega1_EI1", 4.7282e-5, "first bending frequency about n1 (EI1)"},
                {"omega2_EI1", 3.2988e-4, "second bending frequency about n1 (EI1)"},
                {"omega3_EI1", 7.8693e-4, "third bending frequency about n1 (EI1)"},
                {"omega1_EI2", 4.7282e-5, "first bending frequency about n2 (EI2)"},
                {"omega2_EI2", 3.2988e-4, "second bending frequency about n2 (EI2)"},
                {"omega3_EI2", 7.8693e-4, "third bending frequency about n2 (EI2)"},
                {"omega1_twist", 2.5100e-5, "first torsional frequency"},
                {"omega2_twist", 2.2591e-4, "second torsional frequency"}};
    std::vector<GateSpec> gates;
    std::vector<MetricSpec> metrics;
    for (const auto& row : rows) {
      metrics.push_back(error_metric(row.name, "", fmt::format("relative error of the {}", row.what), 2.0, true));
      const bool twist = std::string(row.name).find("twist") != std::string::npos;
      gates.push_back(order_gate(row.name, 2.0,
                                 twist ? "piecewise-linear angle, consistent mass: (k ell)^2/24, O(N^-2)"
                                       : "Rayleigh-Ritz with piecewise-constant curvature: O(N^-2) (ALGORITHMS.md §1.7)"));
      gates.push_back(measured_bound(row.name, row.measured, hf, 2.0));
    }
    gates.push_back(lower_bound_gate("min_relative_excess", 0.0, GateScope::AllLevels,
                                     "Rayleigh-Ritz: discrete frequencies lie above the continuous ones"));
    metrics.push_back(diagnostic_metric("min_relative_excess", "min over the eight of (omega - exact)/exact (>= 0)"));
    metrics.push_back(diagnostic_metric("torsion_discrete_relative",
                                        "max |omega_twist - omega_d| / omega_d, omega_d^2 = (6 GJ / (rho I0 ell^2)) "
                                        "(1 - cos k ell)/(2 + cos k ell) the discrete closed form"));
    metrics.push_back(invariant_metric("torsion_discrete_roundoff",
                                       "max over the torsional modes of |omega_twist / omega_d - 1| / (eps (N^2 + "
                                       "(omega_twist / omega_min)^2)): the closed-form comparison in units of its "
                                       "round-off"));
    metrics.push_back(diagnostic_metric("mode_mixing", "largest off-family share of a classified mode's kinetic norm"));
    metrics.push_back(diagnostic_metric("restricted_vs_full",
                                        "max |omega_EI1 (kappa1 block alone, bending_frequencies) / omega_EI1 (full) - 1|"));
    metrics.push_back(invariant_metric("restricted_vs_full_roundoff",
                                       "restricted_vs_full per mode / (eps (N^2 + (omega_EI1 / omega_min)^2)), its round-off"));
    // Round-off gates: the eigensolver works on K^{-1/2} M K^{-1/2} (1/omega^2), so a mode carries a
    // relative error ~ eps (omega / omega_min)^2, plus the growth of M's assembly error with N (~ N^2
    // eps; measured torsion_discrete_relative 1.2e-15 at N = 8, 4.9e-14 at 64, 2.5e-13 at 128). Both
    // comparisons are reported in units of eps (N^2 + (omega / omega_min)^2), so the bound follows L,
    // EI, GJ and N (issue 14, class 5: the former absolute 1e-12 failed at L = 1e3 and 1e-3 on
    // comparisons exact to their round-off). Measured over L = 1e-3, 1, 1e3, 1e6 and N = 8 .. 128:
    // torsion_discrete_roundoff <= 0.29, restricted_vs_full_roundoff <= 0.12; both bounded by 1.
    gates.push_back(upper_bound_gate("torsion_discrete_roundoff", 1.0, GateScope::AllLevels,
                                     "the twist is a linear finite element bar with consistent mass: its discrete "
                                     "frequencies in closed form, to round-off eps (N^2 + (omega / omega_min)^2)"));
    gates.push_back(upper_bound_gate("restricted_vs_full_roundoff", 1.0, GateScope::AllLevels,
                                     "the kappa1 block alone and the full 3N problem: the same modes to round-off "
                                     "eps (N^2 + (omega / omega_min)^2)"));
    Case c = make_case(
        "superhelix/modes", "bending and torsional frequencies of a straight cantilever, tilted clamp",
        "Straight Super-Helix cantilever clamped with a tilted frame, GJ != EI1 != EI2, no load; small oscillations "
        "about q = 0: K v = omega^2 M v on all 3N coordinates, translational inertia rho S and the twist inertia "
        "rho I0 of the cross-sections (rho I1 = rho I2 = 0: no rotary inertia of the bending, as in the "
        "Euler-Bernoulli reference); modes sorted into families by the strain component their eigenvector lives in.",
        "Euler-Bernoulli cantilever omega_n = (beta_n L)^2 sqrt(EI/(rho S L^4)), 1 + cos(beta L) cosh(beta L) = 0, in "
        "each plane; torsion omega_n = (2n - 1) pi / (2L) sqrt(GJ/(rho I0))",
        "Euler-Bernoulli cantilever (Rayleigh, Theory of Sound); Meirovitch, Fundamentals of Vibrations; "
        "ALGORITHMS.md §1.7",
        {length_parameter(1.3),
         make_parameter("GJ", 0.55, 0.0, 1e12, true, false, "force length^2", "twisting stiffness"),
         make_parameter("EI1", 1.7, 0.0, 1e12, true, false, "force length^2", "bending stiffness about n1"),
         make_parameter("EI2", 3.1, 0.0, 1e12, true, false, "force length^2", "bending stiffness about n2"),
         make_parameter("rhoS", 0.8, 0.0, 1e12, true, false, "mass/length", "line density"),
         make_parameter("rhoI0", 0.07, 0.0, 1e12, true, false, "mass length", "polar mass moment per unit length")},
        elements(levels, {8, 16, 32, 64, 128, 256}), std::move(metrics), std::move(gates), run_modes);
    require_window(c, fmt::format("eps (omega_high / omega_min)^2 <= {:g} over the modes the case measures (EI1, EI2, "
                                  "GJ, rhoS, rhoI0 and L on comparable scales)", kMaxModeRoundOff),
                   check_mode_spread);
    c.info.group = "rod-3d/modes";
    c.info.method = std::string(kMethod) +
                    "; linearised about the straight state: the full 3N generalised eigenproblem K v = omega^2 M v "
                    "(sh::straight_rod_modes, Cholesky of M, dense symmetric eigensolver)";
    registry.add(std::move(c));
  }
  {
    // Measured (rodvv sweep over dt / tau = 4e-3 .. 1.25e-4, tau = 1.2003 at the defaults, 2026-11-28):
    // energy_loss 5.18e-3, 2.74e-3, 1.43e-3, 7.37e-4, 3.78e-4, 1.93e-4 (pairwise orders 0.917 0.938 0.956 0.963
    // 0.974: an O(h^2) part decays; least squares 0.95 over the default levels); every step loses energy
    // (max_energy_increase = 0 at every level); dense vs recursive: relative residual <= 3.5e-15, forward
    // difference <= 1e-12 (cond(M + D) x eps: a diagnostic). With J_scale = 0 the same release gains energy at
    // some steps (up to ~1e-6 |E| for dt <= 1e-3, measured 2026-11-22): the twist is then nearly massless.
    const std::vector<double> levels{2e-3, 1e-3, 5e-4};
    constexpr double kEnergyLossAtFinest = 7.3735e-4;  // at dt / tau = 5e-4
    std::vector<GateSpec> gates{
        order_gate("energy_loss", 1.0, "semi-implicit Euler dissipates at first order in h (ALGORITHMS.md §1.5)"),
        measured_bound("energy_loss", kEnergyLossAtFinest, levels.back(), 1.0),
        // Monotone decay is what the default release shows (max_energy_increase = 0), not a property of
        // the scheme: its velocity terms (gyroscopic torque included) are explicit, and a stronger swing
        // gains energy at some steps (g = 20: 2e-4 |E|; J_scale = 0: 7e-7), so the gate holds at the
        // defaults, like a measured bound.
        [] {
          GateSpec monotone = upper_bound_gate("max_energy_increase", 1e-13, GateScope::AllLevels,
                                               "monotone decay at the default release: any increase is round-off "
                                               "of E (~64 eps |E| summed terms)");
          monotone.measured = true;
          return monotone;
        }(),
        upper_bound_gate("dense_vs_recursive", 1e-12, GateScope::AllLevels,
                         "the O(N) recursion solves the same system as the dense LDL^T (issue gate 1e-12, "
                         "as a relative residual)")};
    Case c = make_case(
        "superhelix/energy-decay", "undamped 3-D swing and twist under gravity: energy decay and dense vs O(N) step",
        "Super-Helix cantilever (N elements, length L, line density rho S, stiffnesses GJ != EI1 != EI2; defaults "
        "0.7, 0.3, (0.03, 0.05, 0.08); a solid elliptic section with semi-axes L/7 and 0.6 L/7: rotational "
        "inertia (rho I0, rho I1, rho I2) = (1.02e-3, 2.7e-4, 7.5e-4) x J_scale at the defaults; natural strains "
        "(0.5, 0, 1.2)/L; tilted clamp) released from its natural shape with strain rates (1.25, 0.85, -0.6) / "
        "(L tau) in every element, tau = L^2 sqrt(rho S / EI1), under gravity g along a direction in none of its "
        "planes, no damping: it swings and twists out of plane. Semi-implicit Euler (implicit elastic term, "
        "explicit velocity terms including the gyroscopic torque omega x J omega); the level is dt / tau.",
        "E = T + U + V (T with the rotational kinetic energy) is conserved by the exact flow; the loss "
        "E(0) - E(t_end) is the error, O(h)",
        "ALGORITHMS.md §1.5-1.7; Bertails et al. 2006; Bertails 2009 (linear time); issue 11 (rotational inertia)",
        // N <= 128: the dense step is O(N^3) per step; measured 0.9 s at N = 32, 5.5 s at 64, 39 s at 128
        // for the whole case (N = 256 would take minutes, issue 14).
        [] {
          Parameters p = superhelix_cases::energy_release_parameters();
          p.insert(p.begin(), integer_parameter("N", 8.0, 1.0, 128.0, "number of elements"));
          p.push_back(make_parameter("J_scale", 1.0, 0.0, 1e3, false, false, "",
                                     "factor on the section's rotational inertia (0: translational inertia only)"));
          return p;
        }(),
        // pairwise orders of the loss 0.93 .. 0.97 from dt = 4e-3 down to 1.25e-4 (an O(h^2) part
        // decays): the default levels start at 2e-3 so that the fit is inside the window
        {"dt/tau", "time step over tau = L^2 sqrt(rho S / EI1)", ResolutionScale::StepSize, levels,
         {4e-3, 2e-3, 1e-3, 5e-4, 2.5e-4, 1.25e-4}},
        {{"energy_loss", MetricKind::Error, "", "(E(0) - E(t_end)) / |E|", false, 1.0},
         diagnostic_metric("max_energy_increase", "max (E_{n+1} - E_n) / |E| (<= round-off: monotone)"),
         {"dense_vs_recursive", MetricKind::Error, "",
          "max over steps of |(M + D)(dv_dense - dv_recursive)| / |(M + D) dv_dense| (relative residual)", false,
          std::nullopt},
         diagnostic_metric("dense_vs_recursive_forward", "max over steps of |dv_dense - dv_recursive|_inf / |dv|_inf"),
         diagnostic_metric("rotational_kinetic_share", "max over steps of T_rotational / T")},
        gates, run_energy);
    // The swing the levels resolve: t_end sqrt(g / L) <= 3 (defaults 0.42): at 3.8 (g = 10, t_end = 1, L = 0.7)
    // and 4.8 (g = 100, t_end = 0.4) the loss's order leaves its window; 3 passes at g = 20, 50, 100
    // (measured 2026-11-26). The horizon t_end / tau <= 0.834 (t_end = 1 at the defaults: at 3 or 10 the order
    // was 0.83 .. 0.85, an O(h^2) part not yet decayed over the longer swing).
    superhelix_cases::require_energy_release_windows(c, 3.0, 0.834);
    registry.add(std::move(c));
  }
  {
    registry.add(make_case(
        "superhelix/curl-at-rest", "a curl at rest stays at rest",
        "Super-Helix with q = q0 (a tight twisted curl, natural strains (2, 5, -3)/L), line density rho S, "
        "stiffnesses GJ != EI1 != EI2, no gravity, no end loads, released from rest: 100 semi-implicit Euler steps "
        "of 0.01 tau (tau = L^2 sqrt(rho S / EI1)) alternating dense and recursive solves.",
        "q(t) = q0, qdot(t) = 0 exactly", "ALGORITHMS.md §1.7 (rest state)",
        [] {
          Parameters p{unit_length_parameter()};
          for (auto& q : cases::section_parameters(0.8, Vec3(0.5, 1.3, 2.1))) p.push_back(q);
          return p;
        }(),
        elements({4, 8, 16}, {4, 8, 16, 32, 64}),
        {{"max_drift", MetricKind::Error, "", "|q - q0|_inf + |qdot|_inf after 100 steps", false, std::nullopt}},
        {upper_bound_gate("max_drift", 1e-300, GateScope::AllLevels, "every force vanishes identically: exactly 0")},
        run_curl));
  }
  {
    // 100 steps x 64 eps (each step rounds the sum zeta + a - g once, ~eps |g|, and the damped rod
    // does not amplify it over 0.1 s): 1.42e-12 relative to max(|q|, 1).
    const double steps_round_off = 100 * 64 * std::numeric_limits<double>::epsilon();
    registry.add(make_case(
        "superhelix/accelerated-root", "a moving clamp: equivalence principle and dense = linear-time",
        "Curved, damped Super-Helix (line density rho S, stiffnesses GJ != EI1 != EI2, with the rotational inertia "
        "of a solid elliptic section) under gravity g, released from a bent, moving state; 100 semi-implicit Euler "
        "steps (h = 1e-3). (1) The clamp accelerates at a = (1.5, -0.7, 3) without rotating; (2) the "
        "clamp moves, accelerates and spins up about a tilted axis.",
        "(1) q(t) equals that of a fixed clamp under gravity g - a (Einstein's equivalence principle); "
        "(2) the dense and the linear-time steps solve the same system",
        "ALGORITHMS.md §1.4-1.6 (base acceleration of the articulated-body recursion); issue 5 (moving root)",
        // L <= 200: the start state is given in strains (curvatures 0.3, rates +-0.5 per unit length),
        // so the initial displacements grow as L^2 against a fixed section and step; measured: passes at
        // L = 200, diverges at 300 (issue 14, class 5: the range a run honours).
        [] {
          Parameters p{make_parameter("L", 1.0, 0.0, 200.0, true, false, "length", "rod length")};
          for (auto& q : cases::section_parameters(0.02, Vec3(0.05, 0.1, 0.13))) p.push_back(q);
          // g <= 1000 with the fixed h = 1e-3 (1e4 diverges in a few steps: explicit velocity terms; measured
          // 2026-11-28; every other parameter passes at the ends of its range, one at a time).
          p.push_back(make_parameter("g", 9.81, 0.0, 1e3, false, false, "length/time^2", "gravity"));
          return p;
        }(),
        elements({4, 8, 16}, {4, 8, 16, 32, 64}),
        {{"equivalence_difference", MetricKind::Error, "", "max over steps |q_moving - q_fixed(g - a)|_inf / max(|q|_inf, 1)",
          false, std::nullopt},
         {"dense_vs_recursive", MetricKind::Error, "",
          "max over steps of |(M + D)(dv_dense - dv_recursive)| / |(M + D) dv_dense| (relative residual)", false,
          std::nullopt},
         diagnostic_metric("dense_vs_recursive_forward", "max over steps of |dv_dense - dv_recursive|_inf / |dv|_inf"),
         diagnostic_metric("tip_z_moving", "tip height after the spinning run")},
        {upper_bound_gate("equivalence_difference", steps_round_off, GateScope::AllLevels,
                          "round-off of zeta + a - g per step, 100 steps x 64 eps"),
         upper_bound_gate("dense_vs_recursive", 1e-12, GateScope::AllLevels,
                          "the two paths solve the same linear system (issue 5: <= 1e-12)")},
        run_accelerated_root));
  }
  superhelix_cases::add_bathe_bolourchi(registry);
  superhelix_cases::add_manufactured(registry);
  superhelix_cases::add_touchdown(registry);
  superhelix_cases::add_lateral_torsional(registry);
  superhelix_cases::add_spinning_clamp_oracle(registry);
  superhelix_cases::add_clothoid_energy_decay(registry);
}

}  // namespace rodvv::harness

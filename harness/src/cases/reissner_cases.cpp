// The extensible, shearable planar rod (planar Reissner; solvers/elastica2d with finite
// axial_stiffness EA and shear_stiffness GA), both discretisations, swept over the element count N:
//
//   elastica/reissner-tension/<scheme>       bar clamped at s = 0, axial dead load F at s = L: end
//                                            displacement F L / EA for every N (round-off gates)
//   elastica/reissner-cantilever/<scheme>    cantilever, vertical dead tip load P L^2/EI = 5,
//                                            EA = 100, GA = 40 (or 100) EI/L^2, against the 30-digit
//                                            mpmath shooting table tests/data/reissner_reference.csv;
//                                            at any other L, EI, P, EA, GA against the shooting
//                                            solver (solvers/elastica2d/shooting.hpp, checked against
//                                            the same table to 7.5e-13)
//   elastica/reissner-critical-load/<scheme> pinned-pinned column: the load at which the discrete
//                                            post-buckled branch emerges vs P (1 + P (1/GA - 1/EA))
//                                            = pi^2 EI / L^2 (references/reissner.hpp)
//
// H for the Reissner rod (invariants/planar_noether.hpp (R): H = 1/2 EI kappa^2 + n.t
// + (n.t)^2/(2 EA) + (n.N)^2/(2 GA) - V) is reported along s; its spread is gated.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "case_builder.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/invariants/planar_noether.hpp"
#include "rodvv/references/reissner.hpp"
#include "rodvv/solvers/elastica2d/shooting.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::harness {

namespace {

namespace ref = rodvv::references;
namespace e2d = rodvv::solvers::elastica2d;
constexpr double kPi = std::numbers::pi;

constexpr const char* kReissnerCitation =
    "Reissner 1972, ZAMP 23:795-804 (planar large-deformation rod with extension and shear); "
    "Simo & Vu-Quoc 1986, CMAME 58:79-116; H: PHYSICS.md §1.1 (compact form n.v + m.u - W - V)";

const e2d::Scheme kSchemes[] = {e2d::Scheme::Polygon, e2d::Scheme::Arcs};

std::string scheme_text(e2d::Scheme scheme) {
  return std::string(scheme == e2d::Scheme::Polygon
                         ? "polygon (nodal: straight edges, compliance at the edge angle)"
                         : "arcs (reduced: exact circular arcs, compliance averaged over the arc)") +
         "; mixed form -h/2 n^T C n per element; Newton on the KKT system, banded LU";
}

std::size_t element_count(double level) { return static_cast<std::size_t>(std::llround(level)); }

MetricSample error_sample(double computed, double reference) {
  return {computed, reference, std::abs(computed - reference)};
}

MetricSpec error_metric(std::string name, std::string unit, std::string description,
                        std::optional<double> order = 2.0) {
  return {std::move(name), MetricKind::Error, std::move(unit), std::move(description), order.has_value(),
          order};
}

MetricSpec spread_metric(std::optional<double> order) {
  return {"H_spread", MetricKind::Invariant, "",
          "max |H(s) - mean H| / natural scale, H with the stretch and shear terms (planar_noether (R))",
          false, order};
}

GateSpec measured_bound(std::string metric, double at_finest, double h_finest) {
  // The error measured at the finest default level, times 2, as C h^2.
  GateSpec gate = scaled_upper_bound_gate(std::move(metric), 2.0 * at_finest / (h_finest * h_finest), 2.0,
                                          GateScope::FinestLevel,
                                          "C = 2 x the error measured at the finest default level / h^2");
  gate.measured = true;
  return gate;
}

void add_noether(LevelOutput& output, const PlanarRodSolution& solution) {
  const auto spread = invariants::planar_noether_spread(solution);
  output.metrics["H_spread"] = {spread.spread, 0.0, spread.spread, 1.0};  // in units of H's natural scale
  output.series.push_back(thin_series("H(s)", "s", "H", solution.s, invariants::planar_noether_h(solution)));
}

Parameter stiffness(std::string name, double value, std::string description) {
  return make_parameter(std::move(name), value, 0.0, 1e12, true, false, "force", std::move(description));
}

Case base_case(std::string name, std::string group, std::string title, e2d::Scheme scheme) {
  Case c;
  c.info.name = std::move(name);
  c.info.family = "elastica";
  c.info.group = std::move(group);
  c.info.title = std::move(title);
  c.info.citation = kReissnerCitation;
  c.info.method = scheme_text(scheme);
  return c;
}

// ---- bar in tension ---------------------------------------------------------------------------

LevelOutput run_tension_level(e2d::Scheme scheme, const Parameters& parameters, double level) {
  const double L = parameter_value(parameters, "L"), EI = parameter_value(parameters, "EI");
  const double F = parameter_value(parameters, "F"), EA = parameter_value(parameters, "EA");
  const double GA = parameter_value(parameters, "GA"), angle = parameter_value(parameters, "angle");
  e2d::Problem problem;
  problem.length = L;
  problem.bending_stiffness = [EI](double) { return EI; };
  problem.start.support = e2d::Support::Clamped;
  problem.start.angle = angle;
  problem.end.load.force_x = F * std::cos(angle);
  problem.end.load.force_y = F * std::sin(angle);
  problem.axial_stiffness = EA;
  problem.shear_stiffness = GA;
  e2d::SolverOptions options;
  options.tolerance = 1e-13;
  const PlanarRodSolution solution = e2d::solve_static(problem, {scheme, element_count(level)}, options);

  const double stretched = L + ref::reissner_bar_end_displacement(F, L, EA);
  LevelOutput output;
  const double error = std::hypot(solution.x.back() - stretched * std::cos(angle),
                                  solution.y.back() - stretched * std::sin(angle));
  // Sized by the larger of L and the stretched length, and by the larger of |F| and EI / L^2 (the
  // residual's force scale): the round-off of a sum of N chords, and of a force balance, follow them (the
  // gates are relative).
  output.metrics["end_displacement"] = {std::hypot(solution.x.back(), solution.y.back()) - L,
                                        stretched - L, error, std::max(L, stretched)};
  double force_error = 0.0;
  for (std::size_t e = 0; e < solution.edge_axial_force.size(); ++e)
    force_error = std::max({force_error, std::abs(solution.edge_axial_force[e] - F),
                            std::abs(solution.edge_shear_force[e])});
  output.metrics["edge_force_error"] = {force_error, 0.0, force_error, std::max(std::abs(F), EI / (L * L))};
  add_noether(output, solution);
  std::vector<double> stretch(solution.s.size());
  for (std::size_t i = 0; i < stretch.size(); ++i) stretch[i] = solution.axial_force[i] / EA;
  output.series.push_back(thin_series("stretch n.t/EA", "s", "eps", solution.s, stretch));
  return output;
}

Case tension_case(e2d::Scheme scheme) {
  const std::string id(e2d::scheme_id(scheme));
  Case c = base_case("elastica/reissner-tension/" + id, "elastica/reissner-tension",
                     "extensible bar under an axial end force, " + id, scheme);
  c.info.physics =
      "Bar clamped at s = 0 at an angle, axial dead force F at s = L, EA and GA finite: a straight "
      "state with n.t = F, n.N = 0, stretch F/EA.";
  c.info.reference = "r(L) = (L + F L / EA) t(angle), exact for any N (n constant, C n exact per element)";
  // L and EI not 1, so that a mix-up of them shows (EI sets only the solver's force scale here).
  c.info.parameters = {make_parameter("L", 1.7, 0.0, 1e6, true, false, "length", "bar length"),
                       stiffness("EI", 2.3, "bending stiffness"),
                       make_parameter("F", 2.0, -1e6, 1e6, true, true, "force", "axial end force (> 0 tension)"),
                       stiffness("EA", 25.0, "axial stiffness"), stiffness("GA", 3.0, "shear stiffness"),
                       make_parameter("angle", 0.4, -kPi, kPi, false, false, "rad", "clamp angle")};
  // A stretch 1 + F/EA in (0, 2001]: at F/EA = 4e4 the arcs' Newton fails (line search at load factor
  // 0.98); 2000 passes on both schemes (measured 2026-11-26).
  require_window(c, "F / EA in (-1, 2000] (a positive stretch 1 + F/EA; at most 2001, where the levels converge)",
                 [](const Parameters& p) {
                   const double F = parameter_value(p, "F"), EA = parameter_value(p, "EA");
                   if (!(F > -EA)) throw InputError("F", "invalid parameter 'F': must be > -EA (stretch 1 + F/EA > 0)");
                   if (!(F <= 2000.0 * EA))
                     throw InputError("F", "invalid parameter 'F' = " + format_value(F) + ": F / EA = " +
                                               format_value(F / EA) +
                                               " must be <= 2000 (a stretch of at most 2001, where the levels converge)");
                 });
  c.info.resolution = {"N", "number of elements", ResolutionScale::Count, {4, 16, 64, 256}, {4, 16, 64, 256, 1024, 4096}};
  c.info.metrics = {
      error_metric("end_displacement", "length", "|r(L) - (L + FL/EA) t| (exact: round-off)", std::nullopt),
      error_metric("edge_force_error", "force", "max over edges of |n.t - F| and |n.N|", std::nullopt),
      spread_metric(std::nullopt)};
  // Round-off: r(L) sums N chords of ~eps error each; 64 N eps (L + FL/EA) at N = 4096 is 1e-10;
  // at the default N <= 256, 64 * 256 * eps = 3.6e-12 of max(L, stretched length) -> 1e-11 for every level.
  // Both gates relative (to max(L, stretched length); to max(|F|, EI/L^2)): absolute ones failed at
  // F = 1e6 (end 1.2e-11, forces 1.2e-10 = eps F) and at F = 1e4 on the arcs.
  GateSpec end = upper_bound_gate("end_displacement", 1e-11, GateScope::AllLevels,
                                  "exact for any N: round-off only (64 N eps of max(L, stretched length), N <= 256)");
  end.relative = true;
  end.name = "end_displacement <= 1e-11 x max(L, stretched length) at every level";
  GateSpec force = upper_bound_gate("edge_force_error", 1e-12, GateScope::AllLevels,
                                    "the force balance is exact: Newton tolerance 1e-13 x 10, of max(|F|, EI/L^2)");
  force.relative = true;
  force.name = "edge_force_error <= 1e-12 x max(|F|, EI/L^2) at every level";
  c.gates = {end, force,
             upper_bound_gate("H_spread", 1e-13, GateScope::AllLevels,
                              "H = F + F^2/(2EA) at every node: round-off (~100 eps)")};
  c.run_level = [scheme](const Parameters& p, double level) { return run_tension_level(scheme, p, level); };
  return c;
}

// ---- cantilever: the mpmath table, or the shooting solver at any other parameters ----------------

// tests/data/reissner_reference.csv (make_reissner_table.py, 30 digits), s = L = 1, EI = 1, P = 5,
// EA = 100; rounded to double. test_reissner_cases checks these against the CSV.
struct TableRow {
  double GA, tip_x, tip_y, tip_theta, H;
};
constexpr TableRow kTable[] = {
    {100.0, 0.61237163927557012813826591682, -0.763791523611912728090351434405,
     -1.21536811761168109594092458288, 4.81248780736311228913598414654},
    {40.0, 0.598662724254652067857758185329, -0.786410364979057123364567123592,
     -1.18983739197582936723860402698, 4.79246321765001971620955493985},
};
constexpr double kTableP = 5.0, kTableEA = 100.0;

struct Cantilever {
  double L, EI, P, EA, GA;
};
Cantilever cantilever_of(const Parameters& p) {
  return {parameter_value(p, "L"), parameter_value(p, "EI"), parameter_value(p, "P"), parameter_value(p, "EA"),
          parameter_value(p, "GA")};
}

e2d::Problem cantilever_problem(const Cantilever& c) {
  e2d::Problem problem;
  problem.length = c.L;
  problem.bending_stiffness = [EI = c.EI](double) { return EI; };
  problem.start.support = e2d::Support::Clamped;
  problem.end.load.force_y = -c.P;
  problem.axial_stiffness = c.EA;
  problem.shear_stiffness = c.GA;
  return problem;
}

struct CantileverReference {
  double tip_x = 0.0, tip_y = 0.0, tip_theta = 0.0, H = 0.0;
  double uncertainty = 0.0;  // estimated error of the reference (0: the 30-digit table)
};

const TableRow* table_row(const Cantilever& c) {
  for (const TableRow& row : kTable)
    if (c.L == 1.0 && c.EI == 1.0 && c.P == kTableP && c.EA == kTableEA && c.GA == row.GA) return &row;
  return nullptr;
}

// Off the table: the shooting solver (RKF78 at 1e-13, Newton to 1e-11; it reproduces the table to
// 7.5e-13, test ShootingReissner.MatchesMpmathTable), started from the arcs solution at N = 64. Its
// uncertainty: the largest change of the four values when the ODE tolerance is 1e-11 instead, an
// upper estimate (the global error follows the tolerance: ShootingAccuracy.ErrorFollowsOdeTolerance).
CantileverReference shooting_reference(const Cantilever& c) {
  const e2d::Problem problem = cantilever_problem(c);
  e2d::SolverOptions discrete_options;
  discrete_options.load_steps = 4;
  const auto guess = e2d::shooting_guess_from(e2d::solve_static(problem, {e2d::Scheme::Arcs, 64}, discrete_options), problem);
  const auto at_tolerance = [&](double ode_tolerance) {
    e2d::ShootingOptions options;
    options.sample_points = 1;
    options.ode_abs_tolerance = options.ode_rel_tolerance = ode_tolerance;
    const PlanarRodSolution solution = e2d::solve_shooting(problem, options, guess);
    return CantileverReference{solution.x.back(), solution.y.back(), solution.theta.back(),
                               invariants::planar_noether_spread(solution).mean, 0.0};
  };
  CantileverReference reference = at_tolerance(1e-13);
  const CantileverReference loose = at_tolerance(1e-11);
  reference.uncertainty = std::max({std::abs(reference.tip_x - loose.tip_x), std::abs(reference.tip_y - loose.tip_y),
                                    std::abs(reference.tip_theta - loose.tip_theta), std::abs(reference.H - loose.H)});
  return reference;
}

CantileverReference cantilever_reference(const Cantilever& c) {
  if (const TableRow* row = table_row(c)) return {row->tip_x, row->tip_y, row->tip_theta, row->H, 0.0};
  return shooting_reference(c);
}

Solution solve_cantilever(e2d::Scheme scheme, const Parameters& parameters, double level) {
  e2d::SolverOptions options;
  options.tolerance = 1e-12;
  options.load_steps = 2;
  return e2d::solve_static(cantilever_problem(cantilever_of(parameters)), {scheme, element_count(level)}, options);
}

// Reads only the solution's nodes and, where given, its forces (H and the strains): a file from an
// extensible, shearable rod code (a Cosserat rod such as PyElastica's) is measured like rodvv's own.
LevelOutput measure_cantilever(const Parameters& parameters, double, const Solution& any) {
  const auto& solution = solution_as<PlanarRodSolution>(any, "planar_rod");
  const Cantilever c = cantilever_of(parameters);
  const CantileverReference reference = cantilever_reference(c);
  LevelOutput output;
  output.metrics["tip_x"] = error_sample(solution.x.back(), reference.tip_x);
  output.metrics["tip_y"] = error_sample(solution.y.back(), reference.tip_y);
  output.metrics["tip_x"].scale = output.metrics["tip_y"].scale = c.L;  // a tip near an axis: the rod's length
  output.metrics["tip_theta"] = error_sample(solution.theta.back(), reference.tip_theta);
  output.metrics["reference_uncertainty"] = {reference.uncertainty, std::nullopt, std::nullopt};
  if (solution.iterations > 0)
    output.metrics["newton_iterations"] = {double(solution.iterations), std::nullopt, std::nullopt};
  output.series.push_back(thin_series("shape|computed", "x", "y", solution.x, solution.y));
  if (solution.axial_force.empty()) return output;  // a file without forces: no H, no strains
  const auto spread = invariants::planar_noether_spread(solution);
  output.metrics["H_mean"] = error_sample(spread.mean, reference.H);
  add_noether(output, solution);
  std::vector<double> stretch(solution.s.size()), shear(solution.s.size());
  for (std::size_t i = 0; i < stretch.size(); ++i) {
    stretch[i] = solution.axial_force[i] / c.EA;
    shear[i] = solution.shear_force.empty() ? 0.0 : solution.shear_force[i] / c.GA;
  }
  output.series.push_back(thin_series("strains|stretch n.t/EA", "s", "strain", solution.s, stretch));
  output.series.push_back(thin_series("strains|shear n.N/GA", "s", "strain", solution.s, shear));
  return output;
}

// Errors at N = 256 measured with `rodvv sweep` (2026-11-21), GA = 40 (critical load: N = 128).
struct CantileverBounds {
  double tip_x, tip_y, tip_theta, H_spread;
};
constexpr CantileverBounds kPolygonBounds{2.275e-06, 4.673e-06, 2.267e-06, 6.67e-06};
constexpr CantileverBounds kArcsBounds{1.170e-06, 1.714e-06, 2.030e-06, 1.06e-05};

Case cantilever_case(e2d::Scheme scheme) {
  const std::string id(e2d::scheme_id(scheme));
  Case c = base_case("elastica/reissner-cantilever/" + id, "elastica/reissner-cantilever",
                     "extensible, shearable cantilever under a dead tip load (default P L^2/EI = 5, EA = 100, GA = 40), " + id,
                     scheme);
  c.info.physics =
      "Cantilever clamped horizontally at s = 0, vertical dead tip load P: theta' = m/EI, "
      "m' = -(r' x n), r' = (1 + n.t/EA) t + (n.N/GA) N, n = (0, -P).";
  c.info.reference =
      "at L = EI = 1, P = 5, EA = 100, GA = 40 or 100: the 30-digit mpmath shooting table "
      "(tests/data/make_reissner_table.py: odefun + findroot on the clamp moment); at any other parameters: the "
      "shooting solver (RKF78 at 1e-13, which reproduces the table to 7.5e-13), its uncertainty reported; tip "
      "position and rotation, H";
  c.info.parameters = {make_parameter("L", 1.0, 0.0, 1e6, true, false, "length", "rod length"),
                       stiffness("EI", 1.0, "bending stiffness"),
                       make_parameter("P", kTableP, 0.0, 1e6, true, false, "force", "dead tip load, downwards"),
                       stiffness("EA", kTableEA, "axial stiffness"),
                       stiffness("GA", 40.0, "shear stiffness (the table has 40 and 100)")};
  c.info.resolution = {"N", "number of elements", ResolutionScale::Count, {32, 64, 128, 256},
                       {32, 64, 128, 256, 512, 1024}};
  c.info.metrics = {error_metric("tip_x", "length", "tip x vs the reference"),
                    error_metric("tip_y", "length", "tip y vs the reference"),
                    error_metric("tip_theta", "rad", "tip section angle vs the reference"),
                    error_metric("H_mean", "force", "mean of H(s) vs the reference H"),
                    {"reference_uncertainty", MetricKind::Diagnostic, "length",
                     "estimated error of the reference (0: the table; shooting: change at ODE tolerance 1e-11)", false,
                     std::nullopt},
                    {"newton_iterations", MetricKind::Diagnostic, "", "Newton iterations", false, std::nullopt},
                    spread_metric(2.0)};
  // The load its levels resolve: P L^2 / EI in [0.005, 20] (the table: 5). Measured, both schemes:
  // every gate passes at 0.005, 0.05, 0.5, 5, 20 and at L = 1e3 or 1e-3 with EI scaled; at 50 the
  // arcs' H spread order leaves its window, at 100 six gates fail (the tip curls past the levels'
  // reach); at 1e-4 and below the tip errors reach their round-off floors (orders undefined).
  cases::require(c, cases::load_window("L", 0.005, 20.0,
                                        "the table's 5: beyond 20 the default levels do not reach the asymptotic "
                                        "range, below 0.005 the tip errors are at round-off"));
  // Strains the levels resolve. The stretch 1 + n.t/EA must stay positive where the rod points
  // against the load (n.t down to -P): EA / P > 1; measured, both schemes, every gate passes at
  // P / EA = 0.9 and P / GA = 1.5 together with P L^2/EI in {0.005, 0.5, 5, 20}; at P / GA = 2 and
  // P L^2/EI = 20 the H spread's order leaves its window (1.85 at P / GA = 12.5, P L^2/EI = 5), and
  // at P / EA = 2 six gates fail.
  cases::require(c, cases::ratio_window("EA", "P", 1.1, std::numeric_limits<double>::infinity(),
                                        "the axial strain P / EA the levels resolve; the stretch vanishes at EA = P"));
  cases::require(c, cases::ratio_window("GA", "P", 0.7, std::numeric_limits<double>::infinity(),
                                        "the shear strain P / GA the levels resolve"));
  const CantileverBounds& b = scheme == e2d::Scheme::Polygon ? kPolygonBounds : kArcsBounds;
  const double h = 1.0 / 256;
  for (const char* metric : {"tip_x", "tip_y", "tip_theta", "H_spread"})
    c.gates.push_back(order_gate(metric, 2.0, "both discretisations are second order in h = L/N"));
  c.gates.push_back(measured_bound("tip_x", b.tip_x, h));
  c.gates.push_back(measured_bound("tip_y", b.tip_y, h));
  c.gates.push_back(measured_bound("tip_theta", b.tip_theta, h));
  c.gates.push_back(measured_bound("H_spread", b.H_spread, h));
  split_level(
      c, [scheme](const Parameters& p, double level) { return solve_cantilever(scheme, p, level); },
      measure_cantilever);
  return c;
}

// ---- critical load ----------------------------------------------------------------------------

struct Column {
  double L, EI, EA, GA;
};

// theta(0)^2 on the first-mode branch at a load (0 if the column stays straight).
double end_rotation_squared(e2d::Scheme scheme, std::size_t n, double load, const Column& column) {
  const auto [L, EI, EA, GA] = column;
  e2d::Problem problem;
  problem.length = L;
  problem.bending_stiffness = [EI](double) { return EI; };
  problem.start.support = e2d::Support::Pinned;
  problem.end.support = e2d::Support::Sliding;
  problem.end.load.force_x = -load;
  problem.axial_stiffness = EA;
  problem.shear_stiffness = GA;
  e2d::InitialGuess guess;
  guess.theta = [L](double s) { return 0.2 * std::cos(kPi * s / L); };
  e2d::SolverOptions options;
  options.tolerance = 1e-13;
  const PlanarRodSolution solution = e2d::solve_static(problem, {scheme, n}, options, guess);
  return solution.theta.front() * solution.theta.front();
}

// Pitchfork: theta0^2 is linear in P near the bifurcation; the zero of the line through
// P0 (1 + delta) and P0 (1 + 2 delta) is the discrete critical load up to ~2 delta^2 relative.
double bifurcation_intercept(e2d::Scheme scheme, std::size_t n, double p0, double delta, const Column& column) {
  const double p1 = p0 * (1 + delta), p2 = p0 * (1 + 2 * delta);
  const double a1 = end_rotation_squared(scheme, n, p1, column);
  const double a2 = end_rotation_squared(scheme, n, p2, column);
  if (!(a2 > a1 && a1 > 0.0))
    throw SolverError("elastica2d-" + std::string(e2d::scheme_id(scheme)),
                      "no post-buckled branch above the trial loads", 0, 0.0);
  return (p1 * a2 - p2 * a1) / (a2 - a1);
}

LevelOutput run_critical_level(e2d::Scheme scheme, const Parameters& parameters, double level) {
  const Column column{parameter_value(parameters, "L"), parameter_value(parameters, "EI"),
                      parameter_value(parameters, "EA"), parameter_value(parameters, "GA")};
  const double exact = ref::reissner_pinned_critical_load(column.L, column.EI, column.EA, column.GA);
  const std::size_t n = element_count(level);
  // Three passes, each from the previous intercept: delta = 1e-2 from the continuum load (above the
  // discrete one, which differs by O(1e-3) at N = 16; intercept ~2e-4 off), then 2e-3 (~1e-5 off),
  // then 2e-4 (~1e-7 relative, far below the discretisation error ~ 5e-5 at N = 128).
  double discrete = exact;
  for (double delta : {1e-2, 2e-3, 2e-4}) discrete = bifurcation_intercept(scheme, n, discrete, delta, column);
  LevelOutput output;
  const double force = column.EI / (column.L * column.L);  // the unit of P_cr
  output.metrics["P_cr"] = error_sample(discrete / force, exact / force);
  return output;
}

Case critical_case(e2d::Scheme scheme) {
  const std::string id(e2d::scheme_id(scheme));
  Case c = base_case("elastica/reissner-critical-load/" + id, "elastica/reissner-critical-load",
                     "extensible, shearable pinned column: onset of buckling, " + id, scheme);
  c.info.physics =
      "Pinned-pinned column (sliding end) under a dead compressive load, EA and GA finite; the load at "
      "which the discrete first-mode post-buckled branch emerges from the straight state (theta0^2 "
      "extrapolated to 0 from two loads just above it).";
  c.info.reference =
      "P (1 + P (1/GA - 1/EA)) = pi^2 EI/L^2 (linearised Reissner column; Haringx's formula for "
      "EA = inf; references/reissner.hpp)";
  // L and EI not 1 (so that a mix-up of them or their powers shows): EA L^2/EI = 50.3, GA L^2/EI = 20.1.
  c.info.parameters = {make_parameter("L", 1.7, 0.0, 1e6, true, false, "length", "column length"),
                       stiffness("EI", 2.3, "bending stiffness"), stiffness("EA", 40.0, "axial stiffness"),
                       stiffness("GA", 16.0, "shear stiffness")};
  // GA <= EA: the first-mode branch then leaves the straight column upwards in P (supercritical), which
  // the intercept of theta0^2 from two loads just above the critical one needs (measured, both schemes:
  // GA = EA passes at EA = 15 .. 1e12; at EA = 50, GA = 85 and 100 .. 1e12 there is no post-buckled
  // branch above the critical load; EA = 20, GA = 30 fails alike). It also keeps the bifurcation of
  // the reference, 1 + 4 P_1 (1/GA - 1/EA) >= 1 > 0.
  require_window(c, "GA <= EA (beyond, the pitchfork can be subcritical)", [](const Parameters& p) {
    const double EA = parameter_value(p, "EA"), GA = parameter_value(p, "GA");
    if (!(GA <= EA))
      throw InputError("GA", "invalid parameters: the shear stiffness GA = " + format_value(GA) +
                                 " must be <= the axial stiffness EA = " + format_value(EA) +
                                 " (a stiffer shear than axial response can make the pitchfork subcritical, with no "
                                 "post-buckled branch above the critical load for the case to extrapolate from)");
  });
  c.info.resolution = {"N", "number of elements", ResolutionScale::Count, {16, 32, 64, 128},
                       {16, 32, 64, 128, 256, 512}};
  c.info.metrics = {error_metric("P_cr", "EI/L^2", "discrete bifurcation load vs the closed form")};
  c.gates = {order_gate("P_cr", 2.0, "the discrete bifurcation load converges at second order"),
             measured_bound("P_cr", scheme == e2d::Scheme::Polygon ? 3.362e-4 : 3.352e-4, 1.0 / 128)};
  c.run_level = [scheme](const Parameters& p, double level) { return run_critical_level(scheme, p, level); };
  return c;
}

}  // namespace

void register_reissner_cases(Registry& registry) {
  for (e2d::Scheme scheme : kSchemes) {
    registry.add(tension_case(scheme));
    registry.add(cantilever_case(scheme));
    registry.add(critical_case(scheme));
  }
}

}  // namespace rodvv::harness

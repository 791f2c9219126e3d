// Planar elastica in frictionless contact (solvers/elastica2d/contact.hpp, soft_wall.hpp), both
// discretisations, swept over the element count N (or over the wall softness b):
//
//   elastica-contact/cavity-free/<scheme>   pinned-pinned column of length L, stiffness EI between walls
//   elastica-contact/cavity-point/<scheme>  y = +/- a, a = 0.1 L, end-shortening 0.020 L (free), 0.026 L
//   elastica-contact/cavity-line/<scheme>   (point contact) and 0.0345 L (line contact, flat ~0.103 L),
//                                            against the elliptic branches of PHYSICS.md §4.1
//                                            (references/cavity.hpp); forces reported in units of EI / L^2,
//                                            lengths in L, curvatures in 1 / L
//   elastica-contact/cavity-point/polygon-lcp  the point contact solved by ContactMethod::NewtonLcp
//                                            (Josephy-Newton with the shared Lemke LCP), gated against
//                                            the same references and against the active-set result
//   elastica-contact/cavity-point/<scheme>-post, -ring  the point contact against a round ceiling that
//                                            touches the rod where the wall y = a does: a post (disk, rod
//                                            outside) of radius 0.15 L above, or a ring (rod inside) of
//                                            radius 5 L about a centre below. Both curve away from the rod there, so
//                                            the solution is the wall's: the cavity references, and P equal
//                                            to the walls' to round-off (issue 13, class 5: the advertised
//                                            disk obstacles had no case)
//   elastica-contact/soft-wall              V(y) = b/(a - y) + b/(a + y), b L / EI = 1e-4 .. 1e-7 (the
//                                            level), N = 256 arcs: P and H tend to the hard wall, H constant
//   elastica-contact/propped-cantilever/<scheme>  clamped, self-weight w, frictionless prop at the
//                                            tip: R = 3wL/8, M_root = wL^2/8 (small deflection)
//
// H = 1/2 EI kappa^2 + n.t - V is reported along s with the contact forces and the tension n.t;
// shapes are drawn with the wall lines.
#include <algorithm>
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
#include "rodvv/references/cavity.hpp"
#include "rodvv/solvers/elastica2d/contact.hpp"
#include "rodvv/solvers/elastica2d/soft_wall.hpp"

namespace rodvv::harness {

namespace {

namespace ref = rodvv::references;
namespace e2d = rodvv::solvers::elastica2d;
constexpr double kPi = std::numbers::pi;

constexpr const char* kCavityCitation =
    "Domokos, Holmes & Royce 1997, J. Nonlinear Sci. 7:281-314; Holmes, Domokos, Schmitt & "
    "Szeberenyi 1999, CMAME 170:175-207; H through contact: PHYSICS.md §1.2, §4.1-4.3";

const e2d::Scheme kSchemes[] = {e2d::Scheme::Polygon, e2d::Scheme::Arcs};

std::size_t element_count(double level) { return static_cast<std::size_t>(std::llround(level)); }

MetricSample error_sample(double computed, double reference) {
  return {computed, reference, std::abs(computed - reference)};
}

MetricSpec error_metric(std::string name, std::string unit, std::string description,
                        std::optional<double> order = 2.0) {
  return {std::move(name), MetricKind::Error, std::move(unit), std::move(description), false, order};
}

MetricSpec invariant_metric(std::string name, std::string description, std::optional<double> order) {
  return {std::move(name), MetricKind::Invariant, "", std::move(description), false, order};
}

GateSpec measured_bound(std::string metric, double at_finest, double h_finest, double order) {
  GateSpec gate = scaled_upper_bound_gate(std::move(metric), 2.0 * at_finest / std::pow(h_finest, order), order,
                                          GateScope::FinestLevel,
                                          "C = 2 x the value measured at the finest default level / h^p");
  gate.measured = true;
  return gate;
}

// The LCP solver of the condensed (Josephy-Newton) path, or none: the active-set path.
using CondensedLcp = std::optional<solvers::contact::LcpMethod>;

std::string scheme_text(e2d::Scheme scheme, CondensedLcp lcp = std::nullopt) {
  if (lcp)
    return std::string(scheme == e2d::Scheme::Polygon ? "polygon (nodal discrete elastica)"
                                                       : "arcs (reduced: exact circular arcs)") +
           "; hard frictionless contact at the nodes by Josephy-Newton: each iterate condenses the banded "
           "KKT onto the LCP in the contact forces of the (node, wall) pairs within a/2 of a wall "
           "(Delassus W = G K^-1 G^T), solved by " +
           (*lcp == solvers::contact::LcpMethod::Lemke ? "Lemke" : "projected Gauss-Seidel") + " (solvers/contact)";
  return std::string(scheme == e2d::Scheme::Polygon ? "polygon (nodal discrete elastica)"
                                                     : "arcs (reduced: exact circular arcs)") +
         "; hard frictionless contact at the nodes by a primal-dual active set around the KKT Newton "
         "solver (one multiplier row per active node, banded LU)";
}

// Shape with the walls, H(s), tension, contact forces.
void add_plots(LevelOutput& out, const PlanarRodSolution& rod, const std::vector<double>& force, double a) {
  out.series.push_back(thin_series("shape|rod", "x", "y", rod.x, rod.y));
  const std::vector<double> ends{rod.x.front(), rod.x.back()};
  out.series.push_back(thin_series("shape|wall y = +a", "x", "y", ends, {a, a}));
  out.series.push_back(thin_series("shape|wall y = -a", "x", "y", ends, {-a, -a}));
  out.series.push_back(thin_series("H(s)", "s", "H", rod.s, invariants::planar_noether_h(rod)));
  out.series.push_back(thin_series("tension n.t", "s", "n.t", rod.s, rod.axial_force));
  if (!force.empty()) out.series.push_back(thin_series("contact force per node", "s", "lambda", rod.s, force));
}

// ---- cavity buckling ----------------------------------------------------------------------------

enum class Regime { Free, Point, Line };

const char* regime_id(Regime r) {
  return r == Regime::Free ? "cavity-free" : r == Regime::Point ? "cavity-point" : "cavity-line";
}

const char* regime_words(Regime r) {
  return r == Regime::Free ? "free (no contact)" : r == Regime::Point ? "point-contact" : "line-contact (flat <= 0.4 L)";
}

// The column's scales: its length L and bending stiffness EI, the imposed shortening d and the wall gap a
// (lengths). Its solution depends on d / L and a / L alone, with forces in units of EI / L^2: the regimes,
// the windows and the measured bounds are stated in those groups (measured at L = EI = 1), and the metrics
// are reported in those units. The defaults are not 1 (as the closed-form elastica cases), so that a
// mix-up of L, EI or their powers shows.
constexpr double kCavityLength = 1.7, kCavityStiffness = 2.3;
constexpr double kDefaultWallGap = 0.1;  // a / L

struct Column {
  double L, EI, d, a;
  double d_hat() const { return d / L; }
  double a_hat() const { return a / L; }
  double force_unit() const { return EI / (L * L); }
};

Column column_of(const Parameters& p) {
  return {parameter_value(p, "L"), parameter_value(p, "EI"), parameter_value(p, "shortening"),
          parameter_value(p, "wall_gap")};
}

// The pinned-pinned column with its end moved in by d (the cavity cases and the soft wall).
e2d::Problem column_problem(const Column& col) {
  e2d::Problem problem;
  problem.length = col.L;
  problem.bending_stiffness = [EI = col.EI](double) { return EI; };
  problem.start.support = e2d::Support::Pinned;
  problem.end.support = e2d::Support::Pinned;
  problem.end.x = col.L - col.d;
  return problem;
}

// The first mode bowed to 0.8 a (admissible between the walls); stepping moves the end.
e2d::InitialGuess bowed_guess(const Column& col) {
  e2d::InitialGuess guess;
  guess.theta = [a = col.a, L = col.L](double s) { return 0.8 * a * kPi / L * std::cos(kPi * s / L); };
  return guess;
}

// The wall gaps the cases honour, a / L: up to 0.3 (the reference's reachable gaps end at 0.33), from 1e-3 (the
// reference's line branch is not bracketed at 1.7e-7; the point cases' own windows start at 0.03).
constexpr double kMinWallGap = 1e-3, kMaxWallGap = 0.3;

void check_wall_gap(const Parameters& p) {
  const Column col = column_of(p);
  if (!cases::inside(col.a_hat(), kMinWallGap, kMaxWallGap))
    throw InputError("wall_gap", fmt::format("invalid parameter 'wall_gap' = {}: the cavity cases honour {} <= "
                                             "wall_gap / L <= {} ({:.6g} .. {:.6g} at L = {})",
                                             format_value(col.a), kMinWallGap, kMaxWallGap, kMinWallGap * col.L,
                                             kMaxWallGap * col.L, format_value(col.L)));
}

// What stands at y = +a above the column (the floor y = -a is always a wall).
enum class Ceiling { Wall, Post, Ring };
constexpr double kPostRadius = 0.15;  // in units of L; any radius: the post curves away from the rod
// In units of L. The ring curves toward the rod (y = a - x^2 / 2R about the contact): it must curve less than
// the rod there (|kappa_c| L = 0.77 at the default shortening: R > 1.3 L) and still hold its pinned ends
// (sqrt(0.487^2 + (R - a)^2) < R: R > 1.2 L at a = 0.1 L).
constexpr double kRingRadius = 5.0;

const char* ceiling_id(Ceiling c) { return c == Ceiling::Wall ? "" : c == Ceiling::Post ? "-post" : "-ring"; }

// The obstacles: the walls, or the floor and a disk touching y = a above the chord's midpoint x = (L - d) / 2.
std::vector<e2d::Obstacle> cavity_obstacles(Ceiling ceiling, const Column& col) {
  const double a = col.a;
  if (ceiling == Ceiling::Wall) return e2d::cavity_walls(a);
  const double x_mid = 0.5 * (col.L - col.d);
  if (ceiling == Ceiling::Post) {
    const double R = kPostRadius * col.L;
    return {e2d::floor_at(-a), e2d::disk_outside({x_mid, a + R}, R)};
  }
  const double R = kRingRadius * col.L;
  return {e2d::floor_at(-a), e2d::disk_inside({x_mid, a - R}, R)};
}

// The ring touches the rod from inside where the rod curves more than it, and must hold the pinned ends:
// InputError naming the parameter otherwise (near the point regime's end kappa_c -> 0 and the rod would
// lean on the ring over a stretch; a narrow gap puts the ends outside it). In units of L.
void check_ring(const Parameters& p) {
  const Column col = column_of(p);
  const double d = col.d_hat(), a = col.a_hat();
  const double x_mid = 0.5 * (1.0 - d);
  if (!(std::hypot(x_mid, kRingRadius - a) < kRingRadius - 0.01))
    throw InputError("wall_gap",
                     fmt::format("invalid parameter 'wall_gap' = {}: the ring of radius {} L touching y = wall_gap does "
                                 "not hold the pinned ends (needs wall_gap / L > {:.4g})",
                                 format_value(col.a), kRingRadius,
                                 kRingRadius - std::sqrt(std::pow(kRingRadius - 0.01, 2) - x_mid * x_mid)));
  const double kappa_c = std::abs(ref::cavity_from_shortening({1.0, 1.0, a}, d).kappa_mid);
  if (!(kappa_c >= 1.5 / kRingRadius))
    throw InputError("shortening", fmt::format("invalid parameter 'shortening' = {}: the rod's curvature at the "
                                               "contact, {:.4g} / L, must be >= 1.5 / ({} L) for the ring to touch it "
                                               "at one point only",
                                               format_value(col.d), kappa_c, kRingRadius));
}

// The longest flat the line case runs: its solvers, measured over wall_gap 0.03 ... 0.2 and flats
// 0.05 ... 0.4 L, pass every gate (but H_spread's order, 1.88 at l = 0.2 L on both schemes' default
// levels, pre-asymptotic: 2.06 over N = 32 ... 1024); beyond, the arcs scheme's active set cycles (l = 0.45 L at wall_gap 0.1:
// "did not settle"; its Lemke path meets an indefinite Delassus matrix there) - not honoured, refused.
constexpr double kLineCaseMaxFlat = 0.4;

// The shortenings d / L of a regime at a wall gap a / L: free below the touch, point contact up to
// the transition where kappa_c = 0, line contact up to a flat of kLineCaseMaxFlat (or the end of the
// reference's line branch, where the side waves stop reaching the walls).
std::pair<double, double> regime_interval(Regime r, double wall_gap) {
  const ref::CavityColumn column{1.0, 1.0, wall_gap};
  if (r == Regime::Free) return {0.0, ref::cavity_touch_shortening(column)};
  if (r == Regime::Point) return {ref::cavity_touch_shortening(column), ref::cavity_transition_shortening(column)};
  const double flat = std::min(kLineCaseMaxFlat, ref::cavity_max_flat_length(column));
  return {ref::cavity_transition_shortening(column), ref::cavity_line_contact(column, flat).shortening};
}

// The interval in units of `unit` (1: the dimensionless d / L; L: a length).
std::string regime_interval_text(Regime r, double wall_gap_over_L, double unit, const char* quantity) {
  const auto [lo, hi] = regime_interval(r, wall_gap_over_L);
  return fmt::format("{:.6g} < {} {} {:.6g}", lo * unit, quantity, r == Regime::Free ? "<" : "<=", hi * unit);
}

// A case of one regime refuses a shortening of another: its references and gates are that regime's
// (a point-contact case at a shortening of the line regime compared a line solution with kappa_c = 0).
void check_regime(Regime r, const Parameters& p) {
  const Column col = column_of(p);
  const double d = col.d_hat();
  const auto [lo, hi] = regime_interval(r, col.a_hat());
  if (!(d > lo && (r == Regime::Free ? d < hi : d <= hi)))
    throw InputError("shortening",
                     fmt::format("invalid parameter 'shortening' = {}: the {} regime at wall_gap = {} and L = {} is {} "
                                 "({})",
                                 format_value(col.d), regime_words(r), format_value(col.a), format_value(col.L),
                                 regime_interval_text(r, col.a_hat(), col.L, "shortening"),
                                 regime_interval_text(r, col.a_hat(), 1.0, "shortening / L")));
}

// The part of the point regime a point case honours, from the touch (0) to the transition (1), and the
// wall gaps (a / L). Measured 2026-11-27 over wall_gap 0.01 .. 0.3 and fractions 0.02 .. 1 (rodvv run at
// each): below 0.1 the curvature step's order is pre-asymptotic on the default levels (0.56 .. 0.88 at 0.02
// and 0.05); at the transition the H spread's O(h) part vanishes (order 2.04) and at 0.8 - 0.9 the
// curvature step is no longer resolved at wall_gap 0.3 (0.111 of its size) - the walls and the ring hold
// to 0.6. The condensed LCP paths and the post stop converging earlier ("Newton with 2 active contacts did
// not converge"): the LCP paths hold to 0.4 (fail at 0.6, wall_gap 0.3), the post to 0.4 at wall_gap <=
// 0.15 (fails at 0.6 from wall_gap 0.12, at 0.2 at wall_gap 0.3). Below wall_gap 0.03 the coarsest level's
// Newton stops ("1 active contact did not converge", wall_gap 0.01 .. 0.025, fractions 0.25 .. 0.6).
struct PointWindow {
  double low = 0.1, high = 0.6;
  double min_wall_gap = 0.03, max_wall_gap = 0.3;
};
PointWindow point_window(CondensedLcp lcp, Ceiling ceiling) {
  if (ceiling == Ceiling::Post) return {0.1, 0.4, 0.03, 0.15};
  if (lcp) return {0.1, 0.4, 0.03, 0.3};
  return {};
}

void check_point_window(const PointWindow& w, const Parameters& p) {
  const Column col = column_of(p);
  const double d = col.d_hat(), a = col.a_hat();
  if (!cases::inside(a, w.min_wall_gap, w.max_wall_gap))
    throw InputError("wall_gap", fmt::format("invalid parameter 'wall_gap' = {}: this case is measured to converge "
                                             "for {} <= wall_gap / L <= {} ({:.6g} .. {:.6g} at L = {}; beyond, its "
                                             "Newton stops)",
                                             format_value(col.a), w.min_wall_gap, w.max_wall_gap,
                                             w.min_wall_gap * col.L, w.max_wall_gap * col.L, format_value(col.L)));
  const auto [touch, transition] = regime_interval(Regime::Point, a);
  const double lo = touch + w.low * (transition - touch), hi = touch + w.high * (transition - touch);
  if (!cases::inside(d, lo, hi))
    throw InputError("shortening", fmt::format("invalid parameter 'shortening' = {}: at wall_gap = {} and L = {} this "
                                               "case honours {:.6g} <= shortening <= {:.6g} ({:.6g} .. {:.6g} L), the "
                                               "fractions {} .. {} of the point regime from the touch to the "
                                               "transition (where its levels are asymptotic and its Newton converges)",
                                               format_value(col.d), format_value(col.a), format_value(col.L),
                                               lo * col.L, hi * col.L, lo, hi, w.low, w.high));
}

LevelOutput run_cavity_level(e2d::Scheme scheme, Regime regime, const Parameters& p, double level,
                             CondensedLcp lcp = std::nullopt, Ceiling ceiling = Ceiling::Wall) {
  const Column col = column_of(p);
  const double L = col.L, a = col.a;
  const ref::CavityState r = ref::cavity_from_shortening({L, col.EI, a}, col.d);
  const double force_unit = col.force_unit();
  const e2d::Problem problem = column_problem(col);
  e2d::SolverOptions options;
  options.load_steps = 8;
  const e2d::InitialGuess guess = bowed_guess(col);
  const std::size_t n = element_count(level);
  e2d::ContactOptions contact;
  if (lcp) {
    contact.method = e2d::ContactMethod::NewtonLcp;
    contact.lcp = *lcp;
    contact.candidate_distance = 0.5 * a;  // the far wall and the pinned ends stay out of the LCP
  }
  const auto c =
      e2d::solve_static_contact(problem, {scheme, n}, cavity_obstacles(ceiling, col), options, guess, contact);
  const PlanarRodSolution& rod = c.rod;

  LevelOutput out;
  if (ceiling != Ceiling::Wall) {
    // The same discrete problem as against the wall while only the node at the midpoint touches: P to
    // round-off, in eps of P.
    const auto walls = e2d::solve_static_contact(problem, {scheme, n}, e2d::cavity_walls(a), options, guess, contact);
    const double P_walls = -walls.rod.force_x[n / 2];
    const double dP = std::abs(-rod.force_x[n / 2] - P_walls) / (std::numeric_limits<double>::epsilon() * std::abs(P_walls));
    out.metrics["P_vs_walls"] = {dP, 0.0, dP};
  }
  if (lcp) {
    // Agreement with the active-set path (same discrete problem, both to residual <= 1e-10), in units of
    // EI / L^2, and the residual of the last LCP relative to its max|b|.
    const auto active = e2d::solve_static_contact(problem, {scheme, n}, e2d::cavity_walls(a), options, guess);
    const double dP = std::abs(rod.force_x[n / 2] - active.rod.force_x[n / 2]) / force_unit;
    out.metrics["P_vs_active_set"] = {dP, 0.0, dP};
    const double lcp_residual = c.lcp_scale > 0.0 ? c.lcp_residual / c.lcp_scale : 0.0;
    out.metrics["lcp_residual"] = {lcp_residual, 0.0, lcp_residual};
    out.metrics["lcp_pivots"] = {double(c.lcp_iterations), std::nullopt, std::nullopt};
    out.metrics["lcp_size"] = {double(c.lcp_candidates), std::nullopt, std::nullopt};
  }
  // Forces in units of EI / L^2, curvatures in 1 / L, lengths in L.
  out.metrics["P"] = error_sample(-rod.force_x[n / 2] / force_unit, r.P / force_unit);
  double wall = 0.0;
  std::vector<double> force(rod.nodes(), 0.0);
  for (const auto& k : c.contacts) {
    wall += k.force;
    force[k.node] += k.force;
  }
  out.metrics["wall_force"] = error_sample(wall / force_unit, r.wall_force / force_unit);
  const auto spread = invariants::planar_noether_spread(rod);
  out.metrics["H_mean"] = error_sample(spread.mean / force_unit, r.H / force_unit);
  // Sizes: H_spread is in units of H's natural scale; the curvature at the contact or 1/L.
  out.metrics["H_spread"] = {spread.spread, 0.0, spread.spread, 1.0};
  const double penetration = std::max(0.0, -*std::min_element(c.min_gap.begin(), c.min_gap.end())) / L;
  out.metrics["penetration"] = {penetration, 0.0, penetration};
  out.metrics["contacts"] = {double(c.contacts.size()), std::nullopt, std::nullopt};
  out.metrics["newton_iterations"] = {double(rod.iterations), std::nullopt, std::nullopt};
  if (regime == Regime::Point) {
    const std::size_t m = n / 2;
    out.metrics["kappa_contact"] = error_sample(std::abs(rod.kappa[m]) * L, r.kappa_mid * L);
    const double size = std::max(std::abs(r.kappa_mid) * L, 1.0);  // kappa_c -> 0 at the transition
    out.metrics["kappa_contact"].scale = size;
    const double jump =
        std::max(std::abs(rod.kappa[m + 1] - rod.kappa[m]), std::abs(rod.kappa[m] - rod.kappa[m - 1])) * L;
    out.metrics["kappa_step"] = {jump, 0.0, jump, size};
  }
  if (regime == Regime::Free)
    out.metrics["kappa_mid"] = error_sample(std::abs(rod.kappa[n / 2]) * L, r.kappa_mid * L);
  if (regime == Regime::Line && !c.contacts.empty()) {
    // Flat length: the contact-force centroids of the two halves (the concentrated edge reactions
    // spread over a few nodes).
    double sl = 0, fl = 0, sr = 0, fr = 0;
    for (const auto& k : c.contacts) {
      (rod.s[k.node] < 0.5 * L ? sl : sr) += k.force * rod.s[k.node];
      (rod.s[k.node] < 0.5 * L ? fl : fr) += k.force;
    }
    out.metrics["flat_length"] = error_sample((sr / fr - sl / fl) / L, r.flat_length / L);
    // The flat: the nodes from the first to the last contact with the wall the middle of the run holds. In
    // the continuum it carries no distributed force (kappa = 0 there, so m' = 0 and the shear vanishes),
    // and its inner nodes may be inactive (lambda = 0), at any g >= -64 eps (L + max|r|) ~ 5e-14 (an
    // inactive node of a polygon's flat is in equilibrium with straight edges: on the wall to round-off).
    // Measured as each vertex's offset from the chord of its neighbours, |kappa_i| h^2 / 2 (kappa_i the
    // turning angle / h), a length like the gaps (in L): a bound on kappa alone would grow as 1 / h^2 (a sag
    // of 1.6e-14 over eleven inactive nodes is kappa = 1.6e-10 at N = 256, wall_gap 0.2, L = 1).
    const std::size_t middle = c.contacts[c.contacts.size() / 2].obstacle;
    std::size_t first = rod.nodes(), last = 0;
    for (const auto& k : c.contacts)
      if (k.obstacle == middle) first = std::min(first, k.node), last = std::max(last, k.node);
    double flat_offset = 0.0;
    for (std::size_t i = first + 1; i < last; ++i) {
      const double h = 0.5 * (rod.s[i + 1] - rod.s[i - 1]);
      flat_offset = std::max(flat_offset, 0.5 * std::abs(rod.kappa[i]) * h * h);
    }
    out.metrics["flat_offset"] = {flat_offset / L, 0.0, flat_offset / L};
  }
  add_plots(out, rod, force, a);
  if (ceiling != Ceiling::Wall) {  // draw the disk's arc over the chord instead of the wall y = a
    const bool post = ceiling == Ceiling::Post;
    const double R = (post ? kPostRadius : kRingRadius) * L, x_mid = 0.5 * (L - col.d), yc = post ? a + R : a - R;
    std::vector<double> xs, ys;
    for (int i = 0; i <= 100; ++i) {
      const double x = x_mid + std::min(R, x_mid) * (2.0 * i / 100.0 - 1.0);
      xs.push_back(x);
      const double half = std::sqrt(std::max(0.0, R * R - (x - x_mid) * (x - x_mid)));
      ys.push_back(post ? yc - half : yc + half);
    }
    for (auto& series : out.series)
      if (series.name == "shape|wall y = +a") series = thin_series(post ? "shape|post" : "shape|ring", "x", "y", xs, ys);
  }
  return out;
}

// Gates. Values measured with `rodvv sweep ... --levels 32,64,128,256` (2026-11-21) at N = 256.
void order_and_bound(Case& c, const char* metric, double order, double at_256, const std::string& why) {
  c.gates.push_back(order_gate(metric, order, why));
  c.gates.push_back(measured_bound(metric, at_256, 1.0 / 256, order));
}

void add_cavity_gates(Case& c, e2d::Scheme scheme, Regime regime) {
  const bool arcs = scheme == e2d::Scheme::Arcs;
  const std::string second = "smooth solution functional: both discretisations are second order in h = L/N";
  // Penetration: a contact row holds g = 0 to the Newton tolerance; inactive nodes are accepted
  // down to g = -64 eps (L + max|r|) ~ 5e-14 (2.5e-14 L at the defaults): bound 1e-13 at every level.
  c.gates.push_back(upper_bound_gate("penetration", 1e-13, GateScope::AllLevels,
                                     "never beyond round-off: 64 eps (L + max|r|) / L < 1e-13"));
  if (regime == Regime::Free) {
    order_and_bound(c, "P", 2.0, 1.2512e-4, second);
    order_and_bound(c, "H_mean", 2.0, arcs ? 1.2989e-4 : 1.2007e-4, second);
    order_and_bound(c, "H_spread", 2.0, arcs ? 1.8990e-6 : 1.4708e-6, "H drift of a smooth discrete solution is O(h^2)");
    order_and_bound(c, "kappa_mid", 2.0, arcs ? 1.1430e-5 : 5.5228e-6, second);
    c.gates.push_back(upper_bound_gate("wall_force", 0.0, GateScope::AllLevels, "no contact: exactly zero force"));
    return;
  }
  if (regime == Regime::Point) {
    order_and_bound(c, "P", 2.0, arcs ? 1.7389e-3 : 3.7396e-4, second);
    order_and_bound(c, "wall_force", 2.0, arcs ? 8.3702e-4 : 1.6037e-4, second);
    order_and_bound(c, "H_mean", 2.0, arcs ? 1.7913e-3 : 3.7834e-4, second);
    // polygon: H at the contact node uses the mean of the two edge forces across the concentrated
    // force, an O(h) local error (measured order 0.99); arcs: O(h^2) (1.98).
    order_and_bound(c, "H_spread", arcs ? 2.0 : 1.0, arcs ? 1.8856e-6 : 1.7574e-4,
                    arcs ? "O(h^2) through the contact" : "O(h) at the contact node (edge-force average across the kink)");
    // arcs: the node curvature is the mean of the two element curvatures across the kink in kappa
    // (kappa' jumps by the contact force): O(h); polygon: the vertex curvature, O(h^2).
    order_and_bound(c, "kappa_contact", arcs ? 1.0 : 2.0, arcs ? 4.3783e-3 : 1.6532e-6,
                    arcs ? "node value = mean of the elements across the kink: O(h)" : second);
    // Continuity: neighbours differ by |kappa'| h (kappa' = shear / EI jumps but stays bounded);
    // a jump in kappa would keep this O(1).
    order_and_bound(c, "kappa_step", 1.0, arcs ? 4.3341e-3 : 8.7782e-3, "kappa continuous: step to the neighbours = O(h)");
    return;
  }
  // Line contact: the lift-off points fall between nodes, so the error oscillates with their
  // position in the grid (measured pairwise orders 0.5..5): no order gate, an envelope C h^2 at every
  // level, C = 2 x max_N err(N) N^2 over the default levels (polygon 341 at N = 256, arcs 497 at 128).
  for (const char* metric : {"P", "wall_force", "H_mean"}) {
    GateSpec gate = scaled_upper_bound_gate(metric, arcs ? 2.0 * 497.0 : 2.0 * 341.0, 2.0, GateScope::AllLevels,
                                            "envelope C h^2, C = 2 x the largest err N^2 measured (lift-off between nodes)");
    gate.measured = true;
    c.gates.push_back(gate);
  }
  GateSpec flat = scaled_upper_bound_gate("flat_length", arcs ? 2.0 * 0.106 : 2.0 * 0.0101, 1.0, GateScope::AllLevels,
                                          "envelope C h, C = 2 x the largest err N measured (contact-force centroids)");
  flat.measured = true;
  c.gates.push_back(flat);
  // H_spread is O(h^2), but its constant moves with the lift-off points' places between nodes as the other
  // metrics' do: over the honoured window (wall_gap 0.04 .. 0.3, twelve shortenings across the regime, both
  // schemes; 2026-11-28) the fitted order on N = 32 .. 256 lies in 1.77 .. 2.0 (pairwise 1.61 .. 2.14), and
  // doubling the levels does not settle it (1.86 .. 2.0 on 64 .. 512). The order's band is that measured one
  // (the window [1.6, 2.5] still refuses an O(h) drift); its magnitude is bounded at the defaults.
  c.gates.push_back(order_range_gate("H_spread", 1.7, 2.0,
                                     "H drift O(h^2), also across the flat segment; the fitted order moves in 1.77 .. "
                                     "2.0 with the lift-off points' places between nodes (measured over the window)"));
  c.gates.push_back(measured_bound("H_spread", arcs ? 6.0224e-6 : 4.9524e-6, 1.0 / 256, 2.0));
  if (!arcs)  // polygon: the nodes of the run are on the wall, edges flat: kappa = 0 to round-off
    c.gates.push_back(upper_bound_gate("flat_offset", 2e-13, GateScope::AllLevels,
                                       "the flat on the wall to round-off: a vertex off its neighbours' chord by at "
                                       "most twice the gaps' 1e-13 (measured <= 1.2e-15 over the regimes)"));
}

Case cavity_case(e2d::Scheme scheme, Regime regime, CondensedLcp lcp = std::nullopt, Ceiling ceiling = Ceiling::Wall) {
  const bool pgs = lcp == solvers::contact::LcpMethod::ProjectedGaussSeidel;
  const std::string id =
      std::string(e2d::scheme_id(scheme)) + (lcp ? (pgs ? "-pgs" : "-lcp") : "") + ceiling_id(ceiling);
  const double d = regime == Regime::Free ? 0.020 : regime == Regime::Point ? 0.026 : 0.0345;  // d / L
  Case c;
  c.info.name = std::string("elastica-contact/") + regime_id(regime) + "/" + id;
  c.info.family = "elastica-contact";
  c.info.group = std::string("elastica-contact/") + regime_id(regime);
  c.info.title = std::string("Euler buckling in a cavity, shortening ") + std::to_string(d).substr(0, 6) + " L, " + id;
  c.info.physics =
      "Pinned-pinned elastica of length L and bending stiffness EI between frictionless rigid walls y = +/- a, "
      "end-shortening d imposed; hard contact 0 <= g _|_ lambda >= 0 at the nodes. The solution depends on "
      "d / L and a / L alone: forces are reported in units of EI / L^2, curvatures in 1 / L, lengths in L.";
  c.info.reference =
      "elliptic branches of PHYSICS.md §4.1 (references/cavity.hpp: free first mode, point contact with "
      "tilted force, line contact with inflexional half waves); H constant along s through contact";
  c.info.citation = kCavityCitation;
  c.info.method = scheme_text(scheme, lcp);
  c.info.parameters = {
      make_parameter("L", kCavityLength, 1e-6, 1e6, false, false, "length", "rod length"),
      make_parameter("EI", kCavityStiffness, 1e-6, 1e12, false, false, "force length^2", "bending stiffness"),
      make_parameter("shortening", d * kCavityLength, 0.0, 1e6, true, false, "length",
                     std::string("imposed end-shortening L - chord, inside the ") + regime_words(regime) +
                         " regime of the wall gap (at wall_gap = 0.1 L: " +
                         regime_interval_text(regime, kDefaultWallGap, 1.0, "shortening / L") + ")"),
      make_parameter("wall_gap", kDefaultWallGap * kCavityLength, 0.0, 1e6, true, false, "length",
                     "walls at y = +/- wall_gap")};
  require_window(c, fmt::format("{} <= wall_gap / L <= {}", kMinWallGap, kMaxWallGap), check_wall_gap);
  require_window(c, std::string("shortening inside the ") + regime_words(regime) + " regime of wall_gap",
                 [regime](const Parameters& p) { check_regime(regime, p); });
  c.info.resolution = {"N", "number of elements", ResolutionScale::Count, {32, 64, 128, 256},
                       {32, 64, 128, 256, 512, 1024}};
  c.info.metrics = {error_metric("P", "EI/L^2", "compressive end load vs the reference"),
                    error_metric("wall_force", "EI/L^2", "total contact force vs the reference"),
                    error_metric("H_mean", "EI/L^2", "mean of H(s) vs the reference H"),
                    invariant_metric("H_spread", "max |H(s) - mean| / natural scale", 2.0),
                    invariant_metric("penetration", "max(0, -min gap) / L over the nodes", std::nullopt),
                    {"contacts", MetricKind::Diagnostic, "", "active contact nodes", false, std::nullopt},
                    {"newton_iterations", MetricKind::Diagnostic, "", "Newton iterations", false, std::nullopt}};
  if (regime == Regime::Free)
    c.info.metrics.push_back(error_metric("kappa_mid", "1/L", "|kappa| at midspan vs 4kK/L"));
  if (regime == Regime::Point) {
    c.info.metrics.push_back(error_metric("kappa_contact", "1/L", "|kappa| at the contact node vs |kappa_c|"));
    c.info.metrics.push_back(invariant_metric(
        "kappa_step", "max |kappa_{c+-1} - kappa_c| L at the contact node: O(h) if kappa is continuous", 1.0));
  }
  if (regime == Regime::Line) {
    c.info.metrics.push_back(error_metric("flat_length", "L",
                                          "distance of the contact-force centroids of the two halves vs l",
                                          std::nullopt));
    c.info.metrics.push_back(invariant_metric(
        "flat_offset", "max |kappa| h^2 / (2 L) (a vertex's offset from its neighbours' chord) inside the flat",
        std::nullopt));
  }
  add_cavity_gates(c, scheme, regime);
  if (lcp) {
    // N = 256 alone costs 0.23 s (87..175 candidate pairs, one banded solve each per iteration):
    // it moves to the extended sweep; the C h^p bounds measured at 256 stay valid at 128 (x 4).
    c.info.resolution.default_levels = {32, 64, 128};
    c.info.metrics.push_back(
        invariant_metric("P_vs_active_set", "|P(NewtonLcp) - P(active set)| / (EI / L^2)", std::nullopt));
    c.info.metrics.push_back(invariant_metric("lcp_residual", "natural-map residual of the last LCP / max|b|", std::nullopt));
    c.info.metrics.push_back({"lcp_pivots", MetricKind::Diagnostic, "",
                              pgs ? "PGS sweeps, all Newton iterations" : "Lemke pivots, all Newton iterations",
                              false, std::nullopt});
    c.info.metrics.push_back({"lcp_size", MetricKind::Diagnostic, "", "pairs in the last LCP", false, std::nullopt});
    // Both paths stop at ||residual||_inf <= 1e-10; the solutions differ by at most kappa x the sum
    // of the residuals. kappa for forces measured <= 3.5e2 at N <= 64 (tests/solvers/
    // test_elastica2d_contact.cpp) and 9e2 here at N = 128 (P differs by 4.1e-8 with residuals
    // 4.6e-11; L = EI = 1); bound 3.5e3 x the two tolerances (2e-10) = 7e-7 (in EI / L^2: the unit is 0.80
    // at the defaults, and Newton's tolerance is on the residual in the solver's units).
    c.gates.push_back(upper_bound_gate("P_vs_active_set", 7e-7, GateScope::AllLevels,
                                       "same discrete problem: kappa (<= 3.5e3) x both tolerances (2e-10)"));
    c.gates.push_back(upper_bound_gate("lcp_residual", 1e-13, GateScope::AllLevels,
                                       pgs ? "PGS sweeps until the residual is <= its tolerance 1e-13 max|b|"
                                           : "Lemke is exact: round-off, below the LCP tolerance 1e-13 max|b|"));
  }
  if (regime == Regime::Point) {
    const PointWindow w = point_window(lcp, ceiling);
    require_window(c, fmt::format("shortening in the fractions {} .. {} of the point regime, wall_gap / L in [{}, {}] "
                                  "(where the levels are asymptotic and Newton converges)",
                                  w.low, w.high, w.min_wall_gap, w.max_wall_gap),
                   [w](const Parameters& p) { check_point_window(w, p); });
  }
  if (ceiling == Ceiling::Ring)
    require_window(c, "the ring curves less than the rod at the contact (|kappa_c| >= 1.5 / (5 L)) and holds the pinned ends",
                   [](const Parameters& p) { check_ring(p); });
  if (ceiling != Ceiling::Wall) {
    c.info.physics = ceiling == Ceiling::Post
                         ? "Pinned-pinned elastica of length L and stiffness EI above the frictionless wall y = -a "
                           "and below a rigid post (disk of radius 0.15 L) whose lowest point is at (chord / 2, a); "
                           "end-shortening d imposed; hard contact at the nodes. Depends on d / L and a / L alone."
                         : "Pinned-pinned elastica of length L and stiffness EI above the frictionless wall y = -a "
                           "and inside a rigid ring of radius 5 L whose highest point is at (chord / 2, a); "
                           "end-shortening d imposed; hard contact at the nodes. Depends on d / L and a / L alone.";
    c.info.reference += "; the round ceiling touches where the wall y = a does and curves away from the rod there, "
                        "so the solution is the walls'";
    c.info.metrics.push_back(invariant_metric("P_vs_walls", "|P - P(walls)| / (eps P(walls))", std::nullopt));
    // One active node at the same place with the same normal (0, -1): the same Newton systems, up to the
    // rounding of the disk's gap |r - c| - R, which cancels two numbers of the disk's size (0.4 L for the post,
    // 10 L for the ring, against a = 0.1 L) and moves the contact height by that many eps; the load P feels it
    // through the column's stiffness. Measured (2026-11-28, N = 32 .. 512, both schemes, Newton's residual in
    // the problem's units): at most 51 eps (post) and 555 eps (ring; 716 with the unscaled residual,
    // 2026-11-27); bound twice the post's and about twice the ring's largest.
    GateSpec same_as_walls = upper_bound_gate(
        "P_vs_walls", ceiling == Ceiling::Post ? 104.0 : 1500.0, GateScope::AllLevels,
        "the same discrete problem as against the wall, up to the rounding of the disk's gap at the disk's size "
        "(measured <= 51 eps for the post, 716 eps for the ring of radius 5 L; about twice that)");
    same_as_walls.measured = true;
    c.gates.push_back(same_as_walls);
  }
  c.run_level = [scheme, regime, lcp, ceiling](const Parameters& p, double level) {
    return run_cavity_level(scheme, regime, p, level, lcp, ceiling);
  };
  return c;
}

// ---- soft walls -------------------------------------------------------------------------------

// PHYSICS.md §4.2 (scipy solve_bvp, tolerance 1e-10; 7 significant digits), shortening 0.026, wall gap 0.1,
// L = EI = 1: b, P and H in units of EI / L, EI / L^2, EI / L^2.
struct SoftRow {
  double b, P, H;
};
constexpr SoftRow kSoftTable[] = {{1e-4, 23.99986, -23.84183}, {1e-5, 20.19246, -19.93396},
                                  {1e-6, 19.10895, -18.82219}, {1e-7, 18.84631, -18.55272}};

// The level is the dimensionless softness b L / EI; P and H are reported in units of EI / L^2.
LevelOutput run_soft_level(const Parameters& p, double softness) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
  const Column col{L, EI, 0.026 * L, 0.1 * L};
  const double a = col.a, b = softness * EI / L, force_unit = col.force_unit();
  const std::size_t n = element_count(parameter_value(p, "N"));
  e2d::SolverOptions options;
  options.load_steps = 16;
  const PlanarRodSolution rod =
      e2d::solve_soft_walls(column_problem(col), {e2d::Scheme::Arcs, n}, a, b, options, bowed_guess(col));
  const ref::CavityState hard = ref::cavity_from_shortening({L, EI, a}, col.d);
  LevelOutput out;
  const auto spread = invariants::planar_noether_spread(rod);
  const double P = -rod.force_x[n / 2] / force_unit, H = spread.mean / force_unit;
  out.metrics["P_vs_hard"] = error_sample(P, hard.P / force_unit);
  out.metrics["H_vs_hard"] = error_sample(H, hard.H / force_unit);
  out.metrics["H_spread"] = {spread.spread, 0.0, spread.spread, 1.0};
  for (const SoftRow& row : kSoftTable)
    if (std::abs(row.b - softness) <= 1e-12 * softness) {
      out.metrics["P_vs_table"] = error_sample(P, row.P);
      out.metrics["H_vs_table"] = error_sample(H, row.H);
    }
  double ymax = 0.0;
  for (double y : rod.y) ymax = std::max(ymax, y);
  out.metrics["wall_clearance"] = {(a - ymax) / L, std::nullopt, std::nullopt};
  add_plots(out, rod, {}, a);
  std::vector<double> h_partial(rod.nodes());
  for (std::size_t i = 0; i < rod.nodes(); ++i)
    h_partial[i] = 0.5 * EI * rod.kappa[i] * rod.kappa[i] + rod.axial_force[i];
  out.series.push_back(thin_series("h = 1/2 EI kappa^2 + n.t (not conserved)", "s", "h", rod.s, h_partial));
  return out;
}

Case soft_case() {
  Case c;
  c.info.name = "elastica-contact/soft-wall";
  c.info.family = "elastica-contact";
  c.info.group = "elastica-contact/soft-wall";
  c.info.title = "soft walls V = b/(a - y) + b/(a + y) -> hard wall as b -> 0, shortening 0.026 L";
  c.info.physics =
      "Pinned-pinned elastica of length L and bending stiffness EI, end-shortening 0.026 L, distributed "
      "potential V(y) = b/(a - y) + b/(a + y), a = 0.1 L; the level is the softness b L / EI (continuation in "
      "b from 1e-4 EI / L). P and H are reported in units of EI / L^2.";
  c.info.reference =
      "PHYSICS.md §4.2 table (solve_bvp, 7 digits) per b L / EI; hard-wall limit P = 18.77024913497 EI / L^2, "
      "H = -18.47467025139 EI / L^2 (§4.1); H = 1/2 EI kappa^2 + n.t - V constant along s for every b";
  c.info.citation = "PHYSICS.md §4.2 (reconstruction of the seed slides' soft-wall example); §1.2";
  c.info.method = "arcs, N = 256, potential through the Potential hook; Newton on the KKT system";
  c.info.parameters = {make_parameter("L", kCavityLength, 1e-6, 1e6, false, false, "length", "rod length"),
                       make_parameter("EI", kCavityStiffness, 1e-6, 1e12, false, false, "force length^2",
                                      "bending stiffness"),
                       integer_parameter("N", 256, 16, 4096, "number of elements")};
  // No extended sweep: below b = 1e-7 the §4.2 table has no row (so the table gates would have no
  // evidence), and at the fixed N = 256 the barrier layer is no longer resolved (measured at b = 1e-8:
  // H_spread 5.31e-5, twice its 2.63e-5 at 1e-7). `--extended` runs the default levels.
  c.info.resolution = {"b", "wall softness b L / EI", ResolutionScale::StepSize, {1e-4, 1e-5, 1e-6, 1e-7}, {}};
  c.info.metrics = {error_metric("P_vs_hard", "EI/L^2", "P - P_hard (-> 0 as b -> 0, about b^0.6)", std::nullopt),
                    error_metric("H_vs_hard", "EI/L^2", "mean H - H_hard", std::nullopt),
                    error_metric("P_vs_table", "EI/L^2", "P vs the §4.2 table (7 digits)", std::nullopt),
                    error_metric("H_vs_table", "EI/L^2", "mean H vs the §4.2 table", std::nullopt),
                    invariant_metric("H_spread", "max |H(s) - mean| / natural scale", std::nullopt),
                    {"wall_clearance", MetricKind::Diagnostic, "L", "(a - max y) / L", false, std::nullopt}};
  // Measured 2026-11-21 (N = 256): P_vs_hard 5.23, 1.42, 0.340, 0.0778, least-squares order 0.63 in
  // b (PHYSICS.md §4.2: "roughly b^0.6"); table errors <= 1.76e-3 (discretisation at N = 256,
  // table rounding 5e-6); H_spread <= 2.63e-5 (grows as b -> 0 at fixed N: the barrier layer thins).
  c.gates = {order_gate("P_vs_hard", 0.6, "soft -> hard wall roughly like b^0.6 (measured 0.63)"),
             order_gate("H_vs_hard", 0.6, "soft -> hard wall roughly like b^0.6 (measured 0.63)"),
             upper_bound_gate("P_vs_table", 2.0 * 1.76e-3, GateScope::AllLevels, "2 x measured (N = 256 discretisation)"),
             upper_bound_gate("H_vs_table", 2.0 * 1.77e-3, GateScope::AllLevels, "2 x measured (N = 256 discretisation)"),
             upper_bound_gate("H_spread", 2.0 * 2.63e-5, GateScope::AllLevels, "H constant for every b: 2 x measured")};
  c.run_level = [](const Parameters& p, double b) { return run_soft_level(p, b); };
  return c;
}

// ---- propped cantilever -----------------------------------------------------------------------

LevelOutput run_propped_level(e2d::Scheme scheme, const Parameters& p, double level) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), w = parameter_value(p, "w");
  const std::size_t n = element_count(level);
  e2d::Problem problem;
  problem.length = L;
  problem.bending_stiffness = [EI](double) { return EI; };
  problem.start.support = e2d::Support::Clamped;
  problem.potential.value = [w](double, double y) { return w * y; };
  problem.potential.gradient = [w](double, double) { return Eigen::Vector2d(0.0, w); };
  e2d::Obstacle prop = e2d::floor_at(0.0);
  prop.s_min = L - 0.5 * L / double(n);  // acts on the tip node only
  const auto c = e2d::solve_static_contact(problem, {scheme, n}, {prop});
  LevelOutput out;
  // In units of w L (the reaction) and w L^2 (the moment EI kappa).
  const double R = c.contacts.empty() ? 0.0 : c.contacts.front().force;
  const double reaction = R / (w * L), moment = -EI * c.rod.kappa[0] / (w * L * L);
  out.metrics["tip_reaction"] = {reaction, 3.0 / 8.0, std::abs(reaction - 3.0 / 8.0)};
  out.metrics["root_moment"] = {moment, 1.0 / 8.0, std::abs(moment - 1.0 / 8.0)};
  std::vector<double> force(c.rod.nodes(), 0.0);
  force.back() = R;
  out.series.push_back(thin_series("shape|rod", "x", "y", c.rod.x, c.rod.y));
  out.series.push_back(thin_series("H(s)", "s", "H", c.rod.s, invariants::planar_noether_h(c.rod)));
  return out;
}

Case propped_case(e2d::Scheme scheme) {
  const std::string id(e2d::scheme_id(scheme));
  Case c;
  c.info.name = "elastica-contact/propped-cantilever/" + id;
  c.info.family = "elastica-contact";
  c.info.group = "elastica-contact/propped-cantilever";
  c.info.title = "propped cantilever under self-weight (frictionless tip prop), " + id;
  c.info.physics =
      "Cantilever clamped horizontally at s = 0, length L, bending stiffness EI, weight w per length (V = w y), "
      "a frictionless unilateral prop y >= 0 at s = L only.";
  c.info.reference = "Euler-Bernoulli small deflection: tip reaction R = 3wL/8, root moment wL^2/8 "
                     "(nonlinear correction ~ (wL^3/EI)^2 = 1e-6 relative at the default wL^3/EI = 1.07e-3)";
  c.info.citation = "ALGORITHMS.md §4.3 (a); Timoshenko & Gere, propped cantilever";
  c.info.method = scheme_text(scheme);
  // L and EI not 1 (so that a mix-up of them or their powers shows); w L^3 / EI = 1.07e-3.
  c.info.parameters = {make_parameter("L", 1.7, 1e-6, 1e6, false, false, "length", "rod length"),
                       make_parameter("EI", 2.3, 1e-6, 1e12, false, false, "force length^2", "bending stiffness"),
                       make_parameter("w", 5e-4, 0.0, 1e12, true, false, "force/length", "weight per unit length")};
  c.info.resolution = {"N", "number of elements", ResolutionScale::Count, {8, 16, 32, 64}, {8, 16, 32, 64, 128, 256}};
  c.info.metrics = {error_metric("tip_reaction", "wL", "R / (wL) vs 3/8"),
                    error_metric("root_moment", "wL^2", "|M(0)| / (wL^2) vs 1/8")};
  // Measured at N = 64 (2026-11-21): polygon 4.58e-5 both, arcs 2.29e-5 both; order 2.00.
  const double at64 = scheme == e2d::Scheme::Polygon ? 4.5771e-5 : 2.2890e-5;
  for (const char* metric : {"tip_reaction", "root_moment"}) {
    c.gates.push_back(order_gate(metric, 2.0, "lumped weight and vertex moments: O(h^2)"));
    c.gates.push_back(measured_bound(metric, at64, 1.0 / 64, 2.0));
  }
  c.run_level = [scheme](const Parameters& p, double level) { return run_propped_level(scheme, p, level); };
  // The top measured at L = EI = 1 before L and EI were parameters (2026-11-21). The bottom (2026-11-28): at
  // w L^3 / EI = 1.07e-10 the load is at the solver's tolerance and no level touches the prop (R = 0, order 0);
  // at 1.07e-9 every gate passes; the window starts ten times above (1e-8 passes the extended levels too).
  cases::require(c, cases::weight_window(1e-8, 1e-2, "where the tip's sag is far above round-off and the "
                                                     "small-deflection reference's (w L^3 / EI)^2 stays below the "
                                                     "levels' discretisation error"));
  return c;
}

}  // namespace

void register_contact_cases(Registry& registry) {
  for (Regime regime : {Regime::Free, Regime::Point, Regime::Line})
    for (e2d::Scheme scheme : kSchemes) registry.add(cavity_case(scheme, regime));
  registry.add(cavity_case(e2d::Scheme::Polygon, Regime::Point, solvers::contact::LcpMethod::Lemke));
  // The same LCPs by projected Gauss-Seidel (issue 13, class 5: the advertised PGS path had no case).
  // Measured at N = 32, 64, 128: 16, 53, 162 sweeps in all, P within 4.1e-8 of the active-set path.
  registry.add(cavity_case(e2d::Scheme::Polygon, Regime::Point, solvers::contact::LcpMethod::ProjectedGaussSeidel));
  // The disk obstacles (issue 13, class 5): a post and a ring in place of the wall y = a.
  for (Ceiling ceiling : {Ceiling::Post, Ceiling::Ring})
    for (e2d::Scheme scheme : kSchemes) registry.add(cavity_case(scheme, Regime::Point, std::nullopt, ceiling));
  registry.add(soft_case());
  for (e2d::Scheme scheme : kSchemes) registry.add(propped_case(scheme));
}

}  // namespace rodvv::harness

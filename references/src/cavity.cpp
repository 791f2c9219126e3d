// Pinned-pinned elastica in a cavity (PHYSICS.md §4.1); formulas in cavity.hpp. The Jacobi
// quantities at the contact come from the incomplete integrals of the amplitude asin(sin(psi/2)/k):
// v = F(amp, k), E(am v) = E(amp, k), cn v = cos(amp), dn v = cos(psi/2) (elliptic.hpp, Carlson).
#include "rodvv/references/cavity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "elliptic.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/references/elastica.hpp"

namespace rodvv::references {
namespace {

constexpr double kMaxFlat = 0.6;  // line branch tabulated up to l = 0.6 L (PHYSICS.md §4.1)
// The tallest inflexional half wave: max over phi0 of sin(phi0) (2E/K - 1) = a / L', reached at
// phi0 = 1.02342521748698585 (mpmath, 30 digits: 0.642140994038159897). A line contact with side
// waves of length L' exists only for a / L' below it.
constexpr double kTallestHalfWave = 0.642140994038159897;
// The line branch stops where a / L' = 0.999 of that: the first root of the 1-degree scan in
// line_phi0 is then found (the scan's grid misses the flat maximum by at most ~8e-5 < 6.4e-4), and
// phi0, which has a square-root singularity at the tangency, stays well conditioned.
constexpr double kReachableFraction = 0.999;

template <class F>
double root(const char* method, F f, double a, double b) {
  const double fa = f(a), fb = f(b);
  if (!(fa * fb <= 0.0))
    throw SolverError(method, std::string(method) + ": root not bracketed", 0, std::min(std::abs(fa), std::abs(fb)));
  if (fa == 0.0) return a;
  if (fb == 0.0) return b;
  return detail::solve_bracketed(method, f, a, b, fa, fb);
}

void validate(const CavityColumn& c) {
  require_positive("L", c.L);
  require_positive("EI", c.EI);
  // Beyond 0.3207 L the point contact never flattens (no inflexional half wave of length L/2 reaches
  // the wall), and the branches this reference follows end.
  require_open_interval("wall_gap", c.gap, 0.0, 0.5 * kReachableFraction * kTallestHalfWave * c.L);
}

// Point-contact geometry for given (psi, phi0): the contact point of the left half.
struct HalfWave {
  double lambda, x, y, kappa;
};
HalfWave point_half(const CavityColumn& c, double psi, double phi0) {
  const double k = std::sin(0.5 * phi0), kp = std::cos(0.5 * phi0);
  const double K = detail::complete_k(kp), E = detail::complete_e(kp);
  const double sa = std::min(1.0, std::sin(0.5 * psi) / k);
  const double ca = std::sqrt((1.0 - sa) * (1.0 + sa));
  const double delta = std::cos(0.5 * psi);
  const double v = detail::incomplete_f(sa, ca, delta);
  const double ev = detail::incomplete_e(sa, ca, delta, k);
  HalfWave h;
  h.lambda = 2.0 * (K + v) / c.L;
  const double xi = (2.0 * (E + ev) - (K + v)) / h.lambda;
  const double eta = 2.0 * k * ca / h.lambda;
  h.x = xi * std::cos(psi) - eta * std::sin(psi);
  h.y = xi * std::sin(psi) + eta * std::cos(psi);
  h.kappa = 2.0 * k * h.lambda * ca;
  return h;
}

// 2E/K - 1 for phi0, from K - E without cancellation.
double chord_ratio(double phi0) {
  const double k = std::sin(0.5 * phi0), kp = std::cos(0.5 * phi0);
  return 1.0 - 2.0 * detail::complete_k_minus_e(k, kp) / detail::complete_k(kp);
}

// phi0 of the line-contact half wave: first root of sin(phi0) (2E/K - 1) = a/L'.
double line_phi0(double target) {
  auto g = [&](double p) { return std::sin(p) * chord_ratio(p) - target; };
  const double step = std::numbers::pi / 180.0;
  double lo = 1e-6;
  for (double hi = step; hi < 2.2; lo = hi, hi += step)
    if (g(hi) > 0.0) return root("cavity line-contact phi0", g, lo, hi);
  throw InputError("flat_length", "invalid parameter 'flat_length': no inflexional half wave reaches the wall");
}

double psi_transition(const CavityColumn& c) { return line_phi0(c.gap / (0.5 * c.L)); }


}  // namespace

CavityState cavity_point_contact(const CavityColumn& c, double psi) {
  validate(c);
  const double pt = psi_transition(c);
  require_closed_interval("psi", psi, 0.0, pt);
  // phi0 in (psi, pi): y_c rises from y(psi) <= a to a maximum (0.403 L at psi = 0, phi0 = 1.985)
  // and falls again; the contact is the first crossing, bracketed by a 1-degree scan.
  auto f = [&](double phi0) { return point_half(c, psi, phi0).y - c.gap; };
  double phi0 = pt;
  if (psi != pt) {
    const double step = std::numbers::pi / 180.0;
    double lo = std::max(psi, 1e-12), hi = lo + step;
    while (hi < 0.95 * std::numbers::pi && f(hi) < 0.0) lo = hi, hi += step;
    phi0 = root("cavity point-contact phi0", f, lo, std::min(hi, 0.95 * std::numbers::pi));
  }
  const HalfWave h = point_half(c, psi, phi0);
  CavityState s;
  s.regime = CavityRegime::PointContact;  // psi = 0: touching with zero force
  const double F = c.EI * h.lambda * h.lambda;
  s.psi = psi;
  s.phi0 = phi0;
  s.theta0 = phi0 + psi;
  s.P = F * std::cos(psi);
  s.wall_force = 2.0 * F * std::sin(psi);
  s.kappa_mid = h.kappa;
  s.H = -F * std::cos(phi0);
  s.shortening = c.L - 2.0 * h.x;
  return s;
}

CavityState cavity_line_contact(const CavityColumn& c, double l) {
  validate(c);
  require_closed_interval("flat_length", l, 0.0, cavity_max_flat_length(c));
  const double side = 0.5 * (c.L - l);
  const double phi0 = line_phi0(c.gap / side);
  const double K = detail::complete_k(std::cos(0.5 * phi0));
  const double F = c.EI * (2.0 * K / side) * (2.0 * K / side);
  CavityState s;
  s.regime = CavityRegime::LineContact;
  s.psi = s.phi0 = phi0;
  s.theta0 = 2.0 * phi0;
  s.P = F * std::cos(phi0);
  s.edge_force = F * std::sin(phi0);
  s.wall_force = 2.0 * s.edge_force;
  s.H = -s.P;
  s.flat_length = l;
  s.shortening = c.L - l - 2.0 * side * chord_ratio(phi0) * std::cos(phi0);
  return s;
}

double cavity_touch_shortening(const CavityColumn& c) {
  return cavity_point_contact(c, 0.0).shortening;
}

double cavity_transition_shortening(const CavityColumn& c) {
  return cavity_line_contact(c, 0.0).shortening;
}

// 0.6 L, or shorter where the side waves could not reach the walls (a / L' <= kReachableFraction x
// the tallest half wave, L' = (L - l) / 2).
double cavity_max_flat_length(const CavityColumn& c) {
  validate(c);
  return std::min(kMaxFlat * c.L, c.L - 2.0 * c.gap / (kReachableFraction * kTallestHalfWave));
}

double cavity_max_shortening(const CavityColumn& c) {
  return cavity_line_contact(c, cavity_max_flat_length(c)).shortening;
}

CavityState cavity_from_shortening(const CavityColumn& c, double d) {
  validate(c);
  const double d_max = cavity_max_shortening(c);
  require_open_interval("shortening", d, 0.0, std::nextafter(d_max, 2.0 * d_max));
  const double d_touch = cavity_touch_shortening(c);
  const double d_line = cavity_transition_shortening(c);
  if (d <= d_touch) {  // free first mode: 2 L (1 - E/K) = d
    const PinnedColumn col{c.L, c.EI};
    const double theta_touch = cavity_point_contact(c, 0.0).theta0;
    auto f = [&](double t0) { return pinned_solution(col, t0).shortening - d; };
    // Upper end widened by 1e-6: d_touch (point branch) and the pinned column's shortening at
    // theta_touch agree only to round-off.
    const double t0 = root("cavity free theta0", f, 1e-9, theta_touch * (1.0 + 1e-6));
    const PinnedSolution p = pinned_solution(col, t0);
    CavityState s;
    s.regime = CavityRegime::Free;
    s.shortening = p.shortening;
    s.P = p.P;
    s.H = p.H;
    s.kappa_mid = p.kappa_M;
    s.phi0 = s.theta0 = t0;
    return s;
  }
  if (d <= d_line) {
    const double pt = psi_transition(c);
    auto f = [&](double psi) { return cavity_point_contact(c, psi).shortening - d; };
    return cavity_point_contact(c, root("cavity point-contact psi", f, 0.0, pt));
  }
  auto f = [&](double l) { return cavity_line_contact(c, l).shortening - d; };
  return cavity_line_contact(c, root("cavity flat length", f, 0.0, cavity_max_flat_length(c)));
}

}  // namespace rodvv::references

// Closed-form planar elastica (PHYSICS.md §3; Love 1944 §§262-263; Byrd & Friedman 1971;
// Mattiasson 1981). See elastica.hpp for the conventions.
//
// Accuracy notes (measured against tests/data/elastica_reference.csv; numbers in the test):
//  * Every modulus comes with an accurate complementary modulus: k' = cos(theta0/2) (pinned,
//    flagpole; libm reduces theta0/2 near pi/2 exactly), k' = sqrt((1 - k)(1 + k)) (general elastica;
//    1 - k is exact for k >= 1/2), k' = sin(beta/2) with beta = pi/2 - phi_L (cantilever).
//  * Half angles: sin(theta/2) = k sn u and cos(theta/2) = dn u, so theta = 2 atan2(k sn, dn), which
//    stays well conditioned where 2 asin(k sn) does not (k sn -> 1).
//  * K - E = k^2/3 R_D(0, k'^2, 1) (no cancellation for small k) gives the end shortening.
//  * Cantilever: the root equation sqrt(alpha) = K - F(psi0) is rewritten with the addition theorem
//    F(phi) + F(psi) = K for tan(phi) tan(psi) = 1/k' (from sn(K - u) = cd u, DLMF 22.4.3) as
//    sqrt(alpha) = F(chi, k), sin(chi) = sqrt(sin phi_L)/k, cos(chi) = k'/k, delta(chi) = sqrt(2) k':
//    no cancellation for small alpha. The shape follows from psi = am(K - v), v = lambda (L - s)
//    (sn(K - v) = cd v, cn(K - v) = k' sd v, dn(K - v) = k' nd v, DLMF 22.4.3), and
//    E(am(K - v)) = E - eps(v) + k^2 sn v cd v (the addition theorem of eps, DLMF 22.16.27).
#include "rodvv/references/elastica.hpp"

#include <boost/math/tools/roots.hpp>
#include <boost/math/tools/toms748_solve.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "elliptic.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {
namespace {

using detail::solve_bracketed;
using std::numbers::pi;
using std::numbers::sqrt2;

void require_s_in_span(double s, double L) { require_closed_interval("s", s, 0.0, L); }

// Modulus k = sin(a/2) and k' = cos(a/2) for an angle a in (0, pi).
struct Moduli {
  double k;
  double kp;
};
Moduli half_angle_moduli(double angle) { return {std::sin(0.5 * angle), std::cos(0.5 * angle)}; }

// ---------------------------------------------------------------------------------------------
// Cantilever with a dead tip load: the moduli as functions of the tip rotation.
// Exactly one of phi_L and beta = pi/2 - phi_L is the solved (exact) variable; the other is derived,
// so that k' = sin(beta/2) is accurate also when phi_L -> pi/2 (alpha large).
struct CantileverModuli {
  double phi_L;
  double k;
  double kp;
  double sin_phi_L;
};

CantileverModuli moduli_from_phi(double phi_L) {
  // k = cos(pi/4 - phi_L/2) = (cos h + sin h)/sqrt 2, k' = sin(pi/4 - phi_L/2) = (cos h - sin h)/sqrt 2
  // with h = phi_L/2 <= pi/8 (no cancellation: cos h - sin h >= 0.54).
  const double h = 0.5 * phi_L;
  const double c = std::cos(h);
  const double s = std::sin(h);
  return {phi_L, (c + s) / sqrt2, (c - s) / sqrt2, std::sin(phi_L)};
}

CantileverModuli moduli_from_beta(double beta) {
  return {0.5 * pi - beta, std::cos(0.5 * beta), std::sin(0.5 * beta), std::cos(beta)};
}

// F(chi, k) with sin(chi) = sqrt(sin phi_L)/k, cos(chi) = k'/k, delta(chi) = sqrt 2 k'
// (equals K - F(psi0, k), the scaled length lambda L of the rod).
double scaled_length(const CantileverModuli& m) {
  return detail::incomplete_f(std::sqrt(m.sin_phi_L) / m.k, m.kp / m.k, sqrt2 * m.kp);
}

// The tip rotation solving sqrt(alpha) = F(chi(phi_L), k(phi_L)) (increasing in phi_L).
CantileverModuli solve_cantilever(double alpha) {
  const double target = std::sqrt(alpha);
  const double quarter = 0.25 * pi;
  const double at_quarter = scaled_length(moduli_from_phi(quarter)) - target;
  if (at_quarter >= 0.0) {
    // phi_L in (0, pi/4]: the residual is -sqrt(alpha) < 0 at phi_L = 0.
    if (at_quarter == 0.0) return moduli_from_phi(quarter);
    const auto f = [target](double phi) { return scaled_length(moduli_from_phi(phi)) - target; };
    return moduli_from_phi(
        solve_bracketed("cantilever tip rotation (phi_L)", f, 0.0, quarter, -target, at_quarter));
  }
  // phi_L in (pi/4, pi/2): solve for beta = pi/2 - phi_L in (beta_min, pi/4); the residual
  // decreases in beta and behaves like ln(8/beta) - sqrt(alpha) for small beta. A geometric scan
  // (factor 16) first brackets the root in [beta/16, beta], on which TOMS 748 converges quickly
  // (on the whole interval it would bisect for ~150 steps when beta ~ 1e-43, alpha ~ 1e4).
  // beta_min keeps k'^2 = sin^2(beta/2) ~ 2.5e-201 above the smallest argument GSL's R_D accepts
  // (5 DBL_MIN^(2/3) ~ 6e-206); with 1e-150, alpha ~ 1e5 ended in a GSL domain error.
  constexpr double kBetaMin = 1e-100;
  const auto f = [target](double beta) { return scaled_length(moduli_from_beta(beta)) - target; };
  double hi = quarter;
  double f_hi = at_quarter;
  double lo = hi / 16.0;
  double f_lo = f(lo);
  while (!(f_lo > 0.0) && lo > kBetaMin) {
    hi = lo;
    f_hi = f_lo;
    lo = std::max(lo / 16.0, kBetaMin);
    f_lo = f(lo);
  }
  if (!(f_lo > 0.0))
    throw InputError("alpha", "invalid parameter 'alpha' = P L^2/EI = " + format_value(alpha) +
                                  ": too large, the tip rotation is within 1e-100 of pi/2 (must be "
                                  "<= about 5.4e4)");
  if (f_hi == 0.0) return moduli_from_beta(hi);
  return moduli_from_beta(
      solve_bracketed("cantilever tip rotation (pi/2 - phi_L)", f, lo, hi, f_lo, f_hi));
}

void validate(const TipLoadedCantilever& c) {
  require_positive("L", c.L);
  require_positive("EI", c.EI);
  require_positive("P", c.P);
  const double alpha = c.P * c.L * c.L / c.EI;
  require_positive("alpha = P L^2/EI", alpha);  // catches underflow/overflow of the product
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// 1. Inflexional elastica (PHYSICS.md §3.1).
ElasticaPoint inflexional_point(const InflexionalElastica& e, double s) {
  require_positive("EI", e.EI);
  require_positive("P", e.P);
  require_open_interval("k", e.k, 0.0, 1.0);
  require_finite("u0", e.u0);
  require_finite("x0", e.x0);
  require_finite("y0", e.y0);
  require_finite("s", s);
  const double k = e.k;
  const double kp = std::sqrt((1.0 - k) * (1.0 + k));
  const double lambda = std::sqrt(e.P / e.EI);
  const double K = detail::complete_k(kp);
  const double E = detail::complete_e(kp);
  const auto at = detail::jacobi_epsilon(std::fma(lambda, s, e.u0), k, kp, K, E);
  const auto start = detail::jacobi_epsilon(e.u0, k, kp, K, E);
  ElasticaPoint p;
  p.theta = 2.0 * std::atan2(k * at.sn, at.dn);
  p.kappa = 2.0 * k * lambda * at.cn;
  p.x = e.x0 + 2.0 / lambda * (at.epsilon - start.epsilon) - s;
  p.y = e.y0 - 2.0 * k / lambda * (at.cn - start.cn);
  return p;
}

double inflexional_invariant(const InflexionalElastica& e) {
  require_positive("EI", e.EI);
  require_positive("P", e.P);
  require_open_interval("k", e.k, 0.0, 1.0);
  // 2k^2 - 1 = k^2 - k'^2 = (k - k')(k + k') would need k'; fma keeps it to one rounding.
  return e.P * std::fma(2.0 * e.k, e.k, -1.0);
}

// ---------------------------------------------------------------------------------------------
// 2. Pinned-pinned column (PHYSICS.md §3.2).
namespace {
void validate(const PinnedColumn& column, double theta0) {
  require_positive("L", column.L);
  require_positive("EI", column.EI);
  require_open_interval("theta0", theta0, 0.0, pi);
}
}  // namespace

PinnedSolution pinned_solution(const PinnedColumn& column, double theta0) {
  validate(column, theta0);
  const auto [k, kp] = half_angle_moduli(theta0);
  const double K = detail::complete_k(kp);
  const double k_minus_e = detail::complete_k_minus_e(k, kp);
  const double L = column.L;
  PinnedSolution out;
  out.theta0 = theta0;
  out.k = k;
  out.P = 4.0 * K * K * column.EI / (L * L);
  out.y_M = L * k / K;
  out.kappa_M = 4.0 * k * K / L;
  out.shortening = 2.0 * L * k_minus_e / K;  // 2 L (1 - E/K)
  out.chord = L - out.shortening;            // L (2E/K - 1)
  out.H = -out.P * std::cos(theta0);
  return out;
}

ElasticaPoint pinned_point(const PinnedColumn& column, double theta0, double s) {
  validate(column, theta0);
  require_s_in_span(s, column.L);
  const auto [k, kp] = half_angle_moduli(theta0);
  const double K = detail::complete_k(kp);
  const double E = detail::complete_e(kp);
  const double L = column.L;
  // v = K - lambda s with lambda = 2K/L, written as K (1 - 2 s/L): exact v = 0 at midspan and
  // v = -K at s = L; |v| <= K so no reduction is needed.
  const double v = K * (1.0 - 2.0 * (s / L));
  const auto f = detail::jacobi_epsilon(v, k, kp, K, E);
  ElasticaPoint p;
  p.theta = 2.0 * std::atan2(k * f.sn, f.dn);
  p.kappa = -4.0 * k * K / L * f.cn;
  p.x = L / K * (E - f.epsilon) - s;
  p.y = L * k / K * f.cn;
  return p;
}

double pinned_theta0_from_load(const PinnedColumn& column, double P) {
  require_positive("L", column.L);
  require_positive("EI", column.EI);
  require_positive("P", P);
  const double p_euler = pi * pi * column.EI / (column.L * column.L);
  // Scaled length lambda L = L sqrt(P/EI) must exceed pi = 2 K(0).
  const double target = column.L * std::sqrt(P / column.EI);
  if (!(P > p_euler) || !(target > pi))
    throw InputError("P", "invalid parameter 'P' = " + format_value(P) +
                              ": below the buckling load P_Euler = pi^2 EI/L^2 = " +
                              format_value(p_euler) + "; must be > P_Euler");
  const auto f = [target](double theta0) {
    return 2.0 * detail::complete_k(std::cos(0.5 * theta0)) - target;
  };
  const double hi = std::nextafter(pi, 0.0);  // largest theta0 < pi in double
  const double f_hi = f(hi);
  if (!(f_hi > 0.0))
    throw InputError("P", "invalid parameter 'P' = " + format_value(P) +
                              ": too large, theta0 would be indistinguishable from pi in double "
                              "precision (P L^2/EI must be < about 6000)");
  return solve_bracketed("pinned theta0 from load", f, 0.0, hi, f(0.0), f_hi);
}

// ---------------------------------------------------------------------------------------------
// 3. Cantilever with a vertical dead tip load (PHYSICS.md §3.5).
CantileverTip cantilever_tip(const TipLoadedCantilever& cantilever) {
  validate(cantilever);
  const double alpha = cantilever.P * cantilever.L * cantilever.L / cantilever.EI;
  const CantileverModuli m = solve_cantilever(alpha);
  const CantileverPoint tip = cantilever_point(cantilever, cantilever.L);
  CantileverTip out;
  out.alpha = alpha;
  out.phi_L = m.phi_L;
  out.k = m.k;
  // tan(psi0) = 1/sqrt(sin phi_L)   (sin psi0 = 1/(sqrt2 k), cos psi0 = sqrt(sin phi_L)/(sqrt2 k)).
  out.psi0 = std::atan2(1.0, std::sqrt(m.sin_phi_L));
  // x_L / L = sqrt(2 sin phi_L / alpha).
  out.u = cantilever.L * (1.0 - std::sqrt(2.0 * m.sin_phi_L / alpha));
  out.w = tip.w;
  out.H = cantilever.P * m.sin_phi_L;
  return out;
}

CantileverPoint cantilever_point(const TipLoadedCantilever& cantilever, double s) {
  validate(cantilever);
  require_s_in_span(s, cantilever.L);
  const double L = cantilever.L;
  const double alpha = cantilever.P * L * L / cantilever.EI;
  const CantileverModuli m = solve_cantilever(alpha);
  const double k = m.k;
  const double kp = m.kp;
  const double lambda = std::sqrt(cantilever.P / cantilever.EI);
  const double K = detail::complete_k(kp);
  const double E = detail::complete_e(kp);
  // v = lambda (L - s) in [0, sqrt(alpha)] (<= K): the scaled distance from the tip.
  const double root_alpha = std::sqrt(alpha);
  const double v = root_alpha * (1.0 - s / L);
  const auto f = detail::jacobi_epsilon(v, k, kp, K, E);
  // At the clamp (v = sqrt(alpha)), am = chi: eps(sqrt(alpha)) = E(chi, k).
  const double eps_clamp = detail::incomplete_e(std::sqrt(m.sin_phi_L) / k, kp / k, sqrt2 * kp, k);
  CantileverPoint p;
  // sin phi = (k^2 cn^2 - k'^2)/dn^2, cos phi = 2 k k' cn/dn^2.
  p.phi = std::atan2(k * k * f.cn * f.cn - kp * kp, 2.0 * k * kp * f.cn);
  p.kappa = 2.0 * lambda * k * kp * f.sn / f.dn;
  // lambda x = 2k (cos psi0 - cos psi) = sqrt(2 sin phi_L) - 2 k k' sd v.
  p.x = (std::sqrt(2.0 * m.sin_phi_L) - 2.0 * k * kp * f.sn / f.dn) / lambda;
  // lambda w = lambda s - 2 [E(psi) - E(psi0)],
  // E(psi) - E(psi0) = eps(V) - eps(v) + k^2 sn v cd v - sqrt(sin phi_L / 2),  V = sqrt(alpha).
  const double e_diff =
      eps_clamp - f.epsilon + k * k * f.sn * f.cn / f.dn - std::sqrt(0.5 * m.sin_phi_L);
  p.w = s - 2.0 * e_diff / lambda;
  return p;
}

// ---------------------------------------------------------------------------------------------
// 4a. End moment: a circular arc of curvature M/EI.
namespace {
void validate(const EndMomentCantilever& c) {
  require_positive("L", c.L);
  require_positive("EI", c.EI);
  require_finite("M", c.M);
}
}  // namespace

ElasticaPoint end_moment_point(const EndMomentCantilever& c, double s) {
  validate(c);
  require_s_in_span(s, c.L);
  const double kappa = c.M / c.EI;
  const double theta = kappa * s;
  ElasticaPoint p;
  p.theta = theta;
  p.kappa = kappa;
  if (theta == 0.0) {
    p.x = s;
    p.y = 0.0;
    return p;
  }
  // x = s sin(theta)/theta, y = s (1 - cos theta)/theta = 2 s sin^2(theta/2)/theta: accurate for
  // small theta (no 1 - cos cancellation) and equal to (EI/M) sin, (EI/M)(1 - cos).
  const double half = std::sin(0.5 * theta);
  p.x = std::sin(theta) / kappa;
  p.y = 2.0 * half * half / kappa;
  return p;
}

double end_moment_invariant(const EndMomentCantilever& c) {
  validate(c);
  return c.M * c.M / (2.0 * c.EI);
}

double roll_up_moment(double L, double EI) {
  require_positive("L", L);
  require_positive("EI", EI);
  return 2.0 * pi * EI / L;
}

// ---------------------------------------------------------------------------------------------
// 4b. Flagpole: the quarter wave, pinned-pinned formulas with L -> 2L (PHYSICS.md §3.4).
FlagpoleSolution flagpole_solution(const Flagpole& f) {
  require_positive("L", f.L);
  require_positive("EI", f.EI);
  require_open_interval("theta_tip", f.theta_tip, 0.0, pi);
  const auto [k, kp] = half_angle_moduli(f.theta_tip);
  const double K = detail::complete_k(kp);
  FlagpoleSolution out;
  out.k = k;
  out.P = K * K * f.EI / (f.L * f.L);
  out.delta = 2.0 * k * f.L / K;
  out.shortening = 2.0 * f.L * detail::complete_k_minus_e(k, kp) / K;
  out.H = -out.P * std::cos(f.theta_tip);
  return out;
}

// ---------------------------------------------------------------------------------------------
// 4c. Euler critical loads.
namespace {
// The root of tan x = x in (pi, 3 pi/2), as the zero of g(x) = sin x - x cos x (g(pi) = pi > 0,
// g(3 pi/2) = -1 < 0; no poles of tan).
double clamped_pinned_root() {
  const auto g = [](double x) { return std::sin(x) - x * std::cos(x); };
  const double a = pi;
  const double b = 1.5 * pi;
  return solve_bracketed("root of tan x = x", g, a, b, g(a), g(b));
}
}  // namespace

double euler_coefficient(EndConditions ends) {
  switch (ends) {
    case EndConditions::PinnedPinned:
      return pi * pi;
    case EndConditions::ClampedFree:
      return 0.25 * pi * pi;
    case EndConditions::ClampedClamped:
      return 4.0 * pi * pi;
    case EndConditions::ClampedPinned: {
      static const double x = clamped_pinned_root();
      return x * x;
    }
  }
  throw InputError("ends", "invalid parameter 'ends': unknown EndConditions value");
}

double euler_critical_load(EndConditions ends, double L, double EI) {
  require_positive("L", L);
  require_positive("EI", EI);
  return euler_coefficient(ends) * EI / (L * L);
}

}  // namespace rodvv::references

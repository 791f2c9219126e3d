#include "rodvv/references/twisted_rod.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "bracketed_root.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {
constexpr double kPi = std::numbers::pi;

void validate(const LocalizedHelicalBuckling& rod) {
  require_positive("B", rod.B);
  require_positive("T", rod.T);
  require_finite("M", rod.M);
  const double bound = 2.0 * std::sqrt(rod.B * rod.T);
  if (!(std::abs(rod.M) < bound))
    throw InputError("M", "invalid parameter 'M' = " + format_value(rod.M) + ": must satisfy |M| < 2 sqrt(B T) = " +
                              format_value(bound) + " (M^2 < 4 B T)");
}
}  // namespace

LocalizedHelicalBucklingSolution localized_helical_buckling(const LocalizedHelicalBuckling& rod) {
  validate(rod);
  const double B = rod.B, T = rod.T, M = rod.M;
  LocalizedHelicalBucklingSolution out;
  out.omega = M / (2.0 * B);
  out.alpha = std::sqrt(4.0 * B * T - M * M) / (2.0 * B);
  out.amplitude = 2.0 * B * out.alpha / T;
  out.cos_phi_max = M * M / (2.0 * B * T) - 1.0;
  out.end_shortening = 2.0 * out.amplitude;
  return out;
}

LocalizedHelicalBucklingPoint localized_helical_buckling_point(const LocalizedHelicalBuckling& rod, double s) {
  const LocalizedHelicalBucklingSolution sol = localized_helical_buckling(rod);
  require_finite("s", s);
  const double A = sol.amplitude, a = sol.alpha, w = sol.omega;
  const double sech = 1.0 / std::cosh(a * s);  // 0 beyond overflow: the straight tails
  const double th = std::tanh(a * s), sn = std::sin(w * s), cs = std::cos(w * s);
  LocalizedHelicalBucklingPoint point;
  point.position = Vec3(A * sn * sech, -A * cs * sech, s - A * th);
  point.tangent = Vec3(A * sech * (w * cs - a * sn * th), A * sech * (w * sn + a * cs * th), 1.0 - A * a * sech * sech);
  point.cos_phi = point.tangent.z();
  point.envelope = th * th;
  return point;
}

FiniteHelicalBucklingSolution finite_helical_buckling(const FiniteHelicalBuckling& rod) {
  require_positive("B", rod.B);
  require_positive("C", rod.C);
  require_positive("L", rod.L);
  require_open_interval("D", rod.D, 0.0, rod.L);
  require_finite("Phi", rod.Phi);
  const double d = rod.D / rod.L, k = 4.0 * rod.B / (rod.C * d);
  // Phi = f(theta) = k sin(2 theta) + 4 theta, increasing on [0, theta_end] (header, item 2)
  const double theta_end = 0.5 * std::acos(-std::min(1.0, rod.C * d / (2.0 * rod.B)));
  auto f = [k](double theta) { return k * std::sin(2.0 * theta) + 4.0 * theta; };
  auto residual = [&](double theta) { return f(theta) - rod.Phi; };
  const double phi_end = f(theta_end);
  if (!(rod.Phi > 0.0 && rod.Phi <= phi_end))
    throw InputError("Phi", "invalid parameter 'Phi' = " + format_value(rod.Phi) + ": must be in (0, " +
                                format_value(phi_end) + "] (the end rotations of the onset branch at D/L = " +
                                format_value(d) + ")");
  const double f_end = phi_end - rod.Phi;  // >= 0; 0 only at Phi = Phi_end: the bracket end is the root
  const double theta = f_end == 0.0 ? theta_end
                                    : detail::solve_bracketed("finite_helical_buckling", residual, 0.0, theta_end,
                                                              -rod.Phi, f_end);
  const double sn = std::sin(theta);
  FiniteHelicalBucklingSolution out;
  out.m = 4.0 * std::sin(2.0 * theta) / d;
  out.t = 16.0 * sn * sn / (d * d);
  out.M = out.m * rod.B / rod.L;
  out.T = out.t * rod.B / (rod.L * rod.L);
  out.alpha = 4.0 * sn * sn / (d * rod.L);
  out.cos_phi_max = std::cos(2.0 * theta);
  return out;
}

double greenhill_critical_moment(const GreenhillColumn& column) {
  require_positive("B", column.B);
  require_positive("L", column.L);
  const double euler = kPi * kPi * column.B / (column.L * column.L);
  require_finite("P", column.P);
  if (!(column.P < euler))
    throw InputError("P", "invalid parameter 'P' = " + format_value(column.P) +
                              ": must be below the Euler load pi^2 B / L^2 = " + format_value(euler));
  const double k = kPi / column.L;
  return 2.0 * column.B * std::sqrt(k * k - column.P / column.B);
}

double greenhill_critical_load(const GreenhillColumn& column, double M) {
  require_positive("B", column.B);
  require_positive("L", column.L);
  require_finite("M", M);
  const double k = kPi / column.L, half = M / (2.0 * column.B);
  return column.B * (k * k - half * half);
}

MichellRingSolution michell_ring(const MichellRing& ring) {
  require_positive("B", ring.B);
  require_positive("C", ring.C);
  require_positive("L", ring.L);
  MichellRingSolution out;
  out.twist_turns = std::numbers::sqrt3 * ring.B / ring.C;
  out.twist_angle = 2.0 * kPi * out.twist_turns;
  out.twisting_moment = 2.0 * kPi * std::numbers::sqrt3 * ring.B / ring.L;
  return out;
}

double prandtl_cantilever_gamma() {
  // phi(xi = 1) = sum_k c_k, c_0 = 1, c_k = -gamma^2 c_{k-1} / (4k (4k - 1)) (header, item 5); near
  // gamma = 4 the terms fall below 1e-20 by k = 12, 30 terms leave nothing. The first root is the only
  // sign change on [3, 5] (the second is 2 j_{-1/4,2} ~ 10.3).
  auto clamp_twist = [](double gamma) {
    const double g2 = gamma * gamma;
    double term = 1.0, sum = 1.0;
    for (int k = 1; k <= 30; ++k) {
      term *= -g2 / (4.0 * k * (4.0 * k - 1.0));
      sum += term;
    }
    return sum;
  };
  return detail::solve_bracketed("prandtl_cantilever_gamma", clamp_twist, 3.0, 5.0, clamp_twist(3.0),
                                 clamp_twist(5.0));
}

double lateral_torsional_cantilever_critical_load(const LateralTorsionalCantilever& beam) {
  require_positive("EI_weak", beam.EI_weak);
  require_positive("GJ", beam.GJ);
  require_positive("L", beam.L);
  return prandtl_cantilever_gamma() * std::sqrt(beam.EI_weak * beam.GJ) / (beam.L * beam.L);
}

}  // namespace rodvv::references

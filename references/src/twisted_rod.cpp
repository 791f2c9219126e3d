#include "rodvv/references/twisted_rod.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <string>

#include <Eigen/Dense>

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

namespace {
using Complex = std::complex<double>;

// (e^z - 1)/z and (e^z - 1 - z)/z^2, by their Taylor series where the closed form cancels (|z| < 1/2:
// 25 terms leave < 2^-25/25! ~ 1e-33).
Complex exp_ratio_1(Complex z) {
  if (std::abs(z) >= 0.5) return (std::exp(z) - 1.0) / z;
  Complex sum = 0.0, term = 1.0;
  for (int n = 1; n <= 25; ++n) sum += (term /= double(n)), term *= z;
  return sum;
}
Complex exp_ratio_2(Complex z) {
  if (std::abs(z) >= 0.5) return (std::exp(z) - 1.0 - z) / (z * z);
  Complex sum = 0.0, term = 0.5;
  for (int n = 2; n <= 26; ++n) sum += term, term *= z / double(n + 1);
  return sum;
}

enum class ColumnEnds { PinnedSemiTangential, Clamped };

// Im(det(A(M)) e^{-i M L/(2B)}) of the linearised column (header, 3b and 3c): zero at a critical moment.
double column_determinant(const GreenhillColumn& c, ColumnEnds ends, double M) {
  const double B = c.B, L = c.L, root = std::sqrt(M * M + 4.0 * B * c.P);
  const double k1 = (M + root) / (2.0 * B), k2 = -2.0 * c.P / (M + root);  // k1 k2 = -P/B without cancellation
  const Complex i(0.0, 1.0), e1 = std::exp(i * k1 * L), z2 = i * k2 * L;
  // columns: w = a + b s + d1 e^{i k1 s} + d2 phi2(s), phi2 = (e^{i k2 s} - 1 - i k2 s)/(i k2)^2,
  // phi2(L) = L^2 g2(z2), phi2'(L) = L g1(z2), phi2''(L) = e^{z2}; phi2 = phi2' = 0, phi2'' = 1 at s = 0
  Eigen::Matrix4cd a;
  a.row(0) << 1.0, 0.0, 1.0, 0.0;                        // w(0) = 0
  a.row(1) << 1.0, L, e1, L * L * exp_ratio_2(z2);       // w(L) = 0
  if (ends == ColumnEnds::Clamped) {
    a.row(2) << 0.0, 1.0, i * k1, 0.0;                   // w'(0) = 0
    a.row(3) << 0.0, 1.0, i * k1 * e1, L * exp_ratio_1(z2);  // w'(L) = 0
  } else {
    const double half = 0.5 * M;  // the semi-tangential end moment's share: i B w'' + (M/2) w' = 0
    const Complex end1 = -i * B * k1 * k1 + half * i * k1;  // (i B d^2/ds^2 + (M/2) d/ds) e^{i k1 s} at s = 0
    a.row(2) << 0.0, half, end1, i * B;
    a.row(3) << 0.0, half, end1 * e1, i * B * std::exp(z2) + half * L * exp_ratio_1(z2);
  }
  return (a.determinant() * std::exp(-i * M * L / (2.0 * B))).imag();
}

// The first sign change of column_determinant above the moment where k1,2 become real (for tension,
// M^2 > -4 B P: below, the straight rod is stable, as the helical threshold M^2 = 4 B T says): a scan
// in steps of pi B/(16 L), 1/32 of the spacing of the axial problem's successive roots, then TOMS 748.
double first_critical_moment(const GreenhillColumn& column, ColumnEnds ends, double euler, const char* method) {
  require_positive("B", column.B);
  require_positive("L", column.L);
  require_finite("P", column.P);
  if (!(column.P < euler))
    throw InputError("P", "invalid parameter 'P' = " + format_value(column.P) + ": must be below the Euler load " +
                              (ends == ColumnEnds::Clamped ? "4 pi^2 B / L^2 = " : "pi^2 B / L^2 = ") +
                              format_value(euler));
  const double step = kPi * column.B / (16.0 * column.L);
  double low = (column.P < 0.0 ? 2.0 * std::sqrt(-column.B * column.P) : 0.0) + 1e-3 * step;
  const auto f = [&](double M) { return column_determinant(column, ends, M); };
  double f_low = f(low);
  for (int n = 0; n < 4096; ++n) {
    const double high = low + step, f_high = f(high);
    if ((f_low < 0.0) != (f_high < 0.0)) return detail::solve_bracketed(method, f, low, high, f_low, f_high);
    low = high;
    f_low = f_high;
  }
  throw SolverError(method, std::string(method) + ": no sign change of the determinant in 4096 steps of pi B/(16 L)",
                    4096, f_low);
}
}  // namespace

double greenhill_semitangential_critical_moment(const GreenhillColumn& column) {
  const double euler = kPi * kPi * column.B / (column.L * column.L);
  return first_critical_moment(column, ColumnEnds::PinnedSemiTangential, euler, "Greenhill semi-tangential moment");
}

double clamped_twisted_column_critical_moment(const GreenhillColumn& column) {
  const double euler = 4.0 * kPi * kPi * column.B / (column.L * column.L);
  return first_critical_moment(column, ColumnEnds::Clamped, euler, "clamped twisted column moment");
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

#include "rodvv/solvers/superhelix/element.hpp"

#include <cmath>

namespace rodvv::solvers::superhelix {

namespace {
// Taylor coefficients (in y = x^2) of s0, f1, f2, g1, g2, k = 0 .. 9:
//   s0_k = (-1)^k/(2k+1)!, f1_k = (-1)^k/(2k+2)!, f2_k = (-1)^k/(2k+3)!,
//   g1_k = (-1)^(k+1) 2(k+1)/(2k+4)!, g2_k = (-1)^(k+1) 2(k+1)/(2k+5)!.
struct SeriesTable {
  double s0[10], f1[10], f2[10], g1[10], g2[10];
};
constexpr SeriesTable make_series_table() {
  SeriesTable t{};
  double factorial[25]{};
  factorial[0] = 1.0;
  for (int i = 1; i < 25; ++i) factorial[i] = factorial[i - 1] * i;
  for (int k = 0; k < 10; ++k) {
    const double sign = k % 2 == 0 ? 1.0 : -1.0;
    t.s0[k] = sign / factorial[2 * k + 1];
    t.f1[k] = sign / factorial[2 * k + 2];
    t.f2[k] = sign / factorial[2 * k + 3];
    t.g1[k] = -sign * 2.0 * (k + 1) / factorial[2 * k + 4];
    t.g2[k] = -sign * 2.0 * (k + 1) / factorial[2 * k + 5];
  }
  return t;
}
constexpr SeriesTable kSeries = make_series_table();

// Terms of the y-series needed for a truncation below 1e-20 relative: the k-th coefficient is at
// most 1 / (2k+1)! relative to the first, so y < 1e-4 needs 4 terms (1e-16 / 9!), y < 1e-2 six
// (1e-12 / 13!), y < 1 ten (1 / 21!). Short elements (the common case at large N) take the short sums.
int series_terms(double y) { return y < 1e-4 ? 4 : (y < 1e-2 ? 6 : 10); }

template <std::size_t K>
double horner(const double (&c)[K], double y, int terms) {
  double sum = c[terms - 1];
  for (int k = terms - 2; k >= 0; --k) sum = sum * y + c[k];
  return sum;
}
}  // namespace

HelixCoefficients helix_coefficients(double x2) {
  HelixCoefficients c;
  if (x2 < 1.0) {
    // 10 terms: the first omitted term is below y^10 / 21! < 2e-20 relative.
    const int terms = series_terms(x2);
    c.s0 = horner(kSeries.s0, x2, terms);
    c.f1 = horner(kSeries.f1, x2, terms);
    c.f2 = horner(kSeries.f2, x2, terms);
    c.g1 = horner(kSeries.g1, x2, terms);
    c.g2 = horner(kSeries.g2, x2, terms);
    return c;
  }
  const double x = std::sqrt(x2);
  const double sh = std::sin(0.5 * x), ch = std::cos(0.5 * x);
  const double s = 2.0 * sh * ch, one_minus_cos = 2.0 * sh * sh;  // no cancellation in 1 - cos x
  c.s0 = s / x;
  c.f1 = one_minus_cos / x2;
  c.f2 = (x - s) / (x2 * x);
  c.g1 = (x * s - 2.0 * one_minus_cos) / (x2 * x2);
  c.g2 = (x * one_minus_cos - 3.0 * (x - s)) / (x2 * x2 * x);
  return c;
}

namespace {
// Taylor coefficients (in y) of dg1/dy and dg2/dy, k = 0 .. 11: (k+1) g1_{k+1} and (k+1) g2_{k+1}
// with g1_k, g2_k as above. Used below y = 4, where the first omitted term is below
// 13 * 2 * 14 / 31! * 4^12 ~ 1e-24 (relative to |dg2/dy| ~ 1e-3: 1e-21); the trigonometric forms
// lose ~ |terms| / |value| ~ 30 x^2 eps there, and less beyond.
struct RateTable {
  double dg1[12], dg2[12];
};
constexpr RateTable make_rate_table() {
  RateTable t{};
  double factorial[32]{};
  factorial[0] = 1.0;
  for (int i = 1; i < 32; ++i) factorial[i] = factorial[i - 1] * i;
  for (int k = 0; k < 12; ++k) {
    const int j = k + 1;
    const double sign = j % 2 == 0 ? 1.0 : -1.0;
    t.dg1[k] = (k + 1) * (-sign * 2.0 * (j + 1) / factorial[2 * j + 4]);
    t.dg2[k] = (k + 1) * (-sign * 2.0 * (j + 1) / factorial[2 * j + 5]);
  }
  return t;
}
constexpr RateTable kRates = make_rate_table();

}  // namespace

HelixCoefficientRates helix_coefficient_rates(double x2) {
  HelixCoefficientRates r;
  if (x2 < 4.0) {
    // (k+1) g_{k+1} relative to the first is at most ~1 / (2k+1)! as well: same term counts below 1,
    // all 12 up to 4.
    const int terms = x2 < 1.0 ? series_terms(x2) : 12;
    r.dg1 = horner(kRates.dg1, x2, terms);
    r.dg2 = horner(kRates.dg2, x2, terms);
    return r;
  }
  // d/dy = (1 / 2x) d/dx of g1 = (x sin x - 2 (1 - cos x)) / x^4 and g2 = (x (1 - cos x) - 3 (x - sin x)) / x^5.
  const double x = std::sqrt(x2);
  const double sh = std::sin(0.5 * x), ch = std::cos(0.5 * x);
  const double s = 2.0 * sh * ch, one_minus_cos = 2.0 * sh * sh, c = 1.0 - one_minus_cos;
  const double x4 = x2 * x2;
  r.dg1 = (x2 * c - 5.0 * x * s + 8.0 * one_minus_cos) / (2.0 * x4 * x2);
  r.dg2 = (8.0 * x + 7.0 * x * c + x2 * s - 15.0 * s) / (2.0 * x4 * x2 * x);
  return r;
}

namespace {
// column i of dG/dq_i e0 (see element.hpp), from the coefficients and X e0, X^2 e0.
Mat3 local_jacobian(const Vec3& q, double sigma, const HelixCoefficients& c, const Vec3& Xe0, const Vec3& X2e0) {
  const double s2 = sigma * sigma, s3 = s2 * sigma;
  const Vec3 e0 = Vec3::UnitX();
  Mat3 dG0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 ei = Vec3::Unit(i);
    const Vec3 ei_x_e0 = ei.cross(e0);
    dG0.col(i) = (s2 * s2 * c.g1 * q[i]) * Xe0 + (s2 * c.f1) * ei_x_e0 + (s3 * s2 * c.g2 * q[i]) * X2e0 +
                 (s3 * c.f2) * (ei.cross(Xe0) + q.cross(ei_x_e0));
  }
  return dG0;
}
}  // namespace

PointMaps element_point_maps(const Vec3& q, double sigma) {
  const HelixCoefficients c = helix_coefficients(sigma * sigma * q.squaredNorm());
  const Vec3 Xe0 = q.cross(Vec3::UnitX()), X2e0 = q.cross(Xe0);
  PointMaps maps;
  maps.Ge0 = sigma * Vec3::UnitX() + (sigma * sigma * c.f1) * Xe0 + (sigma * sigma * sigma * c.f2) * X2e0;
  maps.dG0 = local_jacobian(q, sigma, c, Xe0, X2e0);
  return maps;
}

ElementMaps element_maps(const Vec3& q, double sigma) {
  const Mat3 X = skew(q);
  const Mat3 X2 = X * X;
  const HelixCoefficients c = helix_coefficients(sigma * sigma * q.squaredNorm());
  const double s2 = sigma * sigma, s3 = s2 * sigma;
  ElementMaps maps;
  maps.E = Mat3::Identity() + (sigma * c.s0) * X + (s2 * c.f1) * X2;
  maps.G = sigma * Mat3::Identity() + (s2 * c.f1) * X + (s3 * c.f2) * X2;
  const Vec3 Xe0 = q.cross(Vec3::UnitX());
  maps.dG0 = local_jacobian(q, sigma, c, Xe0, q.cross(Xe0));
  return maps;
}

namespace {
// Velocity and bias of c = G(sigma) e0 along qdot (element.hpp), from the coefficients c.
void point_rates(const Vec3& q, const Vec3& qdot, double sigma, const HelixCoefficients& c, ElementRates& out) {
  const double s2 = sigma * sigma, s3 = s2 * sigma, s4 = s2 * s2, s5 = s4 * sigma;
  const Vec3 e0 = Vec3::UnitX();
  const Vec3 Xe0 = q.cross(e0), X2e0 = q.cross(Xe0);
  const Vec3 Pe0 = qdot.cross(e0);                   // d(Xe0)
  const Vec3 mixed = qdot.cross(Xe0) + q.cross(Pe0);  // d(X2e0)
  const double qq = q.dot(qdot), dd = qdot.squaredNorm();
  const HelixCoefficientRates r = helix_coefficient_rates(s2 * q.squaredNorm());
  const double y_rate = 2.0 * s2 * qq;  // d(x^2)/dt
  const double g1_rate = r.dg1 * y_rate, g2_rate = r.dg2 * y_rate;
  const double f1_rate = 0.5 * c.g1 * y_rate, f2_rate = 0.5 * c.g2 * y_rate;
  out.offset = sigma * e0 + (s2 * c.f1) * Xe0 + (s3 * c.f2) * X2e0;
  out.jacobian = local_jacobian(q, sigma, c, Xe0, X2e0);
  out.velocity = (s4 * c.g1 * qq) * Xe0 + (s2 * c.f1) * Pe0 + (s5 * c.g2 * qq) * X2e0 + (s3 * c.f2) * mixed;
  out.bias = (s4 * (g1_rate * qq + c.g1 * dd)) * Xe0 + (s4 * c.g1 * qq + s2 * f1_rate) * Pe0 +
             (s5 * (g2_rate * qq + c.g2 * dd)) * X2e0 + (s5 * c.g2 * qq + s3 * f2_rate) * mixed +
             (2.0 * s3 * c.f2) * qdot.cross(Pe0);
}
}  // namespace

ElementRates element_point_rates(const Vec3& q, const Vec3& qdot, double sigma) {
  ElementRates out;
  point_rates(q, qdot, sigma, helix_coefficients(sigma * sigma * q.squaredNorm()), out);
  return out;
}

ElementEndRates element_end_rates(const Vec3& q, const Vec3& qdot, double sigma) {
  const HelixCoefficients c = helix_coefficients(sigma * sigma * q.squaredNorm());
  ElementEndRates out;
  point_rates(q, qdot, sigma, c, out.point);
  const Mat3 X = skew(q);
  const Mat3 X2 = X * X;
  const double s2 = sigma * sigma, s3 = s2 * sigma;
  out.E = Mat3::Identity() + (sigma * c.s0) * X + (s2 * c.f1) * X2;
  out.G = sigma * Mat3::Identity() + (s2 * c.f1) * X + (s3 * c.f2) * X2;
  const Vec3 q_x_qdot = q.cross(qdot);
  const double y_rate = 2.0 * s2 * q.dot(qdot);
  out.angular_velocity = sigma * qdot + (s2 * c.f1) * q_x_qdot + (s3 * c.f2) * q.cross(q_x_qdot);
  out.angular_bias = (s2 * 0.5 * c.g1 * y_rate) * q_x_qdot + (s3 * 0.5 * c.g2 * y_rate) * q.cross(q_x_qdot) +
                     (s3 * c.f2) * qdot.cross(q_x_qdot);
  return out;
}

ElementSecondDerivatives element_second_derivatives(const Vec3& q, double sigma) {
  const double s2 = sigma * sigma, s3 = s2 * sigma, s4 = s2 * s2, s5 = s4 * sigma;
  const HelixCoefficients c = helix_coefficients(s2 * q.squaredNorm());
  const HelixCoefficientRates r = helix_coefficient_rates(s2 * q.squaredNorm());
  const Mat3 X = skew(q);
  const Mat3 X2 = X * X;
  const Vec3 e0 = Vec3::UnitX();
  const Vec3 Xe0 = q.cross(e0), X2e0 = q.cross(Xe0);
  ElementSecondDerivatives out;
  for (int j = 0; j < 3; ++j) {
    const Vec3 ej = Vec3::Unit(j);
    const Mat3 Ej = skew(ej);
    // dG/dq_j = sigma^4 g1 q_j X + sigma^2 f1 [e_j]x + sigma^5 g2 q_j X^2 + sigma^3 f2 ([e_j]x X + X [e_j]x)
    out.frame_rate[j] = (s4 * c.g1 * q[j]) * X + (s2 * c.f1) * Ej + (s5 * c.g2 * q[j]) * X2 + (s3 * c.f2) * (Ej * X + X * Ej);
    const Vec3 ej_x_e0 = ej.cross(e0);
    const Vec3 mixed_j = ej.cross(Xe0) + q.cross(ej_x_e0);  // ([e_j]x X + X [e_j]x) e0
    for (int k = 0; k < 3; ++k) {
      const Vec3 ek = Vec3::Unit(k);
      const Vec3 ek_x_e0 = ek.cross(e0);
      const Vec3 mixed_k = ek.cross(Xe0) + q.cross(ek_x_e0);  // d(X^2 e0)/dq_k
      const double delta = j == k ? 1.0 : 0.0;
      // d/dq_k of each of the four terms of dG/dq_j e0:
      out.offset_hessian[j].col(k) =
          s4 * ((2.0 * s2 * r.dg1 * q[k] * q[j] + c.g1 * delta) * Xe0 + (c.g1 * q[j]) * ek_x_e0) +
          (s4 * c.g1 * q[k]) * ej_x_e0 +
          s5 * ((2.0 * s2 * r.dg2 * q[k] * q[j] + c.g2 * delta) * X2e0 + (c.g2 * q[j]) * mixed_k) +
          (s5 * c.g2 * q[k]) * mixed_j + (s3 * c.f2) * (ej.cross(ek_x_e0) + ek.cross(ej_x_e0));
    }
  }
  return out;
}

}  // namespace rodvv::solvers::superhelix

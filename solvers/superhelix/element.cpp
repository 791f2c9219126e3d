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

double horner(const double (&c)[10], double y) {
  double sum = c[9];
  for (int k = 8; k >= 0; --k) sum = sum * y + c[k];
  return sum;
}
}  // namespace

HelixCoefficients helix_coefficients(double x2) {
  HelixCoefficients c;
  if (x2 < 1.0) {
    // 10 terms: the first omitted term is below y^10 / 21! < 2e-20 relative.
    c.s0 = horner(kSeries.s0, x2);
    c.f1 = horner(kSeries.f1, x2);
    c.f2 = horner(kSeries.f2, x2);
    c.g1 = horner(kSeries.g1, x2);
    c.g2 = horner(kSeries.g2, x2);
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

}  // namespace rodvv::solvers::superhelix

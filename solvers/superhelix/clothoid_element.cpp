#include "rodvv/solvers/superhelix/clothoid_element.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/element.hpp"

namespace rodvv::solvers::superhelix {

namespace {

using Complex = std::complex<double>;
using Mat3c = Eigen::Matrix<Complex, 3, 3>;
using Vec3c = Eigen::Matrix<Complex, 3, 1>;

template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3> skew_t(const Eigen::Matrix<Scalar, 3, 1>& a) {
  Eigen::Matrix<Scalar, 3, 3> m;
  const Scalar zero(0.0);
  m << zero, -a.z(), a.y(), a.z(), zero, -a.x(), -a.y(), a.x(), zero;
  return m;
}

template <typename Scalar>
struct Pose {
  Eigen::Matrix<Scalar, 3, 3> R;
  Eigen::Matrix<Scalar, 3, 1> r;
  std::size_t max_terms = 0;
};

// One sub-interval of length h from the identity with strain a + s b (s from its own origin).
// Templated so that the same recurrence runs on complex numbers for the complex-step derivative.
template <typename Scalar>
Pose<Scalar> series_piece(const Eigen::Matrix<Scalar, 3, 1>& a, const Eigen::Matrix<Scalar, 3, 1>& b, double h,
                          double tolerance) {
  using M3 = Eigen::Matrix<Scalar, 3, 3>;
  using V3 = Eigen::Matrix<Scalar, 3, 1>;
  const M3 Xa = skew_t<Scalar>(a), Xb = skew_t<Scalar>(b);
  const V3 e0 = V3::UnitX();
  M3 previous = M3::Zero();      // A_{k-1} h^(k-1)
  M3 current = M3::Identity();   // A_k h^k
  Pose<Scalar> pose;
  pose.R = M3::Identity();
  pose.r = h * e0;  // k = 0 term of r: A_0 e0 h
  int small_terms = 0;
  constexpr std::size_t kMaxTerms = 200;
  std::size_t k = 0;
  for (; k < kMaxTerms; ++k) {
    // (k+1) A_{k+1} h^(k+1) = (A_k h^k) [a]x h + (A_{k-1} h^(k-1)) [b]x h^2
    const M3 next = (current * Xa * h + previous * Xb * (h * h)) / static_cast<double>(k + 1);
    pose.R += next;
    pose.r += (next * e0) * (h / static_cast<double>(k + 2));
    previous = current;
    current = next;
    // Stop after two consecutive terms below the tolerance (a single small term can be a zero of
    // an oscillating sequence).
    small_terms = next.cwiseAbs().maxCoeff() < tolerance ? small_terms + 1 : 0;
    if (small_terms >= 2) break;
  }
  if (k == kMaxTerms)
    throw SolverError("super-clothoid series", "no convergence in " + std::to_string(kMaxTerms) + " terms", k,
                      current.cwiseAbs().maxCoeff());
  pose.max_terms = k + 2;
  return pose;
}

// Sub-interval count: largest strain on the element times h at most 2 (ALGORITHMS.md §2). Computed
// from the real parts only, so that a complex-step perturbation does not change the subdivision.
std::size_t piece_count(const Vec3& a, const Vec3& b, double ell) {
  const double strain = a.norm() + b.norm() * ell;
  return static_cast<std::size_t>(std::max(1.0, std::ceil(strain * ell / 2.0)));
}

template <typename Scalar>
Pose<Scalar> compose_pieces(const Eigen::Matrix<Scalar, 3, 1>& a, const Eigen::Matrix<Scalar, 3, 1>& b, double ell,
                            std::size_t pieces, double tolerance) {
  const double h = ell / static_cast<double>(pieces);
  Pose<Scalar> pose;
  pose.R = Eigen::Matrix<Scalar, 3, 3>::Identity();
  pose.r = Eigen::Matrix<Scalar, 3, 1>::Zero();
  for (std::size_t j = 0; j < pieces; ++j) {
    const Pose<Scalar> piece = series_piece<Scalar>(a + (static_cast<double>(j) * h) * b, b, h, tolerance);
    pose.r += pose.R * piece.r;
    pose.R = pose.R * piece.R;
    pose.max_terms = std::max(pose.max_terms, piece.max_terms);
  }
  return pose;
}

void validate_element(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  for (int i = 0; i < 3; ++i) {
    require_finite("a", a[i]);
    require_finite("b", b[i]);
  }
  require_positive("ell", ell);
  if (!(tolerance > 0.0 && tolerance <= 1e-6))
    throw InputError("tolerance", "invalid parameter 'tolerance' = " + format_value(tolerance) +
                                      ": must be a number in (0, 1e-6]");
}

}  // namespace

ClothoidPose clothoid_element(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  validate_element(a, b, ell, tolerance);
  const std::size_t pieces = piece_count(a, b, ell);
  const Pose<double> pose = compose_pieces<double>(a, b, ell, pieces, tolerance);
  ClothoidPose out;
  out.R = pose.R;
  out.r = pose.r;
  out.pieces = pieces;
  out.max_terms = pose.max_terms;
  return out;
}

ClothoidJacobian clothoid_element_jacobian(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  validate_element(a, b, ell, tolerance);
  const std::size_t pieces = piece_count(a, b, ell);
  const Pose<double> pose = compose_pieces<double>(a, b, ell, pieces, tolerance);
  ClothoidJacobian out;
  out.R = pose.R;
  out.r = pose.r;
  // Complex step: f'(p) = Im f(p + i t) / t with no subtractive cancellation, so t can be tiny
  // (1e-30 relative to the strain scale) and the derivative is exact to round-off. The series
  // tolerance test uses |.| of complex terms, i.e. the real part to O(t^2) = 0 in double.
  const double scale = std::max({a.norm(), b.norm() * ell, 1.0 / ell});
  const double t = 1e-30 * scale;
  for (int p = 0; p < 6; ++p) {
    Vec3c ac = a.cast<Complex>(), bc = b.cast<Complex>();
    if (p < 3)
      ac[p] += Complex(0.0, t);
    else
      bc[p - 3] += Complex(0.0, t);
    const Pose<Complex> perturbed = compose_pieces<Complex>(ac, bc, ell, pieces, tolerance);
    const Mat3 dR = perturbed.R.imag() / t;
    // dR/dp = [Theta_p]x R  =>  [Theta_p]x = dR R^T (skew up to round-off; take its axial part).
    const Mat3 W = dR * pose.R.transpose();
    out.rotation.col(p) = 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1));
    out.translation.col(p) = perturbed.r.imag() / t;
  }
  return out;
}

namespace {

// Quantities expanded to second order in a scalar e along a direction: X(e) = X0 + e X1 + e^2 X2.
struct Taylor2 {
  Mat3 m0, m1, m2;
};

Taylor2 multiply(const Taylor2& p, const Taylor2& q) {
  return {p.m0 * q.m0, p.m1 * q.m0 + p.m0 * q.m1, p.m2 * q.m0 + p.m1 * q.m1 + p.m0 * q.m2};
}

struct PoseRates {
  Taylor2 R;
  Vec3 r0, r1, r2;
};

// One sub-interval of length h from the identity, with strain (a + e adot) + s (b + e bdot): the
// series recurrence of series_piece carried to second order in e (products of first-order strain
// matrices with the second-order running terms). Stops when the value part and the two rate parts
// (relative to their running sums) stay below the tolerance for two consecutive terms.
PoseRates series_piece_rates(const Vec3& a, const Vec3& b, const Vec3& adot, const Vec3& bdot, double h,
                             double tolerance) {
  const Mat3 Xa0 = skew(a) * h, Xa1 = skew(adot) * h, Xb0 = skew(b) * (h * h), Xb1 = skew(bdot) * (h * h);
  const Vec3 e0 = Vec3::UnitX();
  Taylor2 previous{Mat3::Zero(), Mat3::Zero(), Mat3::Zero()};
  Taylor2 current{Mat3::Identity(), Mat3::Zero(), Mat3::Zero()};
  PoseRates pose{current, h * e0, Vec3::Zero(), Vec3::Zero()};
  int small_terms = 0;
  constexpr std::size_t kMaxTerms = 200;
  std::size_t k = 0;
  for (; k < kMaxTerms; ++k) {
    const double inv = 1.0 / static_cast<double>(k + 1);
    Taylor2 next;
    next.m0 = (current.m0 * Xa0 + previous.m0 * Xb0) * inv;
    next.m1 = (current.m1 * Xa0 + current.m0 * Xa1 + previous.m1 * Xb0 + previous.m0 * Xb1) * inv;
    next.m2 = (current.m2 * Xa0 + current.m1 * Xa1 + previous.m2 * Xb0 + previous.m1 * Xb1) * inv;
    pose.R.m0 += next.m0;
    pose.R.m1 += next.m1;
    pose.R.m2 += next.m2;
    const double weight = h / static_cast<double>(k + 2);
    pose.r0 += weight * next.m0.col(0);
    pose.r1 += weight * next.m1.col(0);
    pose.r2 += weight * next.m2.col(0);
    previous = current;
    current = next;
    const bool small = next.m0.cwiseAbs().maxCoeff() < tolerance &&
                       next.m1.cwiseAbs().maxCoeff() < tolerance * std::max(1.0, pose.R.m1.cwiseAbs().maxCoeff()) &&
                       next.m2.cwiseAbs().maxCoeff() < tolerance * std::max(1.0, pose.R.m2.cwiseAbs().maxCoeff());
    small_terms = small ? small_terms + 1 : 0;
    if (small_terms >= 2) break;
  }
  if (k == kMaxTerms)
    throw SolverError("super-clothoid rate series", "no convergence in " + std::to_string(kMaxTerms) + " terms", k,
                      current.m0.cwiseAbs().maxCoeff());
  return pose;
}

Vec3 axial(const Mat3& W) { return 0.5 * Vec3(W(2, 1) - W(1, 2), W(0, 2) - W(2, 0), W(1, 0) - W(0, 1)); }

}  // namespace

ClothoidRates clothoid_element_rates(const Vec3& a, const Vec3& b, const Vec3& adot, const Vec3& bdot, double ell,
                                     double tolerance) {
  validate_element(a, b, ell, tolerance);
  for (int i = 0; i < 3; ++i) {
    require_finite("adot", adot[i]);
    require_finite("bdot", bdot[i]);
  }
  const std::size_t pieces = piece_count(a, b, ell);
  const double h = ell / static_cast<double>(pieces);
  PoseRates pose{{Mat3::Identity(), Mat3::Zero(), Mat3::Zero()}, Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (std::size_t j = 0; j < pieces; ++j) {
    const double s = static_cast<double>(j) * h;
    const PoseRates piece = series_piece_rates(a + s * b, b, adot + s * bdot, bdot, h, tolerance);
    // (R, r) <- (R Rp, r + R rp), to second order in e.
    pose.r2 += pose.R.m0 * piece.r2 + pose.R.m1 * piece.r1 + pose.R.m2 * piece.r0;
    pose.r1 += pose.R.m0 * piece.r1 + pose.R.m1 * piece.r0;
    pose.r0 += pose.R.m0 * piece.r0;
    pose.R = multiply(pose.R, piece.R);
  }
  ClothoidRates out;
  out.R = pose.R.m0;
  out.r = pose.r0;
  // e = t: dR/dt = R1, d2R/dt2 = 2 R2; dR/dt R^T = [omega]x, and d/dt [omega]x = skew part of
  // (d2R/dt2) R^T (the other term, dR/dt dR/dt^T, is symmetric).
  out.angular_velocity = axial(pose.R.m1 * out.R.transpose());
  out.angular_bias = axial(2.0 * pose.R.m2 * out.R.transpose());
  out.velocity = pose.r1;
  out.bias = 2.0 * pose.r2;
  return out;
}

}  // namespace rodvv::solvers::superhelix

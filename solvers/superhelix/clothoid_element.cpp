#include "rodvv/solvers/superhelix/clothoid_element.hpp"

#include <algorithm>
#include <array>
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

ClothoidJacobian clothoid_element_jacobian_complex_step(const Vec3& a, const Vec3& b, double ell, double tolerance) {
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

namespace {

// Index of the unordered pair (p, q), p <= q < 6, among the 21 second derivatives.
constexpr int pair_index(int p, int q) { return p * 6 - p * (p - 1) / 2 + (q - p); }

// M [e_i]x by columns, without a product: column j is M (e_i x e_j), and e_i x e_j = e_k,
// e_i x e_k = -e_j for (i, j, k) cyclic.
Mat3 times_axis(const Mat3& M, int i) {
  const int j = (i + 1) % 3, k = (i + 2) % 3;
  Mat3 out;
  out.col(i).setZero();
  out.col(j) = M.col(k);
  out.col(k) = -M.col(j);
  return out;
}

// A pose with its first and second derivatives in the six strain parameters p = (a, b) of the
// element (second derivatives stored for p <= q).
struct PoseJet {
  Mat3 R;
  Vec3 r;
  std::array<Mat3, 6> dR;
  std::array<Vec3, 6> dr;
  std::array<Mat3, 21> ddR;
  std::array<Vec3, 21> ddr;
};

double largest_entry(const Mat3* matrices, std::size_t count) {
  double largest = 0.0;
  for (std::size_t m = 0; m < count; ++m) largest = std::max(largest, matrices[m].cwiseAbs().maxCoeff());
  return largest;
}

// One sub-interval of length h starting at offset s0 of the element, from the identity, with
// strain (a + s0 b) + s b: the recurrence of series_piece differentiated once and (kSecond) twice. Its two
// strain matrices depend on p through d[a + s0 b]x/da_i = [e_i]x, d[a + s0 b]x/db_i = s0 [e_i]x,
// d[b]x/db_i = [e_i]x (both linear in p, so their second derivatives vanish). Stops when the value
// and both derivative parts (relative to their running sums) stay below the tolerance twice.
template <bool kSecond>
PoseJet series_piece_jet(const Vec3& a, const Vec3& b, double s0, double h, double tolerance) {
  const Mat3 Xa = skew(a + s0 * b) * h, Xb = skew(b) * (h * h);
  std::array<double, 6> alpha{}, beta{};  // d(Xa)/dp = alpha_p [e_i]x, d(Xb)/dp = beta_p [e_i]x, i = p mod 3
  for (int p = 0; p < 3; ++p) {
    alpha[p] = h;
    alpha[p + 3] = s0 * h;
    beta[p + 3] = h * h;
  }
  Mat3 previous = Mat3::Zero(), current = Mat3::Identity();  // A_{k-1} h^(k-1), A_k h^k
  std::array<Mat3, 6> d_previous, d_current;
  std::array<Mat3, 21> dd_previous, dd_current;
  for (auto& m : d_previous) m.setZero();
  for (auto& m : d_current) m.setZero();
  for (auto& m : dd_previous) m.setZero();
  for (auto& m : dd_current) m.setZero();
  PoseJet pose;
  pose.R.setIdentity();
  pose.r = h * Vec3::UnitX();
  for (auto& m : pose.dR) m.setZero();
  for (auto& v : pose.dr) v.setZero();
  for (auto& m : pose.ddR) m.setZero();
  for (auto& v : pose.ddr) v.setZero();
  int small_terms = 0;
  constexpr std::size_t kMaxTerms = 200;
  std::size_t k = 0;
  for (; k < kMaxTerms; ++k) {
    const double inv = 1.0 / static_cast<double>(k + 1), weight = h / static_cast<double>(k + 2);
    const Mat3 next = (current * Xa + previous * Xb) * inv;
    std::array<Mat3, 6> d_next;
    for (int p = 0; p < 6; ++p)
      d_next[p] = (d_current[p] * Xa + d_previous[p] * Xb + alpha[p] * times_axis(current, p % 3) +
                   beta[p] * times_axis(previous, p % 3)) * inv;
    std::array<Mat3, 21> dd_next;
    if constexpr (kSecond) {
      // d_current[p] [e_i]x and d_previous[p] [e_i]x, the products every second derivative needs.
      std::array<std::array<Mat3, 3>, 6> d_current_axis, d_previous_axis;
      for (int p = 0; p < 6; ++p)
        for (int i = 0; i < 3; ++i) {
          d_current_axis[p][i] = times_axis(d_current[p], i);
          d_previous_axis[p][i] = times_axis(d_previous[p], i);
        }
      for (int p = 0; p < 6; ++p)
        for (int q = p; q < 6; ++q) {
          const int pq = pair_index(p, q);
          dd_next[pq] = (dd_current[pq] * Xa + dd_previous[pq] * Xb + alpha[q] * d_current_axis[p][q % 3] +
                         alpha[p] * d_current_axis[q][p % 3] + beta[q] * d_previous_axis[p][q % 3] +
                         beta[p] * d_previous_axis[q][p % 3]) * inv;
        }
    }
    pose.R += next;
    pose.r += weight * next.col(0);
    for (int p = 0; p < 6; ++p) {
      pose.dR[p] += d_next[p];
      pose.dr[p] += weight * d_next[p].col(0);
    }
    if constexpr (kSecond)
      for (int pq = 0; pq < 21; ++pq) {
        pose.ddR[pq] += dd_next[pq];
        pose.ddr[pq] += weight * dd_next[pq].col(0);
      }
    previous = current;
    current = next;
    d_previous = d_current;
    d_current = d_next;
    if constexpr (kSecond) {
      dd_previous = dd_current;
      dd_current = dd_next;
    }
    const bool small =
        next.cwiseAbs().maxCoeff() < tolerance &&
        largest_entry(d_next.data(), 6) < tolerance * std::max(1.0, largest_entry(pose.dR.data(), 6)) &&
        (!kSecond ||
         largest_entry(dd_next.data(), 21) < tolerance * std::max(1.0, largest_entry(pose.ddR.data(), 21)));
    small_terms = small ? small_terms + 1 : 0;
    if (small_terms >= 2) break;
  }
  if (k == kMaxTerms)
    throw SolverError("super-clothoid second-derivative series", "no convergence in " + std::to_string(kMaxTerms) +
                      " terms", k, current.cwiseAbs().maxCoeff());
  return pose;
}

// (R, r) <- (R_A R_B, r_A + R_A r_B) with the product rule to first and (kSecond) second order.
template <bool kSecond>
PoseJet compose(const PoseJet& A, const PoseJet& B) {
  PoseJet out;
  out.R = A.R * B.R;
  out.r = A.r + A.R * B.r;
  for (int p = 0; p < 6; ++p) {
    out.dR[p] = A.dR[p] * B.R + A.R * B.dR[p];
    out.dr[p] = A.dr[p] + A.dR[p] * B.r + A.R * B.dr[p];
  }
  for (int p = 0; kSecond && p < 6; ++p)
    for (int q = p; q < 6; ++q) {
      const int pq = pair_index(p, q);
      out.ddR[pq] = A.ddR[pq] * B.R + A.dR[p] * B.dR[q] + A.dR[q] * B.dR[p] + A.R * B.ddR[pq];
      out.ddr[pq] = A.ddr[pq] + A.ddR[pq] * B.r + A.dR[p] * B.dr[q] + A.dR[q] * B.dr[p] + A.R * B.ddr[pq];
    }
  return out;
}

template <bool kSecond>
PoseJet pose_jet(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  validate_element(a, b, ell, tolerance);
  const std::size_t pieces = piece_count(a, b, ell);
  const double h = ell / static_cast<double>(pieces);
  PoseJet pose = series_piece_jet<kSecond>(a, b, 0.0, h, tolerance);
  for (std::size_t j = 1; j < pieces; ++j)
    pose = compose<kSecond>(pose, series_piece_jet<kSecond>(a, b, static_cast<double>(j) * h, h, tolerance));
  return pose;
}

// The pose and its first derivatives: dR/dp R^T = [Theta_p]x.
ClothoidJacobian first_order(const PoseJet& pose) {
  ClothoidJacobian out;
  out.R = pose.R;
  out.r = pose.r;
  const Mat3 Rt = pose.R.transpose();
  for (int p = 0; p < 6; ++p) {
    out.rotation.col(p) = axial(pose.dR[p] * Rt);
    out.translation.col(p) = pose.dr[p];
  }
  return out;
}

}  // namespace

ClothoidJacobian clothoid_element_jacobian(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  return first_order(pose_jet<false>(a, b, ell, tolerance));
}

ClothoidSecondDerivatives clothoid_element_second_derivatives(const Vec3& a, const Vec3& b, double ell,
                                                              double tolerance) {
  const PoseJet pose = pose_jet<true>(a, b, ell, tolerance);
  ClothoidSecondDerivatives out;
  static_cast<ClothoidJacobian&>(out) = first_order(pose);
  const Mat3 Rt = pose.R.transpose();
  // d[Theta_p]x/dq = d2R/dp dq R^T + dR/dp (dR/dq)^T (skew, as the derivative of a skew matrix).
  for (int p = 0; p < 6; ++p)
    for (int q = 0; q < 6; ++q) {
      const int pq = pair_index(std::min(p, q), std::max(p, q));
      out.rotation_rate[q].col(p) = axial(pose.ddR[pq] * Rt + pose.dR[p] * pose.dR[q].transpose());
      out.translation_hessian[q].col(p) = pose.ddr[pq];
    }
  return out;
}

}  // namespace rodvv::solvers::superhelix

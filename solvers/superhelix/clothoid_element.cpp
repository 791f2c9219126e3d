#include "rodvv/solvers/superhelix/clothoid_element.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/element.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// One sub-interval of length h from the identity with strain a + s b (s from its own origin).
ClothoidPose series_piece(const Vec3& a, const Vec3& b, double h, double tolerance) {
  const Mat3 Xa = skew(a), Xb = skew(b);
  const Vec3 e0 = Vec3::UnitX();
  Mat3 previous = Mat3::Zero();      // A_{k-1} h^(k-1)
  Mat3 current = Mat3::Identity();   // A_k h^k
  ClothoidPose pose;
  pose.R = Mat3::Identity();
  pose.r = h * e0;  // k = 0 term of r: A_0 e0 h
  int small_terms = 0;
  constexpr std::size_t kMaxTerms = 200;
  std::size_t k = 0;
  for (; k < kMaxTerms; ++k) {
    // (k+1) A_{k+1} h^(k+1) = (A_k h^k) [a]x h + (A_{k-1} h^(k-1)) [b]x h^2
    const Mat3 next = (current * Xa * h + previous * Xb * (h * h)) / static_cast<double>(k + 1);
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
  pose.pieces = 1;
  pose.max_terms = k + 2;
  return pose;
}

}  // namespace

ClothoidPose clothoid_element(const Vec3& a, const Vec3& b, double ell, double tolerance) {
  for (int i = 0; i < 3; ++i) {
    require_finite("a", a[i]);
    require_finite("b", b[i]);
  }
  require_positive("ell", ell);
  if (!(tolerance > 0.0 && tolerance <= 1e-6))
    throw InputError("tolerance", "invalid parameter 'tolerance' = " + format_value(tolerance) +
                                      ": must be a number in (0, 1e-6]");
  // Sub-interval length: largest strain on the element times h at most 2 (ALGORITHMS.md §2).
  const double strain = a.norm() + b.norm() * ell;
  const auto pieces = static_cast<std::size_t>(std::max(1.0, std::ceil(strain * ell / 2.0)));
  const double h = ell / static_cast<double>(pieces);
  ClothoidPose pose;
  pose.R = Mat3::Identity();
  pose.r = Vec3::Zero();
  for (std::size_t j = 0; j < pieces; ++j) {
    const ClothoidPose piece = series_piece(a + (static_cast<double>(j) * h) * b, b, h, tolerance);
    pose.r += pose.R * piece.r;
    pose.R = pose.R * piece.R;
    pose.max_terms = std::max(pose.max_terms, piece.max_terms);
  }
  pose.pieces = pieces;
  return pose;
}

}  // namespace rodvv::solvers::superhelix

#include "superhelix_on_curve.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/element.hpp"

namespace rodvv::harness::knot_cases {

LaidSuperHelix superhelix_on_curve(const std::vector<Vec3>& curve, std::size_t elements, const Vec3& normal,
                                   double twist) {
  require_at_least("elements", elements, 1);
  require_finite("twist", twist);
  require_at_least("curve points", curve.size(), 2);
  std::vector<double> arclength(curve.size(), 0.0);
  for (std::size_t i = 1; i < curve.size(); ++i) arclength[i] = arclength[i - 1] + (curve[i] - curve[i - 1]).norm();
  const auto point_at = [&](double s) {
    const auto it = std::upper_bound(arclength.begin(), arclength.end(), s);
    const std::size_t j = std::min<std::size_t>(curve.size() - 2, it == arclength.begin() ? 0 : std::size_t(it - arclength.begin()) - 1);
    const double u = std::clamp((s - arclength[j]) / (arclength[j + 1] - arclength[j]), 0.0, 1.0);
    return Vec3(curve[j] + u * (curve[j + 1] - curve[j]));
  };

  LaidSuperHelix laid;
  laid.length = arclength.back();
  laid.root_position = curve.front();
  // The start tangent by the one-sided second-order difference of uniform samples (the first chord's direction is off by
  // half its turning angle, which the tracking would carry along as an oscillation of the curvature).
  const Vec3 n0 = curve.size() < 3 ? Vec3((curve[1] - curve[0]).normalized())
                                   : Vec3((-3.0 * curve[0] + 4.0 * curve[1] - curve[2]).normalized());
  const Vec3 n1 = normal - normal.dot(n0) * n0;
  if (!(n1.norm() > 1e-8 * normal.norm()))
    throw InputError("normal", "invalid parameter 'normal': must not be parallel to the curve's start tangent");
  laid.root_frame.col(0) = n0;
  laid.root_frame.col(1) = n1.normalized();
  laid.root_frame.col(2) = n0.cross(laid.root_frame.col(1));

  const double ell = laid.length / static_cast<double>(elements);
  laid.q = VecX::Zero(3 * static_cast<Eigen::Index>(elements));
  Vec3 p = laid.root_position;
  Mat3 R = laid.root_frame;
  Vec3 previous(twist, 0.0, 0.0);  // the last element's strain: the next one's start
  for (std::size_t e = 0; e < elements; ++e) {
    const Vec3 target = point_at(static_cast<double>(e + 1) * ell);
    Vec3 q = previous;
    // Gauss-Newton on |p + R G(ell; q) e0 - target|^2 over (kappa1, kappa2), twist held, each
    // step shortened to keep the element within a quarter turn (|kappa| ell <= pi / 2): a target
    // the arc cannot reach (a curve sharper than the elements) draws the arc towards it, not round.
    constexpr double kMaxTurn = 0.5 * std::numbers::pi;
    for (int iteration = 0; iteration < 50; ++iteration) {
      const solvers::superhelix::ElementMaps maps = solvers::superhelix::element_maps(q, ell);
      const Vec3 miss = p + R * (maps.G * Vec3::UnitX()) - target;
      Eigen::Matrix<double, 3, 2> J = R * maps.dG0.rightCols<2>();
      // Damped by 1e-12 of the normal matrix's own size (its entries are ~ ell^4: an absolute 1e-12 swamped
      // them below ell ~ 1e-3, and a knot tied at T = 1e6 was laid off its curve and came undone).
      const Eigen::Matrix2d normal_matrix = J.transpose() * J;
      const double damping = 1e-12 * normal_matrix.trace();
      Eigen::Vector2d step = (normal_matrix + damping * Eigen::Matrix2d::Identity()).ldlt().solve(-J.transpose() * miss);
      const double turn = (q.tail<2>() + step).norm() * ell;
      if (turn > kMaxTurn) step = (q.tail<2>() + step) * (kMaxTurn / turn) - q.tail<2>();
      q.tail<2>() += step;
      if (step.norm() * ell <= 1e-14) break;
    }
    const solvers::superhelix::ElementMaps maps = solvers::superhelix::element_maps(q, ell);
    const Vec3 end = p + R * (maps.G * Vec3::UnitX());
    laid.max_miss = std::max(laid.max_miss, (end - target).norm());
    laid.q.segment<3>(3 * static_cast<Eigen::Index>(e)) = q;
    p = end;
    R = R * maps.E;
    previous = q;
  }
  return laid;
}

}  // namespace rodvv::harness::knot_cases

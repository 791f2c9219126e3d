#include "rodvv/solvers/superhelix/kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/element.hpp"

namespace rodvv::solvers::superhelix {

void gauss_legendre(std::size_t n, std::vector<double>& nodes, std::vector<double>& weights) {
  // Newton on the Legendre polynomial P_n from the Chebyshev-like initial guess; converges to
  // round-off in a few iterations for n <= 8.
  nodes.assign(n, 0.0);
  weights.assign(n, 0.0);
  constexpr double kPi = 3.14159265358979323846;
  for (std::size_t i = 0; i < n; ++i) {
    double x = std::cos(kPi * (static_cast<double>(i) + 0.75) / (static_cast<double>(n) + 0.5));
    double dp = 1.0;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1.0, p1 = x;
      for (std::size_t k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * static_cast<double>(k) - 1.0) * x * p1 - (static_cast<double>(k) - 1.0) * p0) /
                          static_cast<double>(k);
        p0 = p1;
        p1 = p2;
      }
      dp = static_cast<double>(n) * (x * p1 - p0) / (x * x - 1.0);
      const double dx = p1 / dp;
      x -= dx;
      if (std::abs(dx) < 1e-16) break;
    }
    nodes[n - 1 - i] = x;
    weights[n - 1 - i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}

Kinematics::Kinematics(const RodModel& model, const VecX& q)
    : elements_(model.elements), ell_(superhelix::element_length(model)), q_(q) {
  if (q.size() != static_cast<Eigen::Index>(3 * elements_))
    throw InputError("q", "invalid parameter 'q': must hold 3 N = " + std::to_string(3 * elements_) +
                              " values, got " + std::to_string(q.size()));
  if (!q.allFinite()) throw InputError("q", "invalid parameter 'q': must be finite");
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  per_element_ = nodes.size();
  base_position_.resize(elements_ + 1);
  base_frame_.resize(elements_ + 1);
  theta_end_.resize(elements_);
  t_end_.resize(elements_);
  points_.reserve(elements_ * per_element_);
  base_position_[0] = model.root_position;
  base_frame_[0] = model.root_frame;
  const Vec3 e0 = Vec3::UnitX();
  for (std::size_t e = 0; e < elements_; ++e) {
    const Vec3 qe = q.segment<3>(3 * e);
    const Mat3& R = base_frame_[e];
    const Vec3& p = base_position_[e];
    for (std::size_t g = 0; g < per_element_; ++g) {
      GaussPoint point;
      point.element = e;
      point.sigma = 0.5 * ell_ * (1.0 + nodes[g]);
      point.mass = model.line_density * 0.5 * ell_ * weights[g];
      const PointMaps maps = element_point_maps(qe, point.sigma);
      point.offset = R * maps.Ge0;
      point.position = p + point.offset;
      point.local_jacobian = R * maps.dG0;
      points_.push_back(point);
    }
    const ElementMaps end = element_maps(qe, ell_);
    base_frame_[e + 1] = R * end.E;
    base_position_[e + 1] = p + R * (end.G * e0);
    theta_end_[e] = R * end.G;
    t_end_[e] = R * end.dG0;
  }
}

Vec3 Kinematics::position(std::size_t e, double sigma) const {
  const ElementMaps maps = element_maps(q_.segment<3>(3 * e), sigma);
  return base_position_[e] + base_frame_[e] * (maps.G * Vec3::UnitX());
}

Mat3 Kinematics::frame(std::size_t e, double sigma) const {
  return base_frame_[e] * element_maps(q_.segment<3>(3 * e), sigma).E;
}

MatX Kinematics::position_jacobian(std::size_t e, double sigma) const {
  MatX J = MatX::Zero(3, 3 * static_cast<Eigen::Index>(elements_));
  const Vec3 r = position(e, sigma);
  for (std::size_t p = 0; p < e; ++p)
    for (int i = 0; i < 3; ++i)
      J.col(static_cast<Eigen::Index>(3 * p) + i) =
          theta_end_[p].col(i).cross(r - base_position_[p + 1]) + t_end_[p].col(i);
  J.block<3, 3>(0, static_cast<Eigen::Index>(3 * e)) =
      base_frame_[e] * element_maps(q_.segment<3>(3 * e), sigma).dG0;
  return J;
}

MatX Kinematics::rotation_jacobian(std::size_t e, double sigma) const {
  MatX J = MatX::Zero(3, 3 * static_cast<Eigen::Index>(elements_));
  for (std::size_t p = 0; p < e; ++p) J.block<3, 3>(0, static_cast<Eigen::Index>(3 * p)) = theta_end_[p];
  J.block<3, 3>(0, static_cast<Eigen::Index>(3 * e)) =
      base_frame_[e] * element_maps(q_.segment<3>(3 * e), sigma).G;
  return J;
}

std::vector<Vec3> Kinematics::point_velocities(const VecX& qdot) const {
  std::vector<Vec3> velocities(points_.size());
  Vec3 omega = Vec3::Zero(), v = Vec3::Zero();
  for (std::size_t e = 0; e < elements_; ++e) {
    const Vec3 rate = qdot.segment<3>(3 * e);
    for (std::size_t g = 0; g < per_element_; ++g) {
      const GaussPoint& point = points_[e * per_element_ + g];
      velocities[e * per_element_ + g] = v + omega.cross(point.offset) + point.local_jacobian * rate;
    }
    v += omega.cross(base_position_[e + 1] - base_position_[e]) + t_end_[e] * rate;
    omega += theta_end_[e] * rate;
  }
  return velocities;
}

double largest_point_motion(const Kinematics& from, const Kinematics& to) {
  double largest = 0.0;
  for (std::size_t g = 0; g < from.points().size(); ++g)
    largest = std::max(largest, (to.points()[g].position - from.points()[g].position).norm());
  return largest;
}

}  // namespace rodvv::solvers::superhelix

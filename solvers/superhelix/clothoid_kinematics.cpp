#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"

#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

ClothoidKinematics::ClothoidKinematics(const RodModel& model, const VecX& q, bool with_points)
    : elements_(model.elements), ell_(superhelix::element_length(model)), q_(q) {
  if (q.size() != static_cast<Eigen::Index>(3 * (elements_ + 1)))
    throw InputError("q", "invalid parameter 'q': must hold 3 (N + 1) = " + std::to_string(3 * (elements_ + 1)) +
                              " nodal strains, got " + std::to_string(q.size()));
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
  for (std::size_t e = 0; e < elements_; ++e) {
    const Mat3& R = base_frame_[e];
    const Vec3& p = base_position_[e];
    for (std::size_t g = 0; with_points && g < per_element_; ++g) {
      ClothoidPoint point;
      point.element = e;
      point.sigma = 0.5 * ell_ * (1.0 + nodes[g]);
      point.mass = model.line_density * 0.5 * ell_ * weights[g];
      const LocalMaps maps = local_maps(e, point.sigma);
      point.offset = R * maps.r;
      point.position = p + point.offset;
      point.frame = R * maps.R;
      point.local_jacobian = R * maps.translation;
      point.local_rotation_jacobian = R * maps.rotation;
      points_.push_back(point);
    }
    const LocalMaps end = local_maps(e, ell_);
    base_frame_[e + 1] = R * end.R;
    base_position_[e + 1] = p + R * end.r;
    theta_end_[e] = R * end.rotation;
    t_end_[e] = R * end.translation;
  }
}

Vec3 ClothoidKinematics::strain(std::size_t e, double sigma) const {
  const Vec3 a = q_.segment<3>(3 * e), c = q_.segment<3>(3 * (e + 1));
  return a + (sigma / ell_) * (c - a);
}

ClothoidKinematics::LocalMaps ClothoidKinematics::local_maps(std::size_t e, double sigma) const {
  const Vec3 a = q_.segment<3>(3 * e);
  const Vec3 b = (q_.segment<3>(3 * (e + 1)) - a) / ell_;
  const ClothoidJacobian j = clothoid_element_jacobian(a, b, sigma);
  LocalMaps maps;
  maps.R = j.R;
  maps.r = j.r;
  // chain rule a = q_Q, b = (q_{Q+1} - q_Q) / ell
  maps.rotation.leftCols<3>() = j.rotation.leftCols<3>() - j.rotation.rightCols<3>() / ell_;
  maps.rotation.rightCols<3>() = j.rotation.rightCols<3>() / ell_;
  maps.translation.leftCols<3>() = j.translation.leftCols<3>() - j.translation.rightCols<3>() / ell_;
  maps.translation.rightCols<3>() = j.translation.rightCols<3>() / ell_;
  return maps;
}

Vec3 ClothoidKinematics::position(std::size_t e, double sigma) const {
  if (sigma == 0.0) return base_position_[e];
  return base_position_[e] + base_frame_[e] * local_maps(e, sigma).r;
}

Mat3 ClothoidKinematics::frame(std::size_t e, double sigma) const {
  if (sigma == 0.0) return base_frame_[e];
  return base_frame_[e] * local_maps(e, sigma).R;
}

MatX ClothoidKinematics::position_jacobian(std::size_t e, double sigma) const {
  MatX J = MatX::Zero(3, static_cast<Eigen::Index>(3 * (elements_ + 1)));
  const Vec3 r = position(e, sigma);
  for (std::size_t p = 0; p < e; ++p)
    for (int i = 0; i < 6; ++i)
      J.col(static_cast<Eigen::Index>(3 * p) + i) += theta_end_[p].col(i).cross(r - base_position_[p + 1]) +
                                                     t_end_[p].col(i);
  if (sigma > 0.0)
    J.block<3, 6>(0, static_cast<Eigen::Index>(3 * e)) += base_frame_[e] * local_maps(e, sigma).translation;
  return J;
}

MatX ClothoidKinematics::rotation_jacobian(std::size_t e, double sigma) const {
  MatX J = MatX::Zero(3, static_cast<Eigen::Index>(3 * (elements_ + 1)));
  for (std::size_t p = 0; p < e; ++p) J.block<3, 6>(0, static_cast<Eigen::Index>(3 * p)) += theta_end_[p];
  if (sigma > 0.0)
    J.block<3, 6>(0, static_cast<Eigen::Index>(3 * e)) += base_frame_[e] * local_maps(e, sigma).rotation;
  return J;
}

}  // namespace rodvv::solvers::superhelix

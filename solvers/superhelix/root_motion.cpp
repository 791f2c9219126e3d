#include "rodvv/solvers/superhelix/root_motion.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::superhelix {

void validate_root_state(const RootState& root) {
  const bool finite = root.position.allFinite() && root.frame.allFinite() && root.velocity.allFinite() &&
                      root.angular_velocity.allFinite() && root.acceleration.allFinite() &&
                      root.angular_acceleration.allFinite();
  if (!finite) throw InputError("root_motion", "invalid parameter 'root_motion': every entry must be finite");
  // Same test as RodModel::root_frame (model.hpp): orthonormal columns and det = +1 to 1e-10.
  const double orthogonality = (root.frame.transpose() * root.frame - Mat3::Identity()).norm();
  const double det = root.frame.determinant();
  if (!(orthogonality <= 1e-10) || !(std::abs(det - 1.0) <= 1e-10))
    throw InputError("root_motion.frame", "invalid parameter 'root_motion.frame': must be a rotation matrix "
                                          "(|R^T R - I| <= 1e-10 and |det R - 1| <= 1e-10), got |R^T R - I| = " +
                                              format_value(orthogonality) + ", det R = " + format_value(det));
}

RootState RootMotion::state_at(const RodModel& model, double t) const {
  RootState root;
  if (!motion) {
    root.position = model.root_position;
    root.frame = model.root_frame;
    return root;
  }
  root = motion(t);
  validate_root_state(root);
  return root;
}

RootMotion uniformly_accelerated_root(const RodModel& model, const Vec3& velocity, const Vec3& acceleration,
                                      const Vec3& axis, double angular_velocity, double angular_acceleration) {
  if (!velocity.allFinite() || !acceleration.allFinite())
    throw InputError("root_motion", "invalid parameter 'root_motion': velocity and acceleration must be finite");
  require_finite("angular_velocity", angular_velocity);
  require_finite("angular_acceleration", angular_acceleration);
  if (!axis.allFinite() || !(axis.norm() > 0.0))
    throw InputError("axis", "invalid parameter 'axis': must be a finite, non-zero vector");
  const Vec3 n = axis.normalized();
  const Vec3 r0 = model.root_position;
  const Mat3 R0 = model.root_frame;
  RootMotion root;
  root.motion = [=](double t) {
    RootState s;
    const double theta = angular_velocity * t + 0.5 * angular_acceleration * t * t;
    s.position = r0 + t * velocity + (0.5 * t * t) * acceleration;
    s.frame = Eigen::AngleAxisd(theta, n).toRotationMatrix() * R0;
    s.velocity = velocity + t * acceleration;
    s.acceleration = acceleration;
    s.angular_velocity = (angular_velocity + angular_acceleration * t) * n;
    s.angular_acceleration = angular_acceleration * n;
    return s;
  };
  return root;
}

}  // namespace rodvv::solvers::superhelix

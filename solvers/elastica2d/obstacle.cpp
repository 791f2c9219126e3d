#include "rodvv/solvers/elastica2d/obstacle.hpp"

#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::elastica2d {

Obstacle floor_at(double level) {
  Obstacle o;
  o.point = Eigen::Vector2d(0.0, level);
  o.normal = Eigen::Vector2d(0.0, 1.0);
  return o;
}

Obstacle ceiling_at(double level) {
  Obstacle o = floor_at(level);
  o.normal = Eigen::Vector2d(0.0, -1.0);
  return o;
}

Obstacle disk_outside(const Eigen::Vector2d& centre, double radius) {
  Obstacle o;
  o.shape = Obstacle::Shape::DiskOutside;
  o.point = centre;
  o.radius = radius;
  return o;
}

Obstacle disk_inside(const Eigen::Vector2d& centre, double radius) {
  Obstacle o = disk_outside(centre, radius);
  o.shape = Obstacle::Shape::DiskInside;
  return o;
}

std::vector<Obstacle> cavity_walls(double gap) {
  require_positive("wall_gap", gap);
  return {floor_at(-gap), ceiling_at(gap)};
}

namespace {
// Sign of the disk distance: +1 outside a post, -1 inside a ring.
double disk_sign(const Obstacle& o) { return o.shape == Obstacle::Shape::DiskOutside ? 1.0 : -1.0; }
}  // namespace

double gap(const Obstacle& o, const Eigen::Vector2d& r) {
  if (o.shape == Obstacle::Shape::HalfPlane) return o.normal.dot(r - o.point);
  return disk_sign(o) * ((r - o.point).norm() - o.radius);
}

Eigen::Vector2d gap_gradient(const Obstacle& o, const Eigen::Vector2d& r) {
  if (o.shape == Obstacle::Shape::HalfPlane) return o.normal;
  const Eigen::Vector2d d = r - o.point;
  const double norm = d.norm();
  // At the centre the distance has no gradient; any unit vector is a valid subgradient.
  if (norm == 0.0) return Eigen::Vector2d(disk_sign(o), 0.0);
  return disk_sign(o) * d / norm;
}

Eigen::Matrix2d gap_hessian(const Obstacle& o, const Eigen::Vector2d& r) {
  if (o.shape == Obstacle::Shape::HalfPlane) return Eigen::Matrix2d::Zero();
  const Eigen::Vector2d d = r - o.point;
  const double norm = d.norm();
  if (norm == 0.0) return Eigen::Matrix2d::Zero();
  const Eigen::Vector2d u = d / norm;
  // d^2 |d| = (I - u u^T) / |d|
  return disk_sign(o) * (Eigen::Matrix2d::Identity() - u * u.transpose()) / norm;
}

void validate(const Obstacle& o, const std::string& name) {
  require_finite(name + ".point.x", o.point.x());
  require_finite(name + ".point.y", o.point.y());
  if (o.shape == Obstacle::Shape::HalfPlane) {
    if (!o.normal.allFinite() || std::abs(o.normal.norm() - 1.0) > 1e-12)
      throw InputError(name + ".normal", "invalid parameter '" + name +
                                             ".normal': must be a finite unit vector (|n| = 1 within 1e-12)");
  } else {
    require_positive(name + ".radius", o.radius);
  }
  require_finite(name + ".s_min", o.s_min);
  if (!(o.s_max >= o.s_min))
    throw InputError(name + ".s_max", "invalid parameter '" + name + ".s_max' = " +
                                          format_value(o.s_max) + ": must be >= s_min = " +
                                          format_value(o.s_min));
}

}  // namespace rodvv::solvers::elastica2d

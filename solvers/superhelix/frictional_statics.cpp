#include "rodvv/solvers/superhelix/frictional_statics.hpp"

#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/bundle_frictional_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr const char* kMethod = "superhelix frictional statics";

bool unit(const Vec3& v) { return v.allFinite() && std::abs(v.norm() - 1.0) <= 1e-10; }

}  // namespace

void validate_obstacles(const std::vector<RigidObstacle>& obstacles) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const RigidObstacle& o = obstacles[i];
    const std::string which = "invalid parameter 'obstacles': obstacle " + std::to_string(i);
    if (!o.point.allFinite()) throw InputError("obstacles", which + " has a point that is not finite");
    if (o.shape != RigidObstacle::Shape::Ball && !unit(o.direction))
      throw InputError("obstacles", which + " must have a finite unit direction (|d| - 1 within 1e-10)");
    if (o.shape == RigidObstacle::Shape::Edge && !(unit(o.side) && std::abs(o.side.dot(o.direction)) <= 1e-10))
      throw InputError("obstacles", which + " (an edge) must have a finite unit side orthogonal to its direction "
                                            "(within 1e-10)");
    if (o.shape != RigidObstacle::Shape::Plane && !(std::isfinite(o.radius) && o.radius > 0.0))
      throw InputError("obstacles", which + " has radius " + format_value(o.radius) + ": must be finite and > 0");
    if (!(std::isfinite(o.mu) && o.mu >= 0.0))
      throw InputError("obstacles", which + " has mu " + format_value(o.mu) + ": must be finite and >= 0");
  }
}

ObstacleProximity obstacle_proximity(const RigidObstacle& obstacle, const Vec3& x) {
  ObstacleProximity result;
  const Vec3 offset = x - obstacle.point;
  switch (obstacle.shape) {
    case RigidObstacle::Shape::Plane:
      result.gap = obstacle.direction.dot(offset);
      result.normal = obstacle.direction;
      return result;
    case RigidObstacle::Shape::Ball:
    case RigidObstacle::Shape::Cylinder: {
      const bool cylinder = obstacle.shape == RigidObstacle::Shape::Cylinder;
      const Mat3 off_axis =
          cylinder ? Mat3(Mat3::Identity() - obstacle.direction * obstacle.direction.transpose()) : Mat3::Identity();
      const Vec3 radial = off_axis * offset;
      const double distance = radial.norm();
      if (!(distance > 0.0))
        throw SolverError(kMethod, "a Gauss point lies on the obstacle's centre or axis: no normal there", 0, 0.0);
      result.gap = distance - obstacle.radius;
      result.normal = radial / distance;
      result.normal_gradient = (off_axis - result.normal * result.normal.transpose()) / distance;
      return result;
    }
    case RigidObstacle::Shape::Edge: {
      // Coordinates across the two faces; beyond both, the rounding (a cylinder about the edge's axis).
      const double up = obstacle.direction.dot(offset), out = obstacle.side.dot(offset);
      if (up > 0.0 && out > 0.0) {
        const Vec3 radial = up * obstacle.direction + out * obstacle.side;
        const double distance = std::hypot(up, out);
        const Mat3 off_axis =
            obstacle.direction * obstacle.direction.transpose() + obstacle.side * obstacle.side.transpose();
        result.gap = distance - obstacle.radius;
        result.normal = radial / distance;
        result.normal_gradient = (off_axis - result.normal * result.normal.transpose()) / distance;
      } else {  // over a face (or inside, where the nearer face's distance is the larger coordinate)
        const bool top = up >= out;
        result.gap = (top ? up : out) - obstacle.radius;
        result.normal = top ? obstacle.direction : obstacle.side;
      }
      return result;
    }
  }
  return result;
}

FrictionalStaticResult frictional_start(const RodModel& model, const VecX& q) {
  validate(model);
  FrictionalStaticResult start;
  start.q = q;
  start.root_position = model.root_position;
  start.root_frame = model.root_frame;
  const Kinematics kinematics(model, q);  // checks q
  for (const auto& point : kinematics.points()) start.points.push_back(point.position);
  return start;
}

FrictionalStaticResult solve_frictional_increment(const RodModel& model, const std::vector<RigidObstacle>& obstacles,
                                                  const FrictionalStaticResult& previous,
                                                  const FrictionalStaticOptions& options) {
  BundleFrictionalResult bundle;  // one strand, no other strand to touch
  bundle.strands = {previous};
  return solve_bundle_frictional_increment({model}, obstacles, {}, bundle, options).strands.front();
}

}  // namespace rodvv::solvers::superhelix

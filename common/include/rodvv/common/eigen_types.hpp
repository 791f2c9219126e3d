#pragma once
// Eigen aliases shared by every rod family (planar and 3-D), so that solution structs agree on types.
#include <Eigen/Core>

namespace rodvv {
using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Mat3 = Eigen::Matrix3d;
using VecX = Eigen::VectorXd;
using MatX = Eigen::MatrixXd;
}  // namespace rodvv

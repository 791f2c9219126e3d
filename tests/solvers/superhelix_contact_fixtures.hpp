#pragma once
// Rods that touch themselves, shared by the Super-Helix's self-contact tests (barrier and hard law).
#include <cmath>
#include <cstddef>
#include <numbers>

#include <Eigen/Geometry>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace superhelix_contact_fixtures {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;

inline constexpr double kLength = 1.3;

inline sh::RodModel rod(std::size_t elements) {
  sh::RodModel model;
  model.length = kLength;
  model.elements = elements;
  model.root_position = Vec3(0.2, -0.1, 0.4);
  model.root_frame = Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  return model;
}

// A uniform Super-Helix q = (tau, kappa1, kappa2) is a circular helix of curvature |(kappa1, kappa2)|
// and torsion tau: radius a = kappa / |q|^2, axial advance b = tau / |q|^2 per radian about the axis,
// |q| radians per unit arclength. 2.5 turns of pitch 2 pi b = 0.05 on L = 1.3.
struct TightHelix {
  double omega = 2.5 * 2.0 * std::numbers::pi / kLength;
  double b = 0.05 / (2.0 * std::numbers::pi);
  double tau = b * omega * omega;
  double kappa = std::sqrt(omega * omega - tau * tau);
  double a = kappa / (omega * omega);
  VecX q(std::size_t elements) const {
    VecX strains(3 * elements);
    for (std::size_t e = 0; e < elements; ++e) strains.segment<3>(3 * e) = Vec3(tau, kappa * std::cos(0.3), kappa * std::sin(0.3));
    return strains;
  }
  // Distance from a point to the next turn: min over delta of 4 a^2 sin^2(delta/2) + b^2 (2 pi + delta)^2,
  // by Newton on its derivative 2 a^2 sin(delta) + 2 b^2 (2 pi + delta) from delta = 0.
  double turn_offset() const {
    double delta = 0.0;
    for (int i = 0; i < 50; ++i)
      delta -= (a * a * std::sin(delta) + b * b * (2 * std::numbers::pi + delta)) / (a * a * std::cos(delta) + b * b);
    return delta;
  }
  double turn_distance() const {
    const double delta = turn_offset();
    return std::sqrt(4 * a * a * std::pow(std::sin(delta / 2), 2) + b * b * std::pow(2 * std::numbers::pi + delta, 2));
  }
};

// Strains that fold a rod onto itself in 3-D with varying curvature and twist.
inline VecX tangled(std::size_t elements, double phase) {
  VecX q(3 * elements);
  for (std::size_t e = 0; e < elements; ++e) {
    const double s = (static_cast<double>(e) + 0.5) / static_cast<double>(elements);
    q.segment<3>(3 * e) = Vec3(2.0 * std::sin(3 * s + phase), 14.0 + 4.0 * std::cos(5 * s + phase), 3.0 * std::sin(7 * s - phase));
  }
  return q;
}

}  // namespace superhelix_contact_fixtures

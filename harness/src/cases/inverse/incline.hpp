#pragma once
// An incline of angle alpha under gravity along -z, as the friction cases lay rods on it: `across`, a
// horizontal line of the plane (at azimuth 0.7 rad, off the coordinate axes), `downhill`, its fall line,
// and `normal`, out of the plane and upward; (across, downhill, normal) is right-handed.
#include <cmath>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::harness::inverse_cases {

struct Incline {
  Vec3 across, downhill, normal;
};

inline Incline incline(double alpha) {
  const Vec3 across(std::cos(0.7), std::sin(0.7), 0.0);
  const Vec3 downhill = -(std::cos(alpha) * across.cross(Vec3::UnitZ()) + std::sin(alpha) * Vec3::UnitZ());
  return {across, downhill, across.cross(downhill)};
}

}  // namespace rodvv::harness::inverse_cases

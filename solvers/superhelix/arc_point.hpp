#pragma once
// A point of a Super-Helix element's helical arc with its tangent and the tangent's rate along the arc:
// what the contact searches' Newton iterations need (self_contact.cpp, arc_pair_contact.cpp). Private.
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix::detail {

struct ArcPoint {
  Vec3 r, tangent, tangent_rate;  // r, n0 and dn0/ds = R (q x e0)
};

inline ArcPoint arc_point(const Kinematics& kinematics, std::size_t e, double sigma) {
  const Mat3 R = kinematics.frame(e, sigma);
  const Vec3 q = kinematics.q().segment<3>(3 * static_cast<Eigen::Index>(e));
  return {kinematics.position(e, sigma), R.col(0), R * q.cross(Vec3::UnitX())};
}

}  // namespace rodvv::solvers::superhelix::detail

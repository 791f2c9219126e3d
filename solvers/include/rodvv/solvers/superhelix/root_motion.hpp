#pragma once
// Prescribed rigid motion of the clamped root of a Super-Helix / super-clothoid rod (issue 5:
// "clamped root, position and frame prescribed, optionally moving"; ALGORITHMS.md §1.2: g_0 driven
// by head motion, §1.4/§1.6: the root's spatial acceleration is the base acceleration).
//
// RootState: the root point r(0) and frame R(0) = [n0 n1 n2] at one time, with their first and
// second time derivatives as world vectors: v = dr0/dt, omega with dR/dt = [omega]x R, a = d2r0/dt2,
// alpha = d omega/dt. The dynamics uses (position, frame) for the kinematics, (omega, alpha, a) in
// the bias acceleration of every point (zeta = Jdot qdot + the root terms, so that r_tt = J qddot +
// zeta); v only enters the point velocities (a uniformly moving root changes nothing: Galilean).
//
// RootMotion: a function of time; empty = the model's fixed root (root_position, root_frame, at
// rest). state_at throws InputError naming "root_motion.frame" for a frame that is not a rotation
// (same 1e-10 test as RodModel::root_frame) and "root_motion" for a non-finite entry.
#include <functional>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct RootState {
  Vec3 position = Vec3::Zero();
  Mat3 frame = Mat3::Identity();
  Vec3 velocity = Vec3::Zero();
  Vec3 angular_velocity = Vec3::Zero();
  Vec3 acceleration = Vec3::Zero();
  Vec3 angular_acceleration = Vec3::Zero();
};

struct RootMotion {
  std::function<RootState(double)> motion;  // empty: fixed at the model's root

  // The (validated) root state at time t.
  RootState state_at(const RodModel& model, double t) const;
  bool is_fixed() const noexcept { return !motion; }
};

// Throws InputError if the state is not finite or its frame is not a rotation.
void validate_root_state(const RootState& root);

// The model's root pose carried by a rigid motion starting at t = 0 from (root_position, root_frame):
// translation r0(t) = r0 + v0 t + a t^2 / 2 and rotation about the fixed world axis `axis` through
// the root point by the angle theta(t) = w0 t + alpha t^2 / 2: R(t) = Rot(axis, theta(t)) R0, so
// omega = theta' axis, omega' = alpha axis. InputError for a zero or non-finite axis.
RootMotion uniformly_accelerated_root(const RodModel& model, const Vec3& velocity, const Vec3& acceleration,
                                      const Vec3& axis = Vec3::UnitZ(), double angular_velocity = 0.0,
                                      double angular_acceleration = 0.0);

}  // namespace rodvv::solvers::superhelix

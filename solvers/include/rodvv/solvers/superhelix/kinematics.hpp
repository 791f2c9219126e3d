#pragma once
// Root-to-tip kinematics of a Super-Helix (ALGORITHMS.md §1.2-1.3), O(N): the product of
// exponentials g_{Q+1} = g_Q exp(ell Xi(q_Q)) from the clamped root, with, per element,
//   base frame R_Q and base point p_Q (Q = 0 .. N; index N is the tip),
//   S_Q = [Theta_Q(ell); T_Q(ell)]: rotation and end translation per unit q_iQ (world),
// and the Gauss-Legendre points of every element (mass m_g = rho S w_g ell / 2), each with its
// position, frame, offset d_g = r_g - p_Q and local position Jacobian T_g = dr_g / dq_Q.
//
// Jacobians (§1.3): for a point on element Q and P < Q,
//   dr/dq_iP = Theta_iP(ell) x (r - p_{P+1}) + T_iP(ell),   dR/dq_iP = [Theta_iP(ell)]x R;
// on its own element dr/dq_iQ = T_iQ(sigma), dR/dq_iQ = [R_Q G(sigma) e_i]x R; 0 for P > Q.
// Velocities: omega_{Q+1} = omega_Q + Theta_Q qdot_Q, v_{Q+1} = v_Q + omega_Q x (p_{Q+1} - p_Q)
// + T_Q qdot_Q, and at a point v_g = v_Q + omega_Q x d_g + T_g qdot_Q (root at rest).
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct GaussPoint {
  std::size_t element = 0;
  double sigma = 0.0;  // offset from the element's start
  double mass = 0.0;   // rho S w ell / 2
  Vec3 position;
  Vec3 offset;  // d = r - p_Q
  Mat3 local_jacobian;  // T_g: column i = dr / dq_iQ
};

// Gauss-Legendre nodes on [-1, 1] and weights, n = 1 .. 8.
void gauss_legendre(std::size_t n, std::vector<double>& nodes, std::vector<double>& weights);

class Kinematics {
 public:
  // Requires a validated model and q of size 3N (InputError "q" otherwise, or non-finite).
  Kinematics(const RodModel& model, const VecX& q);

  std::size_t elements() const noexcept { return elements_; }
  double element_length() const noexcept { return ell_; }
  const VecX& q() const noexcept { return q_; }

  // Index 0 .. N (N = tip).
  const Vec3& base_position(std::size_t i) const { return base_position_[i]; }
  const Mat3& base_frame(std::size_t i) const { return base_frame_[i]; }
  const Vec3& tip_position() const { return base_position_.back(); }
  const Mat3& tip_frame() const { return base_frame_.back(); }
  // S_Q blocks (world): column i per unit q_iQ.
  const Mat3& end_rotation_jacobian(std::size_t e) const { return theta_end_[e]; }
  const Mat3& end_translation_jacobian(std::size_t e) const { return t_end_[e]; }

  const std::vector<GaussPoint>& points() const noexcept { return points_; }
  std::size_t points_per_element() const noexcept { return per_element_; }

  // Any point (element e, offset sigma in [0, ell]).
  Vec3 position(std::size_t e, double sigma) const;
  Mat3 frame(std::size_t e, double sigma) const;
  // 3 x 3N Jacobians dr/dq and Theta (dR/dq_j = [Theta.col(j)]x R).
  MatX position_jacobian(std::size_t e, double sigma) const;
  MatX rotation_jacobian(std::size_t e, double sigma) const;

  // Velocities of the Gauss points (same order as points()) for the rates qdot.
  std::vector<Vec3> point_velocities(const VecX& qdot) const;

 private:
  std::size_t elements_ = 0;
  double ell_ = 0.0;
  VecX q_;
  std::vector<Vec3> base_position_;
  std::vector<Mat3> base_frame_;
  std::vector<Mat3> theta_end_, t_end_;
  std::vector<GaussPoint> points_;
  std::size_t per_element_ = 0;
};

// The largest displacement of a Gauss point between two configurations of the same rod: the step
// control of the statics with self-contact (statics.hpp, hard_self_contact.hpp).
double largest_point_motion(const Kinematics& from, const Kinematics& to);

}  // namespace rodvv::solvers::superhelix

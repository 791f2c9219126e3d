#pragma once
// Root-to-tip kinematics of a super-clothoid rod (ALGORITHMS.md §2; Casati & Bertails-Descoubes
// 2013) on the same RodModel as the Super-Helix (length, N equal elements, root, loads, Gauss points).
//
// Generalised coordinates (the continuous variant of §2): the material strains (twist, kappa1,
// kappa2) at the N + 1 nodes, q in R^{3(N+1)}, q.segment<3>(3 j) = strain at node j (s = j ell),
// linearly interpolated on each element, so the strain is continuous and piecewise affine:
//   kappa(sigma) = a_Q + sigma b_Q,  a_Q = q_Q,  b_Q = (q_{Q+1} - q_Q) / ell   on element Q.
// Per element: base frame R_Q and point p_Q (Q = 0 .. N, N = tip), and the end Jacobians
//   S_Q = [Theta_Q(ell); T_Q(ell)] (3 x 6 each, world): rotation and end translation per unit change
//   of the element's two nodal strains (columns 0-2: node Q, 3-5: node Q + 1),
// from clothoid_element_jacobian (series, forward mode, exact to round-off) by the chain rule
// d/dq_Q = d/da - d/db / ell, d/dq_{Q+1} = d/db / ell. Downstream of an element everything is
// rigidly carried, as for the Super-Helix (§1.3): for a point on element Q and P < Q,
//   dr/dq (through element P) = Theta_P x (r - p_{P+1}) + T_P,
// and a node's columns are the sum over the two elements that share it.
#include <cstddef>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

using Mat36 = Eigen::Matrix<double, 3, 6>;

inline std::size_t clothoid_dof_count(const RodModel& model) { return 3 * (model.elements + 1); }

struct ClothoidPoint {
  std::size_t element = 0;
  double sigma = 0.0;  // offset from the element's start
  double mass = 0.0;   // rho S w ell / 2
  Vec3 position;
  Mat3 frame;
  Vec3 offset;           // d = r - p_Q
  Mat36 local_jacobian;  // dr / d(q_Q, q_{Q+1}) through the element itself
  Mat36 local_rotation_jacobian;  // Theta (dR = [Theta dq]x R) w.r.t. (q_Q, q_{Q+1}) through the element itself
};

class ClothoidKinematics {
 public:
  // Requires a validated model and q of size 3(N+1) (InputError "q" otherwise, or non-finite).
  // with_points = false skips the Gauss points (points() empty): 5x cheaper when only the element
  // ends are needed (statics without gravity).
  ClothoidKinematics(const RodModel& model, const VecX& q, bool with_points = true);

  std::size_t elements() const noexcept { return elements_; }
  double element_length() const noexcept { return ell_; }
  const VecX& q() const noexcept { return q_; }
  // Strain (twist, kappa1, kappa2) at offset sigma on element e.
  Vec3 strain(std::size_t e, double sigma) const;

  const Vec3& base_position(std::size_t i) const { return base_position_[i]; }
  const Mat3& base_frame(std::size_t i) const { return base_frame_[i]; }
  const Vec3& tip_position() const { return base_position_.back(); }
  const Mat3& tip_frame() const { return base_frame_.back(); }
  const Mat36& end_rotation_jacobian(std::size_t e) const { return theta_end_[e]; }
  const Mat36& end_translation_jacobian(std::size_t e) const { return t_end_[e]; }

  const std::vector<ClothoidPoint>& points() const noexcept { return points_; }
  std::size_t points_per_element() const noexcept { return per_element_; }

  // Any point (element e, offset sigma in (0, ell]; sigma = 0 is the base point).
  Vec3 position(std::size_t e, double sigma) const;
  Mat3 frame(std::size_t e, double sigma) const;
  // 3 x 3(N+1) Jacobians dr/dq and Theta (dR/dq_j = [Theta.col(j)]x R).
  MatX position_jacobian(std::size_t e, double sigma) const;
  MatX rotation_jacobian(std::size_t e, double sigma) const;

 private:
  struct LocalMaps {
    Mat3 R;
    Vec3 r;
    Mat36 rotation, translation;  // local (base-frame) derivatives w.r.t. (q_Q, q_{Q+1})
  };
  LocalMaps local_maps(std::size_t e, double sigma) const;

  std::size_t elements_ = 0;
  double ell_ = 0.0;
  VecX q_;
  std::vector<Vec3> base_position_;
  std::vector<Mat3> base_frame_;
  std::vector<Mat36> theta_end_, t_end_;
  std::vector<ClothoidPoint> points_;
  std::size_t per_element_ = 0;
};

}  // namespace rodvv::solvers::superhelix

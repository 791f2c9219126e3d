#pragma once
// The load stiffness of a Super-Helix, D = dF_ext/dq, exactly (no step size) and in O(N^2)
// (ALGORITHMS.md §3.1: (dF/dq)_ij = int rho S g . d2r/dq_i dq_j ds for gravity). The static Jacobian
// is K - lambda D (statics.hpp), the Hessian of the potential K - D (stability.hpp,
// inverse_statics.hpp).
//
// F_a = sum_g J_g,a . f_g + J_tip,a . F + Theta_a . M for point forces f_g (Gauss points), a dead tip
// force F and a dead tip moment M; a = (P, i) is coordinate i of element P, Theta_a and T_a its end
// rotation and translation Jacobians (world, kinematics.hpp). Downstream of element P everything is
// carried rigidly by q_a, so for b = (P', j):
//   P < P':  D_ab = Theta_a . W_b,               W_b = sum_{g downstream of P' (on it included)} J_g,b x f_g
//   P > P':  D_ab = Theta_b . (W_a + Theta_a x M)  (the moment's share: dTheta_a/dq_b = Theta_b x Theta_a)
//   P = P':  D_ab = dTheta_a/dq_b . M_> + Theta_a . (A_> Theta_b - tr(A_>) Theta_b) + dT_a/dq_b . F_>
//                   + sum_{g on P} R_P d2c_g/dq_i dq_j . f_g,
// where, about the element's end p_{P+1}, F_> is the resultant of everything downstream, M_> its
// moment (tip moment included) and A_> = sum d_g f_g^T (d_g = r_g - p_{P+1}); the middle term is
// sum_g f_g . (Theta_a x (Theta_b x d_g)) by (u x d) x f = d (u . f) - u (d . f). With
// W_b = sum_{g on P'} J_g,b x f_g + A_> Theta_b - tr(A_>) Theta_b + T_b x F_>, the suffix sums
// come from one tip-to-root pass (as loads.hpp) and each of the N^2 blocks costs one 3 x 3 product.
// Element-local second derivatives: element_second_derivatives (element.hpp).
// Symmetric for gravity and a dead force (conservative); a dead tip moment adds the unsymmetric
// part of the Ziegler load (P > P' only).
// tests/solvers/test_superhelix_load_stiffness.cpp checks D against central differences of F.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

// point_forces: one per Gauss point (Kinematics::points() order) or empty; 3N square.
MatX generalised_force_jacobian(const Kinematics& kinematics, const std::vector<Vec3>& point_forces,
                                const Vec3& tip_force, const Vec3& tip_moment);

// Dead forces at any points (element, offset sigma in [0, ell]), e.g. contact forces held fixed.
struct PointLoad {
  std::size_t element = 0;
  double sigma = 0.0;
  Vec3 force = Vec3::Zero();
};
MatX point_load_jacobian(const Kinematics& kinematics, const std::vector<PointLoad>& point_loads);

// Gravity m_g g and the dead end force and moment of the model, all scaled by load_factor.
MatX load_stiffness(const RodModel& model, const Kinematics& kinematics, double load_factor = 1.0);

}  // namespace rodvv::solvers::superhelix

#pragma once
// Dynamics of a super-clothoid rod, dense path (ALGORITHMS.md §2: "identical to §1.4-1.5"): the
// Super-Helix Lagrangian on nodal strains q in R^{3(N+1)} (clothoid_kinematics.hpp), with the block
// tridiagonal stiffness K of clothoid_statics.hpp:
//
//   M(q) qddot + K (q - q0) = -gamma K qdot + F_ext(q) - sum_g m_g J_g^T (Jdot_g qdot)
//                             - sum_g Theta_g^T (I_g xi_g + omega_g x (I_g omega_g)),
//   M = sum_g m_g J_g^T J_g + Theta_g^T I_g Theta_g  (point Jacobians J_g, Theta_g =
//   ClothoidKinematics::position_jacobian, rotation_jacobian),
// with the cross-sections' rotational inertia I_g = (w_g ell/2) R_g diag(rho I0, rho I1, rho I2) R_g^T
// (model.hpp; dynamics.hpp for the Super-Helix form of the same terms; with rotational_inertia = 0
// they vanish and the step is the translational-only one),
//
// zeta_g = Jdot_g qdot in one root-to-tip pass: the bias recursion of dynamics.hpp with the
// element-local second-order rates of clothoid_element_rates (series to second order along qdot,
// exact to round-off; it replaced a global central difference with ~1e-11 relative error and two
// extra kinematics constructions); the angular velocity omega_g and angular bias xi_g from the same
// pass. Both paths use these same rates. Semi-implicit Euler as in dynamics.hpp:
//   (M_n + D) dv = h (-K (q_n - q0) + B_n) - D qdot_n,  D = (h^2 + h gamma) K,
//   qdot_{n+1} = qdot_n + dv,  q_{n+1} = q_n + h qdot_{n+1}.
// Two paths:
//   Dense: O(N^2) assembly of M with O(N) point Jacobians, LDL^T O(N^3).
//   Recursive: the articulated-body recursion of §1.6 adapted to shared nodal coordinates, exact
//   and O(N). Element Q moves with its proximal node strain x_Q (shared with its parent) and its
//   distal one x_{Q+1}; K (hence D) is block tridiagonal. A Gauss point is a rigid body: its angular
//   acceleration alpha_Q + Theta_g (x_Q, x_{Q+1}) + xi_g enters the element's quadratic form with the
//   weight I_g, its gyroscopic torque as a linear term. The tip-to-root pass carries the value of
//   the downstream rod as a quadratic form in (A_Q, x_Q) in R^9 (the base spatial acceleration AND
//   the proximal node's rate, instead of the 6 x 6 articulated inertia alone): at element Q it adds
//   the element's point masses and bias wrenches (in y = (A_Q, x_Q, x_{Q+1}) in R^12), the
//   downstream form through A_{Q+1} = X(r_Q) A_Q + S_Q (x_Q, x_{Q+1}), the D blocks D_{Q+1,Q+1} and
//   D_{Q,Q+1}, and eliminates x_{Q+1} (3 x 3 Schur complement). Since D couples node Q+1 only to
//   nodes Q and Q+2, which are both in the form when x_{Q+1} is eliminated, the tridiagonal D needs
//   no Woodbury / Schur correction: the recursion is block Gaussian elimination of (M + D) in
//   tip-to-root order, with the dense coupling of M carried by the 9 x 9 form (symmetrised after every
//   element, as the Super-Helix I^A: its antisymmetric rounding errors grow ~3x per element otherwise). The root-to-tip pass
//   solves node 0 (A_0 = 0) and then x_{Q+1} = -H^-1 (Z21 (A_Q, x_Q) + z2), A_{Q+1} as above.
// InputError for h <= 0 / non-finite, or a state of the wrong size.
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"

namespace rodvv::solvers::superhelix {

// `kinematics` must be built from `model` (M with the rotational inertia of model).
MatX clothoid_mass_matrix(const RodModel& model, const ClothoidKinematics& kinematics);
std::vector<Vec3> clothoid_bias_accelerations(const RodModel& model, const ClothoidKinematics& kinematics,
                                              const VecX& qdot);
// With a moving root: `kinematics` must have been built from root.position / root.frame.
std::vector<Vec3> clothoid_bias_accelerations(const ClothoidKinematics& kinematics, const VecX& qdot,
                                              const RootState& root);
// omega_g (world, with the root's) and xi_g at every Gauss point (the same pass as the bias accelerations).
std::vector<AngularRates> clothoid_angular_rates(const ClothoidKinematics& kinematics, const VecX& qdot,
                                                 const RootState& root = RootState{});
// World rotational inertia I_g of every Gauss point.
std::vector<Mat3> clothoid_point_rotational_inertias(const RodModel& model, const ClothoidKinematics& kinematics);
// Dense path (as before).
VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h);
DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h);
// Either path.
VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// Either path with a prescribed root motion (root_motion.hpp, evaluated at state.time), as for the
// Super-Helix: the kinematics starts from the root pose, zeta carries the root's acceleration terms.
VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                              const RootMotion& root);
DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                           const RootMotion& root);

// Root at rest: 1/2 sum_g m_g |v_g|^2 + 1/2 sum_g omega_g . I_g omega_g (= 1/2 qdot^T M qdot).
double clothoid_kinetic_energy(const RodModel& model, const ClothoidKinematics& kinematics, const VecX& qdot);
// kinetic + elastic + gravity - F_end . r_tip (the end moment has no potential in 3-D).
double clothoid_total_energy(const RodModel& model, const DynamicState& state);

}  // namespace rodvv::solvers::superhelix

#pragma once
// Dynamics of a super-clothoid rod, dense path (ALGORITHMS.md §2: "identical to §1.4-1.5"): the
// Super-Helix Lagrangian on nodal strains q in R^{3(N+1)} (clothoid_kinematics.hpp), with the block
// tridiagonal stiffness K of clothoid_statics.hpp:
//
//   M(q) qddot + K (q - q0) = -gamma K qdot + F_ext(q) - sum_g m_g J_g^T (Jdot_g qdot),
//   M = sum_g m_g J_g^T J_g  (point Jacobians J_g = ClothoidKinematics::position_jacobian),
//
// zeta_g = Jdot_g qdot by a central difference in e of J_g(q + e qdot) qdot
// (e = cbrt(eps) / (L |qdot|_inf), ~1e-11 relative). Semi-implicit Euler as in dynamics.hpp:
//   (M_n + D) dv = h (-K (q_n - q0) + B_n) - D qdot_n,  D = (h^2 + h gamma) K,
//   qdot_{n+1} = qdot_n + dv,  q_{n+1} = q_n + h qdot_{n+1}.
// Dense only (O(N^2) assembly with O(N) Jacobians, LDL^T O(N^3)); the O(N) recursion of §1.6 is not
// implemented for this element. InputError for h <= 0 / non-finite, or a state of the wrong size.
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

MatX clothoid_mass_matrix(const ClothoidKinematics& kinematics);
std::vector<Vec3> clothoid_bias_accelerations(const RodModel& model, const ClothoidKinematics& kinematics,
                                              const VecX& qdot);
VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h);
DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h);

double clothoid_kinetic_energy(const ClothoidKinematics& kinematics, const VecX& qdot);
// kinetic + elastic + gravity - F_end . r_tip (the end moment has no potential in 3-D).
double clothoid_total_energy(const RodModel& model, const DynamicState& state);

}  // namespace rodvv::solvers::superhelix

#pragma once
// Dynamics of a Super-Helix (ALGORITHMS.md §1.4-1.6): Lagrangian with translational inertia
// T = 1/2 int rho S |r_t|^2 ds (Gauss quadrature: point masses m_g), elastic energy
// 1/2 (q - q0)^T K (q - q0), gravity, dead end loads and Rayleigh (stiffness-proportional) damping
// -gamma K qdot:
//
//   M(q) qddot + K (q - q0) = -gamma K qdot + F_ext(q) - sum_g m_g J_g^T (Jdot_g qdot)
//
// Velocity terms: the bias acceleration zeta_g = Jdot_g qdot (plus the root's acceleration terms
// when the root moves, root_motion.hpp) of every Gauss point, in closed form in one root-to-tip pass
// (the Featherstone bias recursion): with omega_Q, alpha_Q, a_Q the angular velocity, the angular
// and the linear bias acceleration of base Q (root values at Q = 0),
//   zeta_g = a_Q + alpha_Q x d_g + omega_Q x (omega_Q x d_g) + 2 omega_Q x u_g + R_Q c''_g,
//   a_{Q+1} = (the same at the element's end),  alpha_{Q+1} = alpha_Q + omega_Q x W_Q + R_Q W'_Q,
//   omega_{Q+1} = omega_Q + W_Q,
// where u_g = T_g qdot_Q, W_Q = R_Q G(ell) qdot_Q, and c'', W' are the element-local second
// directional derivatives of element.hpp (ElementRates). Both paths use this same zeta.
//
// Semi-implicit Euler (§1.5), implicit in the elastic and damping terms, explicit in the rest:
//   (M_n + D) dv = h (-K (q_n - q0) + B_n) - D qdot_n,   D = (h^2 + h gamma) K,
//   qdot_{n+1} = qdot_n + dv,   q_{n+1} = q_n + h qdot_{n+1},
//   B_n = F_ext(q_n) - sum_g m_g J_g^T zeta_g.
// Two paths solve the same linear system:
//   Dense: point Jacobians (O(N^2)), M = sum m_g J_g^T J_g (O(N^3)), LDL^T (O(N^3)).
//   Recursive: the articulated-body recursion of §1.6 (tip-to-root inertias, root-to-tip solve),
//   O(N), with the bias and gravity entering as point wrenches beta_g = h (m_g zeta_g - m_g g) and
//   the end loads as the tip wrench.
// Recursive cost: one root-to-tip pass (kinematics and zeta), one tip-to-root pass (articulated
// inertias, 6 x 6) and one root-to-tip solve, no heap allocation per element (a reused workspace).
// Moving root (root_motion.hpp): the kinematics starts from the root pose at state.time and zeta
// carries the root's acceleration terms (so the forward solve starts from A_0 = 0); overloads with a
// RootMotion argument, the others use the model's fixed root.
// Both throw InputError for h <= 0 or non-finite, or a state of the wrong size / non-finite.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"

namespace rodvv::solvers::superhelix {

struct DynamicState {
  VecX q;
  VecX qdot;
  double time = 0.0;
};

enum class DynamicsPath { Dense, Recursive };

// zeta_g = Jdot_g qdot at every Gauss point (Kinematics::points() order).
std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot);
// The same with a moving root: `kinematics` must have been built from root.position / root.frame.
std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot,
                                     const RootState& root);

// Dense generalised mass matrix sum_g m_g J_g^T J_g (3N x 3N, symmetric positive semi-definite:
// twist rates of a straight element move no mass).
MatX mass_matrix(const Kinematics& kinematics);

// dv of one semi-implicit Euler step by either path.
VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// One full step.
DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// The same with a prescribed root motion, evaluated at state.time.
VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                     const RootMotion& root);
DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                  const RootMotion& root);

// Energies: kinetic 1/2 sum_g m_g |v_g|^2 (= 1/2 qdot^T M qdot), and total = kinetic + elastic +
// gravity - F_end . r_tip (the end moment is left out: it has no potential in 3-D).
double kinetic_energy(const Kinematics& kinematics, const VecX& qdot);
double total_energy(const RodModel& model, const DynamicState& state);

// The lowest `count` circular frequencies of the straight rod (q = 0) bending in the plane of n0
// and n2 (the kappa1 coordinates), from the linearised dynamics K v = omega^2 M v (generalised
// symmetric eigenproblem). Requires count <= N.
VecX bending_frequencies(const RodModel& model, std::size_t count);

}  // namespace rodvv::solvers::superhelix

#pragma once
// Dynamics of a Super-Helix (ALGORITHMS.md §1.4-1.6): Lagrangian with the kinetic energy of the
// translation AND of the rotation of the cross-sections (issue 11),
//   T = 1/2 int rho S |r_t|^2 ds + 1/2 int omega . (R J R^T) omega ds,  J = diag(rho I0, rho I1, rho I2)
// (model.hpp: material components, omega the angular velocity of the material frame), by Gauss
// quadrature: point masses m_g = rho S w_g ell/2 and point rotational inertias
// I_g = (w_g ell/2) R_g J R_g^T (world); elastic energy 1/2 (q - q0)^T K (q - q0), gravity, dead end
// loads and Rayleigh (stiffness-proportional) damping -gamma K qdot:
//
//   M(q) qddot + K (q - q0) = -gamma K qdot + F_ext(q) - sum_g m_g J_g^T zeta_g
//                             - sum_g Theta_g^T (I_g xi_g + omega_g x (I_g omega_g)),
//   M = sum_g m_g J_g^T J_g + Theta_g^T I_g Theta_g,
//
// with J_g = dr_g/dq, Theta_g the rotation Jacobian of the frame at point g (omega_g = omega_root +
// Theta_g qdot, kinematics.hpp), zeta_g = Jdot_g qdot and xi_g = Thetadot_g qdot the translational and
// angular bias accelerations (so r_tt = J qddot + zeta, omega_t = Theta qddot + xi). The rotational
// terms are Euler's equations of each cross-section (Kane's form: the partial angular velocities
// Theta_g times the inertia torque d/dt(I omega) = I omega_t + omega x I omega); the last one is the
// gyroscopic term. With J = 0 the rotational terms are skipped: the translational-only model of the
// 2006 paper, whose M is only semi-definite (twist rates of a straight element move no mass).
//
// Velocity terms: zeta_g and xi_g (plus the root's acceleration terms when the root moves,
// root_motion.hpp) of every Gauss point, in closed form in one root-to-tip pass (the Featherstone
// bias recursion): with omega_Q, alpha_Q, a_Q the angular velocity, the angular and the linear bias
// acceleration of base Q (root values at Q = 0),
//   zeta_g = a_Q + alpha_Q x d_g + omega_Q x (omega_Q x d_g) + 2 omega_Q x u_g + R_Q c''_g,
//   omega_g = omega_Q + W_g,  xi_g = alpha_Q + omega_Q x W_g + R_Q W'_g,
//   a_{Q+1} = (zeta at the element's end),  alpha_{Q+1} = xi at the element's end,  omega_{Q+1} = omega_Q + W_Q,
// where u_g = T_g qdot_Q, W_g = R_Q G(sigma_g) qdot_Q, and c'', W' are the element-local second
// directional derivatives of element.hpp (ElementRates, ElementEndRates). Both paths use these same
// rates; tests/solvers/test_superhelix_rotational_inertia.cpp checks the resulting velocity terms
// against an independent oracle (Lagrange's d/dt dT/dqdot - dT/dq from finite differences of T).
//
// Semi-implicit Euler (§1.5), implicit in the elastic and damping terms, explicit in the rest:
//   (M_n + D) dv = h (-K (q_n - q0) + B_n) - D qdot_n,   D = (h^2 + h gamma) K,
//   qdot_{n+1} = qdot_n + dv,   q_{n+1} = q_n + h qdot_{n+1},
//   B_n = F_ext(q_n) - (the velocity terms above at (q_n, qdot_n)).
// Two paths solve the same linear system:
//   Dense: point Jacobians (O(N^2)), M assembled (O(N^3)), LDL^T (O(N^3)).
//   Recursive: the articulated-body recursion of §1.6 (tip-to-root inertias, root-to-tip solve),
//   O(N). Each Gauss point is a rigid body (mass m_g at offset d_g, rotational inertia I_g about its
//   centre): I_el = sum_g I_p(d_g) + [[I_g, 0], [0, 0]], U_pt = sum_g [[m [d]x T_g + I_g Theta_g]; m T_g],
//   TT = sum_g m T_g^T T_g + Theta_g^T I_g Theta_g (Theta_g = R_Q G(sigma_g), the point's rotation per
//   unit q_Q), and the velocity terms and gravity enter as point wrenches
//   (moment, force) = h (d x f + I_g xi_g + omega_g x I_g omega_g, f),  f = m_g (zeta_g - g), the
//   end loads as the tip wrench.
// The tip-to-root pass symmetrises I^A after every element: the map I^A_{Q+1} -> I^A_Q amplifies the
// antisymmetric part of its rounding errors (~3x per element), which made the O(N) step drift from
// the dense one at large N (1.8e-3 relative at N = 64, h = 1e-3, on a curled rod) before issue 11.
// Recursive cost: one root-to-tip pass (kinematics and rates), one tip-to-root pass (articulated
// inertias, 6 x 6) and one root-to-tip solve, no heap allocation per element (a reused workspace);
// the rotational terms add ~30 % (bench/bench_superhelix.cpp).
// Moving root (root_motion.hpp): the kinematics starts from the root pose at state.time and zeta, xi
// carry the root's acceleration terms (so the forward solve starts from A_0 = 0); overloads with a
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

// Angular velocity omega_g (world, including the root's) and angular bias acceleration xi_g
// (omega_t = Theta_g qddot + xi_g) of the material frame at every Gauss point (Kinematics::points()
// order), from the same root-to-tip pass as bias_accelerations.
struct AngularRates {
  Vec3 angular_velocity;
  Vec3 angular_bias;
};
std::vector<AngularRates> angular_rates(const RodModel& model, const Kinematics& kinematics, const VecX& qdot);
// The same with a moving root: `kinematics` must have been built from root.position / root.frame.
std::vector<AngularRates> angular_rates(const RodModel& model, const Kinematics& kinematics, const VecX& qdot,
                                        const RootState& root);

// World rotational inertia I_g = (w_g ell/2) R_g J R_g^T of every Gauss point (the quadrature of
// the cross-sections' rotational inertia; all zero when model.rotational_inertia = 0).
std::vector<Mat3> point_rotational_inertias(const RodModel& model, const Kinematics& kinematics);

// Dense generalised mass matrix sum_g m_g J_g^T J_g + Theta_g^T I_g Theta_g (3N x 3N, symmetric;
// positive definite when every rho I_k > 0, only semi-definite with rotational_inertia = 0:
// twist rates of a straight element then move no mass). `kinematics` must be built from `model`.
MatX mass_matrix(const RodModel& model, const Kinematics& kinematics);

// dv of one semi-implicit Euler step by either path.
VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// One full step.
DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// The same with a prescribed root motion, evaluated at state.time.
VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                     const RootMotion& root);
DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                  const RootMotion& root);

// Energies (root at rest): kinetic = translational 1/2 sum_g m_g |v_g|^2 + rotational
// 1/2 sum_g omega_g . I_g omega_g (= 1/2 qdot^T M qdot), and total = kinetic + elastic + gravity
// - F_end . r_tip (the end moment is left out: it has no potential in 3-D). `kinematics` must be
// built from `model`.
double kinetic_energy(const RodModel& model, const Kinematics& kinematics, const VecX& qdot);
double rotational_kinetic_energy(const RodModel& model, const Kinematics& kinematics, const VecX& qdot);
double total_energy(const RodModel& model, const DynamicState& state);

// The lowest `count` circular frequencies of the straight rod (q = 0) bending in the plane of n0
// and n2 (the kappa1 coordinates), from the linearised dynamics K v = omega^2 M v (generalised
// symmetric eigenproblem, solved as the standard one of K^{-1/2} M K^{-1/2} with eigenvalues
// 1 / omega^2: the lowest frequencies to relative round-off eps (omega / omega_1)^2 at any N). M
// includes the rotary inertia rho I1 of the bending (a Rayleigh beam); with rotational_inertia[1] = 0
// it is the Euler-Bernoulli rod. Requires count <= N.
VecX bending_frequencies(const RodModel& model, std::size_t count);

// All small oscillations of the straight, unloaded rod (q = 0): the full linearised dynamics
// K v = omega^2 M v on the 3N coordinates (K = generalised_stiffness, M = mass_matrix at q = 0),
// solved like bending_frequencies as the symmetric eigenproblem of K^{-1/2} M K^{-1/2} (eigenvalues
// 1 / omega^2). No family is assumed: on the straight rod the
// twist, kappa1 and kappa2 coordinates decouple (the twist moves no point, kappa1 and kappa2 move the
// points along n2 and n1, and J is diagonal in the common material frame), so every mode lives in
// one of them up to round-off, and component_share tells which. The twist coordinates carry mass
// only through rho I0: M is positive definite iff rho I0 > 0 (InputError "rotational_inertia.twist
// (rho I0)" otherwise). The straight state is an equilibrium only without natural strain, gravity
// and end loads: InputError naming natural_strain, natural_strain_per_element, gravity, end_force or
// end_moment otherwise (the geometric stiffness of loads is not part of K).
// Accuracy: a backward error of a small multiple of eps / omega_min^2 on every 1 / omega^2, i.e.
// |d omega_k^2| ~ eps omega_k^4 / omega_min^2 (relative eps (omega_k / omega_min)^2: the low modes to
// round-off whatever N; omega_min^2 is reported as omega_squared_min). Directions whose 1 / omega^2 is
// below that backward error (the top of the spectrum, when stiffnesses or inertias lie many decades
// apart) come out as omega = +inf with a zero shape and a zero component_share column.
struct StraightRodModes {
  VecX frequencies;       // circular frequencies omega_k, ascending (3N)
  MatX shapes;            // 3N x 3N, column k = v_k, M-normalised (v_k^T M v_k = 1)
  MatX component_share;   // 3 x 3N: share of v_k^T M v_k carried by the twist (row 0), kappa1 (row 1)
                          // and kappa2 (row 2) coordinates, from the diagonal blocks of M (sum 1 up to
                          // the round-off of the off-diagonal blocks)
  double omega_squared_min = 0.0;  // the smallest eigenvalue omega^2 (round-off unit above)
};
StraightRodModes straight_rod_modes(const RodModel& model);

}  // namespace rodvv::solvers::superhelix

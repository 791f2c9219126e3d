#pragma once
// Dynamics of a Super-Helix (ALGORITHMS.md §1.4-1.6): Lagrangian with translational inertia
// T = 1/2 int rho S |r_t|^2 ds (Gauss quadrature: point masses m_g), elastic energy
// 1/2 (q - q0)^T K (q - q0), gravity, dead end loads and Rayleigh (stiffness-proportional) damping
// -gamma K qdot:
//
//   M(q) qddot + K (q - q0) = -gamma K qdot + F_ext(q) - sum_g m_g J_g^T (Jdot_g qdot)
//
// Velocity terms: the bias acceleration zeta_g = Jdot_g qdot = d/de [J_g(q + e qdot) qdot] at
// e = 0 of every Gauss point, by a central difference of the O(N) point velocities
// (e = cbrt(eps) / (L |qdot|_inf): truncation and round-off both ~1e-11 relative).
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
// Both throw InputError for h <= 0 or non-finite, or a state of the wrong size / non-finite.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

struct DynamicState {
  VecX q;
  VecX qdot;
  double time = 0.0;
};

enum class DynamicsPath { Dense, Recursive };

// zeta_g = Jdot_g qdot at every Gauss point (Kinematics::points() order).
std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot);

// Dense generalised mass matrix sum_g m_g J_g^T J_g (3N x 3N, symmetric positive semi-definite:
// twist rates of a straight element move no mass).
MatX mass_matrix(const Kinematics& kinematics);

// dv of one semi-implicit Euler step by either path.
VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);
// One full step.
DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path);

// Energies: kinetic 1/2 sum_g m_g |v_g|^2 (= 1/2 qdot^T M qdot), and total = kinetic + elastic +
// gravity - F_end . r_tip (the end moment is left out: it has no potential in 3-D).
double kinetic_energy(const Kinematics& kinematics, const VecX& qdot);
double total_energy(const RodModel& model, const DynamicState& state);

// The lowest `count` circular frequencies of the straight rod (q = 0) bending in the plane of n0
// and n2 (the kappa1 coordinates), from the linearised dynamics K v = omega^2 M v (generalised
// symmetric eigenproblem). Requires count <= N.
VecX bending_frequencies(const RodModel& model, std::size_t count);

}  // namespace rodvv::solvers::superhelix

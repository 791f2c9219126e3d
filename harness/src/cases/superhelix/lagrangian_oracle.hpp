#pragma once
// An independent oracle for Super-Helix dynamics (issue 13, class 2): the motion of the same
// semi-discrete rod (the same strains q in R^3N) from Lagrange's equations, built from the kinetic
// and potential energies alone and integrated by an adaptive Runge-Kutta-Fehlberg 7(8) (Boost
// odeint) to 1e-10. It shares with the solver only the shape map (Kinematics: positions, frames and
// their q-Jacobians at a point, checked against finite differences and by the exact statics cases);
// none of the solver's mass matrix, velocity terms (bias recursion), articulated-body solve, root
// motion, gravity force, section inertia or time step.
//
// The root is clamped at x0 and turns about a fixed world axis a through x0 by the angle
// theta(t) = Omega t + alpha t^2 / 2 (the oracle's own root motion): the root frame is
// Rot(a, theta(t)) R0. With r(s; q, t) and R(s; q, t) the shape at that root pose,
//   v = Omega(t) a x (r - x0) + J q',   omega = Omega(t) a + Theta q',   Omega(t) = Omega + alpha t,
//   T(q, q', t) = int [ rho S |v|^2 / 2 + (R^T omega) . J_sec (R^T omega) / 2 ] ds,
//   V(q, t)     = - int rho S g . r ds + 1/2 sum_Q ell (q_Q - q0_Q)^T diag(GJ, EI1, EI2) (q_Q - q0_Q),
// with J_sec = rho S diag(a^2 + b^2, b^2, a^2) / 4 of a solid elliptic section with semi-axes a_s along
// n1 and b_s along n2 (computed here from the section, not taken from the model), and the integrals
// by 6-point Gauss-Legendre quadrature per element (Boost; the solver uses its own 4-point rule: the
// two semi-discrete Lagrangians differ by the quadrature error, far below the step's error here). Lagrange:
//   M q'' = -dV/dq + dT/dq - (dp/dq) q' - dp/dt,   p = dT/dq',
// with M and p = M q' + (the root's transport terms) summed from the samples' Jacobians (exact: T is
// quadratic in q'), and dp/dq q', dp/dt, dT/dq, dV/dq by central differences (steps cbrt(eps) of their
// scales: truncation and round-off ~1e-10 relative).
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::harness::superhelix_cases {

struct OracleRod {
  solvers::superhelix::RodModel model;  // shape (length, elements, natural strains, root pose), stiffness, rho S, g
  double section_a = 0.0;                // semi-axis along n1
  double section_b = 0.0;                // semi-axis along n2
  Vec3 spin_axis = Vec3::UnitZ();        // unit
  double spin_rate = 0.0;                // Omega at t = 0
  double spin_acceleration = 0.0;        // alpha
};

struct OracleState {
  VecX q, qdot;
};

// The root frame at t: Rot(a, Omega t + alpha t^2 / 2) R0 (the oracle's own root motion).
Mat3 oracle_root_frame(const OracleRod& rod, double t);

// q'' at (q, q', t).
VecX oracle_acceleration(const OracleRod& rod, const VecX& q, const VecX& qdot, double t);

// The states at the given increasing times > 0 from `start` at t = 0 (RKF78, rtol = atol = 1e-10 on
// (q, q')); SolverError if the integration fails. Computed once per distinct (rod, start, times) in
// a process and shared (the levels of a sweep, on any thread, ask for the same trajectory).
std::vector<OracleState> oracle_trajectory(const OracleRod& rod, const OracleState& start,
                                           const std::vector<double>& times);

}  // namespace rodvv::harness::superhelix_cases

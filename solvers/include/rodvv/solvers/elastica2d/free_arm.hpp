#pragma once
// One free arm of a rod leaving a rigid, straight, frictionless sleeve, with its free length l as an
// UNKNOWN (configurational, variable-length formulation; used by sleeve.hpp).
//
// The arm leaves the sleeve exit e with the sleeve's tangent (clamp angle a) and carries a dead
// force F at its tip. Discretisation: the "polygon" of discretisation.hpp with N edges of length
// h = l / N and edge angles phi_0 .. phi_{N-1}; the clamp angle sits h/2 before the first edge
// midpoint (half-cell clamp term). The discrete potential energy, as a function of (phi, l), is
//
//   Pi_arm(phi, l) = E_b - F . (r_tip - e),
//   E_b   = (B / h) [ (phi_0 - a)^2 + 1/2 sum_{i=1}^{N-1} (phi_i - phi_{i-1})^2 ]   (~ 1 / l)
//   r_tip = e + h sum_i (cos phi_i, sin phi_i)                                      (~ l)
//
// The length enters only through h, so the exact l-derivatives are simple scalings:
//   dPi/dl          = -(E_b + F . (r_tip - e)) / l
//   d2Pi/dl2        = 2 E_b / l^2
//   d2Pi/dl dphi_i  = (dW/dphi_i - dE_b/dphi_i) / l,   W = -F . (r_tip - e) (the load part).
// -dPi/dl is the configurational force with which the arm pulls rod material out of the sleeve.
// Nothing about M^2/(2B) is put in: that it equals M_e^2/(2B) + n.t at the exit (PHYSICS.md §6.1) is
// what the solver's results are checked against.
#include <Eigen/Core>
#include <cstddef>

#include "rodvv/common/planar_rod.hpp"

namespace rodvv::solvers::elastica2d {

struct FreeArm {
  double bending_stiffness = 1.0;              // B > 0
  Eigen::Vector2d exit = Eigen::Vector2d::Zero();  // sleeve exit e (position of the arm's root)
  double exit_angle = 0.0;                     // clamp angle a: outward tangent of the sleeve
  Eigen::Vector2d tip_force = Eigen::Vector2d::Zero();  // dead force F on the tip
  std::size_t elements = 64;                   // N >= 2
};

// Pi_arm, its parts, and its exact first and second derivatives in (phi, l). The phi-phi block is
// tridiagonal (diagonal + one off-diagonal, off[i] couples phi_i and phi_{i+1}).
struct FreeArmDerivatives {
  double energy = 0.0;          // Pi_arm
  double bending_energy = 0.0;  // E_b
  Eigen::Vector2d tip = Eigen::Vector2d::Zero();  // r_tip
  Eigen::VectorXd grad_phi;     // dPi/dphi_i
  double grad_l = 0.0;          // dPi/dl
  Eigen::VectorXd hess_diag;    // d2Pi/dphi_i^2
  Eigen::VectorXd hess_off;     // d2Pi/dphi_i dphi_{i+1} (N - 1 values)
  Eigen::VectorXd hess_phi_l;   // d2Pi/dphi_i dl
  double hess_ll = 0.0;         // d2Pi/dl^2
};

// phi must hold N values and l > 0 (not validated here: callers validate their problem).
FreeArmDerivatives free_arm_derivatives(const FreeArm& arm, const Eigen::VectorXd& phi, double l);

// The arm as a PlanarRodSolution, s from 0 (exit) to l (tip), at nodes s_i = i h:
//   x, y      node positions (exit + running sum of the chords);
//   theta     interior: mean of the adjacent edge angles; exit: a; tip: phi_{N-1} (the free end
//             carries no couple, so kappa(l) = 0 and the half-edge extrapolation adds nothing);
//   kappa     interior: (phi_i - phi_{i-1}) / h; exit: 2 (phi_0 - a) / h, the derivative of the
//             half-cell clamp term, i.e. the reaction moment / B of the discrete moment balance
//             m_0 = m_1 + h F . N(phi_0), a midpoint rule of m' = -n . N: O(h^2) like the interior;
//             tip: 0;
//   force     n = F on every edge and node (exact discrete force balance: no distributed load);
//   axial_force  F . t(theta_i); edge_axial_force F . t(phi_i); shear likewise with N = e_z x t;
//   EI = B, kappa_hat = 0, potential = 0.
PlanarRodSolution free_arm_shape(const FreeArm& arm, const Eigen::VectorXd& phi, double l);

}  // namespace rodvv::solvers::elastica2d

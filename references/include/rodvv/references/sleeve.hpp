#pragma once
// A rod sliding in a rigid, straight, frictionless, bilateral sleeve (PHYSICS.md §6):
//   §6.1 the Eshelby-like force at a sleeve exit (Bigoni, Dal Corso, Bosi & Misseroni 2015,
//        Mech. Mater. 80:368-374), with a tip-loaded free length outside the sleeve;
//   §6.2 the elastica arm scale (Bosi, Misseroni, Dal Corso & Bigoni 2014, Proc. R. Soc. A
//        470:20140232).
//
// Physics (PHYSICS.md §0, §6). Inside the sleeve the rod is straight (kappa = 0), so the Noether
// invariant H = 1/2 B kappa^2 + n.t equals the axial force N there. Outside, each free arm carries a
// vertical dead load P at its tip (kappa = 0 there), so H = P sin(beta) with beta the angle of the
// outward tip tangent below the horizontal. H is continuous at the exit while the tension jumps by
// M_e^2/(2B) (M_e the exit moment).
//
// Each free arm is a cantilever clamped at the exit at an angle theta0 below the horizontal (the
// sleeve axis), with a downward dead tip load P and phi the tangent angle below the horizontal:
//   B phi'' = -P cos phi,  phi(0) = theta0,  phi'(l) = 0,  phi(l) = beta,
//   first integral (this is H):  1/2 B phi'^2 + P sin phi = P sin beta,
// so phi increases monotonically from theta0 to beta < pi/2 and, with lambda = sqrt(P/B),
//   lambda l = K(k) - F(psi0, k),  k^2 = (1 + sin beta)/2,  sin^2 psi0 = (1 + sin theta0)/(1 + sin beta),
//   horizontal extent x = sqrt(2B/P) sqrt(sin beta - sin theta0),  exit moment M = P x,
//   M^2/(2B) = P (sin beta - sin theta0),  drop w = l - (2/lambda) [E(k) - E(psi0, k)].
// (PHYSICS.md §3.5 is theta0 = 0.) The free length l(beta) is strictly increasing on
// (theta0, pi/2), from 0 to infinity: it is the time a pendulum with potential sin(phi) needs from
// phi = theta0 to its turning point beta, i.e. a quarter period (increasing with amplitude, K(k)) minus
// the time from the bottom -pi/2 to theta0 (decreasing with energy), for theta0 > -pi/2. So each
// free length has exactly one tip angle on this (stable, loop-free) branch.
//
// Units: any consistent set (P force, B force x length^2, lengths in length, angles in radians).
// Errors: rodvv::InputError naming the parameter and its range for bad input; rodvv::SolverError
// (iterations, residual) when a root solve fails or no equilibrium exists.
#include <string>

#include "rodvv/common/errors.hpp"

namespace rodvv::references {

// ---------------------------------------------------------------------------------------------
// The building block: one free arm clamped at theta0 below the horizontal, tip load P, length l.
struct InclinedArm {
  double theta0 = 0.0;  // clamp (exit) angle below the horizontal, in (-pi/2, pi/2)
  double P = 1.0;       // downward dead tip load, > 0
  double B = 1.0;       // bending stiffness, > 0
};

struct InclinedArmTip {
  double length = 0.0;       // free length l
  double tip_angle = 0.0;    // beta in (theta0, pi/2)
  double exit_moment = 0.0;  // |M| = B phi'(0) = P x >= 0
  double extent = 0.0;       // horizontal extent x of the arm (>= 0, along its outward direction)
  double drop = 0.0;         // downward vertical drop w of the tip below the exit (may be < 0)
  double invariant = 0.0;    // H = P sin(beta)
};

// Tip state of the arm for a free length l >= 0 (l = 0 gives beta = theta0, zero extent). Solved by
// TOMS 748 on gamma = pi/2 - beta (geometric bracket scan towards small gamma, as for §3.5).
// InputError for theta0 outside (-pi/2, pi/2), P or B not finite and > 0, l < 0 or not finite, and
// ("length") when P l^2/B is so large (above about 5e4) that pi/2 - beta < 2e-100.
InclinedArmTip inclined_arm_tip(const InclinedArm& arm, double length);

// ---------------------------------------------------------------------------------------------
// §6.1 sliding sleeve: straight rigid frictionless bilateral sleeve along e_x, exit at x = 0, rod
// pulled inward by an axial force S at its inner end; free length l outside with a transverse dead
// load P at the tip (load along -e_y). Bending stiffness B. Outside n = -P e_y; at the exit N_out = 0,
// so S = N_in = M_e^2/(2B) = H = P sin(phi_tip).
struct SleeveArm {
  double P = 1.0;  // > 0
  double B = 1.0;  // > 0
};

struct SleeveEquilibrium {
  double free_length = 0.0;   // l solving S = P sin(phi_tip(P l^2 / B))
  double tip_angle = 0.0;     // phi_tip (rotation of the tip tangent, in (0, pi/2))
  double exit_moment = 0.0;   // M_e = P x_tip = sqrt(2 B S)  (magnitude)
  double tension_jump = 0.0;  // N_in - N_out = M_e^2 / (2 B) (evaluated from M_e; equals S)
  double invariant = 0.0;     // H = P sin(phi_tip) = S
  double tip_x = 0.0;         // tip position, exit at the origin: tip_x > 0
  double tip_y = 0.0;         //   tip_y < 0
};

// Given S in (0, P) (the pull must be below P: sin(phi_tip) < 1), the free length l. Closed form
// (no iteration): sin(phi_tip) = S/P fixes the modulus, and lambda l = K(k) - F(psi0, k) is explicit.
// InputError naming "S" with the range (0, P) otherwise (and "P", "B").
SleeveEquilibrium sleeve_equilibrium(const SleeveArm& arm, double S);
// Inverse direction (used for sweeps at fixed l): S for a given free length l > 0, through
// cantilever_tip (elastica.hpp, §3.5) with alpha = P l^2/B. InputError naming "free_length" (and
// the errors of cantilever_tip for alpha beyond its range).
SleeveEquilibrium sleeve_equilibrium_for_length(const SleeveArm& arm, double free_length);

// ---------------------------------------------------------------------------------------------
// §6.2 elastica arm scale. A rod of bending stiffness B passes through a frictionless rigid sleeve of
// length `sleeve_length` whose axis is inclined at alpha (in (-pi/2, pi/2)) above the horizontal; the
// sleeve centre is at the origin, its axis direction d = (cos alpha, sin alpha). The total rod length
// is L > sleeve_length. Arm 1 leaves the lower/left exit (-d sleeve_length/2) along -d; arm 2 the
// upper/right exit (+d sleeve_length/2) along +d. Vertical dead weights P1, P2 (downwards, > 0) hang
// at the free tips. Weightless rod. Arm 1 is an InclinedArm with theta0 = +alpha (mirrored: it runs
// towards -x), arm 2 one with theta0 = -alpha.
// Equilibrium: the axial force N inside the sleeve is H of both arms, P1 sin beta1 = P2 sin beta2,
// and equivalently (Eshelby-like forces at the exits, PHYSICS.md §6.2)
//   N = M1^2/(2B) + P1 sin alpha = M2^2/(2B) - P2 sin alpha,  (P1 + P2) sin alpha = (M2^2 - M1^2)/(2B).
struct ArmScale {
  double alpha = 0.0;          // sleeve inclination above the horizontal [rad]
  double P1 = 1.0;             // weight at the tip of arm 1 (lower/left exit)
  double P2 = 1.0;             // weight at the tip of arm 2 (upper/right exit)
  double B = 1.0;              // bending stiffness
  double L = 2.0;              // total rod length
  double sleeve_length = 0.2;  // in (0, L)
};

struct ArmScaleArm {
  double length = 0.0;       // free length l_i outside the sleeve
  double tip_angle = 0.0;    // beta_i: angle of the outward tip tangent below the horizontal
  double exit_moment = 0.0;  // |M_i| at the exit
  double tip_x = 0.0;        // tip position (global frame above)
  double tip_y = 0.0;
};

struct ArmScaleEquilibrium {
  ArmScaleArm arm1, arm2;
  double axial_force = 0.0;   // N inside the sleeve = P1 sin beta1 = P2 sin beta2 (the invariant H)
  double sleeve_shift = 0.0;  // l2 - l1: > 0 when the rod has slid towards arm 2 (the rod's material
                              // midpoint sits (l2 - l1)/2 of arc length from the sleeve centre, on
                              // the arm-2 side)
};

// Solves f(l1) = P1 sin beta1(l1) - P2 sin beta2(L - sleeve_length - l1) = 0 for l1 by TOMS 748.
// f is strictly increasing in l1 (each beta_i(l_i) is, see above), so the root is unique when it
// exists, and it exists iff f(0) < 0 < f(L - sleeve_length).
// InputError (naming the parameter and range) for P1, P2, B, L not finite and > 0, sleeve_length
// not in (0, L) ("sleeve_length": "a sleeve longer than the rod"), alpha outside (-pi/2, pi/2), and
// ("L") when max(P1, P2) (L - sleeve_length)^2 / B is beyond the range of inclined_arm_tip.
// SolverError (iterations 0, residual f at the end) when no equilibrium exists:
//   f(0) >= 0: arm 2 would be pulled fully into the sleeve (the rod slides towards arm 1);
//   f(L - sleeve_length) <= 0: arm 1 would be pulled fully into the sleeve;
// thrown as ArmPulledIn, which says which.
class ArmPulledIn : public SolverError {
 public:
  ArmPulledIn(int arm, const std::string& method, const std::string& message, double residual)
      : SolverError(method, message, 0, residual), arm_(arm) {}
  int arm() const noexcept { return arm_; }  // 1 or 2: the arm that would be pulled into the sleeve

 private:
  int arm_;
};
ArmScaleEquilibrium arm_scale_equilibrium(const ArmScale& scale);

}  // namespace rodvv::references

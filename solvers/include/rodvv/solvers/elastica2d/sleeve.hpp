#pragma once
// A planar elastica sliding through a rigid, straight, frictionless (bilateral) sleeve: the
// sliding-sleeve benchmark and the elastica arm scale (PHYSICS.md §6.1, §6.2; Bigoni, Dal Corso,
// Bosi & Misseroni 2015, Mech. Mater. 80:368-374; Bosi, Misseroni, Dal Corso & Bigoni 2014,
// Proc. R. Soc. A 470:20140232).
//
// Model (configurational, variable-length). Inside the sleeve the rod is straight and stores no
// energy; only how much of it is outside matters. The unknowns are the free length(s) outside and
// the discrete shape of each free arm (free_arm.hpp: N polygon edges of length l/N, clamped at the
// exit with the sleeve's tangent, dead force at the tip). The total potential
//
//   sleeve:     Pi(phi, l)           = Pi_arm(phi, l) + S l
//               (the inward pull S at the inner end does work -S (L - l); the constant is dropped)
//   arm scale:  Pi(phi1, phi2, l1)   = Pi_arm1(phi1, l1) + Pi_arm2(phi2, L - L_s - l1)
//               (the rod inside the sleeve has the fixed length L_s, so l1 + l2 = L - L_s)
//
// is made stationary jointly in the shape and the length by Newton's method with the exact
// gradient and Hessian (free_arm.hpp). The Hessian is tridiagonal in the angles with one dense
// border row/column for the length; a Newton step is a bordered solve: the banded LU (banded_lu.hpp)
// of the tridiagonal block, two back-substitutions and the Schur complement
//   sigma = d2Pi/dl2 - b . A^{-1} b  = d2Pi*/dl2,
// the second derivative of the energy minimised over the shape at fixed length. sigma < 0 means the
// equilibrium is unstable under the dead loads (it is, for the sleeve under a dead pull S: a longer
// arm pulls harder). Globalisation: backtracking on ||grad Pi||_2 (Armijo 1e-4), no arm shrinking
// by more than 3/4 in a step. Start: the shape is first solved at the starting length (a cantilever,
// length fixed), then shape and length jointly. Sleeve only: if that fails (S/P close to 1, where
// l ~ log(1 / (1 - S/P)) is far from the start) and no initial_length was given, continuation in S
// from S/P = 1/2 in 16 steps evenly spaced in log(1 - S/P).
//
// Axial force inside the sleeve. From the stationarity in the length:
//   sleeve:    N_in = -dPi_arm/dl           (= S to the Newton tolerance)
//   arm scale: N    = -dPi_arm1/dl1 = -dPi_arm2/dl2
// (the arm's configurational force, free_arm.hpp). The solver never uses M^2/(2B): the exit
// moment M_e (free_arm_shape: the discrete clamp reaction, O(h^2)) and the axial force just outside
// N_out = n.t at the exit (n = tip load, exact discrete force balance) are read from the arm, and
// the checks N_in - N_out = M_e^2/(2B) and H continuity at the exit (PHYSICS.md §6.1) are made by
// the callers.
//
// Geometry and signs. Sleeve: the exit is at the origin, the sleeve axis is e_x, the arm leaves
// along +e_x and the dead load -P e_y acts at its tip. Arm scale: sleeve centre at the origin, axis
// d = (cos alpha, sin alpha); arm 1 leaves the exit -d L_s/2 along -d (clamp angle alpha + pi),
// arm 2 leaves +d L_s/2 along +d (clamp angle alpha); dead weights -P1 e_y, -P2 e_y at the tips.
// beta_i = angle of the outward tip tangent below the horizontal (arm 1: theta_tip - pi,
// arm 2: -theta_tip).
//
// Failure: rodvv::InputError naming the parameter for bad input; rodvv::SolverError (iterations,
// residual) when Newton does not converge, the line search fails, the bordered system is singular,
// or the arm would have to leave the sleeve entirely (l >= the available length).
#include <cstddef>
#include <optional>

#include "rodvv/common/planar_rod.hpp"

namespace rodvv::solvers::elastica2d {

struct SleeveProblem {
  double bending_stiffness = 1.0;  // B > 0
  double tip_load = 1.0;           // P > 0 (dead, downward, at the free tip)
  double pull = 0.5;               // S in (0, P): inward axial pull at the inner end
  double rod_length = 10.0;        // L > 0: total length; the free length must come out < L
};

struct ArmScaleProblem {
  double bending_stiffness = 1.0;  // B > 0
  double angle = 0.0;              // alpha in (-pi/2, pi/2): inclination of the sleeve axis
  double weight1 = 1.0;            // P1 > 0 at the tip of arm 1 (leaves along -d)
  double weight2 = 1.0;            // P2 > 0 at the tip of arm 2 (leaves along +d)
  double rod_length = 1.0;         // L > 0
  double sleeve_length = 0.1;      // L_s in (0, L)
};

struct SleeveSolverOptions {
  std::size_t elements = 64;        // N per arm, >= 2
  double tolerance = 1e-11;         // on ||grad Pi||_inf in the problem's own units (angle rows / sqrt(B P),
                                    // the length row / P; P the tip load, the larger weight), in (0, 1)
  std::size_t max_iterations = 100;  // Newton iterations, >= 1
  // Starting free length (sleeve: l; arm scale: l1). Default: sleeve sqrt(2 B S) / P (the
  // small-deflection balance S = (P l)^2 / (2B) would give it, used only as a start);
  // arm scale (L - L_s) / 2.
  std::optional<double> initial_length;
};

// One free arm at equilibrium.
struct ArmEquilibrium {
  double free_length = 0.0;
  double exit_angle = 0.0;             // clamp angle a (outward sleeve tangent)
  double tip_angle = 0.0;              // theta at the tip (counter-clockwise from e_x)
  double exit_moment = 0.0;            // m at the exit = B kappa_e (counter-clockwise), O(h^2)
  double exit_axial_force = 0.0;       // N_out = n.t just outside the exit
  double configurational_force = 0.0;  // -dPi_arm/dl at the solution
  double bending_energy = 0.0;
  double tip_x = 0.0, tip_y = 0.0;
  PlanarRodSolution shape;             // s = 0 at the exit .. l at the tip
};

struct SleeveSolution {
  ArmEquilibrium arm;
  double axial_force_inside = 0.0;  // N_in = -dPi_arm/dl
  double tension_jump = 0.0;        // N_in - N_out
  double tip_angle_below = 0.0;     // phi_tip = -theta_tip (PHYSICS.md §6.1 table)
  double length_stiffness = 0.0;    // sigma = d2Pi*/dl2 at the solution
  std::size_t iterations = 0;
  double residual = 0.0;            // final scaled ||grad Pi||_inf (SleeveSolverOptions::tolerance)
};

struct ArmScaleSolution {
  ArmEquilibrium arm1, arm2;
  double axial_force = 0.0;        // N = -dPi_arm1/dl1
  double axial_force_arm2 = 0.0;   // -dPi_arm2/dl2 (= N to the Newton tolerance)
  double beta1 = 0.0, beta2 = 0.0;  // tip angles below the horizontal
  double sleeve_shift = 0.0;       // l2 - l1 (> 0: the rod has slid towards arm 2)
  double length_stiffness = 0.0;   // sigma = d2Pi*/dl1^2
  std::size_t iterations = 0;
  double residual = 0.0;
};

// InputError: "bending_stiffness", "tip_load", "pull" (S in (0, P)), "rod_length", "angle",
// "weight1", "weight2", "sleeve_length" (in (0, L): a sleeve longer than the rod), and for the
// options "elements" (>= 2), "tolerance", "max_iterations", "initial_length" (in (0, available)).
void validate(const SleeveProblem& problem);
void validate(const ArmScaleProblem& problem);
void validate(const SleeveSolverOptions& options);

SleeveSolution solve_sleeve(const SleeveProblem& problem, const SleeveSolverOptions& options = {});
ArmScaleSolution solve_arm_scale(const ArmScaleProblem& problem,
                                 const SleeveSolverOptions& options = {});

}  // namespace rodvv::solvers::elastica2d

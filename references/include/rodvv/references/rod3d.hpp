#pragma once
// Closed-form references for three-dimensional Kirchhoff rods (PHYSICS.md §7.1, §3.4;
// ALGORITHMS.md §1.7). Pure functions of a parameter struct; Eigen types only (no Boost / GSL).
//
// Conventions: arclength s in [0, L]; Kirchhoff rod (inextensible, unshearable); material frame
// (n0, n1, n2) with n0 the tangent (ALGORITHMS.md §1.1); bending stiffness B = EI, twisting
// stiffness C = GJ; internal force n and moment m act from (s, L] on [0, s] (PHYSICS.md §0).
// Bad input throws rodvv::InputError naming the parameter and its range.
//
//  1. Uniform helix held by an axial wrench (Love 1944 §§270-271; PHYSICS.md §7.1): radius R,
//     pitch angle alpha (tangent vs the axis e_z), twisting moment M_t = m.t, isotropic bending B;
//     the material frame co-rotates with the Frenet frame (uniform body strains
//     u = (tau, kappa, 0) in (n0, n1, n2) = (t, b, -N)), so a natural twist
//     u_hat0 = tau - M_t / C produces M_t.
//  2. Small-deflection cantilever under self weight: tip deflection w rho S g L^4 / (8 EI).
//  3. Euler-Bernoulli clamped-free frequencies omega_n = (beta_n L)^2 sqrt(EI / (rho S L^4)),
//     beta_n L the n-th positive root of 1 + cos x cosh x = 0, computed (bisection on
//     cos x + 1/cosh x, an equivalent form without overflow) to the last bit.
//  4. End-moment roll-up in 3-D: a cantilever clamped with tangent t0 and a dead end moment M a
//     (a a unit vector normal to t0) bends into a circle of radius EI/M in the plane of t0 and
//     a x t0; M L / EI = 2 pi closes it. H = M^2 / (2 EI) (n = 0).
#include <cstddef>

#include <Eigen/Geometry>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::references {

// ---- 1. helix under an axial wrench ---------------------------------------------------------
struct AxialWrenchHelix {
  double B = 1.0;                // bending stiffness, > 0
  double C = 1.0;                // twisting stiffness, > 0
  double radius = 1.0;           // > 0
  double pitch_angle = 0.5;      // alpha in (0, pi/2): angle between tangent and axis
  double twisting_moment = 0.0;  // M_t = m . t, finite
};

struct AxialWrenchHelixSolution {
  double kappa = 0.0;          // curvature sin^2(alpha) / R
  double tau = 0.0;            // torsion sin(alpha) cos(alpha) / R (= material twist)
  double darboux = 0.0;        // sqrt(kappa^2 + tau^2) = sin(alpha) / R
  double axial_force = 0.0;    // F: n = F e_z (tension > 0) = (M_t - B tau) sin(alpha) / R
  double axial_moment = 0.0;   // M: m + (r - r_axis) x n = M e_z = B sin^3(alpha)/R + M_t cos(alpha)
  double natural_twist = 0.0;  // u_hat0 = tau - M_t / C
  double H = 0.0;              // Noether H = n.t + m.u - W = F cos(alpha) + B kappa^2 / 2 + M_t tau - M_t^2 / (2C)
};

AxialWrenchHelixSolution axial_wrench_helix(const AxialWrenchHelix& helix);

// A point of the helix with axis e_z through the origin, r(0) = (R, 0, 0):
// r(s) = (R cos phi, R sin phi, s cos alpha), phi = s sin(alpha) / R.
struct HelixPoint {
  Vec3 position;
  Mat3 frame;   // material frame (n0, n1, n2) = (t, b, -N) as columns
  Vec3 force;   // n(s) (world)
  Vec3 moment;  // m(s) = B kappa b + M_t t (world)
};
HelixPoint axial_wrench_helix_point(const AxialWrenchHelix& helix, double s);  // s finite

// ---- 2. self weight ------------------------------------------------------------------------
// Tip deflection of a clamped-free Euler-Bernoulli beam under a uniform load w (force / length):
// w L^4 / (8 EI). Requires w >= 0 finite, L > 0, EI > 0.
double self_weight_tip_deflection(double load_per_length, double L, double EI);

// ---- 3. cantilever frequencies ---------------------------------------------------------------
// The n-th root (n >= 1) of 1 + cos x cosh x = 0: 1.8751040687119611, 4.6940911329741746, ...
double cantilever_beta_l(std::size_t n);
// omega_n = (beta_n L)^2 sqrt(EI / (rho S L^4)). Requires EI, rho S, L > 0, n >= 1.
double cantilever_frequency(std::size_t n, double EI, double line_density, double L);

// ---- 4. end-moment roll-up -------------------------------------------------------------------
struct EndMomentRollUp {
  double L = 1.0;   // > 0
  double EI = 1.0;  // > 0
  double M = 0.0;   // moment magnitude, finite (0: straight)
  Vec3 root_position = Vec3::Zero();
  Vec3 tangent = Vec3::UnitX();  // unit
  Vec3 axis = Vec3::UnitZ();     // unit, normal to tangent: the moment is M axis
};
struct RollUpPoint {
  Vec3 position;
  Vec3 tangent;
};
RollUpPoint end_moment_roll_up_point(const EndMomentRollUp& rod, double s);  // s in [0, L]
double end_moment_roll_up_invariant(const EndMomentRollUp& rod);           // M^2 / (2 EI)

}  // namespace rodvv::references

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
//  5. Special Cosserat (shearable, extensible) rod with constant body strains (PHYSICS.md §7.1,
//     §1.1): see SpecialCosseratHelix below.
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

// The n-th clamped-free mode shape at x = s / L in [0, 1], scaled to 1 at the tip, and its slope
// d/dx: phi(x) = cosh bx - cos bx - sigma (sinh bx - sin bx), sigma = (cosh b + cos b) /
// (sinh b + sin b), b = beta_n L, evaluated as sinh(b (1 - x)) + cosh bx sin b - sinh bx cos b over
// sinh b + sin b for the hyperbolic part, which cancels no digits (the textbook form loses ~b / ln 10
// digits). Requires 1 <= n <= 50 (cosh b finite with room) and x in [0, 1].
struct ModeShapePoint {
  double value = 0.0;  // phi(x) / phi(1)
  double slope = 0.0;  // phi'(x) / phi(1), per unit x
};
ModeShapePoint cantilever_mode_shape(std::size_t n, double x);

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

// ---- 5. special Cosserat helix ------------------------------------------------------------------
// A special Cosserat rod (shear and extension; Antman 2005 ch. 8; PHYSICS.md §1.1, §7.1) with
// isotropic bending and shear, in the material components of this code (index 0 = the director
// n0 along the rod): K = diag(C, B, B) acting on u = (twist, kappa1, kappa2), S = diag(EA, GA, GA)
// acting on v - e0 (v = R^T r'), no natural curvature, v_hat = e0. Constant body strains are an
// equilibrium without distributed loads iff (body components) the force N = S (v - e0) and the
// moment M = K u satisfy u x N = 0 and u x M + v x N = 0: N = lambda u and, with
// v = e0 + lambda S^-1 u and u = (u0, u1, u2),
//     lambda^2 u0 (1/EA - 1/GA) + lambda + (B - C) u0 = 0,
// of which the root that tends to (C - B) u0 as EA, GA -> inf is taken (written without
// cancellation: lambda = 2 (C - B) u0 / (1 + sqrt(1 - 4 u0^2 (1/EA - 1/GA)(B - C)))).
// (PHYSICS.md writes the tangent director as d3: its u = (u1, 0, u3) is u = (u3, u1, 0) here; its
// example B = 1, C = 0.7, GA = 50, EA = 200, u = (0.5, 0.8, 0) gives lambda = -0.14983162862297,
// radius 0.899886505361503, advance 0.527767502020969.)
// The frame rotates about the fixed axis a = R0 u/|u| at the rate |u|: R(s) = R0 exp(s [u]x); the
// centreline is a helix about a with advance v.u/|u| per unit s and radius |v_perp|/|u|
// (v_perp = v - (v.u/|u|^2) u), through the axis point r0 + R0 (u x v)/|u|^2; the force
// n = lambda R0 u is constant and along the axis; m + (r - r_axis) x n = M a, M = u.K u/|u|
// (the axial wrench). H = n.v + m.u - W_bend - W_shear (V = 0) = lambda u0 + W_bend + W_shear
// with W_bend = u.K u/2, W_shear = lambda^2 u.S^-1 u/2 (PHYSICS.md §1.1).
// Bad input -> InputError naming the parameter: B, C, EA, GA not positive finite; u non-finite
// or without a bending part (u1 = u2 = 0: the helix axis and lambda are undefined; "u");
// no real root (1 - 4 u0^2 (1/EA - 1/GA)(B - C) < 0; "u"); root_frame not a rotation (1e-12).
struct SpecialCosseratHelix {
  double B = 1.0;   // bending stiffness (both axes), > 0
  double C = 1.0;   // twisting stiffness, > 0
  double GA = 1.0;  // shear stiffness (both axes), > 0
  double EA = 1.0;  // extensional stiffness, > 0
  Vec3 u = Vec3(0.5, 0.8, 0.0);  // body strains (twist, kappa1, kappa2), (u1, u2) != 0
  Vec3 root_position = Vec3::Zero();
  Mat3 root_frame = Mat3::Identity();  // R0, a rotation
};

struct SpecialCosseratHelixSolution {
  double lambda = 0.0;           // N = lambda u
  Vec3 strain_v;                 // v = e0 + lambda S^-1 u (body)
  Vec3 force_body;               // N = lambda u
  Vec3 moment_body;              // M = K u
  Vec3 axis;                     // a = R0 u / |u| (world, unit)
  Vec3 axis_point;               // a point of the helix axis, r0 + R0 (u x v) / |u|^2 (world)
  double rate = 0.0;             // |u|: rotation rate of the frame about a
  double advance = 0.0;          // v.u/|u|: axial advance per unit s
  double radius = 0.0;           // |v_perp| / |u|
  double axial_force = 0.0;      // n.a = lambda |u|
  double axial_moment = 0.0;     // (m + (r - r_axis) x n).a = u.K u / |u|
  double bending_energy = 0.0;   // W_bend = u.K u / 2
  double shear_energy = 0.0;     // W_shear = (v - e0).S(v - e0) / 2
  double H = 0.0;                // n.v + m.u - W_bend - W_shear
};
SpecialCosseratHelixSolution special_cosserat_helix(const SpecialCosseratHelix& rod);

// Pose and stresses at arclength s (finite): r(s) = r0 + s (v.a_b) a + R0 [sin(ks)/k v_perp +
// (1 - cos(ks))/k (u_b x v_perp)] (a_b = u/|u|, k = |u|), R(s) = R0 exp(s [u]x) (Rodrigues),
// n = R N, m = R M (world).
struct CosseratHelixPoint {
  Vec3 position;
  Mat3 frame;
  Vec3 force;
  Vec3 moment;
};
CosseratHelixPoint special_cosserat_helix_point(const SpecialCosseratHelix& rod, double s);

}  // namespace rodvv::references

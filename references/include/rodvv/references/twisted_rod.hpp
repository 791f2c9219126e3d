#pragma once
// Closed-form and semi-closed-form references for twisted Kirchhoff rods (PHYSICS.md §7.2, §7.3;
// PRIOR_ART.md §4.5, §4.6). Pure functions of a parameter struct; Eigen types only.
//
// Conventions: isotropic, inextensible, unshearable rod; bending stiffness B = EI, twisting
// stiffness C = GJ; internal force n and moment m act from (s, L] on [0, s] (PHYSICS.md §0);
// tension T > 0 pulls, a compressive load P > 0 pushes; the twisting moment M = m.t. Any consistent
// units (e.g. N m^2 for B, C; N for T, P; N m for M; m for L, D, s; rad for angles).
// Bad input throws rodvv::InputError naming the parameter and its allowed range; a root finder that
// fails throws rodvv::SolverError.
//
//  1. Localized helical buckling of an infinite rod (Love 1944, ch. XIX; van der Heijden &
//     Thompson 2000, Nonlinear Dyn. 21:71; PHYSICS.md §7.3): tension T, twisting moment M,
//     M^2 < 4 B T. With omega = M/(2B), alpha = sqrt(4BT - M^2)/(2B), A = 2 B alpha / T:
//         r(s) = (A sin(omega s)/cosh(alpha s), -A cos(omega s)/cosh(alpha s), s - A tanh(alpha s)),
//         n = T e_z, m = B t x t' + M t;  |r'| = 1 because A (omega^2 + alpha^2) = 2 alpha;
//         cos phi(s) = t.e_z = 1 - A alpha sech^2(alpha s), cos phi_max = M^2/(2BT) - 1 (at s = 0),
//         (cos phi - cos phi_max)/(1 - cos phi_max) = tanh^2(alpha s)  (the envelope),
//         end shortening Delta = int (1 - t.e_z) ds = 2A = 4 B alpha / T; max lateral radius A.
//     M = 0 is the planar homoclinic loop. PHYSICS.md example: B = 1.345, T = 2, M = 1.9 gives
//     alpha = 0.994032859265497, cos phi_max = -0.328996282527881, Delta = 2.67394839142419.
//  2. The same solution used for a finite rod of length L with imposed end rotation Phi and end
//     shortening D (Neukirch, van der Heijden & Thompson 2002, JMPS 50:1175, eqs. 13-15; PyElastica
//     examples/HelicalBucklingCase): m = M L/B and t = T L^2/B solve
//         D/L = sqrt(16/t (1 - m^2/(4t))),   Phi = m B/C + 4 arccos(m/(2 sqrt t)).
//     Reduction (derived here): with m >= 0 put m/(2 sqrt t) = cos theta, theta in [0, pi/2]; then
//     cos phi_max = m^2/(2t) - 1 = cos 2 theta (theta = phi_max/2) and, d = D/L,
//         sqrt t = 4 sin(theta)/d,  m = 4 sin(2 theta)/d,  alpha L = 4 sin^2(theta)/d,
//         Phi = f(theta) = (4B/(C d)) sin(2 theta) + 4 theta,
//     one equation in theta. f(0) = 0 and f' = 4 + (8B/(C d)) cos(2 theta) > 0 on [0, theta_end),
//     theta_end = arccos(-min(1, C d/(2B)))/2 <= pi/2: the branch that starts at the onset of
//     localization (PyElastica's). It is solved by TOMS 748 on [0, theta_end]; 0 < Phi <= f(theta_end)
//     is required. PyElastica's case B = 1.345, C = 0.789, Phi = 27 (2 pi), D = 0.03 L:
//     m = 98.5414961711907418, t = 2900.99320579213075, alpha L = 21.7574490434410,
//     cos phi_max = 0.673638264348385. The infinite-rod curve approximates the finite clamped rod
//     only when alpha L >> 1.
//  3. Greenhill's twisted column (Greenhill 1883, Proc. Inst. Mech. Eng.; Timoshenko & Gere 1961,
//     Theory of Elastic Stability; PRIOR_ART.md §4.6): pinned ends, compressive load P
//     (P < 0: tension) and an axial twisting moment M e_z at the ends. The lateral deflection
//     w = u + i v of the linearised equilibrium B w'' - i M w' + P w = 0, w(0) = w(L) = 0, is
//     non-trivial first when (M/2B)^2 + P/B = (pi/L)^2:
//         M_cr = 2 B sqrt((pi/L)^2 - P/B)   (P < pi^2 B/L^2),   P_cr = B ((pi/L)^2 - (M/2B)^2).
//     The end moment is Greenhill's constant axial vector; other end-moment models (semi-tangential,
//     quasi-tangential) are different problems (Ziegler 1977), so a solver must apply the same one.
//  3b. The same column with SEMI-TANGENTIAL end torques (Ziegler 1977): the end moment is
//     M (e_z + w'/2), half-way between the axial vector and the rotated tangent. It is conservative,
//     and it is what a pinned end whose cross-section rotation is held by parallel transport from
//     the support's axis applies (a discrete elastic rod's twist-held pinned end): the reaction
//     couple that keeps the section's angle about t fixed while t tilts from e_z has the
//     perpendicular part -(M/2) w' relative to t (the transported frame turns about t at second
//     order only). Moment balance (complex w = u + i v, lateral end force N):
//         B w''' - i M w'' + P w' = -N,   w(0) = w(L) = 0,   i B w'' + (M/2) w' = 0 at s = 0, L,
//     (axial torque: i B w'' + M w' = 0 there, which gives 3.). With k1,2 the roots of
//     B k^2 - M k - P = 0, w = a + b s + d1 e^{i k1 s} + d2 (e^{i k2 s} - 1 - i k2 s)/(i k2)^2 (the last
//     tends to s^2/2 as P -> 0), and the 4 x 4 determinant times e^{-i M L/(2B)} is purely imaginary
//     for M^2 + 4 B P > 0: M_cr is the first sign change of its imaginary part above
//     max(0, 2 sqrt(-B P)), found by a scan and TOMS 748. At P = 0, x = M_cr L/B solves
//     x/2 + arctan(x/6) = pi: x = 4.911287725758880608 (mpmath), not 2 pi.
//  3c. The same column with CLAMPED ends (w = w' = 0 at s = 0, L; the end sections turned about the
//     fixed axis, so no end-torque model enters): same solution, determinant and scan, P below the
//     clamped Euler load 4 pi^2 B/L^2. At P = 0, x = M_cr L/B = 2 y with tan y = y:
//     x = 8.98681891581812835 (the twisted clamped rod's 2.86 pi).
//  4. Michell's twisted ring (Michell 1889/90; Goriely 2006, J. Elasticity 84:281; PHYSICS.md §7.2):
//     a closed ring of length L = 2 pi R (bending B = Goriely's A, twist C) is stable iff its total
//     twist angle Phi < Phi_c = 2 pi sqrt(3) B/C (Tw < sqrt(3) B/C turns), i.e. iff the twisting
//     moment M = C Phi/L < M_c = sqrt(3) B/R.
//  5. Lateral-torsional buckling of a cantilever (Michell 1899, Phil. Mag. 48:298; Prandtl 1899,
//     dissertation; Timoshenko & Gere 1961, lateral buckling of a cantilever): clamped at x = 0,
//     free at x = L, tip load P at the centroid (= shear centre), no warping stiffness. Lateral deflection u(x), twist phi(x), signs
//     such that the strong-axis moment P (L - x) turned through phi bends the weak axis:
//         EI_weak u'' = P (L - x) phi,   GJ phi' = P (u(L) - u) - P (L - x) u'
//     (the second: the moment of the tip load about the tangent (1, ., u')). Differentiating it once
//     (the P u' terms cancel) and using the first:
//         GJ phi'' + P^2 (L - x)^2 / EI_weak phi = 0,  phi(0) = 0 (clamped), phi'(L) = 0 (no tip
//     torque). With s = x/L and xi = 1 - s:  phi_xixi + gamma^2 xi^2 phi = 0,
//     gamma^2 = P^2 L^4/(EI_weak GJ), phi(xi = 1) = 0, phi_xi(0) = 0. The solution regular at the tip
//     with zero slope is sqrt(xi) J_{-1/4}(gamma xi^2/2) (order 1/4 = 1/(2+2), argument
//     gamma xi^2/2), equivalently its Frobenius series phi = sum_k c_k xi^(4k), c_0 = 1,
//     c_k = -gamma^2 c_{k-1}/(4k (4k - 1)). The clamp condition phi(1) = sum_k c_k = 0 gives
//     J_{-1/4}(gamma/2) = 0: gamma = 2 j_{-1/4,1} = 4.0125993435789008 (computed here as the first
//     root of the series by TOMS 748; PRIOR_ART.md's 4.012599, classical 4.013), and
//         P_cr = gamma sqrt(EI_weak GJ) / L^2.
//     Only the classical value is provided: it assumes EI_strong -> infinity (no in-plane
//     prebuckling deflection). At a finite EI_weak/EI_strong the prebuckling deflection changes the
//     critical load; no correction for this loading could be derived and cited reliably here, so
//     compare a solver at a large EI_strong/EI_weak (and GJ/EI_strong small), or check that its
//     critical load tends to this value as the ratios go to zero.
#include <numbers>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::references {

// ---- 1. localized helical buckling, infinite rod -----------------------------------------------
struct LocalizedHelicalBuckling {
  double B = 1.0;  // bending stiffness, > 0
  double T = 1.0;  // tension, > 0
  double M = 0.0;  // twisting moment, |M| < 2 sqrt(B T)
};

struct LocalizedHelicalBucklingSolution {
  double omega = 0.0;           // M / (2B): rotation rate of the lateral displacement
  double alpha = 0.0;           // sqrt(4BT - M^2) / (2B): localization rate
  double amplitude = 0.0;       // A = 2 B alpha / T: max lateral radius (at s = 0)
  double cos_phi_max = 0.0;     // M^2 / (2BT) - 1: min of t.e_z (at s = 0)
  double end_shortening = 0.0;  // Delta = 4 B alpha / T
};
LocalizedHelicalBucklingSolution localized_helical_buckling(const LocalizedHelicalBuckling& rod);

struct LocalizedHelicalBucklingPoint {
  Vec3 position;          // r(s)
  Vec3 tangent;           // t = r'(s), unit
  double cos_phi = 0.0;   // t.e_z
  double envelope = 0.0;  // (cos phi - cos phi_max) / (1 - cos phi_max) = tanh^2(alpha s)
};
LocalizedHelicalBucklingPoint localized_helical_buckling_point(const LocalizedHelicalBuckling& rod,
                                                               double s);  // s finite

// ---- 2. finite-rod relations (Neukirch et al. 2002) ----------------------------------------------
struct FiniteHelicalBuckling {
  double B = 1.345;                      // bending stiffness, > 0
  double C = 0.789;                      // twisting stiffness, > 0
  double L = 1.0;                        // length, > 0
  double Phi = 54.0 * std::numbers::pi;  // imposed end rotation (rad), 0 < Phi <= Phi_end
  double D = 0.03;                       // end shortening, 0 < D < L
};

struct FiniteHelicalBucklingSolution {
  double m = 0.0;            // M L / B
  double t = 0.0;            // T L^2 / B
  double M = 0.0;            // twisting moment m B / L
  double T = 0.0;            // tension t B / L^2
  double alpha = 0.0;        // localization rate sqrt(4t - m^2) / (2L)
  double cos_phi_max = 0.0;  // m^2 / (2t) - 1
};
// Phi outside (0, Phi_end], Phi_end = f(theta_end) (see 2. above): InputError "Phi" with the range.
FiniteHelicalBucklingSolution finite_helical_buckling(const FiniteHelicalBuckling& rod);

// ---- 3. Greenhill ---------------------------------------------------------------------------------
struct GreenhillColumn {
  double B = 1.0;  // bending stiffness, > 0
  double L = 1.0;  // length between the pins, > 0
  double P = 0.0;  // compressive load (< 0: tension), P < pi^2 B / L^2 for the moment
};
double greenhill_critical_moment(const GreenhillColumn& column);  // M_cr = 2B sqrt((pi/L)^2 - P/B)
// P_cr = B ((pi/L)^2 - (M/2B)^2) for the twisting moment M (finite); column.P is not used.
double greenhill_critical_load(const GreenhillColumn& column, double M);
// 3b: the critical twisting moment with semi-tangential end torques (P < pi^2 B/L^2, as above).
double greenhill_semitangential_critical_moment(const GreenhillColumn& column);
// 3c: the critical twisting moment of the clamped column (P < 4 pi^2 B/L^2).
double clamped_twisted_column_critical_moment(const GreenhillColumn& column);

// ---- 4. Michell ring ------------------------------------------------------------------------------
struct MichellRing {
  double B = 1.0;  // bending stiffness (Goriely's A), > 0
  double C = 1.0;  // twisting stiffness, > 0
  double L = 1.0;  // ring length 2 pi R, > 0
};
struct MichellRingSolution {
  double twist_angle = 0.0;      // Phi_c = 2 pi sqrt(3) B / C
  double twist_turns = 0.0;      // Phi_c / (2 pi) = sqrt(3) B / C
  double twisting_moment = 0.0;  // M_c = C Phi_c / L = sqrt(3) B / R
};
MichellRingSolution michell_ring(const MichellRing& ring);

// ---- 5. lateral-torsional buckling of a cantilever ------------------------------------------------
// gamma = 2 j_{-1/4,1} = 4.0125993435789008, the first positive root of the Frobenius series above.
double prandtl_cantilever_gamma();
struct LateralTorsionalCantilever {
  double EI_weak = 1.0;  // weak-axis bending stiffness, > 0
  double GJ = 1.0;       // torsional stiffness, > 0
  double L = 1.0;        // length, > 0
};
double lateral_torsional_cantilever_critical_load(const LateralTorsionalCantilever& beam);  // gamma sqrt(EI GJ)/L^2

}  // namespace rodvv::references

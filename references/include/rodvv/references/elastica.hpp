#pragma once
// Closed-form planar elastica (PHYSICS.md §0, §3; Love 1944 §§262-263; Timoshenko & Gere 1961 §2.7;
// Bisshopp & Drucker 1945; Mattiasson 1981, IJNME 17:145-153).
//
// Conventions (PHYSICS.md §0): arclength s in [0, L]; tangent t = (cos theta, sin theta); signed
// curvature kappa = theta'; bending stiffness EI; naturally straight, inextensible rod. Any consistent
// units: P in force, EI in force x length^2, lengths in length, angles in radians. The invariant
// H = 1/2 EI kappa^2 + n.t (PHYSICS.md §0) is reported in force units.
// Conventions of the libraries: GSL's gsl_sf_elljac_e takes the parameter m = k^2, its ellint
// functions take the modulus k (PHYSICS.md §2.5). All elliptic quantities here are evaluated from an
// accurate complementary modulus k' (never sqrt(1 - k^2)) with Carlson's R_F, R_D and a descending
// Landen transformation before GSL's elljac when k' < 1/2, as in pendulum.cpp.
// Errors: an invalid parameter throws rodvv::InputError naming it and its range; a failed root solve
// or a GSL status other than success throws rodvv::SolverError (iterations and residual).
//
// Cases:
//  1. The general inflexional elastica with compressive end load n = -P e_x (PHYSICS.md §3.1).
//  2. The pinned-pinned column in its first buckled mode (PHYSICS.md §3.2-3.3), bowed towards +y:
//     theta(0) = theta0 > 0, theta(L/2) = 0, theta(L) = -theta0, y(0) = y(L) = 0, x(0) = 0, and its
//     inverse (theta0 from P).
//  3. The clamped-free cantilever with a vertical dead tip load P (PHYSICS.md §3.5): clamp at s = 0,
//     phi = angle of the tangent measured DOWNWARD from the horizontal, x horizontal, w downward.
//  4. Cantilever under an end moment (exact circle), the flagpole (clamped-free, axial tip load,
//     PHYSICS.md §3.4) and Euler's critical loads.

namespace rodvv::references {

// A point of a planar elastica: tangent angle, signed curvature and position.
struct ElasticaPoint {
  double theta = 0.0;  // [rad]
  double kappa = 0.0;  // theta' [1/length]
  double x = 0.0;
  double y = 0.0;
};

// ---------------------------------------------------------------------------------------------
// 1. Inflexional elastica (PHYSICS.md §3.1), lambda = sqrt(P/EI), u = lambda s + u0:
//    sin(theta/2) = k sn(u, k),  kappa = 2 k lambda cn(u, k),
//    x = x0 + (2/lambda)[eps(u) - eps(u0)] - s,  y = y0 - (2k/lambda)[cn(u) - cn(u0)],
//    eps(u) = E(am u, k) (Jacobi epsilon, any real u: eps(u + 2K) = eps(u) + 2E).
// Requires EI > 0, P > 0, 0 < k < 1 and finite u0, x0, y0; s any finite value.
struct InflexionalElastica {
  double EI = 1.0;
  double P = 1.0;
  double k = 0.5;   // modulus, k = sin(theta_max / 2)
  double u0 = 0.0;  // phase at s = 0
  double x0 = 0.0;  // position at s = 0
  double y0 = 0.0;
};

ElasticaPoint inflexional_point(const InflexionalElastica& elastica, double s);
double inflexional_invariant(const InflexionalElastica& elastica);  // H = P (2 k^2 - 1)

// ---------------------------------------------------------------------------------------------
// 2. Pinned-pinned column, first mode (PHYSICS.md §3.2), k = sin(theta0/2), lambda L = 2 K(k).
// Requires L > 0, EI > 0, 0 < theta0 < pi.
struct PinnedColumn {
  double L = 1.0;
  double EI = 1.0;
};

struct PinnedSolution {
  double theta0 = 0.0;      // end rotation [rad], theta(0) = theta0 = -theta(L)
  double k = 0.0;           // modulus sin(theta0/2)
  double P = 0.0;           // compressive load 4 K^2 EI / L^2
  double y_M = 0.0;         // midspan deflection L k / K
  double kappa_M = 0.0;     // |kappa(L/2)| = 4 k K / L
  double chord = 0.0;       // x(L) = L (2E/K - 1); negative beyond theta0 = 130.71 deg
  double shortening = 0.0;  // L - chord = 2 L (1 - E/K)
  double H = 0.0;           // -P cos(theta0)
};

PinnedSolution pinned_solution(const PinnedColumn& column, double theta0);
// theta(s), kappa(s) = -(4 k K/L) cn(v), x(s), y(s) = (L k/K) cn(v), v = K (1 - 2 s/L); s in [0, L].
ElasticaPoint pinned_point(const PinnedColumn& column, double theta0, double s);
// Inverse problem: the theta0 in (0, pi) with 2 K(sin(theta0/2)) = L sqrt(P/EI). Requires
// P > P_Euler = pi^2 EI / L^2 (InputError otherwise, which states P_Euler). Bracketing TOMS 748
// on theta0. Throws InputError if P is so large that theta0 is indistinguishable from pi.
double pinned_theta0_from_load(const PinnedColumn& column, double P);

// ---------------------------------------------------------------------------------------------
// 3. Clamped-free cantilever, vertical dead tip load (PHYSICS.md §3.5), alpha = P L^2 / EI:
//    EI phi'' = -P cos phi, phi(0) = 0, phi'(L) = 0; k^2 = (1 + sin phi_L)/2,
//    sqrt(alpha) = K(k) - F(psi0, k), psi0 = asin(1/(k sqrt 2)).
// Requires L > 0, EI > 0, P > 0 (so alpha > 0). Solved with TOMS 748 on phi_L (or on
// pi/2 - phi_L when the tip rotation is beyond pi/4, so that k' stays accurate); alpha up to
// about 5.4e4 (beyond, pi/2 - phi_L < 1e-100: InputError naming alpha).
struct TipLoadedCantilever {
  double L = 1.0;
  double EI = 1.0;
  double P = 1.0;  // downward dead load at the free end
};

struct CantileverTip {
  double alpha = 0.0;  // P L^2 / EI
  double phi_L = 0.0;  // tip rotation [rad], in (0, pi/2)
  double u = 0.0;      // horizontal tip displacement (shortening of the projection), L - x(L)
  double w = 0.0;      // vertical (downward) tip deflection
  double k = 0.0;      // modulus, k^2 = (1 + sin phi_L)/2
  double psi0 = 0.0;   // asin(1/(k sqrt 2))
  double H = 0.0;      // invariant 1/2 EI phi'^2 + P sin phi = P sin phi_L
};

struct CantileverPoint {
  double phi = 0.0;    // tangent angle below the horizontal [rad]
  double kappa = 0.0;  // phi' [1/length]
  double x = 0.0;      // horizontal position
  double w = 0.0;      // downward deflection
};

CantileverTip cantilever_tip(const TipLoadedCantilever& cantilever);
// cantilever_point re-solves the tip rotation on every call (a pure function; ~40 R_F evaluations).
CantileverPoint cantilever_point(const TipLoadedCantilever& cantilever, double s);  // s in [0, L]

// ---------------------------------------------------------------------------------------------
// 4a. Cantilever (clamped at s = 0 along +x) under an end moment M: a circular arc,
//     theta = M s/EI, x = (EI/M) sin(M s/EI), y = (EI/M)(1 - cos(M s/EI)); M = 0 gives the straight
//     rod. H = M^2 / (2 EI) since n = 0. Requires L > 0, EI > 0, finite M; s in [0, L].
struct EndMomentCantilever {
  double L = 1.0;
  double EI = 1.0;
  double M = 1.0;
};

ElasticaPoint end_moment_point(const EndMomentCantilever& cantilever, double s);
double end_moment_invariant(const EndMomentCantilever& cantilever);  // M^2 / (2 EI)
// The end moment that rolls the rod into a full circle: M L / EI = 2 pi.
double roll_up_moment(double L, double EI);

// 4b. Flagpole: clamped at s = 0 (theta = 0), free tip with axial compressive dead load P and tip
//     rotation theta_tip (PHYSICS.md §3.4): a quarter wave, P L^2/EI = K(k)^2, k = sin(theta_tip/2).
//     Requires L > 0, EI > 0, 0 < theta_tip < pi.
struct Flagpole {
  double L = 1.0;
  double EI = 1.0;
  double theta_tip = 0.5;
};

struct FlagpoleSolution {
  double k = 0.0;
  double P = 0.0;           // K^2 EI / L^2
  double delta = 0.0;       // lateral tip deflection 2 k L / K
  double shortening = 0.0;  // L - x_tip = 2 L (1 - E/K)
  double H = 0.0;           // -P cos(theta_tip)
};

FlagpoleSolution flagpole_solution(const Flagpole& flagpole);

// 4c. Euler critical loads P_cr = c EI / L^2 (PHYSICS.md §3.4).
enum class EndConditions { PinnedPinned, ClampedFree, ClampedClamped, ClampedPinned };
// c: pi^2, pi^2/4, 4 pi^2, and x^2 with x the root of tan x = x in (pi, 3 pi/2) (computed by TOMS
// 748 on sin x - x cos x, not tabulated).
double euler_coefficient(EndConditions ends);
double euler_critical_load(EndConditions ends, double L, double EI);  // L > 0, EI > 0

}  // namespace rodvv::references

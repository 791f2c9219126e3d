#pragma once
// Private helpers of rodvv_references: Jacobi elliptic functions and elliptic integrals evaluated
// from an accurate complementary modulus k' (shared by pendulum.cpp and elastica.cpp).
//
// Why k' is an argument (PHYSICS.md §2.5 practical notes): near k -> 1 the complementary modulus
// sqrt(1 - k^2) formed from k carries a relative error eps/k'^2. Callers compute k' directly
// (cos(theta0/2), sin(beta/2), ...). GSL's elljac takes m = k^2 and forms 1 - m itself, so below
// kLandenThreshold a descending Landen transformation (DLMF 22.7.1-22.7.3) is applied first. The
// integrals use Carlson's symmetric forms (DLMF 19.25) with arguments built from k' directly.
//
// Every GSL call runs with the abort handler off and its status checked (gsl_checked.hpp).
namespace rodvv::references::detail {

// Below this complementary modulus the Landen transformation is applied before calling GSL. With
// k' >= 0.5 the error GSL makes in sqrt(1 - m) is at most (eps/2)/k'^2 = 2 eps relative.
inline constexpr double kLandenThreshold = 0.5;

struct Jacobi {
  double sn;
  double cn;
  double dn;
};

// sn, cn, dn(u | m = k^2) given the modulus k and an accurate complementary modulus kp.
Jacobi jacobi(double u, double k, double kp);

// Complete integrals from the accurate complementary modulus (and k = sqrt(1 - kp^2) supplied by
// the caller where needed):
double complete_k(double kp);                          // K = R_F(0, k'^2, 1)               DLMF 19.25.1
double complete_e(double kp);                          // E = k'^2/3 [R_D(0,k'^2,1) + R_D(0,1,k'^2)]
double complete_k_minus_e(double k, double kp);        // K - E = k^2/3 R_D(0, k'^2, 1)     DLMF 19.25.1

// Incomplete integrals of the first and second kind for an amplitude phi in [-pi/2, pi/2] given by
// sin(phi), cos(phi) >= 0 and delta = sqrt(1 - k^2 sin^2 phi) >= 0 (DLMF 19.25.5, 19.25.9):
//   F = s R_F(c^2, delta^2, 1),  E = s R_F(c^2, delta^2, 1) - k^2 s^3 / 3 R_D(c^2, delta^2, 1).
double incomplete_f(double sin_phi, double cos_phi, double delta);
double incomplete_e(double sin_phi, double cos_phi, double delta, double k);

// u = j 2K + r with |r| <= K (up to rounding), j = floor((u + K)/(2K)); fma makes u - j 2K a
// single rounding. j is an integer stored as a double.
struct Reduced {
  double r;
  double index;
};
Reduced reduce_half_period(double u, double K);

// Jacobi functions and the Jacobi epsilon eps(u) = E(am u, k) = int_0^u dn^2 for any real u, with
// the reduction above: sn, cn change sign with j, dn does not (DLMF 22.4.3), eps(u) = 2jE + eps(r)
// (DLMF 22.16.29); am u = j pi + atan2(sn r, cn r).
struct JacobiEpsilon {
  double sn;
  double cn;
  double dn;
  double epsilon;
};
JacobiEpsilon jacobi_epsilon(double u, double k, double kp, double K, double E);

}  // namespace rodvv::references::detail

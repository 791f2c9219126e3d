#pragma once
// Frictional contact as a second-order cone complementarity problem (ALGORITHMS.md §4.1, §4.2):
// n contacts, each with a local force r_k = (r_N, r_T1, r_T2) in its frame (normal first) and a
// friction coefficient mu_k; u = W r + b (W symmetric positive semidefinite, 3n x 3n: a Delassus or
// compliance operator; b the free velocities, or the free term of a QP). Two per-contact laws:
//  - Coulomb (Signorini-Coulomb, the forward problem): 0 <= u_N _|_ r_N >= 0; u_T = 0 and
//    |r_T| <= mu r_N, or r_T = -mu r_N u_T / |u_T|. Equivalently (De Saxce) r in K_mu,
//    u + mu |u_T| e_N in K_mu*, orthogonal.
//  - SecondOrderCone (plain SOC complementarity, the inverse statics' SOCQP of ALGORITHMS.md §3.2):
//    K_mu ∋ r _|_ u ∈ K_mu*, the KKT conditions of min 1/2 r^T W r + b^T r over r in K_mu.
// K_mu = {|r_T| <= mu r_N}, K_mu* = {mu |u_T| <= u_N} (its dual).
//
// Solver: block (nonsmooth) Gauss-Seidel, as So-bogus does for both laws (Daviet, Bertails-Descoubes
// & Boissieux 2011): sweep over the contacts, b~_k = b_k + sum_{j != k} W_kj r_j, and solve the 3 x 3
// local problem exactly:
//   take-off: r = 0 when b~ is admissible (Coulomb: b~_N >= 0; SOC: b~ in K_mu*);
//   stick / interior: r = -W_kk^-1 b~ when it lies in K_mu (u = 0);
//   slide / boundary: r = r_N (1, mu cos phi, mu sin phi), r_N > 0, with
//     Coulomb: u = s (0, -cos phi, -sin phi), s > 0   (u_N = 0, u_T against r_T),
//     SOC:     u = t (mu, -cos phi, -sin phi), t >= 0 (on the dual cone's boundary, orthogonal to r),
//   i.e. r_N W_kk d(phi) - t g(phi) = -b~, linear in (r_N, t) at fixed phi; it is solvable where
//   det[W_kk d, g, b~] = 0, a smooth 2 pi-periodic function of phi: its roots are bracketed on 256
//   sub-intervals and refined by TOMS 748 (Boost), and the root with r_N > 0, t >= 0 (smallest local
//   residual) is taken. This replaces the quartic of Daviet et al. (the same sliding equations,
//   solved in phi instead of in a Lagrange multiplier) and is exact to round-off.
// mu = 0: frictionless, r = (max(0, -b~_N / W_NN), 0, 0).
// Residual: the natural map max_k |r_k - P_K(r_k - rho_k u^_k)| / scale with u^ = u + mu |u_T| e_N
// (Coulomb) or u (SOC), rho_k = 1 / |W_kk|_F, scale = max_k |b_k| / |W_kk|_F (units of r); sweeps
// stop below `tolerance`. Also reported: the largest cone violation max_k (|r_T| - mu r_N)_+ / scale.
// Failures: no convergence within max_sweeps -> SolverError (sweeps, residual). Bad input (sizes, a
// non-finite entry, W not symmetric to 100 eps max|W|, a diagonal block that is not positive
// definite, mu < 0 or non-finite) -> InputError naming the argument.
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::contact {

enum class ConeLaw { Coulomb, SecondOrderCone };

struct ConeSettings {
  double tolerance = 1e-12;
  std::size_t max_sweeps = 100000;
};

struct ConeSolution {
  VecX r, u;  // u = W r + b
  std::size_t sweeps = 0;
  double residual = 0.0;
  double cone_violation = 0.0;
};

// P_{K_mu}(x), x = (x_N, x_T).
Vec3 project_onto_friction_cone(const Vec3& x, double mu);

// One contact, exactly (see above). W: 3 x 3 symmetric positive definite. `guess` (optional, the
// Gauss-Seidel's previous force of the contact) first seeds Newton on the sliding angle, then brackets
// it within 0.05 rad of its own, and the 256-interval scan runs only when neither gives an admissible root.
Vec3 solve_local_cone_problem(const Mat3& W, const Vec3& b, double mu, ConeLaw law, const Vec3* guess = nullptr);
// The same with W's inverse given (the Gauss-Seidel inverts each contact's block once).
Vec3 solve_local_cone_problem(const Mat3& W, const Mat3& W_inverse, const Vec3& b, double mu, ConeLaw law,
                              const Vec3* guess = nullptr);

// One contact's term of the residual: |r - P_K(r - u^ / |W_kk|_F)| (u^ as above).
double contact_natural_map(const Mat3& W_kk, const Vec3& r, const Vec3& u, double mu, ConeLaw law);

// The scaled natural-map residual and cone violation of a candidate r (u = W r + b recomputed).
double cone_residual(const MatX& W, const VecX& b, const VecX& mu, const VecX& r, ConeLaw law);

ConeSolution solve_cone_complementarity(const MatX& W, const VecX& b, const VecX& mu, ConeLaw law,
                                        const ConeSettings& settings = {});

}  // namespace rodvv::solvers::contact

#pragma once
// The three-dimensional Noether (Maddocks) invariant of an elastic rod (PHYSICS.md §1.1) from a
// SpatialRodSolution (common/spatial_rod.hpp), in both forms of the seed slides (002):
//
//  compact (R^3 x SO(3)):  H = n.v + m.u - W_bend - W_shear - V
//      body components: n_b = R^T n, m_b = R^T m, u, v; W_bend = 1/2 (u - u_hat).K(u - u_hat).
//      Since m_b = K (u - u_hat), m.u - W_bend = W_bend + m.u_hat: the m.u_hat term of a naturally
//      curved rod is included (the naive W + n.v - V is not conserved when u_hat != 0).
//  flattened (R^n, explicit chart):  H = sum_i dL/dq'_i q'_i - L
//      with q = (r, p), p the unit quaternion of R (Eigen's chart; the sign of p does not matter),
//      q' = (r', p') = (R v, 1/2 p (x) (0, u)), and
//      L(q, q') = W_bend(u(p, p')) + W_shear + V(r) + n.(r' - R(p) v),
//      u(p, p') = 2 Im(conj(p) (x) p') (linear in p'), so dL/dr' = n and
//      dL/dp' = (du/dp')^T K (u - u_hat), du/dw' = -2 x, du/dx' = 2 (w I - [x]x) for p = (w, x).
//  Shear and extension (special Cosserat rod): W_shear per unit length is read from
//  solution.shear_energy (empty: 0, a Kirchhoff rod) and v from solution.strain_v (!= e0). In the
//  flattened form the shear energy is a function W_shear(v), v = R(p)^T r', whose dL/dr' is
//  R dW_shear/dv = n, so the sum is again n.r' + m.u and the multiplier form used here (n given,
//  constraint term n.(r' - R(p) v) = 0) is the same number: the two forms agree with shear too
//  (checked on the exact special Cosserat helix, tests/invariants/test_noether3d.cpp).
//  The two agree to round-off (u is linear in q' at fixed q) whenever the stored m is the
//  constitutive moment R K (u - u_hat): the flattened form takes m from dW/du, the compact form
//  reads the stored m (so their difference also checks a solver's constitutive output).
//
// H is constant along an equilibrium whose Lagrangian has no explicit s dependence: uniform
// stiffness, constant natural strain, a potential V(r) (gravity included through V).
//
// Bad input throws rodvv::InputError naming the field: no stations ("solution.s"), arrays of
// different lengths ("solution.<field>"), non-finite values, non-positive stiffness
// ("solution.stiffness"), a frame that is not a rotation to 1e-8 ("solution.frame").
#include <cstddef>
#include <vector>

#include "rodvv/common/spatial_rod.hpp"

namespace rodvv::invariants {

void validate_spatial_solution(const SpatialRodSolution& solution);

// H at every station.
std::vector<double> noether3d_compact(const SpatialRodSolution& solution);
std::vector<double> noether3d_flattened(const SpatialRodSolution& solution);

struct Noether3dSummary {
  double mean = 0.0;             // mean of the compact H over the stations
  double spread = 0.0;           // max |H_i - mean|
  double form_difference = 0.0;  // max |H_compact,i - H_flattened,i|
  double scale = 0.0;            // natural size: max over stations of |n.v| + |m.u| + W + |V|
};
Noether3dSummary noether3d_summary(const SpatialRodSolution& solution);

}  // namespace rodvv::invariants

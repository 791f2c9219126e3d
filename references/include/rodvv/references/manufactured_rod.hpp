#pragma once
// A manufactured equilibrium of the inextensible, unshearable Kirchhoff rod (the method of manufactured
// solutions, Roache 2002; issue 13): choose the material strains u(s) and the internal force n(s), and the
// equilibrium equations give the distributed force f(s) and couple c(s) that hold the rod there. A rod
// solver loaded with f, c, clamped at s = 0 with the manufactured root frame and loaded at s = L with
// n(L), m(L) must then reproduce the manufactured shape at its own order - a general 3-D configuration with
// twist, anisotropic stiffness and a natural strain, which no closed-form case has.
//
// Conventions (common/spatial_rod.hpp): the frame R = (t, d1, d2) with R' = R [u]x, u = (twist, kappa1,
// kappa2) in material components; r' = t (inextensible, unshearable); m = R K (u - u_hat), K = diag(GJ,
// EI1, EI2); n, m are the force and moment the part beyond s exerts on the part before it. Then
//   n' + f = 0,  m' + t x n + c = 0  (Kirchhoff),  so  f = -n',  c = -m' - t x n,
//   m' = R ([u]x K (u - u_hat) + K u').
// The manufactured fields (L = length, S = sin(pi s / L), C2 = cos(2 pi s / L)):
//   u(s) = strain_mean + strain_sine S + strain_cosine C2     (material components)
//   n(s) = force_root + force_slope s / L + force_sine S      (world components)
// and r(s), R(s) integrate r' = R e1, R' = R [u]x from root_position, root_frame by GSL's rk8pd (Prince-
// Dormand 8(9)) to 1e-14, as a quaternion-free ODE re-orthonormalised only at the output.
//
// couple_free: a manufactured equilibrium with c = 0, for a solver that takes distributed forces but no
// distributed couples (the Super-Helix's point forces). The moment balance then fixes what is not chosen:
// m' must be normal to t, which is Kirchhoff's twist equation
//   GJ u0' = -(u x K (u - u_hat))_0,  u0(0) = strain_mean[0] + strain_cosine[0]
// (integrated with the frame; the twist's other coefficients are unused), and the normal part of n,
//   n = T(s) t + t x m',  T(s) = tension_root + tension_slope s / L + tension_sine S
// (force_* unused); then f = -n' = -(T' t + T t' + t' x m' + t x m''), with t' = R (u x e1) and
// m'' = R ([u]x ([u]x a + K u') + [u']x a + [u]x K u' + K u''), a = K (u - u_hat).
// tests/data/make_manufactured_rod_table.py integrates the same definition with mpmath (30 digits).
//
// InputError for a length or stiffness not finite and > 0, a non-finite vector or a root frame that is
// not a rotation (to 1e-12), stations outside [0, L] or not ascending.
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::references {

struct ManufacturedRod {
  double length = 1.0;
  Vec3 stiffness = Vec3::Ones();  // (GJ, EI1, EI2)
  Vec3 natural_strain = Vec3::Zero();
  Vec3 root_position = Vec3::Zero();
  Mat3 root_frame = Mat3::Identity();
  Vec3 strain_mean = Vec3::Zero();
  Vec3 strain_sine = Vec3::Zero();
  Vec3 strain_cosine = Vec3::Zero();
  Vec3 force_root = Vec3::Zero();
  Vec3 force_slope = Vec3::Zero();
  Vec3 force_sine = Vec3::Zero();
  bool couple_free = false;  // see above: c = 0, the twist and the normal force follow from the balance
  double tension_root = 0.0, tension_slope = 0.0, tension_sine = 0.0;  // T(s) of couple_free
};

struct ManufacturedStation {
  double s = 0.0;
  Vec3 position = Vec3::Zero();
  Mat3 frame = Mat3::Identity();     // (t, d1, d2)
  Vec3 strain = Vec3::Zero();        // u(s)
  Vec3 force = Vec3::Zero();         // n(s), world
  Vec3 moment = Vec3::Zero();        // m(s) = R K (u - u_hat), world
  Vec3 force_density = Vec3::Zero();   // f(s) = -n'(s)
  Vec3 couple_density = Vec3::Zero();  // c(s) = -m'(s) - t x n
};

// The manufactured fields at the stations s (ascending, in [0, L]).
std::vector<ManufacturedStation> manufactured_stations(const ManufacturedRod& rod, const std::vector<double>& s);


// The loads of consecutive cells [breaks[k], breaks[k+1]] (breaks ascending in [0, L]): the force
// int f ds = n(a) - n(b), exactly (n from the stations), and the couple int c ds by 8-point Gauss-Legendre (GSL's glfixed) on
// each cell, its stations integrated in one pass.
std::vector<Vec3> manufactured_cell_forces(const ManufacturedRod& rod, const std::vector<double>& breaks);
std::vector<Vec3> manufactured_cell_couples(const ManufacturedRod& rod, const std::vector<double>& breaks);

}  // namespace rodvv::references

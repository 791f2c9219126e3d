#pragma once
// The planar counterpart of manufactured_rod.hpp (the method of manufactured solutions) for the planar elastica
// solvers, whose loads are a potential field V(x, y) and dead end loads, not forces given along s.
#include <vector>

namespace rodvv::references {

// The planar manufactured elastica (inextensible, unshearable; PHYSICS.md §0 conventions): a chosen tangent
// angle theta(s) and bending stiffness EI(s), a chosen potential field V(x, y) per unit length and dead end
// loads F, M at the free tip s = L; the equilibrium then fixes the rest:
//   r' = t,  n' = grad V(r),  n(L) = F,  m' = -(t x n)_z,  m(L) = M,
// and the natural curvature that makes the chosen shape the equilibrium, kappa_hat = theta' - m / EI. A planar
// solver given EI(s), kappa_hat(s), V and F, M, clamped at r(0), theta(0), must reproduce theta(s), r(s), n(s),
// m(s). Fields (S = sin(pi s / L), C2 = cos(2 pi s / L)):
//   theta(s) = theta_root + theta_slope s / L + theta_sine S + theta_cosine (C2 - 1)
//   EI(s)    = stiffness (1 + stiffness_variation S)
//   V(x, y)  = 1/2 field_xx x^2 + field_xy x y + field_y y
// r(L) by rk8pd forward from the root, then every station by rk8pd backward from L (1e-14), the
// four-component ODE (x, y, n) with m (five). InputError for non-finite input, L or stiffness not > 0,
// |stiffness_variation| >= 1, stations outside [0, L].
struct ManufacturedPlanarRod {
  double length = 1.0;
  double root_x = 0.0, root_y = 0.0;
  double theta_root = 0.0, theta_slope = 0.0, theta_sine = 0.0, theta_cosine = 0.0;
  double stiffness = 1.0, stiffness_variation = 0.0;
  double field_xx = 0.0, field_xy = 0.0, field_y = 0.0;
  double tip_force_x = 0.0, tip_force_y = 0.0, tip_moment = 0.0;
};

struct ManufacturedPlanarStation {
  double s = 0.0, x = 0.0, y = 0.0, theta = 0.0, kappa = 0.0;
  double force_x = 0.0, force_y = 0.0, moment = 0.0;
  double bending_stiffness = 0.0, natural_curvature = 0.0;
};

// The stations at s (each in [0, L], any order).
std::vector<ManufacturedPlanarStation> manufactured_planar_stations(const ManufacturedPlanarRod& rod,
                                                                    const std::vector<double>& s);

}  // namespace rodvv::references

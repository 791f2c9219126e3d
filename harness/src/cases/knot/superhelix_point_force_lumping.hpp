#pragma once
// What a point force does to H(s) at the station of the Super-Helix element that carries it.
//
// A Super-Helix element has one strain u_e, and its equilibrium makes K (u_e - u0) the element's average of
// the static moment (material components): K (u_e - u0) ell = int_e R^T M ds, M(s) the moment about r(s) of
// every load beyond s (the virtual work of a variation of u_e). A point force F at s_c puts a kink in M,
// M'(s_c+) - M'(s_c-) = t(s_c) x F (from M' = -t x n, n losing F at s_c), and the average of a kinked line
// over [-ell/2, ell/2] exceeds its midpoint value by ell phi(xi) (t x F), phi(xi) = (1/2 - |xi|)^2 / 2,
// xi = the force's offset from the midpoint / ell (phi = 1/8 at the midpoint, 0 at the element's ends).
// The station's H = n.t + m.u - W(u) (W = 1/2 (u - u0).K (u - u0); dH/du = K u at fixed n and t) takes the
// element's strain for the continuum's u0 + K^-1 M(midpoint), so it misses the continuum's H by, to leading order,
//   Delta H_e = u_e . R_e^T sum_{F in e} ell phi(xi_F) (t_F x F),
// first order in ell with a coefficient set by where the force falls in its element: the O(h) spikes of
// H at the contact set that the issue asks to measure and explain. Smooth loads leave only the midpoint
// rule's O(ell^2). Away from point forces, and once the spike is subtracted, H converges at that order.
#include <cstddef>
#include <vector>

#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/common/eigen_types.hpp"

namespace rodvv::harness::knot_cases {

// A force F at offset x in [0, ell] on element e, where the centreline's tangent is t.
struct ElementPointForce {
  std::size_t element = 0;
  double offset = 0.0;
  Vec3 tangent = Vec3::Zero();
  Vec3 force = Vec3::Zero();
};

// Delta H_e above at each station of a Super-Helix solution struct (one station per element, at its
// midpoint: superhelix/solution.hpp), 0 at elements without a point force. InputError when a force's
// element has no station or its offset leaves [0, element_length].
std::vector<double> point_force_lumping_of_H(const SpatialRodSolution& solution, double element_length,
                                             const std::vector<ElementPointForce>& forces);

}  // namespace rodvv::harness::knot_cases

#pragma once
// Element compliance of the extensible, shearable (planar Reissner) rod in the mixed
// (Hellinger-Reissner) form of lagrangian.hpp: the element constraint
//   r_{i+1} - r_i - g_i - h C_i n_i = 0
// comes from adding -h/2 n_i^T C_i n_i to the Lagrangian, so n_i is the element force and C_i n_i
// its (stretch, shear) strain vector in global axes (Reissner 1972; Simo & Vu-Quoc 1986).
//
// Pointwise C(theta) = t t^T / EA + N N^T / GA = alpha I + beta R(2 theta) with
//   alpha = (1/EA + 1/GA) / 2,  beta = (1/EA - 1/GA) / 2,  R(psi) = [cos psi, sin psi; sin psi, -cos psi]
// (t t^T = (I + R(2 theta)) / 2, N N^T = (I - R(2 theta)) / 2). Per element:
//   polygon: C at the edge angle phi_i (midpoint rule, O(h^2));
//   arcs:    the exact mean of C(theta(s)) over the arc, theta linear from a to b:
//            alpha I + beta sinc(b - a) R(a + b), so h C_i n_i is the exact strain displacement of an
//            arc element under a constant force (no distributed load), as the chord g_i is exact
//            for the bending part. sinc and its derivatives come from arc_geometry.hpp.
// EA = GA gives C = I / EA, independent of the angles.
#include <Eigen/Core>

#include "rodvv/solvers/elastica2d/discretisation.hpp"

namespace rodvv::solvers::elastica2d {

struct ElementCompliance {
  Eigen::Matrix2d c;         // C_i
  Eigen::Matrix2d d[2];      // dC_i / d angle_k (k = 0: phi_i or theta_i; k = 1: theta_{i+1}, arcs only)
  Eigen::Matrix2d dd[2][2];  // d^2 C_i / d angle_k d angle_l
};

// axial_compliance = 1/EA, shear_compliance = 1/GA (0 for a rigid direction). Polygon reads a0 only.
ElementCompliance element_compliance(Scheme scheme, double a0, double a1, double axial_compliance,
                                     double shear_compliance) noexcept;

}  // namespace rodvv::solvers::elastica2d

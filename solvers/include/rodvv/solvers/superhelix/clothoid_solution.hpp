#pragma once
// The 3-D solution struct (common/spatial_rod.hpp) of a super-clothoid configuration q (nodal
// strains, clothoid_kinematics.hpp), so that the 3-D invariants (invariants/noether3d) can be
// evaluated on clothoid equilibria.
//
// Stations (where strains and stresses are sampled): by default the two Gauss-Legendre points
// sigma = (1 -+ 1/sqrt(3)) ell / 2 of every element. Why there: at equilibrium the affine strain
// field is (up to the geometric nonlinearity) the L2 projection of the continuous moment onto
// continuous piecewise-linear functions, K (u_h - u_hat) = P1(m); on a uniform mesh its error is
// f'' (sigma (ell - sigma)/2 - ell^2/12) to leading order (f the exact field), which vanishes
// exactly at these two points: the strain superconverges there. What remains is the frame, whose
// error inside an element is the integral of that pattern from the element's start, O(ell^3)
// (it vanishes only at the nodes), so H sampled at the Gauss points is O(h^3) asymptotically,
// against O(h^2) at nodes or midpoints (the O(h^2) nodal strains). Measured on the heavy cantilever
// (superhelix/clothoid-heavy-cantilever): relative spreads 2.8e-4, 5.4e-5, 8.1e-6, 1.1e-6 at
// N = 8 .. 64 (pairwise orders 2.38, 2.72, 2.87), nodes 1.05e-3 .. 1.86e-5 (order 1.9-2.0),
// midpoints 7.6e-4 .. 9.7e-6 (2.0-2.2). Nodes and midpoints are available for that comparison.
//
// At every station: position and frame by the element series (clothoid_element.hpp) from the
// element's base pose, u = the affine strain, v = e0 (Kirchhoff), m = R K (u - u_hat)
// (constitutive law), n from force balance n' + f = 0 with the dead loads,
// n(s) = F_end + rho S g (L - s) (exact for any configuration: the loads are dead),
// V = -rho S g . r, W_shear = 0. Vertices: the N + 1 nodes (element ends).
// Bad input: as validate_clothoid(model) and ClothoidKinematics (q of size 3 (N + 1), finite).
#include <string>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

enum class ClothoidStations {
  Gauss,      // 2 per element at the Gauss-Legendre points (default, superconvergent strain)
  Midpoints,  // 1 per element at sigma = ell / 2
  Nodes,      // the N + 1 nodes s = j ell (both ends included)
};

SpatialRodSolution make_clothoid_solution(const RodModel& model, const VecX& q,
                                          ClothoidStations stations = ClothoidStations::Gauss,
                                          std::string method = "super-clothoid");

}  // namespace rodvv::solvers::superhelix

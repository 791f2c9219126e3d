#pragma once
// The two discretisations of the planar elastica (problem.hpp), behind one solver interface
// (solve_static.hpp). Both use N elements of equal length h = L / N, nodes s_i = i h.
//
//   Polygon ("polygon", nodal, the discrete elastica): N straight inextensible edges with angles
//     phi_i; discrete curvature (phi_i - phi_{i-1}) / h on interior vertex i; bending energy
//     sum_i EI(s_i) / (2h) (phi_i - phi_{i-1} - h kappa_hat(s_i))^2. A clamped end at angle a adds the
//     half-cell term EI / h (phi_0 - a - (h/2) kappa_hat(0))^2 (and its mirror at s = L), i.e. the
//     clamp angle sits h/2 from the first edge midpoint. Positions are second-order accurate
//     (midpoint rule of r' = t).
//   Arcs ("arcs", reduced coordinates, the planar Super-Helix / "super-circles"): constant curvature
//     kappa_e on each element, so every element is an exact circular arc; bending energy
//     sum_e EI(s_e) h / 2 (kappa_e - kappa_hat(s_e))^2 at element midpoints s_e. An end-moment
//     cantilever (an exact circle) is reproduced to round-off for every N.
//
// Distributed potential: trapezoidal rule at the nodes, sum_i w_i V(r_i), w_i = h (h/2 at the
// two end nodes), for both discretisations.
#include <cstddef>
#include <string_view>

namespace rodvv::solvers::elastica2d {

enum class Scheme { Polygon, Arcs };

struct Discretisation {
  Scheme scheme = Scheme::Polygon;
  std::size_t elements = 64;  // N >= 2
};

std::string_view scheme_id(Scheme scheme);        // "polygon", "arcs"
Scheme scheme_from_id(std::string_view id);       // InputError for an unknown id

// Throws rodvv::InputError for N < 2 (field "elements") or N > 2^24.
void validate(const Discretisation& discretisation);

}  // namespace rodvv::solvers::elastica2d

#pragma once
// Solid fraction of a general (curved) monotone reference map (ALGORITHMS.md §6.2; issue 6).
//
// The solver's own state is the nodal xi, linear in each cell, and cell_fields (discretisation.hpp)
// clips it exactly. A map given as a function x -> xi(x) (an initial condition, the exact d'Alembert
// map of §6.1, ...) is curved inside the cells, so the clipped nodal values no longer give the part
// of a cell the solid occupies. Here:
//   x_left, x_right  the material points xi = 0 and xi = L0, located by bisection inside the
//                    bracketing cell down to two adjacent doubles (round-off, no tolerance to pick)
//   phi_c            |[x_c, x_{c+1}] ∩ [x_left, x_right]| / dx   (1 and 0 exactly off the edges)
//   l_c              clip(xi(x_{c+1})) - clip(xi(x_c)) = ∫_cell rho/rho0 dx, exact for any
//                    monotone map (the clipped values telescope, so sum l_c = L0)
// Choice of bisection over TOMS748 (Boost.Math) or subsampling (Levin et al. 2011): only two roots
// are needed per map, so the ~60 evaluations per root of bisection cost nothing, while bisection
// keeps its bracket whatever the curvature (no tolerance parameter, no convergence failure) and
// subsampling with n samples per cell is only O(1/n) accurate.
// For a piecewise-linear map phi_c equals cell_fields' l_c / dxi_c to round-off
// (tests/solvers/test_eulerian1d_solid_fraction.cpp).
#include <cstddef>
#include <functional>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/eulerian1d/problem.hpp"

namespace rodvv::solvers::eulerian1d {

// x -> xi(x): the material coordinate of the point at x; must be strictly increasing on the grid.
using ReferenceMap = std::function<double(double)>;

// Monotonicity is checked at the nodes and at samples_per_cell - 1 equally spaced interior points
// of each cell (1: nodes only). A fold narrower than the sample spacing is not seen.
struct MapSampling {
  std::size_t samples_per_cell = 8;
};

struct SolidFraction {
  VecX fraction;      // phi_c, one per cell
  VecX solid_length;  // l_c, one per cell
  double x_left = 0.0;   // xi(x_left) = 0
  double x_right = 0.0;  // xi(x_right) = L0
  std::size_t evaluations = 0;  // calls of the map (sampling + bisection)
};

// Nodal values xi(x_j) of a general map (e.g. for Problem::xi0). Throws InputError("xi0", ...) if
// the map is not finite or not strictly increasing at the samples (det F = 1/xi_x <= 0), and
// InputError("samples_per_cell", ...) if samples_per_cell == 0.
VecX sample_reference_map(const Grid& grid, const ReferenceMap& xi, const MapSampling& sampling = {});

// The solid fraction of the general map xi on the grid. Throws InputError("xi0", ...) as
// sample_reference_map does and also if the solid 0 <= xi <= L0 does not lie inside the grid
// (xi(x_min) <= 0 and xi(x_max) >= L0 needed, as in validate()).
SolidFraction solid_fraction(const Grid& grid, const Material& material, const ReferenceMap& xi,
                             const MapSampling& sampling = {});

// Root of xi(x) = X in [a, b] given xi(a) <= X <= xi(b), by bisection until a and b are adjacent
// doubles; returns the end whose value is closer to X. Adds the evaluations to *evaluations.
double locate_material_point(const ReferenceMap& xi, double X, double a, double b,
                             std::size_t* evaluations = nullptr);

}  // namespace rodvv::solvers::eulerian1d

#pragma once
// The SpatialRodSolution (common/spatial_rod.hpp) of a discrete elastic rod state, so that the 3-D
// invariants (invariants/noether3d.hpp) and metrics read a nodal rod exactly as a Super-Helix.
//
// Stations are the interior vertices x_i, where curvature and twist live (PHYSICS.md §1.4):
//  - s_i = vertex_arclength(i) (model.hpp); frame: the rotation halfway between the material frames of edges i-1 and i;
//  - strain_u = integrated strain / Voronoi length (discrete_energy.hpp); strain_v = (stretch, 0, 0)
//    (the mean of |e|/ebar of the two edges; 1 for an inextensible rod); W_shear = the stretching
//    energy per unit length 1/2 EA (stretch - 1)^2 (0 for an inextensible rod);
//  - force_n: the mean of the internal forces of edges i-1 and i, where the internal force of edge j
//    is the sum of the elastic vertex forces beyond it (= the external force on (s, L] at an
//    equilibrium, PHYSICS.md §0), so that contact or any other load enters with nothing special-cased;
//    the couple (M x t)/|e| by which the tip moment is applied is not a force of the rod and is taken
//    out of the tip edge's force;
//  - moment_m = R K (u - u_hat) (world); potential = -rho S g.x_i.
// A vertex next to a clamped end edge is not a station: the clamped edge carries the support's
// reaction couple as a pair of forces, which is not the rod's internal force.
// Vertices: those on [0, L], with the frame of the adjacent edge at the ends and the station frame
// inside; a clamped end contributes its support point (the clamped edge's midpoint).
#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

SpatialRodSolution make_solution(const RodModel& model, const RodState& state);

}  // namespace rodvv::solvers::rod3d

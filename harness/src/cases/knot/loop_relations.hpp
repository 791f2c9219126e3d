#pragma once
// The loose-knot relations of an open knot's loop (PHYSICS.md §5.1, the tension elastica homoclinic),
// measured on any 3-D rod's solution struct, for the trefoil cases of both rods.
#include <cstddef>
#include <string>

#include "rodvv/common/spatial_rod.hpp"

namespace rodvv::harness::knot_cases {

struct LoopRelations {
  double perpendicular_ratio = 0.0;  // mean 1/2 B kappa^2 / T where t.e_x changes sign (loose limit 1)
  std::size_t perpendicular_points = 0;
  double apex_ratio = 0.0;  // B kappa_apex^2 / (4 T) (loose limit 1)
};

// At the stations where the tangent turns through perpendicular to the pull e_x (t.e_x changes sign;
// kappa interpolated linearly in t.e_x), and at the apex of the loop: the station between the first
// and the last of them whose tangent points most against the pull. kappa = |(u1, u2)| (u0 = twist).
// SolverError(method, ...) with the solve's iterations and residual when there is no loop (fewer
// than 2 such points).
LoopRelations loop_relations(const SpatialRodSolution& solution, double B, double T, const std::string& method,
                             std::size_t iterations, double residual);

}  // namespace rodvv::harness::knot_cases

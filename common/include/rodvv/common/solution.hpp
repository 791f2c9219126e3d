#pragma once
// Any solution a rodvv solver returns and a rodvv check reads: a planar rod, a 3-D rod, a
// one-degree-of-freedom trajectory (the pendulum) or a 3-D rod's trajectory (ARCHITECTURE.md,
// "Which way the arrows point"). A case whose level splits into a solver run and measurements of its
// solution measures a Solution, whoever computed it: rodvv's own solvers in a sweep, another
// solver's files in `rodvv check`.
#include <variant>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/common/rod_trajectory.hpp"
#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/common/trajectory.hpp"

namespace rodvv {

using Solution = std::variant<PlanarRodSolution, SpatialRodSolution, Trajectory, RodTrajectory>;

// The name of each alternative, as the solution-file format spells it.
inline const char* solution_kind(const Solution& solution) {
  switch (solution.index()) {
    case 0: return "planar_rod";
    case 1: return "spatial_rod";
    case 2: return "trajectory";
    default: return "rod_trajectory";
  }
}

}  // namespace rodvv

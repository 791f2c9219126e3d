#pragma once
// Time history of a 3-D rod: the vertex positions at the recorded times, as a dynamic 3-D solver
// writes them and a dynamic 3-D case measures them (ARCHITECTURE.md, "Which way the arrows point";
// the solution-file kind "rod_trajectory"). Plain data.
//
// Conventions as in spatial_rod.hpp: arclength s in [0, L] along each snapshot's vertices (s[0] = 0),
// positions in world components. Each snapshot may have its own vertices (a solver that remeshes).
#include <cstddef>
#include <string>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv {

struct RodSnapshot {
  std::vector<double> s;      // vertex arclengths, strictly increasing from 0
  std::vector<Vec3> position; // r(s), world
};

struct RodTrajectory {
  std::string method;
  std::vector<double> t;               // recorded times, strictly increasing
  std::vector<RodSnapshot> snapshots;  // snapshots[k] at t[k]
  std::size_t steps = 0;               // time steps taken

  std::size_t size() const noexcept { return t.size(); }
};

}  // namespace rodvv

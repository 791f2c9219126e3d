#pragma once
// The 3-D solution struct (common/spatial_rod.hpp) of a Super-Helix configuration q.
//   stations at the element midpoints s = (Q + 1/2) ell, where the constant element strain is a
//   second-order approximation of the continuous strain: position and frame (closed form),
//   u = q_Q, v = e0, m = R K (q_Q - q0_Q) (constitutive law), n from force balance n' + f = 0 with
//   the dead loads, n(s) = F_end + rho S g (L - s), V = -rho S g . r;
//   vertices: the N + 1 element ends.
#include <string>

#include "rodvv/common/spatial_rod.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::solvers::superhelix {

SpatialRodSolution make_solution(const RodModel& model, const VecX& q, std::string method = "super-helix");

}  // namespace rodvv::solvers::superhelix

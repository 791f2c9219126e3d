#pragma once
// The load at which the stability eigenvalue of a family of equilibria crosses zero
// (solvers/rod3d/linearized.hpp: stability_eigenvalue), found by TOMS 748 on a bracket: the critical
// load of a buckling problem posed on the nodal rod (rod3d/lateral-torsional).
#include <functional>
#include <string>

namespace rodvv::harness::rod3d_cases {

// eigenvalue(load) must change sign on [low, high] (SolverError naming `what` otherwise); the root is
// found to a relative 1e-13 of the load. An InputError "state" from the linearisation (the statics'
// equilibrium not at rest to its tolerance) becomes a SolverError: a level failure, not bad input.
double critical_load(const std::function<double(double load)>& eigenvalue, double low, double high,
                     const std::string& what);

}  // namespace rodvv::harness::rod3d_cases

#pragma once
// Internal building blocks shared by solve_static.cpp and continuation.cpp (namespace detail; not a
// stable interface): the initial state from a guess, one damped Newton solve on the KKT system of a
// DiscreteLagrangian, and the conversion of a converged state into a PlanarRodSolution. The
// behaviour is documented in solve_static.hpp.
#include <Eigen/Core>
#include <cstddef>
#include <string>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace rodvv::solvers::elastica2d::detail {

struct NewtonState {
  BandedLU lu;                 // factorisation of the last KKT matrix
  std::size_t iterations = 0;  // accumulated over calls
  double residual = 0.0;       // ||grad L||_inf at the last evaluation
};

std::string method_name(Scheme scheme);

Eigen::VectorXd initial_state(const DiscreteLagrangian& lag, const Problem& problem,
                              const InitialGuess& guess);

// Each KKT residual component over its scale in the problem's own units (length L = problem.length,
// stiffness EI(0)): force balance EI/L^2, moment balance EI/L, element constraints and prescribed
// positions L, prescribed angles 1. With L = EI = 1 the scaled residual is grad L itself.
Eigen::VectorXd residual_scales(const DiscreteLagrangian& lag);
// The scale of each unknown, (EI/L) / residual scale: positions L, angles 1, forces EI/L^2, the
// multipliers of prescribed angles EI/L (the continuation's arc-length metric, continuation.hpp).
Eigen::VectorXd unknown_scales(const DiscreteLagrangian& lag);

// Newton with backtracking on ||D grad L||_2 (D = 1/residual_scales) until ||D grad L||_inf <=
// options.tolerance (or a step at round-off), so that convergence does not depend on the units
// (a rod of L = 1e6 converges like one of L = 1); throws SolverError on failure.
void newton(const DiscreteLagrangian& lag, Eigen::VectorXd& z, const SolverOptions& options,
            NewtonState& state);

PlanarRodSolution fill_solution(const DiscreteLagrangian& lag, const Eigen::VectorXd& z);

}  // namespace rodvv::solvers::elastica2d::detail

#pragma once
// Newton with load stepping on a generalised-force residual r(q, lambda) = K (q - q0) - lambda F(q),
// shared by the Super-Helix (statics.hpp) and the super-clothoid (clothoid_statics.hpp) rods: only
// the residual differs between the two element types.
//
// Jacobian dr/dq: exact when the caller passes one (the Super-Helix, load_stiffness.hpp), otherwise
// by central differences of the residual (step cbrt(eps) max(|q_j|, 1/L), truncation error ~1e-11
// relative: the super-clothoid); direction by GMRES preconditioned by diag(J), LU with partial
// pivoting when GMRES stalls (newton_direction); backtracking line search on 1/2 |r|^2 (Armijo
// 1e-4, step halved down to 2^-30). Load stepping: lambda_k = k / load_steps, each step starting
// from the previous one. Convergence: |r|_inf <= tolerance * scale, scale = max(k_max |q|_inf,
// k_max / L, load_scale), or a Newton step at round-off (|dq|_inf L <= 64 eps (1 + |q|_inf L)).
// Failure: rodvv::SolverError(method, ...) with iterations and residual.
#include <cstddef>
#include <functional>
#include <string>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::superhelix {

struct StaticOptions {
  std::size_t load_steps = 1;       // >= 1
  std::size_t max_iterations = 50;  // per load step, >= 1
  double tolerance = 1e-12;         // relative, in (0, 1)
  VecX initial_q;                   // empty: start from q0
};

struct StaticResult {
  VecX q;
  std::size_t iterations = 0;  // Newton iterations over all load steps
  double residual = 0.0;       // final |r|_inf
};

using StaticResidual = std::function<VecX(const VecX& q, double load_factor)>;
// dr/dq at (q, load_factor); empty: central differences of the residual.
using StaticJacobian = std::function<MatX(const VecX& q, double load_factor)>;

// Scales of the convergence test (see above).
struct NewtonScales {
  double stiffness_max = 1.0;  // |K|_inf
  double length = 1.0;         // L
  double load_scale = 0.0;     // |F_ext(q0)|_inf at full load

  // max(k_max |q|_inf, k_max / L, load_scale): what the residual at q is small against.
  double residual_scale(const VecX& q) const;
  // |dq|_inf L <= 64 eps (1 + |q|_inf L): a Newton step at round-off.
  bool round_off_step(const VecX& direction, const VecX& q) const;
};

// A line search that found no acceptable step: the iteration has converged when its step or its
// residual is already at round-off (|r|_inf <= 1e3 tolerance scale); otherwise SolverError(method,
// "line search failed at load factor ...", iterations, |r|_inf).
void require_residual_floor(bool round_off_step, double norm, double tolerance, double scale, double load_factor,
                            const std::string& method, std::size_t iterations);

// Validates the options (InputError names load_steps / max_iterations / tolerance / initial_q) and
// returns the start: initial_q, or q0 when it is empty. Shared by every static Newton iteration.
VecX newton_start(const StaticOptions& options, const VecX& q0);

MatX central_difference_jacobian(const StaticResidual& residual, const VecX& q, double load_factor,
                                 double length);

// d solving J d = -r: GMRES (diagonal preconditioner, relative tolerance 1e-13, at most min(n, 200)
// iterations, restart 60), else LU with partial pivoting. O(n^2) per GMRES iteration.
VecX newton_direction(const MatX& J, const VecX& residual);

// Validates the options (InputError names load_steps / max_iterations / tolerance / initial_q).
StaticResult newton_load_stepping(const StaticResidual& residual, const VecX& q0, const NewtonScales& scales,
                                  const StaticOptions& options, const std::string& method,
                                  const StaticJacobian& jacobian = {});

}  // namespace rodvv::solvers::superhelix

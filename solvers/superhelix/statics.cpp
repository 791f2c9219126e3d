#include "rodvv/solvers/superhelix/statics.hpp"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

VecX static_residual(const RodModel& model, const VecX& q, double load_factor) {
  const Kinematics kinematics(model, q);
  return generalised_stiffness(model).cwiseProduct(q - natural_strain_vector(model)) -
         external_generalised_force(model, kinematics, load_factor);
}

MatX static_jacobian(const RodModel& model, const VecX& q, double load_factor) {
  const Eigen::Index n = q.size();
  MatX J(n, n);
  const double step_scale = std::cbrt(std::numeric_limits<double>::epsilon());
  VecX shifted = q;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double step = step_scale * std::max(std::abs(q[j]), 1.0 / model.length);
    shifted[j] = q[j] + step;
    const VecX plus = static_residual(model, shifted, load_factor);
    shifted[j] = q[j] - step;
    const VecX minus = static_residual(model, shifted, load_factor);
    shifted[j] = q[j];
    J.col(j) = (plus - minus) / (2.0 * step);
  }
  return J;
}

StaticResult solve_static(const RodModel& model, const StaticOptions& options) {
  validate(model);
  require_at_least("load_steps", options.load_steps, 1);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  const VecX q0 = natural_strain_vector(model);
  StaticResult result;
  result.q = options.initial_q.size() == 0 ? q0 : options.initial_q;
  if (result.q.size() != q0.size())
    throw InputError("initial_q", "invalid parameter 'initial_q': must be empty or hold 3 N = " +
                                      std::to_string(q0.size()) + " values");
  const VecX k = generalised_stiffness(model);
  const double k_max = k.lpNorm<Eigen::Infinity>();
  const double load_scale =
      external_generalised_force(model, Kinematics(model, q0), 1.0).lpNorm<Eigen::Infinity>();
  constexpr double kEps = std::numeric_limits<double>::epsilon();

  for (std::size_t step = 1; step <= options.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(options.load_steps);
    VecX residual = static_residual(model, result.q, lambda);
    bool converged = false;
    for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
      const double scale = std::max({k_max * result.q.lpNorm<Eigen::Infinity>(), k_max / model.length,
                                     load_scale});
      const double norm = residual.lpNorm<Eigen::Infinity>();
      if (norm <= options.tolerance * scale) {
        converged = true;
        break;
      }
      ++result.iterations;
      const MatX J = static_jacobian(model, result.q, lambda);
      const VecX direction = -J.partialPivLu().solve(residual);
      if (!direction.allFinite())
        throw SolverError("superhelix Newton", "singular Jacobian", result.iterations, norm);
      // backtracking on 1/2 |r|^2
      const double merit = residual.squaredNorm();
      double alpha = 1.0;
      VecX trial_q, trial_residual;
      bool accepted = false;
      for (int halving = 0; halving <= 30; ++halving, alpha *= 0.5) {
        trial_q = result.q + alpha * direction;
        trial_residual = static_residual(model, trial_q, lambda);
        if (trial_residual.squaredNorm() <= (1.0 - 2e-4 * alpha) * merit) {
          accepted = true;
          break;
        }
      }
      const bool round_off_step = direction.lpNorm<Eigen::Infinity>() * model.length <=
                                  64.0 * kEps * (1.0 + result.q.lpNorm<Eigen::Infinity>() * model.length);
      if (!accepted) {
        if (round_off_step || norm <= 1e3 * options.tolerance * scale) {
          converged = true;  // already at the round-off floor of the residual
          break;
        }
        throw SolverError("superhelix Newton", "line search failed at load factor " + format_value(lambda),
                          result.iterations, norm);
      }
      result.q = trial_q;
      residual = trial_residual;
      if (round_off_step) {
        converged = true;
        break;
      }
    }
    result.residual = residual.lpNorm<Eigen::Infinity>();
    if (!converged) {
      const double scale = std::max({k_max * result.q.lpNorm<Eigen::Infinity>(), k_max / model.length,
                                     load_scale});
      if (result.residual > options.tolerance * scale)
        throw SolverError("superhelix Newton",
                          "no convergence at load factor " + format_value(lambda), result.iterations,
                          result.residual);
    }
  }
  return result;
}

}  // namespace rodvv::solvers::superhelix

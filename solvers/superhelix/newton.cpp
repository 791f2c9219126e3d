#include "rodvv/solvers/superhelix/newton.hpp"

#include <Eigen/LU>
#include <unsupported/Eigen/IterativeSolvers>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::superhelix {

MatX central_difference_jacobian(const StaticResidual& residual, const VecX& q, double load_factor,
                                 double length) {
  const Eigen::Index n = q.size();
  MatX J(n, n);
  const double step_scale = std::cbrt(std::numeric_limits<double>::epsilon());
  VecX shifted = q;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double step = step_scale * std::max(std::abs(q[j]), 1.0 / length);
    shifted[j] = q[j] + step;
    const VecX plus = residual(shifted, load_factor);
    shifted[j] = q[j] - step;
    const VecX minus = residual(shifted, load_factor);
    shifted[j] = q[j];
    J.col(j) = (plus - minus) / (2.0 * step);
  }
  return J;
}

// The Newton direction J d = -r. A reduced rod's Jacobian K - D is dense, so a direct solve is
// O(n^3) (dense LU was 70 % of a statics solve at N = 256). The stiffness K is diagonal and
// dominates: the spectrum of K^-1 D is that of a compact operator (the continuum's load stiffness
// relative to its bending stiffness), so GMRES preconditioned by diag(J) needs a number of
// iterations independent of N, each one O(n^2) product. Relative linear tolerance 1e-13: the Newton
// step is then exact to round-off and the iteration keeps its quadratic convergence. GMRES that
// stalls (far from equilibrium, near a limit point: J nearly singular or indefinite) falls back to
// LU with partial pivoting, so the iteration never depends on the Krylov method's luck.
VecX newton_direction(const MatX& J, const VecX& residual) {
  Eigen::GMRES<MatX, Eigen::DiagonalPreconditioner<double>> gmres;
  gmres.setTolerance(1e-13);
  gmres.setMaxIterations(std::min<Eigen::Index>(J.rows(), 200));
  gmres.set_restart(60);
  gmres.compute(J);
  VecX direction = -gmres.solve(residual);
  if (gmres.info() == Eigen::Success && direction.allFinite()) return direction;
  return -J.partialPivLu().solve(residual);
}

double NewtonScales::residual_scale(const VecX& q) const {
  return std::max({stiffness_max * q.lpNorm<Eigen::Infinity>(), stiffness_max / length, load_scale});
}

bool NewtonScales::round_off_step(const VecX& direction, const VecX& q) const {
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  return direction.lpNorm<Eigen::Infinity>() * length <= 64.0 * kEps * (1.0 + q.lpNorm<Eigen::Infinity>() * length);
}

void require_residual_floor(bool round_off_step, double norm, double tolerance, double scale, double load_factor,
                            const std::string& method, std::size_t iterations) {
  if (round_off_step || norm <= 1e3 * tolerance * scale) return;
  throw SolverError(method, "line search failed at load factor " + format_value(load_factor), iterations, norm);
}

VecX newton_start(const StaticOptions& options, const VecX& q0) {
  require_at_least("load_steps", options.load_steps, 1);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  const VecX start = options.initial_q.size() == 0 ? q0 : options.initial_q;
  if (start.size() != q0.size())
    throw InputError("initial_q", "invalid parameter 'initial_q': must be empty or hold " +
                                      std::to_string(q0.size()) + " values (one per degree of freedom)");
  if (!start.allFinite()) throw InputError("initial_q", "invalid parameter 'initial_q': must be finite");
  return start;
}

StaticResult newton_load_stepping(const StaticResidual& static_residual, const VecX& q0,
                                  const NewtonScales& scales, const StaticOptions& options,
                                  const std::string& method, const StaticJacobian& jacobian) {
  StaticResult result;
  result.q = newton_start(options, q0);

  for (std::size_t step = 1; step <= options.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(options.load_steps);
    VecX residual = static_residual(result.q, lambda);
    bool converged = false;
    for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
      const double scale = scales.residual_scale(result.q);
      const double norm = residual.lpNorm<Eigen::Infinity>();
      check_time_budget("superhelix Newton", result.iterations, norm);
      if (norm <= options.tolerance * scale) {
        converged = true;
        break;
      }
      ++result.iterations;
      const MatX J = jacobian ? jacobian(result.q, lambda)
                              : central_difference_jacobian(static_residual, result.q, lambda, scales.length);
      const VecX direction = newton_direction(J, residual);
      if (!direction.allFinite()) throw SolverError(method, "singular Jacobian", result.iterations, norm);
      // backtracking on 1/2 |r|^2
      const double merit = residual.squaredNorm();
      double alpha = 1.0;
      VecX trial_q, trial_residual;
      bool accepted = false;
      for (int halving = 0; halving <= 30; ++halving, alpha *= 0.5) {
        trial_q = result.q + alpha * direction;
        trial_residual = static_residual(trial_q, lambda);
        if (trial_residual.squaredNorm() <= (1.0 - 2e-4 * alpha) * merit) {
          accepted = true;
          break;
        }
      }
      const bool round_off_step = scales.round_off_step(direction, result.q);
      if (!accepted) {
        require_residual_floor(round_off_step, norm, options.tolerance, scale, lambda, method, result.iterations);
        converged = true;
        break;
      }
      result.q = trial_q;
      residual = trial_residual;
      if (round_off_step) {
        converged = true;
        break;
      }
    }
    result.residual = residual.lpNorm<Eigen::Infinity>();
    if (!converged && result.residual > options.tolerance * scales.residual_scale(result.q))
      throw SolverError(method, "no convergence at load factor " + format_value(lambda), result.iterations,
                        result.residual);
  }
  return result;
}

}  // namespace rodvv::solvers::superhelix

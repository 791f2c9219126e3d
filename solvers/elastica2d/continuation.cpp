#include "rodvv/solvers/elastica2d/continuation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/lagrangian.hpp"
#include "rodvv/solvers/elastica2d/newton.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

using Eigen::VectorXd;

// d(grad L)/d lambda: grad L is affine in the load factor.
VectorXd load_derivative(DiscreteLagrangian& lag, const VectorXd& z, double lambda) {
  lag.set_load_factor(1.0);
  VectorXd d = lag.gradient(z);
  lag.set_load_factor(0.0);
  d -= lag.gradient(z);
  lag.set_load_factor(lambda);
  return d;
}

struct Tangent {
  VectorXd z;
  double lambda = 0.0;
};

// The arc-length metric's inner product on z, in the problem's own units: sum a_i b_i / u_i^2 with
// u = unknown_scales (newton.hpp), so that the steps do not depend on L and EI.
struct Metric {
  VectorXd inverse_square_scale;
  double dot(const VectorXd& a, const VectorXd& b) const {
    return a.cwiseProduct(b).cwiseProduct(inverse_square_scale).sum();
  }
};

// Corrector: Newton on the bordered system from the predicted (z, lambda). Returns false (state
// unchanged) if it does not converge within options.max_iterations or hits a singular matrix.
bool correct(DiscreteLagrangian& lag, const SolverOptions& options, const Metric& metric,
             const VectorXd& residual_scale, const VectorXd& z_k, double lambda_k, const Tangent& t, double w,
             double ds, VectorXd& z, double& lambda, detail::NewtonState& state, std::size_t& used) {
  for (std::size_t it = 0; it <= options.max_iterations; ++it) {
    lag.set_load_factor(lambda);
    const VectorXd f = lag.gradient(z);
    const double g = w * metric.dot(t.z, z - z_k) + t.lambda * (lambda - lambda_k) - ds;
    const double r = f.cwiseQuotient(residual_scale).lpNorm<Eigen::Infinity>();  // as in newton()
    if (!std::isfinite(r)) return false;
    state.residual = r;
    if (r <= options.tolerance && std::abs(g) <= options.tolerance * std::max(1.0, ds)) {
      used = it;
      return true;
    }
    if (it == options.max_iterations) return false;
    if (!state.lu.factorize(lag.hessian(z))) return false;
    const VectorXd a = state.lu.solve(-f);
    const VectorXd b = state.lu.solve(-load_derivative(lag, z, lambda));
    const double denominator = w * metric.dot(t.z, b) + t.lambda;
    if (!(std::abs(denominator) > 0.0)) return false;
    const double dlambda = -(g + w * metric.dot(t.z, a)) / denominator;
    z += a + dlambda * b;
    lambda += dlambda;
    ++state.iterations;
  }
  return false;
}

}  // namespace

void validate(const ContinuationOptions& options) {
  require_finite("continuation.initial_load_factor", options.initial_load_factor);
  require_finite("continuation.final_load_factor", options.final_load_factor);
  if (options.final_load_factor == options.initial_load_factor)
    throw InputError("continuation.final_load_factor",
                     "invalid parameter 'continuation.final_load_factor' = " +
                         format_value(options.final_load_factor) +
                         ": must differ from initial_load_factor");
  require_positive("continuation.step", options.step);
  if (!(options.max_step >= options.step) || !std::isfinite(options.max_step))
    throw InputError("continuation.max_step", "invalid parameter 'continuation.max_step' = " +
                                                  format_value(options.max_step) +
                                                  ": must be finite and >= step");
  require_open_interval("continuation.min_step", options.min_step, 0.0,
                        std::nextafter(options.step, 2.0 * options.step));
  require_at_least("continuation.max_points", options.max_points, 2);
}

std::vector<BranchPoint> trace_branch(const Problem& problem, const Discretisation& discretisation,
                                      const SolverOptions& options, const InitialGuess& guess,
                                      const ContinuationOptions& continuation) {
  validate(options);
  validate(continuation);
  DiscreteLagrangian lag(problem, discretisation);
  const std::string method = detail::method_name(discretisation.scheme);
  detail::NewtonState state;

  double lambda = continuation.initial_load_factor;
  const double direction = continuation.final_load_factor > lambda ? 1.0 : -1.0;
  lag.set_load_factor(lambda);
  VectorXd z = detail::initial_state(lag, problem, guess);
  detail::newton(lag, z, options, state);

  std::vector<BranchPoint> branch;
  auto record = [&](double at) {
    BranchPoint p;
    p.load_factor = at;
    p.solution = detail::fill_solution(lag, z);
    p.solution.iterations = state.iterations;
    p.solution.residual = state.residual;
    branch.push_back(std::move(p));
  };
  record(lambda);

  const double w = 1.0 / static_cast<double>(z.size());
  const Metric metric{detail::unknown_scales(lag).cwiseAbs2().cwiseInverse()};
  const VectorXd residual_scale = detail::residual_scales(lag);
  // Initial tangent: (dz/dlambda, 1), normalised in the metric w |dz|^2 + dlambda^2.
  Tangent t;
  if (!state.lu.factorize(lag.hessian(z)))
    throw SolverError(method, "KKT matrix singular at the first branch point", state.iterations,
                      state.residual);
  t.z = state.lu.solve(-load_derivative(lag, z, lambda));
  t.lambda = 1.0;
  {
    const double norm = std::sqrt(w * metric.dot(t.z, t.z) + 1.0);
    t.z *= direction / norm;
    t.lambda = direction / norm;
  }

  double ds = continuation.step;
  while (branch.size() < continuation.max_points) {
    VectorXd z_new = z + ds * t.z;
    double lambda_new = lambda + ds * t.lambda;
    std::size_t used = 0;
    if (!correct(lag, options, metric, residual_scale, z, lambda, t, w, ds, z_new, lambda_new, state, used)) {
      ds *= 0.5;
      if (ds < continuation.min_step)
        throw SolverError(method,
                          "continuation step fell below min_step at load factor " +
                              format_value(lambda),
                          state.iterations, state.residual);
      continue;
    }
    // Secant tangent, normalised.
    Tangent next;
    next.z = (z_new - z) / ds;
    next.lambda = (lambda_new - lambda) / ds;
    const double norm = std::sqrt(w * metric.dot(next.z, next.z) + next.lambda * next.lambda);
    next.z /= norm;
    next.lambda /= norm;
    const bool passed = direction * (lambda_new - continuation.final_load_factor) >= 0.0;
    if (passed) {
      // Land exactly on the final load factor from the linear interpolation of the last two points.
      const double fraction = (continuation.final_load_factor - lambda) / (lambda_new - lambda);
      z += fraction * (z_new - z);
      lambda = continuation.final_load_factor;
      lag.set_load_factor(lambda);
      detail::newton(lag, z, options, state);
      record(lambda);
      return branch;
    }
    z = std::move(z_new);
    lambda = lambda_new;
    t = std::move(next);
    lag.set_load_factor(lambda);
    record(lambda);
    if (used <= 3) ds = std::min(continuation.max_step, 1.5 * ds);
    if (used > 6) ds = std::max(continuation.min_step, 0.7 * ds);
  }
  throw SolverError(method,
                    "continuation reached max_points = " + std::to_string(continuation.max_points) +
                        " before the final load factor (now " + format_value(lambda) + ")",
                    state.iterations, state.residual);
}

}  // namespace rodvv::solvers::elastica2d

#include "rodvv/solvers/superhelix/statics.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"

#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace rodvv::solvers::superhelix {

VecX static_residual(const RodModel& model, const VecX& q, double load_factor) {
  const Kinematics kinematics(model, q);
  VecX r = generalised_stiffness(model).cwiseProduct(q - natural_strain_vector(model)) -
           external_generalised_force(model, kinematics, load_factor);
  // Self-contact is a constraint, not a load: never scaled by the load factor.
  if (model.self_contact.radius > 0.0)
    r -= self_contact_generalized_force(kinematics, self_contacts(kinematics, model.self_contact));
  return r;
}

MatX static_jacobian(const RodModel& model, const VecX& q, double load_factor) {
  const Kinematics kinematics(model, q);
  MatX J = load_stiffness(model, kinematics, load_factor);  // in place: one n x n buffer, not two
  J *= -1.0;
  J.diagonal() += generalised_stiffness(model);
  if (model.self_contact.radius > 0.0)
    J += self_contact_hessian(kinematics, model.self_contact, self_contacts(kinematics, model.self_contact));
  return J;
}

double static_potential(const RodModel& model, const VecX& q, double load_factor) {
  validate(model);
  if (!model.end_moment.isZero(0.0))
    throw InputError("end_moment", "invalid parameter 'end_moment': a dead end moment has no potential (Ziegler); "
                                   "must be 0 for the static potential");
  const Kinematics kinematics(model, q);
  double potential = elastic_energy(model, q) +
                     load_factor * (gravity_energy(model, kinematics) - model.end_force.dot(kinematics.tip_position()));
  if (model.self_contact.radius > 0.0)
    potential += self_contact_energy(model.self_contact, self_contacts(kinematics, model.self_contact));
  return potential;
}

namespace {

// The largest displacement of a Gauss point between two configurations.
double largest_point_motion(const Kinematics& from, const Kinematics& to) {
  double largest = 0.0;
  for (std::size_t g = 0; g < from.points().size(); ++g)
    largest = std::max(largest, (to.points()[g].position - from.points()[g].position).norm());
  return largest;
}

// Statics with self-contact: the equilibrium minimises the potential, so Newton is globalised on it
// (see the header).
StaticResult minimise_potential(const RodModel& model, const StaticOptions& options, const NewtonScales& scales) {
  require_at_least("load_steps", options.load_steps, 1);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  const VecX k = generalised_stiffness(model);
  StaticResult result;
  result.q = options.initial_q.size() == 0 ? natural_strain_vector(model) : options.initial_q;
  if (result.q.size() != k.size())
    throw InputError("initial_q", "invalid parameter 'initial_q': must be empty or hold " + std::to_string(k.size()) +
                                      " values (one per degree of freedom)");
  if (!result.q.allFinite()) throw InputError("initial_q", "invalid parameter 'initial_q': must be finite");
  (void)static_potential(model, result.q);  // refuses a dead end moment before any work
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  const double max_motion = 1.5 * model.self_contact.radius;  // per step: no strand passes through another (header)
  const char* method = "superhelix potential Newton";
  for (std::size_t step = 1; step <= options.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(options.load_steps);
    VecX residual = static_residual(model, result.q, lambda);
    double potential = static_potential(model, result.q, lambda);
    double shift = 0.0;  // Levenberg shift mu, in units of K
    bool converged = false;
    for (std::size_t iteration = 0; iteration < options.max_iterations && !converged; ++iteration) {
      const double scale =
          std::max({scales.stiffness_max * result.q.lpNorm<Eigen::Infinity>(), scales.stiffness_max / scales.length,
                    scales.load_scale});
      const double norm = residual.lpNorm<Eigen::Infinity>();
      check_time_budget(method, result.iterations, norm);
      if (norm <= options.tolerance * scale) {
        converged = true;
        break;
      }
      ++result.iterations;
      const MatX hessian = static_jacobian(model, result.q, lambda);
      // (H + mu K) d = -r with the smallest mu (0, then 1e-6, x 10) whose matrix is positive definite:
      // d is then a descent direction of the potential.
      VecX direction;
      for (double mu = shift;; mu = std::max(1e-6, 10.0 * mu)) {
        MatX shifted = hessian;
        shifted.diagonal() += mu * k;
        const Eigen::LLT<MatX> cholesky(shifted);
        if (cholesky.info() == Eigen::Success) {
          direction = -cholesky.solve(residual);
          shift = mu;
          break;
        }
        if (mu > 1e12) throw SolverError(method, "no positive definite shift of the Hessian", result.iterations, norm);
      }
      const Kinematics here(model, result.q);
      const double slope = residual.dot(direction);
      // A step that would move a point by more than the cap starts scaled down to it (not halved past it).
      const double full_motion = largest_point_motion(here, Kinematics(model, result.q + direction));
      const bool capped = full_motion > max_motion;
      double alpha = capped ? 0.99 * max_motion / full_motion : 1.0;
      bool accepted = false;
      VecX trial_q, trial_residual;
      for (int halving = 0; halving <= 40; ++halving, alpha *= 0.5) {
        trial_q = result.q + alpha * direction;
        const Kinematics there(model, trial_q);
        if (largest_point_motion(here, there) > max_motion) continue;
        const double trial_potential = static_potential(model, trial_q, lambda);
        trial_residual = static_residual(model, trial_q, lambda);
        // Armijo on the potential; near the solution its decrease drowns in rounding, so a step that
        // halves the residual is taken too.
        if (trial_potential <= potential + 1e-4 * alpha * slope ||
            trial_residual.lpNorm<Eigen::Infinity>() <= 0.5 * norm) {
          potential = trial_potential;
          accepted = true;
          break;
        }
      }
      const bool round_off_step = direction.lpNorm<Eigen::Infinity>() * scales.length <=
                                  64.0 * kEps * (1.0 + result.q.lpNorm<Eigen::Infinity>() * scales.length);
      if (!accepted) {
        if (round_off_step || norm <= 1e3 * options.tolerance * scale) {
          converged = true;  // already at the round-off floor of the residual
          break;
        }
        throw SolverError(method, "line search failed at load factor " + format_value(lambda), result.iterations,
                          norm);
      }
      result.q = trial_q;
      residual = trial_residual;
      if (alpha == 1.0) shift = shift > 1e-6 ? 0.1 * shift : 0.0;  // a full step: trust the Hessian more
      if (round_off_step) converged = true;
    }
    result.residual = residual.lpNorm<Eigen::Infinity>();
    const double scale = std::max({scales.stiffness_max * result.q.lpNorm<Eigen::Infinity>(),
                                   scales.stiffness_max / scales.length, scales.load_scale});
    if (!converged && result.residual > options.tolerance * scale)
      throw SolverError(method, "no convergence at load factor " + format_value(lambda), result.iterations,
                        result.residual);
  }
  return result;
}

}  // namespace

StaticResult solve_static(const RodModel& model, const StaticOptions& options) {
  validate(model);
  const VecX q0 = natural_strain_vector(model);
  NewtonScales scales;
  scales.stiffness_max = generalised_stiffness(model).lpNorm<Eigen::Infinity>();
  scales.length = model.length;
  scales.load_scale = external_generalised_force(model, Kinematics(model, q0), 1.0).lpNorm<Eigen::Infinity>();
  if (model.self_contact.radius > 0.0) return minimise_potential(model, options, scales);
  const StaticResidual residual = [&model](const VecX& x, double lambda) {
    return static_residual(model, x, lambda);
  };
  const StaticJacobian jacobian = [&model](const VecX& x, double lambda) { return static_jacobian(model, x, lambda); };
  return newton_load_stepping(residual, q0, scales, options, "superhelix Newton", jacobian);
}

}  // namespace rodvv::solvers::superhelix

#include "rodvv/solvers/superhelix/statics.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"

#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/tip_guide.hpp"

namespace rodvv::solvers::superhelix {

namespace {

bool has_barrier(const RodModel& model) { return model.self_contact.radius > 0.0 && !is_hard(model.self_contact); }

// A configuration with what every static quantity needs from it: its kinematics and, with a contact
// barrier, its contacts (found once, shared by the residual, the potential and the Jacobian).
struct Configuration {
  Configuration(const RodModel& model, Kinematics at)
      : kinematics(std::move(at)),
        contacts(has_barrier(model) ? self_contacts(kinematics, model.self_contact) : std::vector<ArcContact>{}) {}
  Configuration(const RodModel& model, const VecX& q) : Configuration(model, Kinematics(model, q)) {}
  Kinematics kinematics;
  std::vector<ArcContact> contacts;
};

VecX residual_of(const RodModel& model, const Configuration& at, double load_factor) {
  const VecX& q = at.kinematics.q();
  VecX r = generalised_stiffness(model).cwiseProduct(q - natural_strain_vector(model)) -
           external_generalised_force(model, at.kinematics, load_factor);
  // Self-contact is a constraint, not a load: never scaled by the load factor.
  if (has_barrier(model)) r -= self_contact_generalized_force(at.kinematics, at.contacts);
  // The sliding clamp is a support, not a load: never scaled either.
  if (has_tip_guide(model)) r += tip_guide_gradient(model.tip_guide, at.kinematics);
  return r;
}

MatX jacobian_of(const RodModel& model, const Configuration& at, double load_factor) {
  MatX J = load_stiffness(model, at.kinematics, load_factor);  // in place: one n x n buffer, not two
  J *= -1.0;
  J.diagonal() += generalised_stiffness(model);
  if (has_barrier(model)) J += self_contact_hessian(at.kinematics, model.self_contact, at.contacts);
  if (has_tip_guide(model)) J += tip_guide_hessian(model.tip_guide, at.kinematics);
  return J;
}

// The potential of a model validated to have one (no dead end moment).
double potential_of(const RodModel& model, const Configuration& at, double load_factor) {
  const Kinematics& kinematics = at.kinematics;
  double potential = elastic_energy(model, kinematics.q()) +
                     load_factor * (gravity_energy(model, kinematics) - model.end_force.dot(kinematics.tip_position()));
  if (has_barrier(model)) potential += self_contact_energy(model.self_contact, at.contacts);
  if (has_tip_guide(model)) potential += tip_guide_energy(model.tip_guide, kinematics);
  return potential;
}

void require_potential(const RodModel& model) {
  if (!model.end_moment.isZero(0.0))
    throw InputError("end_moment", "invalid parameter 'end_moment': a dead end moment has no potential (Ziegler); "
                                   "must be 0 for the static potential");
}

}  // namespace

VecX static_residual(const RodModel& model, const VecX& q, double load_factor) {
  return residual_of(model, Configuration(model, q), load_factor);
}

MatX static_jacobian(const RodModel& model, const VecX& q, double load_factor) {
  return jacobian_of(model, Configuration(model, q), load_factor);
}

double static_potential(const RodModel& model, const VecX& q, double load_factor) {
  validate(model);
  require_potential(model);
  return potential_of(model, Configuration(model, q), load_factor);
}

namespace {

// Statics with self-contact: the equilibrium minimises the potential, so Newton is globalised on it
// (see the header).
StaticResult minimise_potential(const RodModel& model, const StaticOptions& options, const NewtonScales& scales) {
  require_potential(model);
  const VecX k = generalised_stiffness(model);
  StaticResult result;
  result.q = newton_start(options, natural_strain_vector(model));
  const double max_motion = 1.5 * model.self_contact.radius;  // per step: no strand passes through another (header)
  const char* method = "superhelix potential Newton";
  for (std::size_t step = 1; step <= options.load_steps; ++step) {
    const double lambda = static_cast<double>(step) / static_cast<double>(options.load_steps);
    Configuration here(model, result.q);
    VecX residual = residual_of(model, here, lambda);
    double potential = potential_of(model, here, lambda);
    double shift = 0.0;  // Levenberg shift mu, in units of K
    bool converged = false;
    for (std::size_t iteration = 0; iteration < options.max_iterations && !converged; ++iteration) {
      const double scale = scales.residual_scale(result.q);
      const double norm = residual.lpNorm<Eigen::Infinity>();
      check_time_budget(method, result.iterations, norm);
      if (norm <= options.tolerance * scale) {
        converged = true;
        break;
      }
      ++result.iterations;
      const MatX hessian = jacobian_of(model, here, lambda);
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
      const double slope = residual.dot(direction);
      // A step that would move a point by more than the cap starts scaled down to it (not halved past it).
      const double full_motion = largest_point_motion(here.kinematics, Kinematics(model, result.q + direction));
      const bool capped = full_motion > max_motion;
      double alpha = capped ? 0.99 * max_motion / full_motion : 1.0;
      std::optional<Configuration> there;
      VecX trial_residual;
      for (int halving = 0; halving <= 40; ++halving, alpha *= 0.5) {
        Kinematics moved(model, result.q + alpha * direction);
        if (largest_point_motion(here.kinematics, moved) > max_motion) continue;
        Configuration trial(model, std::move(moved));
        const double trial_potential = potential_of(model, trial, lambda);
        trial_residual = residual_of(model, trial, lambda);
        // Armijo on the potential; near the solution its decrease drowns in rounding, so a step that
        // halves the residual is taken too.
        if (trial_potential <= potential + 1e-4 * alpha * slope ||
            trial_residual.lpNorm<Eigen::Infinity>() <= 0.5 * norm) {
          potential = trial_potential;
          there.emplace(std::move(trial));
          break;
        }
      }
      const bool round_off_step = scales.round_off_step(direction, result.q);
      if (!there) {
        require_residual_floor(round_off_step, norm, options.tolerance, scale, lambda, method, result.iterations);
        converged = true;
        break;
      }
      result.q = there->kinematics.q();
      residual = trial_residual;
      here = std::move(*there);
      if (alpha == 1.0) shift = shift > 1e-6 ? 0.1 * shift : 0.0;  // a full step: trust the Hessian more
      if (round_off_step) converged = true;
    }
    result.residual = residual.lpNorm<Eigen::Infinity>();
    if (!converged && result.residual > options.tolerance * scales.residual_scale(result.q))
      throw SolverError(method, "no convergence at load factor " + format_value(lambda), result.iterations,
                        result.residual);
  }
  return result;
}

}  // namespace

NewtonScales static_newton_scales(const RodModel& model) {
  NewtonScales scales;
  scales.stiffness_max = generalised_stiffness(model).lpNorm<Eigen::Infinity>();
  scales.length = model.length;
  scales.load_scale = external_generalised_force(model, Kinematics(model, natural_strain_vector(model)), 1.0)
                          .lpNorm<Eigen::Infinity>();
  return scales;
}

StaticResult solve_static(const RodModel& model, const StaticOptions& options) {
  validate(model);
  const VecX q0 = natural_strain_vector(model);
  const NewtonScales scales = static_newton_scales(model);
  if (is_hard(model.self_contact))
    throw InputError("self_contact.law", "invalid parameter 'self_contact.law': hard self-contact has its forces as "
                                         "unknowns; solve it with solve_static_with_hard_contact "
                                         "(hard_self_contact.hpp)");
  if (model.self_contact.radius > 0.0) return minimise_potential(model, options, scales);
  const StaticResidual residual = [&model](const VecX& x, double lambda) {
    return static_residual(model, x, lambda);
  };
  const StaticJacobian jacobian = [&model](const VecX& x, double lambda) { return static_jacobian(model, x, lambda); };
  return newton_load_stepping(residual, q0, scales, options, "superhelix Newton", jacobian);
}

}  // namespace rodvv::solvers::superhelix

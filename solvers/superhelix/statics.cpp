#include "rodvv/solvers/superhelix/statics.hpp"

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

StaticResult solve_static(const RodModel& model, const StaticOptions& options) {
  validate(model);
  const VecX q0 = natural_strain_vector(model);
  NewtonScales scales;
  scales.stiffness_max = generalised_stiffness(model).lpNorm<Eigen::Infinity>();
  scales.length = model.length;
  scales.load_scale = external_generalised_force(model, Kinematics(model, q0), 1.0).lpNorm<Eigen::Infinity>();
  const StaticResidual residual = [&model](const VecX& x, double lambda) {
    return static_residual(model, x, lambda);
  };
  const StaticJacobian jacobian = [&model](const VecX& x, double lambda) { return static_jacobian(model, x, lambda); };
  return newton_load_stepping(residual, q0, scales, options, "superhelix Newton", jacobian);
}

}  // namespace rodvv::solvers::superhelix

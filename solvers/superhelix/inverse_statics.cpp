#include "rodvv/solvers/superhelix/inverse_statics.hpp"

#include <algorithm>
#include <string>

#include <Eigen/Eigenvalues>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

namespace {
constexpr double kSymmetryTolerance = 1e-7;  // as stability.hpp

// q0 = q - K^-1 F, with F given (the one formula of both entry points).
// The inverse problem here is posed for the loads of loads.hpp; self-contact forces enter it as
// unknowns (inverse_contact.hpp), not as a barrier.
void validate_inverse(const RodModel& model) {
  validate(model);
  if (model.self_contact.radius != 0.0)
    throw InputError("self_contact", "invalid parameter 'self_contact': inverse statics does not take the barrier "
                                     "self-contact (contact forces are unknowns of inverse_contact); its radius must be 0");
  if (model.tip_guide.stiffness != 0.0)
    throw InputError("tip_guide", "invalid parameter 'tip_guide': inverse statics is posed for a free tip under the "
                                  "loads of loads.hpp; its stiffness must be 0");
}

VecX rest_strain(const RodModel& model, const VecX& q, const VecX& force) {
  return q - force.cwiseQuotient(generalised_stiffness(model));
}
}  // namespace

// validate(model), then Kinematics checks q (InputError "q": size 3N, finite).
VecX natural_strain_for(const RodModel& model, const VecX& q) {
  validate_inverse(model);
  const Kinematics kinematics(model, q);
  return rest_strain(model, q, external_generalised_force(model, kinematics));
}

InverseStatics inverse_statics(const RodModel& model, const VecX& q) {
  validate_inverse(model);
  const Kinematics kinematics(model, q);
  const VecX k = generalised_stiffness(model);
  const VecX force = external_generalised_force(model, kinematics);
  InverseStatics result;
  result.natural_strain = rest_strain(model, q, force);
  const VecX elastic = k.cwiseProduct(q - result.natural_strain);
  const double scale = std::max({(k.cwiseProduct(q)).lpNorm<Eigen::Infinity>(), force.lpNorm<Eigen::Infinity>(),
                                 k.maxCoeff() / model.length});
  result.residual = (elastic - force).lpNorm<Eigen::Infinity>() / scale;

  const MatX D = load_stiffness(model, kinematics);
  const double largest = D.cwiseAbs().maxCoeff();
  const double asymmetry = largest > 0.0 ? (D - D.transpose()).cwiseAbs().maxCoeff() / largest : 0.0;
  if (!(asymmetry <= kSymmetryTolerance))
    throw InputError("end_moment", "invalid parameter 'end_moment': the load stiffness is not symmetric (relative "
                                   "asymmetry " + format_value(asymmetry) + " > " + format_value(kSymmetryTolerance) +
                                       ", a dead end moment): no stability criterion; natural_strain_for gives q0");
  const VecX w = k.cwiseSqrt().cwiseInverse();
  const MatX scaled = w.asDiagonal() * (0.5 * (D + D.transpose())) * w.asDiagonal();
  Eigen::SelfAdjointEigenSolver<MatX> solver(scaled, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("superhelix inverse statics (dense symmetric eigensolver)", "eigenvalue iteration did not converge",
                      0, 0.0);
  const double lambda_max = solver.eigenvalues()[solver.eigenvalues().size() - 1];
  result.critical_stiffness_factor = std::max(lambda_max, 0.0);
  result.stability_eigenvalue = 1.0 - lambda_max;
  return result;
}

RodModel model_at_rest_in(const RodModel& model, const VecX& q, double stiffness_factor) {
  require_positive("stiffness_factor", stiffness_factor);
  RodModel scaled = model;
  scaled.stiffness *= stiffness_factor;
  const VecX q0 = natural_strain_for(scaled, q);
  set_natural_strain_vector(scaled, q0);
  return scaled;
}

RodModel stable_rest_model(const RodModel& model, const VecX& q, double margin) {
  require_open_interval("margin", margin, 0.0, 10.0);
  const double factor = std::max(1.0, (1.0 + margin) * inverse_statics(model, q).critical_stiffness_factor);
  return model_at_rest_in(model, q, factor);
}

}  // namespace rodvv::solvers::superhelix

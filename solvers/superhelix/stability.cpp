#include "rodvv/solvers/superhelix/stability.hpp"

#include <algorithm>
#include <string>

#include <Eigen/Eigenvalues>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::solvers::superhelix {

double stability_eigenvalue(const RodModel& model, const VecX& q, const StabilityOptions& options) {
  validate(model);
  if (q.size() != Eigen::Index(dof_count(model)))
    throw InputError("q", "invalid parameter 'q': must hold " + std::to_string(dof_count(model)) + " values");
  if (!q.allFinite()) throw InputError("q", "invalid parameter 'q': must be finite");
  const VecX k = generalised_stiffness(model);
  const VecX elastic = k.cwiseProduct(q - natural_strain_vector(model));
  const VecX r = static_residual(model, q, 1.0);
  // The residual a computed equilibrium can have: q0 = q - K^-1 F rounds to eps |q|, so K (q - q0)
  // carries eps |K q| even where F is far smaller (a stiff rod; inverse_statics.hpp).
  const double scale = std::max({elastic.cwiseAbs().maxCoeff(), (elastic - r).cwiseAbs().maxCoeff(),
                                 k.cwiseProduct(q).cwiseAbs().maxCoeff()});
  if (!(r.cwiseAbs().maxCoeff() <= options.equilibrium_tolerance * scale))
    throw InputError("q", "invalid parameter 'q': not an equilibrium (scaled residual " +
                              format_value(r.cwiseAbs().maxCoeff() / scale) + " > " +
                              format_value(options.equilibrium_tolerance) + ")");
  const MatX j = static_jacobian(model, q, 1.0);
  const double largest = j.cwiseAbs().maxCoeff();
  const double asymmetry = largest > 0.0 ? (j - j.transpose()).cwiseAbs().maxCoeff() / largest : 0.0;
  if (!(asymmetry <= options.symmetry_tolerance))
    throw InputError("end_moment", "invalid parameter 'end_moment': the static Jacobian is not symmetric (relative "
                                   "asymmetry " + format_value(asymmetry) + " > " +
                                       format_value(options.symmetry_tolerance) +
                                       ", the load stiffness of a dead end moment): no stability eigenvalue");
  const VecX w = k.cwiseSqrt().cwiseInverse();
  const MatX a = w.asDiagonal() * (0.5 * (j + j.transpose())) * w.asDiagonal();
  Eigen::SelfAdjointEigenSolver<MatX> solver(a, Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("superhelix stability (dense symmetric eigensolver)", "eigenvalue iteration did not converge", 0, 0.0);
  return solver.eigenvalues()[0];
}

}  // namespace rodvv::solvers::superhelix

#include "rodvv/solvers/superhelix/inverse_contact.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "contact_checks.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "sweep_order.hpp"

namespace rodvv::solvers::superhelix {

Mat3 contact_frame(const Vec3& normal) {
  Eigen::Index axis = 0;
  normal.cwiseAbs().minCoeff(&axis);
  const Vec3 t1 = (Vec3::Unit(axis) - normal[axis] * normal).normalized();
  Mat3 frame;
  frame << normal, t1, normal.cross(t1);
  return frame;
}

namespace {
void check_contacts(const RodModel& model, const std::vector<RodContact>& contacts) {
  const std::size_t points = model.elements * model.gauss_points;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const RodContact& c = contacts[k];
    if (c.point >= points)
      throw InputError("contacts", "invalid parameter 'contacts': contact " + std::to_string(k) + " names Gauss point " +
                                       std::to_string(c.point) + ", must be below " + std::to_string(points));
    detail::check_contact_normal_and_mu(k, c.normal, c.mu);
  }
}
}  // namespace

InverseContactResult inverse_statics_with_contacts(const RodModel& model, const VecX& q,
                                                   const std::vector<RodContact>& contacts,
                                                   const InverseContactOptions& options) {
  validate(model);
  check_contacts(model, contacts);
  require_positive("gamma", options.gamma);
  const Kinematics kinematics(model, q);  // checks q (InputError "q": 3N finite values)
  const VecX preferred = options.preferred_rest.size() == 0 ? q : options.preferred_rest;
  if (preferred.size() != q.size() || !preferred.allFinite())
    throw InputError("preferred_rest", "invalid parameter 'preferred_rest': must be empty or hold 3 N = " +
                                           std::to_string(q.size()) + " finite values");

  const VecX k = generalised_stiffness(model);
  const VecX force = external_generalised_force(model, kinematics);
  const auto m = Eigen::Index(contacts.size());
  InverseContactResult result;
  for (const RodContact& contact : contacts) result.frames.push_back(contact_frame(contact.normal));
  // The Gauss-Seidel's order (sweep_order.hpp): H, W, b, mu and r are in it.
  std::vector<std::size_t> distal_point;
  for (const RodContact& contact : contacts) distal_point.push_back(contact.point);
  const std::vector<std::size_t> order = detail::free_end_first_order(distal_point);
  MatX H(3 * m, q.size());
  VecX mu(m);
  for (Eigen::Index c = 0; c < m; ++c) {
    const RodContact& contact = contacts[order[std::size_t(c)]];
    const GaussPoint& point = kinematics.points()[contact.point];
    H.middleRows(3 * c, 3) =
        result.frames[order[std::size_t(c)]].transpose() * kinematics.position_jacobian(point.element, point.sigma);
    mu[c] = contact.mu;
  }
  const MatX HKinv = H * k.cwiseInverse().asDiagonal();
  MatX W = HKinv * HKinv.transpose();
  const double gamma = options.gamma * (m > 0 ? W.trace() / double(3 * m) : 1.0);
  W.diagonal().array() += 2.0 * gamma;
  W = 0.5 * (W + W.transpose());
  const VecX z = q - force.cwiseQuotient(k) - preferred;
  const VecX b = -HKinv * z;
  const contact::ConeSolution socqp =
      contact::solve_cone_complementarity(W, b, mu, contact::ConeLaw::SecondOrderCone, options.solver);
  result.local_forces.resize(3 * m);
  for (Eigen::Index c = 0; c < m; ++c)
    result.local_forces.segment<3>(3 * Eigen::Index(order[std::size_t(c)])) = socqp.r.segment<3>(3 * c);
  result.sweeps = socqp.sweeps;
  result.residual = socqp.residual;
  result.cone_violation = socqp.cone_violation;
  for (Eigen::Index c = 0; c < m; ++c)
    result.forces.push_back(result.frames[std::size_t(c)] * result.local_forces.segment<3>(3 * c));
  result.natural_strain = q - (force + H.transpose() * socqp.r).cwiseQuotient(k);
  return result;
}

RodModel contact_model(const RodModel& model, const std::vector<RodContact>& contacts,
                       const InverseContactResult& result) {
  RodModel at_rest = model;
  set_natural_strain_vector(at_rest, result.natural_strain);
  at_rest.point_forces.assign(model.elements * model.gauss_points, Vec3::Zero());
  for (std::size_t c = 0; c < contacts.size(); ++c) at_rest.point_forces[contacts[c].point] += result.forces[c];
  return at_rest;
}

}  // namespace rodvv::solvers::superhelix

#include "rodvv/solvers/superhelix/inverse_bundle.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "contact_checks.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/factored_delassus.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "sweep_order.hpp"

namespace rodvv::solvers::superhelix {

namespace {

void check_contacts(const std::vector<RodModel>& strands, const std::vector<BundleContact>& contacts) {
  const auto check_point = [&](std::size_t k, std::size_t strand, std::size_t point) {
    const std::string which = "invalid parameter 'contacts': contact " + std::to_string(k);
    if (strand >= strands.size())
      throw InputError("contacts", which + " names strand " + std::to_string(strand) + ", must be below " +
                                       std::to_string(strands.size()));
    const std::size_t points = strands[strand].elements * strands[strand].gauss_points;
    if (point >= points)
      throw InputError("contacts", which + " names Gauss point " + std::to_string(point) + " of strand " +
                                       std::to_string(strand) + ", must be below " + std::to_string(points));
  };
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const BundleContact& c = contacts[k];
    check_point(k, c.strand, c.point);
    if (c.other_strand != kObstacle) {
      check_point(k, c.other_strand, c.other_point);
      if (c.other_strand == c.strand && c.other_point == c.point)
        throw InputError("contacts", "invalid parameter 'contacts': contact " + std::to_string(k) +
                                         " joins Gauss point " + std::to_string(c.point) + " of strand " +
                                         std::to_string(c.strand) + " to itself");
    }
    detail::check_contact_normal_and_mu(k, c.normal, c.mu);
  }
}

// frame^T dx_g/dq over the strand's first 3 (e + 1) coordinates, e the point's element: a point moves
// with the elements up to its own only (factored_delassus.hpp keeps the leading columns).
using ContactRows = Eigen::Matrix<double, 3, Eigen::Dynamic>;
ContactRows contact_rows(const Mat3& frame, const Kinematics& kinematics, std::size_t point) {
  const GaussPoint& g = kinematics.points()[point];
  return frame.transpose() * kinematics.position_jacobian(g.element, g.sigma).leftCols(Eigen::Index(3 * (g.element + 1)));
}

// A contact between two rods presses them apart along the line between its points: its normal must be
// the direction from the other point to this one (to 1e-6, an angle a normal computed from the two
// points in single precision meets). Obstacle contacts carry the obstacle's normal, which the bundle
// does not know.
void check_normals(const std::vector<Kinematics>& kinematics, const std::vector<BundleContact>& contacts) {
  constexpr double kNormalTolerance = 1e-6;
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const BundleContact& c = contacts[k];
    if (c.other_strand == kObstacle) continue;
    const Vec3 apart = kinematics[c.strand].points()[c.point].position -
                       kinematics[c.other_strand].points()[c.other_point].position;
    const std::string which = "invalid parameter 'contacts': contact " + std::to_string(k);
    if (!(apart.norm() > 0.0))
      throw InputError("contacts", which + " joins two points at the same place: its normal is undefined");
    if (!((c.normal - apart.normalized()).norm() <= kNormalTolerance))
      throw InputError("contacts", which + "'s normal is inconsistent with its points: it must point from Gauss point " +
                                       std::to_string(c.other_point) + " of strand " + std::to_string(c.other_strand) +
                                       " to Gauss point " + std::to_string(c.point) + " of strand " +
                                       std::to_string(c.strand) + " (within 1e-6), is " +
                                       format_value((c.normal - apart.normalized()).norm()) + " off");
  }
}

}  // namespace

InverseBundleResult inverse_statics_of_bundle(const std::vector<RodModel>& strands, const std::vector<VecX>& q,
                                              const std::vector<BundleContact>& contacts,
                                              const InverseBundleOptions& options) {
  if (q.size() != strands.size())
    throw InputError("q", "invalid parameter 'q': must hold one target per strand (" + std::to_string(strands.size()) +
                              "), got " + std::to_string(q.size()));
  for (const RodModel& model : strands) validate(model);
  check_contacts(strands, contacts);
  require_positive("gamma", options.gamma);

  // Per strand: its kinematics at the target (checks q), K^-1, the weight K^-2 of the factored W and
  // K^-2 F, which b takes from every contact on the strand.
  std::vector<Kinematics> kinematics;
  std::vector<VecX> compliance, force, weighted_force;
  contact::FactoredDelassus W;
  for (std::size_t s = 0; s < strands.size(); ++s) {
    kinematics.emplace_back(strands[s], q[s]);
    compliance.push_back(generalised_stiffness(strands[s]).cwiseInverse());
    force.push_back(external_generalised_force(strands[s], kinematics[s]));
    W.body_weights.push_back(compliance[s].cwiseAbs2());
    weighted_force.push_back(W.body_weights[s].cwiseProduct(force[s]));
  }
  check_normals(kinematics, contacts);
  const auto m = Eigen::Index(contacts.size());
  InverseBundleResult result;
  for (const BundleContact& c : contacts) result.frames.push_back(contact_frame(c.normal));
  // The Gauss-Seidel's order (sweep_order.hpp): W, b, mu and r are in it.
  std::vector<std::size_t> distal_point;
  for (const BundleContact& c : contacts)
    distal_point.push_back(c.other_strand == kObstacle ? c.point : std::max(c.point, c.other_point));
  const std::vector<std::size_t> order = detail::free_end_first_order(distal_point);
  VecX mu(m), b = VecX::Zero(3 * m);
  double trace = 0.0;
  for (Eigen::Index k = 0; k < m; ++k) {
    const BundleContact& c = contacts[order[std::size_t(k)]];
    const Mat3& frame = result.frames[order[std::size_t(k)]];
    mu[k] = c.mu;
    std::vector<contact::ContactSide> sides{{c.strand, contact_rows(frame, kinematics[c.strand], c.point)}};
    if (c.other_strand == c.strand) {  // a self-contact: one side, frame^T (J_a - J_b)
      const ContactRows other = contact_rows(frame, kinematics[c.strand], c.other_point);
      ContactRows merged = ContactRows::Zero(3, std::max(sides[0].rows.cols(), other.cols()));
      merged.leftCols(sides[0].rows.cols()) = sides[0].rows;
      merged.leftCols(other.cols()) -= other;
      sides[0].rows = std::move(merged);
    } else if (c.other_strand != kObstacle) {
      sides.push_back({c.other_strand, -contact_rows(frame, kinematics[c.other_strand], c.other_point)});
    }
    // b = sum_s H_s K_s^-2 F_s (the header's z_s = -K_s^-1 F_s with q0bar = q).
    for (const contact::ContactSide& side : sides)
      b.segment<3>(3 * k) += side.rows * weighted_force[side.body].head(side.rows.cols());
    W.sides.push_back(std::move(sides));
    trace += contact::diagonal_block(W, std::size_t(k)).trace();
  }
  const double gamma = options.gamma * (m > 0 ? trace / double(3 * m) : 1.0);
  W.compliance = VecX::Constant(m, 2.0 * gamma);
  const contact::ConeSolution socqp =
      contact::solve_cone_complementarity(W, b, mu, contact::ConeLaw::SecondOrderCone, options.solver);
  result.local_forces.resize(3 * m);
  for (Eigen::Index k = 0; k < m; ++k)
    result.local_forces.segment<3>(3 * Eigen::Index(order[std::size_t(k)])) = socqp.r.segment<3>(3 * k);
  result.sweeps = socqp.sweeps;
  result.residual = socqp.residual;
  result.cone_violation = socqp.cone_violation;

  // q0_s = q_s - K_s^-1 (F_s + H_s^T r).
  std::vector<VecX> load = force;
  for (Eigen::Index k = 0; k < m; ++k)
    for (const contact::ContactSide& side : W.sides[std::size_t(k)])
      load[side.body].head(side.rows.cols()).noalias() += side.rows.transpose() * socqp.r.segment<3>(3 * k);
  for (std::size_t s = 0; s < strands.size(); ++s)
    result.natural_strain.push_back(q[s] - compliance[s].cwiseProduct(load[s]));
  return result;
}

std::vector<RodModel> bundle_rest_models(const std::vector<RodModel>& strands,
                                         const std::vector<BundleContact>& contacts,
                                         const InverseBundleResult& result) {
  if (result.natural_strain.size() != strands.size() || result.frames.size() != contacts.size() ||
      result.local_forces.size() != Eigen::Index(3 * contacts.size()))
    throw InputError("result", "invalid parameter 'result': must be the inverse statics of these strands and contacts");
  check_contacts(strands, contacts);
  std::vector<RodModel> rest = strands;
  for (std::size_t s = 0; s < strands.size(); ++s) {
    RodModel& model = rest[s];
    if (result.natural_strain[s].size() != Eigen::Index(dof_count(model)))
      throw InputError("result", "invalid parameter 'result': the rest shape of strand " + std::to_string(s) +
                                     " must hold " + std::to_string(dof_count(model)) + " values");
    set_natural_strain_vector(model, result.natural_strain[s]);
    model.point_forces.assign(model.elements * model.gauss_points, Vec3::Zero());
  }
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    const BundleContact& c = contacts[k];
    const Vec3 force = result.frames[k] * result.local_forces.segment<3>(Eigen::Index(3 * k));
    rest[c.strand].point_forces[c.point] += force;
    if (c.other_strand != kObstacle) rest[c.other_strand].point_forces[c.other_point] -= force;
  }
  return rest;
}

}  // namespace rodvv::solvers::superhelix

#include "rodvv/solvers/superhelix/solution.hpp"

#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/tip_guide.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// hard_contacts: the hard law's contacts with their multipliers (nullptr: the barrier's, found here).
SpatialRodSolution solution_of(const RodModel& model, const VecX& q, const std::vector<ArcContact>* hard_contacts,
                               std::string method) {
  validate(model);
  const Kinematics kinematics(model, q);
  const std::size_t n = model.elements;
  const double ell = element_length(model);
  // Self-contact: its point forces (each contact's force at the point and its reaction at the foot,
  // at arclengths along the rod) enter n(s) = sum of the forces beyond s; V_eff(s) enters V.
  struct PointForce {
    double s;
    Vec3 force;
  };
  std::vector<PointForce> contact_forces;
  // Dead forces at the Gauss points (the contact forces of inverse and frictional statics) likewise.
  for (std::size_t g = 0; g < model.point_forces.size(); ++g) {
    const auto& point = kinematics.points()[g];
    contact_forces.push_back({static_cast<double>(point.element) * ell + point.sigma, model.point_forces[g]});
  }
  const bool barrier = model.self_contact.radius > 0.0 && !hard_contacts;
  const std::vector<ArcContact> found =
      barrier ? self_contacts(kinematics, model.self_contact) : std::vector<ArcContact>{};
  for (const auto& pair : hard_contacts ? *hard_contacts : found) {
    contact_forces.push_back({static_cast<double>(pair.first) * ell + pair.s, pair.force * pair.normal});
    contact_forces.push_back({static_cast<double>(pair.second) * ell + pair.t, -pair.force * pair.normal});
  }
  SpatialRodSolution solution;
  solution.method = std::move(method);
  solution.length = model.length;
  for (std::size_t e = 0; e < n; ++e) {
    const double s = (static_cast<double>(e) + 0.5) * ell;
    const Vec3 u = q.segment<3>(3 * e), u_hat = natural_strain(model, e);
    const Mat3 R = kinematics.frame(e, 0.5 * ell);
    const Vec3 r = kinematics.position(e, 0.5 * ell);
    append_station(solution, model, s, r, R, u, u_hat);
    for (const auto& f : contact_forces)  // a force at the station itself counts half
      solution.force_n.back() += (f.s > s ? 1.0 : f.s == s ? 0.5 : 0.0) * f.force;
    if (barrier) solution.potential.back() += contact_field(kinematics, model.self_contact, e, 0.5 * ell);
  }
  // A sliding clamp's reaction at the tip is carried by every section, as the end force is.
  if (has_tip_guide(model)) {
    const Vec3 reaction = tip_guide_reaction(model.tip_guide, kinematics).force;
    for (auto& force : solution.force_n) force += reaction;
  }
  append_vertices(solution, kinematics, n, ell);
  return solution;
}

}  // namespace

SpatialRodSolution make_solution(const RodModel& model, const VecX& q, std::string method) {
  if (is_hard(model.self_contact))
    throw InputError("self_contact.law", "invalid parameter 'self_contact.law': with hard self-contact the contact "
                                         "forces are the statics' multipliers; pass them to make_solution");
  return solution_of(model, q, nullptr, std::move(method));
}

SpatialRodSolution make_solution(const RodModel& model, const VecX& q, const std::vector<ArcContact>& contacts,
                                 std::string method) {
  if (!is_hard(model.self_contact))
    throw InputError("self_contact.law", "invalid parameter 'self_contact.law': contact forces are given only with "
                                         "hard self-contact (the barrier's follow from q)");
  const std::size_t n = model.elements;
  for (const auto& c : contacts)
    if (!(c.first < n && c.second < n && c.force >= 0.0 && std::isfinite(c.force) && c.normal.allFinite()))
      throw InputError("contacts", "invalid parameter 'contacts': each needs elements below " + std::to_string(n) +
                                       ", a finite force >= 0 and a finite normal");
  return solution_of(model, q, &contacts, std::move(method));
}

void append_station(SpatialRodSolution& solution, const RodModel& model, double s, const Vec3& r, const Mat3& R,
                    const Vec3& u, const Vec3& u_hat) {
  solution.s.push_back(s);
  solution.position.push_back(r);
  solution.frame.push_back(R);
  solution.strain_u.push_back(u);
  solution.strain_v.push_back(Vec3::UnitX());
  solution.stiffness.push_back(model.stiffness);
  solution.natural_strain.push_back(u_hat);
  solution.moment_m.push_back(R * model.stiffness.cwiseProduct(u - u_hat));
  solution.force_n.push_back(model.end_force + model.line_density * (model.length - s) * model.gravity);
  solution.potential.push_back(-model.line_density * model.gravity.dot(r));
  solution.shear_energy.push_back(0.0);
}

}  // namespace rodvv::solvers::superhelix

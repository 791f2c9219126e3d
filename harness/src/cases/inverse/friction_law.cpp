#include "friction_law.hpp"

#include <algorithm>
#include <cmath>

#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"

namespace rodvv::harness::inverse_cases {

FrictionLaw friction_law(const std::vector<solvers::superhelix::FrictionalContact>& contacts, double mu) {
  FrictionLaw law;
  double largest_normal = 0.0;
  for (const auto& c : contacts) largest_normal = std::max(largest_normal, c.local_force[0]);
  for (const auto& c : contacts) {
    const double r_N = c.local_force[0], r_T = c.local_force.tail<2>().norm();
    law.cone_violation = std::max(law.cone_violation, std::max(0.0, r_T - mu * r_N) / largest_normal);
    if (!(r_N > 1e-9 * largest_normal)) continue;
    ++law.loaded;
    const double slip = c.slip.tail<2>().norm();
    if (!(r_T >= (1.0 - 1e-9) * mu * r_N) || !(slip > 0.0)) continue;
    ++law.sliding;
    law.slip_alignment =
        std::max(law.slip_alignment, 1.0 + c.local_force.tail<2>().dot(c.slip.tail<2>()) / (r_T * slip));
  }
  return law;
}

NoetherAlongContacts noether_along_contacts(const solvers::superhelix::RodModel& model,
                                            const solvers::superhelix::FrictionalStaticResult& state, double scale) {
  namespace sh = solvers::superhelix;
  sh::RodModel loaded = model;
  loaded.point_forces.assign(model.elements * model.gauss_points, Vec3::Zero());
  for (const auto& c : state.contacts) loaded.point_forces[c.point] += c.force;
  const SpatialRodSolution solution = sh::make_solution(loaded, state.q);
  const sh::Kinematics kinematics(model, state.q);
  const auto H = invariants::noether3d_flattened(solution);
  const double ell = sh::element_length(model);
  struct Jump {
    double s, tangential;  // where, and f.t there
  };
  std::vector<Jump> jumps;
  for (const auto& c : state.contacts) {
    const auto& point = kinematics.points()[c.point];
    jumps.push_back({double(point.element) * ell + point.sigma,
                     c.force.dot(kinematics.frame(point.element, point.sigma).col(0))});
  }
  NoetherAlongContacts out;
  double reference = 0.0;
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    double passed = 0.0;
    for (const auto& jump : jumps)
      passed += (jump.s < solution.s[i] ? 1.0 : jump.s == solution.s[i] ? 0.5 : 0.0) * jump.tangential;
    if (i == 0) reference = H[0] + passed;
    out.balance = std::max(out.balance, std::abs(H[i] + passed - reference) / scale);
    out.deviation = std::max(out.deviation, std::abs(H[i] - H[0]) / scale);
  }
  return out;
}

GateSpec contact_envelope_gate(const std::string& metric, double constant) {
  GateSpec gate = scaled_upper_bound_gate(
      metric, constant, 1.0, GateScope::AllLevels,
      "twice the first-order envelope of the errors measured at the default levels (the contact regions' ends move "
      "within elements as N changes, so the constant jumps and no order is fitted)");
  gate.measured = true;
  return gate;
}

}  // namespace rodvv::harness::inverse_cases

#include "friction_law.hpp"

#include <algorithm>

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

}  // namespace rodvv::harness::inverse_cases

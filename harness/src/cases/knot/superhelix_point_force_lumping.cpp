#include "superhelix_point_force_lumping.hpp"

#include <cmath>
#include <string>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"

namespace rodvv::harness::knot_cases {

std::vector<double> point_force_lumping_of_H(const SpatialRodSolution& solution, double element_length,
                                             const std::vector<ElementPointForce>& forces) {
  std::vector<double> delta_H(solution.s.size(), 0.0);
  for (const auto& f : forces) {
    if (f.element >= solution.s.size() || !(f.offset >= 0.0 && f.offset <= element_length))
      throw InputError("forces", "invalid parameter 'forces': each needs an element below " +
                                     std::to_string(solution.s.size()) + " and an offset in [0, element_length]");
    const std::size_t e = f.element;
    const double xi = f.offset / element_length - 0.5;  // from the element's midpoint, in elements
    const double phi = 0.5 * (0.5 - std::abs(xi)) * (0.5 - std::abs(xi));
    // The element's moment K (u_e - u0) minus the static moment at its midpoint, material components;
    // the strain error is K^-1 of it, and dH/du = K u turns that into u . of it.
    const Vec3 moment_excess = solution.frame[e].transpose() * f.tangent.cross(f.force) * (element_length * phi);
    delta_H[e] += solution.strain_u[e].dot(moment_excess);
  }
  return delta_H;
}

}  // namespace rodvv::harness::knot_cases

#include "incline.hpp"

#include <cmath>

#include <Eigen/Geometry>

namespace rodvv::harness::inverse_cases {

Incline incline(double alpha) {
  const Vec3 across(std::cos(0.7), std::sin(0.7), 0.0);
  const Vec3 downhill = -(std::cos(alpha) * across.cross(Vec3::UnitZ()) + std::sin(alpha) * Vec3::UnitZ());
  return {across, downhill, across.cross(downhill)};
}

solvers::superhelix::RodModel rod_across_incline(const Parameters& p, std::size_t elements, const Incline& incline) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI");
  solvers::superhelix::RodModel m;
  m.length = L;
  m.elements = elements;
  m.stiffness = Vec3(0.6 * EI, 1.4 * EI, EI);
  m.line_density = parameter_value(p, "rhoS");
  m.gravity = Vec3(0.0, 0.0, -parameter_value(p, "g"));
  m.gauss_points = 1;
  m.root_position = Vec3(0.3, -0.2, 0.1) * L;
  m.root_frame << incline.across, incline.downhill, incline.normal;
  return m;
}

}  // namespace rodvv::harness::inverse_cases

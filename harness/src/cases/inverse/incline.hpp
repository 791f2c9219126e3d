#pragma once
// An incline of angle alpha under gravity along -z, as the friction cases lay rods on it: `across`, a
// horizontal line of the plane (at azimuth 0.7 rad, off the coordinate axes), `downhill`, its fall line,
// and `normal`, out of the plane and upward; (across, downhill, normal) is right-handed.
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/harness/parameters.hpp"
#include "rodvv/solvers/superhelix/model.hpp"

namespace rodvv::harness::inverse_cases {

struct Incline {
  Vec3 across, downhill, normal;
};

Incline incline(double alpha);

// The Super-Helix both friction cases lay across the fall line: `elements` elements, clamped at
// (0.3, -0.2, 0.1) L with its tangent along `across`, bending in the plane about n2 = the normal (EI2 = EI,
// EI1 = 1.4 EI, GJ = 0.6 EI), one Gauss point per element (the contacts' points are the weight's
// quadrature points); L, EI, rhoS and g from the parameters.
solvers::superhelix::RodModel rod_across_incline(const Parameters& p, std::size_t elements, const Incline& incline);

}  // namespace rodvv::harness::inverse_cases

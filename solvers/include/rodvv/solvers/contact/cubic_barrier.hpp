#pragma once
// The smooth self-contact barrier shared by the rods (ALGORITHMS.md §4; PHYSICS.md §1.2, §5): two
// pieces of a tube of radius h whose centrelines come closer than the contact distance 2h store
//     phi(d) = (k/3) (2h - d)^3          (d < 2h; 0 beyond),
// C^2 in d, so Newton keeps its quadratic convergence through contact changes. The repulsive force
// is -phi'(d) = k (2h - d)^2 and a contact carrying the force f overlaps by sqrt(f / k): the hard
// (complementarity) contact is the limit k -> infinity.
#include <algorithm>

namespace rodvv::solvers::contact {

struct CubicBarrier {
  double radius = 0.0;     // h > 0: the tube's radius (contact distance 2h)
  // k > 0: force / length^2 per segment pair (nodal rod), force / length^3 per unit length (Super-Helix)
  double stiffness = 0.0;

  double overlap(double distance) const { return std::max(0.0, 2.0 * radius - distance); }
  // phi(d)
  double energy(double distance) const {
    const double o = overlap(distance);
    return stiffness / 3.0 * o * o * o;
  }
  // -phi'(d) = k (2h - d)^2 >= 0
  double force(double distance) const {
    const double o = overlap(distance);
    return stiffness * o * o;
  }
  // phi''(d) = 2 k (2h - d) >= 0
  double force_rate(double distance) const { return 2.0 * stiffness * overlap(distance); }
};

}  // namespace rodvv::solvers::contact

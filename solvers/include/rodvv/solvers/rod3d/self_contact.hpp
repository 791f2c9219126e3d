#pragma once
// Frictionless self-contact of the nodal rod (discrete elastic rod) through a smooth barrier
// (ALGORITHMS.md §4; PHYSICS.md §1.2, §5): the rod is a tube of radius h around its centreline
// polyline, and two of its segments touch when their distance d reaches 2h. Each pair of segments
// closer than 2h stores the energy
//     phi(d) = (k/3) (2h - d)^3          (d < 2h; 0 beyond),
// C^2 in the positions, so Newton keeps its quadratic convergence through contact changes; the
// repulsive force is -phi'(d) = k (2h - d)^2 along the line of closest points, and the overlap at a
// contact carrying the force f is sqrt(f/k): the hard (complementarity) limit is k -> infinity.
//
// Distance and its derivatives. d is the distance between the closest points of the two segments
// (solvers/contact/segment_proximity.hpp: closest_points), a function of their 12 endpoint
// coordinates. Within a fixed active set (each closest-point parameter interior or at 0 or 1) it is
// an explicit function (the parameters by the 2 x 2 normal equations, or one of them fixed and the
// other by its 1-D equation), differentiated twice by forward-mode jets (solvers/rod3d/taylor2.hpp):
// exact gradient and Hessian. Across active-set changes d is C^1 and phi C^2 in the positions.
//
// Which segments can touch: segments i and j with |i - j| <= m never count, m = max(1, ceil(pi h /
// ebar)): two segments of a tube of radius h whose centreline curvature radius stays >= h come within
// 2h of each other only through a fold of arclength >= pi h (a half turn of radius h), so closer
// neighbours along the rod are in contact only through the rod's own thickness.
//
// The broad phase is the sort-and-sweep of segment_proximity (O(N log N) for a rod).
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::rod3d {

struct SelfContact {
  double radius = 0.0;     // h > 0 (0: no self-contact)
  double stiffness = 0.0;  // k > 0, force / length^2
};

// m = max(1, ceil(pi h / ebar)) (see above).
std::size_t contact_excluded_neighbours(double radius, double edge_length);

// One pair of segments closer than 2h.
struct ContactPair {
  std::size_t first = 0, second = 0;  // segments (segment i joins vertices i and i + 1), first < second
  double s = 0.0, t = 0.0;            // closest-point parameters on them
  double distance = 0.0;              // d < 2h
  Vec3 normal = Vec3::Zero();         // unit, from the second segment's closest point to the first's
  double force = 0.0;                 // k (2h - d)^2 >= 0: pushes the first along +normal, the second along -normal
};

// The pairs in contact at the vertex positions x (an open polyline of N + 1 vertices, edges of rest
// length edge_length), sorted by (first, second). InputError: radius or stiffness not finite and > 0,
// edge_length not > 0.
std::vector<ContactPair> self_contacts(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length);

// phi(d) = (k/3) (2h - d)^3 for d < 2h, else 0: the barrier energy of one pair at distance d.
double contact_pair_energy(const SelfContact& contact, double distance);

// Sum of phi over the pairs in contact.
double self_contact_energy(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length);

// Gradient of the energy with respect to the vertex coordinates (entry i: d/dx_i; minus the contact
// force on vertex i), and, if hessian is given, the Hessian as triplets on the coordinate indices
// 3 i + c (duplicates summed by setFromTriplets).
void self_contact_derivatives(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length,
                              std::vector<Vec3>& gradient, std::vector<Eigen::Triplet<double>>* hessian);

}  // namespace rodvv::solvers::rod3d

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
//
// Hard contact (law = Hard): the constraint d >= 2h itself, with no barrier and no energy; the pair
// forces are unknowns of the statics (statics.hpp: complementarity solved inside Newton), reported in
// StaticResult::contacts. Here the hard law only changes what the geometry returns (pairs with force
// 0) and makes the energy and its derivatives vanish. Statics only: the dynamics refuses it.
#include <array>
#include <cstddef>
#include <vector>

#include <Eigen/SparseCore>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::rod3d {

enum class ContactLaw { Barrier, Hard };

struct SelfContact {
  double radius = 0.0;     // h > 0 (0: no self-contact)
  double stiffness = 0.0;  // barrier: k > 0, force / length^2; hard: 0
  ContactLaw law = ContactLaw::Barrier;
};

inline bool is_hard(const SelfContact& contact) { return contact.law == ContactLaw::Hard; }

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
// length edge_length), sorted by (first, second); hard law: the pairs closer than 2h, force 0 (the
// forces are the statics' unknowns). InputError: radius not finite and > 0, stiffness not finite and
// > 0 (barrier) or not 0 (hard), edge_length not > 0.
std::vector<ContactPair> self_contacts(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length);

// The pairs closer than `reach` (>= 2h): the candidates of the hard contact's linearised constraints.
// Force as in self_contacts (barrier law: its force, 0 beyond 2h).
std::vector<ContactPair> contact_candidates(const SelfContact& contact, const std::vector<Vec3>& x,
                                            double edge_length, double reach);

// The largest fraction alpha in (0, 1] of the vertex displacements u (one per vertex of x) that no two
// segments can pass through each other on the way. Along the straight path x + t alpha u (t in [0, 1])
// the distance of two segments a, b changes by at most t alpha w_ab, w_ab = max |u_a. - u_b.| over their
// four pairs of end points (a point of a segment is a convex combination of its ends). So a pair
// d >= 2h apart keeps at least h if alpha w_ab <= d - h, and a pair in contact (d < 2h, inside the
// barrier) keeps half its distance if alpha w_ab <= d / 2; alpha is the largest value that meets both
// for every pair. A rigid translation has w = 0 and is not shortened. The barrier, seen only at the
// ends of a step, cannot stop a segment that jumps through another within it: this does.
// InputError: as self_contacts, or u not one finite vector per vertex.
double pass_through_free_fraction(const SelfContact& contact, const std::vector<Vec3>& x, const std::vector<Vec3>& u,
                                  double edge_length);

// The pair's four vertices a0, a1, b0, b1 (segment i joins vertices i and i + 1), in the order of
// distance_gradient's blocks.
inline std::array<std::size_t, 4> pair_vertices(const ContactPair& pair) {
  return {pair.first, pair.first + 1, pair.second, pair.second + 1};
}

// d(distance)/d(a0, a1, b0, b1) of a pair at its closest points (the envelope theorem: the parameters'
// motion does not change d to first order): (n (1 - s), n s, -n (1 - t), -n t), n = pair.normal.
std::array<Vec3, 4> distance_gradient(const ContactPair& pair);

// -sum_c f_c d^2 d_c / dx^2 over the pairs (f_c = pair.force, held fixed): the stiffness of given pair
// forces as the pairs' geometry turns (the hard law's forces; with the barrier's forces it is the part
// of its Hessian at fixed force). Triplets on the coordinate indices 3 i + c, as below.
void contact_force_hessian(const std::vector<Vec3>& x, const std::vector<ContactPair>& pairs,
                           std::vector<Eigen::Triplet<double>>& hessian);

// phi(d) = (k/3) (2h - d)^3 for d < 2h, else 0: the barrier energy of one pair at distance d (0: hard law).
double contact_pair_energy(const SelfContact& contact, double distance);

// Sum of phi over the pairs in contact.
double self_contact_energy(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length);

// Gradient of the energy with respect to the vertex coordinates (entry i: d/dx_i; minus the contact
// force on vertex i), and, if hessian is given, the Hessian as triplets on the coordinate indices
// 3 i + c (duplicates summed by setFromTriplets).
void self_contact_derivatives(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length,
                              std::vector<Vec3>& gradient, std::vector<Eigen::Triplet<double>>* hessian);

}  // namespace rodvv::solvers::rod3d

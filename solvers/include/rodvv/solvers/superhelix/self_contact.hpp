#pragma once
// Frictionless self-contact of a Super-Helix (ALGORITHMS.md §4; PHYSICS.md §1.2, §5.1): the rod is a
// tube of radius h around its centreline, and two of its elements touch when their HELICAL ARCS (the
// closed-form centreline, not chords of it) come closer than 2h. Each pair of elements in contact
// stores the cubic barrier energy phi(d) of the nodal rod (contact/cubic_barrier.hpp) at the distance d
// of the arcs' closest points.
//
// Which elements can touch: elements P < Q with Q - P <= m never count, m = max(1, ceil(pi h / ell))
// (the nodal rod's rule, rod3d/self_contact.hpp: a fold that brings the tube onto itself has an
// arclength of at least pi h, and on a straight rod elements m + 1 apart are m ell >= pi h > 2h apart).
//
// Broad phase. Each element's arc is cut into c chords of arclength ell / c. A curve of curvature at
// most kappa lies within kappa a^2 / 8 of its chord of arclength a (the circle is the extreme case), and
// an element's centreline curvature is |(kappa1, kappa2)| (constant on it), so with
// delta = kappa_max (ell / c)^2 / 8 every pair of elements whose arcs come within 2h has chords within
// 2h + 2 delta: the sort-and-sweep of contact/segment_proximity.hpp on the chord polyline with that
// cutoff finds them all (c is chosen so that delta <= h / 10, at most 32 chords per element; beyond,
// the cutoff grows with delta and stays a superset).
//
// Narrow phase. For a candidate pair (P, Q) the squared distance f(s, t) = 1/2 |r_P(s) - r_Q(t)|^2 on
// [0, ell]^2 is minimised by projected Newton (exact gradient and Hessian from the element's tangent
// n0 and its derivative R (q x e0)), started at the closest chord points, with backtracking on f. One
// contact per element pair: an element is short against its radius of curvature where contact matters
// (the fold rule above), so two arcs have a single local minimum of distance near their chords' one.
//
// Generalised force. At a minimiser (s*, t*) the distance's gradient in q is n . (dr_P/dq(s*) -
// dr_Q/dq(t*)) (the envelope theorem: f is stationary in the free parameters, and a parameter at a
// bound stays there to first order), n the unit vector from r_Q(t*) to r_P(s*); the contact's
// generalised force is -phi'(d) times it. A test compares it with central differences of the energy.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

// SelfContact (radius h, barrier stiffness k) is declared in model.hpp.
// InputError naming "radius" or "stiffness" unless finite and > 0.
void validate(const SelfContact& contact);

// m = max(1, ceil(pi h / ell)): elements at most m apart never count.
std::size_t contact_excluded_elements(double radius, double element_length);

// The closest points of the arcs of elements `first` and `second`, from a start (s0, t0).
struct ArcClosestPoints {
  double s = 0.0, t = 0.0;  // offsets on the two elements, in [0, ell]
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();
  double distance = 0.0;
  int iterations = 0;
};
ArcClosestPoints closest_points_on_arcs(const Kinematics& kinematics, std::size_t first, std::size_t second,
                                        double s0, double t0);

// One pair of elements in contact (d < 2h).
struct ArcContact {
  std::size_t first = 0, second = 0;  // elements, first < second
  double s = 0.0, t = 0.0;            // closest-point offsets on them, in [0, ell]
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();  // the closest points
  double distance = 0.0;
  Vec3 normal = Vec3::Zero();  // unit, from q to p: the force on `first` is +force normal
  double force = 0.0;          // k (2h - d)^2
};

// The pairs of elements in contact, sorted by (first, second), by the broad phase above.
// SolverError when two arcs intersect (d = 0: no normal).
std::vector<ArcContact> self_contacts(const Kinematics& kinematics, const SelfContact& contact);
// The same from every pair of elements (O(N^2) pairs, each started from its best chord pair): the
// oracle of the broad phase's tests.
std::vector<ArcContact> self_contacts_all_pairs(const Kinematics& kinematics, const SelfContact& contact);

// Sum of the barrier energies of the pairs in contact.
double self_contact_energy(const SelfContact& contact, const std::vector<ArcContact>& contacts);
// The contact forces' generalised force Q = -dE/dq (size 3N): sum over pairs of
// force (dr_P/dq(s)^T n - dr_Q/dq(t)^T n).
VecX self_contact_generalized_force(const Kinematics& kinematics, const std::vector<ArcContact>& contacts);

// The energy's Hessian d2E/dq2 (3N square, symmetric) at fixed contact set: with d(q) the pair's
// distance at its minimiser z* = (s*, t*), J = dr_P/dq(s*) - dr_Q/dq(t*), phi' = -force:
//   d2E = phi'' J^T n n^T J + phi' [ J^T (I - n n^T) J / d + n . d2(Delta)/dq2 - D_qz D_zz^+ D_zq ],
// where n . d2(Delta)/dq2 is the dead-load stiffness of the unit forces +-n at the two points
// (load_stiffness.hpp: point_load_jacobian), D_zz = d2|Delta|/dz2 and D_qz = d2|Delta|/dq dz over the
// free parameters (a parameter at the end of its element stays there), by the implicit function
// theorem on d|Delta|/dz = 0. A singular D_zz (arcs parallel along a valley of minimisers) is
// pseudo-inverted. Tested against central differences of the generalised force.
MatX self_contact_hessian(const Kinematics& kinematics, const SelfContact& contact,
                          const std::vector<ArcContact>& contacts);

}  // namespace rodvv::solvers::superhelix

#pragma once
// Frictionless self-contact of a Super-Helix (ALGORITHMS.md §4; PHYSICS.md §1.2, §5.1): the rod is a
// tube of radius h around its centreline, and two stretches of it touch when their centrelines come
// closer than 2h. The distances are measured on the HELICAL ARCS (the closed-form centreline), not
// on chords of it.
//
// A line contact with a barrier per unit length. Contact between rods is distributed along them (a
// ply's strands touch along lines; a knot's crossings over patches of length ~h), so the barrier is a
// line integral: every point r(s) of the centreline that comes within 2h of another stretch stores
//     psi(d) = (k/3) (2h - d)^3   per unit length (k: force / length^3; contact/cubic_barrier.hpp),
// d the distance from r(s) to its foot on the other stretch (a local minimum of the distance to the
// whole curve), and the line force density there is k (2h - d)^2 along the unit normal. Both sides
// of a contact carry it, each with half the weight, so that two parallel strands store psi(d) per
// unit length and exchange equal and opposite forces. The integral over s is the rod's Gauss
// quadrature (model.gauss_points per element, the points of Kinematics::points()): one contact per
// Gauss point and foot, carrying its weight w ell / 2 (times 1/2). A foot is the minimiser of the
// point's distance to one element's arc, kept when it is a local minimum along the whole curve: in
// the element's interior, or at an end of the rod (the root's start, the tip's end) with the distance
// growing into the rod. A minimum at an end of any other element is not one of the curve's: the
// centreline is C^1, so the distance keeps falling into the neighbouring element, whose search finds
// it (a minimum exactly at a junction, with zero slope, is lost only to round-off). Unlike a
// closest-point pair per element pair, the foot of a point is unique also along parallel strands, so
// the energy is smooth there and converges with N to the continuum line contact.
//
// Which elements can touch: elements P and Q with |P - Q| <= m never count, m = max(1, ceil(pi h /
// ell)) (the nodal rod's rule, rod3d/self_contact.hpp: a fold that brings the tube onto itself has an
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
// Narrow phase: projected Newton on f(t) = 1/2 |r - r_Q(t)|^2 over [0, ell] (exact derivatives from
// the element's tangent n0 and its rate R (q x e0)), started at the element's chord vertex nearest to
// the point.
//
// Hard law: the constraint d >= 2h between the closest points of two arcs (arc_pair_contact.hpp,
// hard_self_contact.hpp); the barrier's energy, force and field are then 0.
//
// Generalised force and Hessian. At a foot t* the distance's gradient is n . (dr_P/dq(s) - dr_Q/dq(t*))
// (envelope theorem), n the unit vector from the foot to the point; a contact's generalised force is
// its force times that. The Hessian (self_contact_hessian) adds the normal's rotation, the dead-load
// stiffness of the held forces and the foot's motion (implicit function theorem on f'(t*) = 0).
// Both are checked against central differences in the tests.
#include <cstddef>
#include <utility>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"

namespace rodvv::solvers::superhelix {

// SelfContact (radius h, barrier stiffness k per unit length) is declared in model.hpp.
// InputError naming "radius" or "stiffness" unless finite and > 0.
void validate(const SelfContact& contact);

// m = max(1, ceil(pi h / ell)): elements at most m apart never count.
std::size_t contact_excluded_elements(double radius, double element_length);

// The foot of `point` on the arc of `element`: the t in [0, ell] minimising |point - r(t)|, by
// projected Newton from t0; t = 0 or ell when the minimum over the arc is at that end (the distance
// growing into the element).
struct ArcFoot {
  double t = 0.0;
  Vec3 position = Vec3::Zero();
  double distance = 0.0;
  int iterations = 0;
};
ArcFoot foot_on_arc(const Kinematics& kinematics, const Vec3& point, std::size_t element, double t0);

// One contact: a Gauss point of element `first` at offset s, its foot on element `second` at t.
struct ArcContact {
  std::size_t first = 0, second = 0;  // the point's element and the foot's, |first - second| > m
  double s = 0.0, t = 0.0;            // offsets on them, in [0, ell]
  double weight = 0.0;                // quadrature weight (length): w_g ell / 4 (half of each side's)
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();  // the point and its foot
  double distance = 0.0;
  Vec3 normal = Vec3::Zero();  // unit, from q to p: the force on the point is +force normal
  double force = 0.0;          // weight k (2h - d)^2 (force)
};

// The contacts, sorted by (first, s, second), by the broad phase above. SolverError when a point
// lies on another stretch's centreline (d = 0: no normal). With the hard law (model.hpp) the pairs
// of closest points of two arcs closer than 2h instead (arc_pair_contact.hpp), force 0: the forces are
// the complementarity's unknowns (hard_self_contact.hpp).
std::vector<ArcContact> self_contacts(const Kinematics& kinematics, const SelfContact& contact);
// The broad phase alone: the element pairs (P < Q, more than m apart, sorted) whose arcs may come closer
// than `reach` (finite, >= 2h; InputError "reach" otherwise).
std::vector<std::pair<std::size_t, std::size_t>> contact_element_pairs(const Kinematics& kinematics,
                                                                       const SelfContact& contact, double reach);
// The same from every pair of elements (O(N^2) pairs): the oracle of the broad phase's tests.
std::vector<ArcContact> self_contacts_all_pairs(const Kinematics& kinematics, const SelfContact& contact);

// Sum of weight psi(d) over the contacts.
double self_contact_energy(const SelfContact& contact, const std::vector<ArcContact>& contacts);
// The contact forces' generalised force Q = -dE/dq (size 3N): sum of force (dr_P/dq(s)^T n - dr_Q/dq(t)^T n).
VecX self_contact_generalized_force(const Kinematics& kinematics, const std::vector<ArcContact>& contacts);

// The contact field V_eff(s) felt at the point (element, sigma), per unit length, for the Noether
// quantity H = ... - V_eff (PHYSICS.md §1.2): half the barrier density of the point's feet,
//   V_eff(s) = 1/2 sum_feet psi(d(s)).
// Why half: in this model's continuum limit E = 1/2 int sum_feet psi(d(s)) ds, the force density at s
// is the point's own pull -1/2 psi'(d) n plus the reactions of the points whose feet lie at s. The
// reactions are normal to the rod at s (n is perpendicular to the tangent at a foot); the own pull's
// tangential part is -1/2 psi'(d) n . t = -d/ds (1/2 psi(d(s))). So dH/ds = -f_c . t (PHYSICS.md
// §1.2) integrates to H - 1/2 sum psi(d(s)) = const. (A symmetric pair potential U gives the full
// field int U dsigma instead: the nodal rod's.) The hard law has no field: 0.
double contact_field(const Kinematics& kinematics, const SelfContact& contact, std::size_t element, double sigma);

// The energy's Hessian d2E/dq2 (3N square, symmetric) at a fixed contact set: with J = dr_P/dq(s) -
// dr_Q/dq(t*), per contact (weight w, force f = -w psi'):
//   w psi'' J^T n n^T J - f [ J^T (I - n n^T) J / d + n . d2(Delta)/dq2 - D_qt D_tt^-1 D_tq ],
// where n . d2(Delta)/dq2 is the dead-load stiffness of unit forces +-n at the two points
// (load_stiffness.hpp: point_load_jacobian), D_tt = d2|Delta|/dt2 and D_qt = d2|Delta|/dq dt (a foot at
// the end of its element stays there). Tested against central differences of the generalised force.
MatX self_contact_hessian(const Kinematics& kinematics, const SelfContact& contact,
                          const std::vector<ArcContact>& contacts);

}  // namespace rodvv::solvers::superhelix

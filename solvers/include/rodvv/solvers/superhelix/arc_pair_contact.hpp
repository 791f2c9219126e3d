#pragma once
// Contact between two helical arcs of a Super-Helix at their CLOSEST POINTS: the geometry of the hard
// self-contact (hard_self_contact.hpp; ALGORITHMS.md §4). For elements P < Q that the broad phase pairs
// (self_contact.hpp: contact_element_pairs), the local minimum (s*, t*) in [0, ell]^2 of
//     D(s, t) = 1/2 |r_P(s) - r_Q(t)|^2
// by projected Newton in two variables (exact derivatives from the tangents and their rates), started at
// the pair's closest points of a previous configuration when given (an iteration then follows one
// minimum; shallow minima of side-by-side strands otherwise jump between basins), else at the nearest of
// 5 x 5 points of the two arcs. Every pair's minimum over its box counts, at an element end
// too: d_PQ(q) = min over the box is continuous in q, and the tube does not pass through itself iff every
// d_PQ >= 2h. (Keeping only minima of the whole curves - interior ones - was tried first: where strands
// run side by side in the trefoil's braid, the shallow minima wander across element junctions, so the
// constraints came and went between Newton iterations and Newton-LCP never settled.) A minimum at a
// junction is found by both pairs sharing it, identical rows of the LCP that Lemke's lexicographic rule
// handles; at an equilibrium a pair whose minimum is at an element end is inactive unless the true minimum
// of the two curves sits exactly there.
//
// Why the closest points and not the barrier's Gauss points and feet: a hard contact is a concentrated
// force, and at a Gauss point the foot's normal is perpendicular to the foot's tangent only; a point
// force with a component along the rod's own tangent makes H (PHYSICS.md §1.2) jump by f n.t there,
// which the barrier's field V_eff absorbs but a hard contact (no field) cannot. At interior closest points
// n is perpendicular to both tangents (dD/ds = dD/dt = 0), so the force does no work along either rod
// and H is continuous through it.
//
// The constraint's value is d*(q) = min_(s,t) |r_P(s) - r_Q(t)|, its gradient n^T (dr_P/dq(s*) -
// dr_Q/dq(t*)) (envelope theorem; self_contact_generalized_force gives sum f times it), and its Hessian
//     d2d*/dq2 = J^T (I - n n^T) J / d + n . d2(Delta)/dq2 - D_qx D_xx^-1 D_xq,
// J = dr_P/dq(s*) - dr_Q/dq(t*), x the free ones of (s, t) (an end of the rod stays there), D_xx = the 2 x 2
// Hessian of d in x, D_qx = d2 d / dq dx. Along two parallel strands D_xx is singular (the closest points
// slide together at no change of d): that direction's term is dropped (its D_qx vanishes with it).
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace rodvv::solvers::superhelix {

// The closest-point pairs of the arcs closer than `reach` (finite, >= 2h), sorted by (first, second):
// first = P, s = s*, second = Q, t = t*, p and q the two points, normal from q to p, force 0, weight 0.
// SolverError when two centrelines intersect (d = 0: no normal).
// previous: closest points found before (sorted by pair), whose (s, t) start the search of their pair.
std::vector<ArcContact> closest_arc_pairs(const Kinematics& kinematics, const SelfContact& contact, double reach,
                                          const std::vector<ArcContact>& previous = {});

// -sum_c f_c d2d*_c/dq2 (3N square, symmetric): the stiffness of the contacts' forces f_c (held) as the
// pairs turn and their closest points slide, i.e. the Hessian of the contact term of the hard law's
// Lagrangian. Tested against central differences of the generalised force.
MatX closest_pair_force_stiffness(const Kinematics& kinematics, const std::vector<ArcContact>& contacts);

}  // namespace rodvv::solvers::superhelix

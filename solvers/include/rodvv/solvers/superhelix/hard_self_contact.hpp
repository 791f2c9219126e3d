#pragma once
// Statics of a Super-Helix with HARD frictionless self-contact (model.self_contact.law = Hard;
// ALGORITHMS.md §4.2 (v), §4.3): the constraint d_c >= 2h between the closest points of two helical arcs
// (arc_pair_contact.hpp: one pair c per pair of elements that the broad phase finds), with no barrier and
// no energy. The forces lambda_c are unknowns; at an equilibrium
//     r(q) = K (q - q0) - F_ext(q) = sum_c lambda_c G_c^T,     0 <= lambda_c  _|_  g_c = d_c - 2h >= 0,
// G_c = dd_c/dq = n_c^T (dr_P/dq(s*) - dr_Q/dq(t*)) (envelope theorem at the closest points).
// This is the Super-Helix analogue of the nodal rod's Newton-LCP (rod3d/statics.hpp, hard_contact_step.hpp).
//
// One Newton-LCP iteration at q with the candidates c (pairs closer than the reach 3h: no step moves a
// Gauss point by more than h / 2, so no pair outside it can close within a step) linearises both:
//     A dq = -r + G^T lambda,     0 <= lambda  _|_  g + G dq >= 0,
// with A = dr/dq (statics.hpp's exact Jacobian) + the geometric stiffness of the candidates' current
// forces (closest_pair_force_stiffness: the normals turn and the closest points slide under held forces;
// without it Newton is only linear) + rho sum_{lambda_c > 0} G_c^T G_c (an augmentation that does not
// move the solution - a step keeping those contacts closed has G_c dq = 0 - but makes A positive definite
// where the elastic stiffness alone is not: a knot is held together by its contacts) + mu K (a Levenberg
// shift, below; it adds pseudo-time mass and does not move the fixed point either). With dq = dq_free + X lambda (dq_free = -A^-1 r, X = A^-1 G^T) the LCP
//     0 <= lambda  _|_  W lambda + b >= 0,   W = G X (symmetrised),  b = g + G dq_free,
// is solved by Lemke's method (contact/lcp.hpp, verified). lambda is the total contact force, not an
// increment: at a fixed point dq = 0, r = G^T lambda and lambda _|_ g.
//
// Globalisation: pseudo-transient continuation (Kelley & Keyes 1998), the shift mu being the inverse
// pseudo-time step (as on the nodal rod). A step is cut to move no Gauss point by more than h / 2 and
// taken whole when the equilibrium measure (below) stays within 10 x the larger of its value here and its
// value here under the step's own forces (those change discontinuously with the active set); a trial with
// a candidate closer than h (a strand pushed through another) is a step too long. A step that lowered the
// measure and was not cut divides mu by the measure's ratio (clamped to [1.2, 10]; below 1e-6 mu is 0:
// Newton itself), a cut one multiplies it by the cut (at most 10 x), a failed step or LCP by 4 (from 1e-6,
// up to 1e12: then SolverError). A backtracking line search on the measure (Armijo 1e-4), tried first,
// crawled at steps of 1e-8 on the trefoil: the measure is a max norm of forces that jump.
//
// Equilibrium measure: max(|r - G^T lambda|_inf / S, max_c |min(lambda_c / F, g_c / L)|) with S the
// Newton residual scale (newton.hpp) and F = max(|F_end|, rho S |g| L, max(EI1, EI2, GJ) / L^2) a force
// scale; converged when it is <= options.tolerance. Load steps as in newton.hpp (lambda_k = k / steps).
// Failure: SolverError naming the method, the iterations and the measure.
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace rodvv::solvers::superhelix {

struct HardContactStatics {
  StaticResult statics;              // q, Newton-LCP iterations, and the final equilibrium measure
  std::vector<ArcContact> contacts;  // the candidates at q (closest-point pairs); force = the multiplier lambda_c >= 0
  std::size_t lcp_pivots = 0;        // Lemke pivots over all iterations
};

// InputError "self_contact.law" unless the model has hard self-contact; "end_moment" for a dead end moment
// (not conservative: A would not be symmetric, nor W).
HardContactStatics solve_static_with_hard_contact(const RodModel& model, const StaticOptions& options = {});

// F above: the force against which the multipliers are measured.
double hard_contact_force_scale(const RodModel& model);

}  // namespace rodvv::solvers::superhelix

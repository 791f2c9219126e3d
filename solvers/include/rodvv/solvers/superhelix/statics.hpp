#pragma once
// Static equilibrium of a Super-Helix (ALGORITHMS.md §1.4 with qdot = 0): the stationarity of the
// potential energy, written as the residual
//
//   r(q) = K (q - q0) - F_ext(q)         (K = diag(GJ, EI1, EI2) ell per element)
//
// where F_ext are the generalised forces of gravity and of the dead end force and moment
// (loads.hpp). For gravity and an end force r is the gradient of 1/2 (q-q0)^T K (q-q0) + V(q);
// a dead end moment is not conservative for general 3-D rotations (Ziegler), so the Jacobian is
// not symmetric in general and Newton works on r itself.
// Self-contact (model.self_contact, radius > 0): r gains -Q_c, the barrier's generalised force
// (self_contact.hpp; never scaled by the load factor), and the Jacobian its exact Hessian. The
// equilibrium then minimises the potential (static_potential; a dead end moment, which has none, is
// refused), and Newton is globalised on it, not on |r|: a barrier makes |r| non-convex enough that
// its line search stalls at minima of |r| that are no equilibria. Direction (H + mu K) d = -r with
// the smallest Levenberg shift mu (0, else from 1e-6 by x 10; after a full step mu / 10) that makes
// the matrix positive definite (Cholesky); Armijo 1e-4 on the potential, or a step that halves |r|_inf
// (near the solution the potential's decrease drowns in rounding); and no Gauss point moves by more
// than 1.5 h per step (a longer step starts scaled down to that motion), so that no strand passes
// through another: two strands in contact (d <= 2h) come out on each other's far side at the same
// energy only after a relative motion of about 4h; 3h leaves them overlapping by h or more, a barrier
// energy the line search rejects. Same convergence test as Newton.
//
// Hard self-contact (model.self_contact.law = Hard): the residual, potential and Jacobian here are the
// rod's without the contacts, whose forces are unknowns (hard_self_contact.hpp solves for both);
// solve_static refuses such a model (InputError "self_contact.law").
//
// A sliding clamp at the tip (model.tip_guide, tip_guide.hpp): r gains the gradient of its springs'
// energy (never scaled by the load factor), the Jacobian their Hessian, the potential their energy.
//
// Newton (newton.hpp, shared with the super-clothoid): the exact Jacobian dr/dq = K - lambda dF_ext/dq
// (load_stiffness.hpp, O(N^2); it replaced central differences of the residual, whose ~1e-11
// truncation made Newton linear with a contraction ~1e-10), LU with partial pivoting, backtracking
// line search on 1/2 |r|^2 (Armijo 1e-4, step halved down to 2^-30).
// Load stepping: loads scaled by lambda_k = k / load_steps, each step starting from the previous.
// Convergence: |r|_inf <= tolerance * scale, scale = max(|K|_inf |q|_inf, |K|_inf / L,
// |F_ext(q0)|_inf), or a Newton step at round-off (|dq|_inf <= 64 eps (1 + |q|_inf) L).
// Failure: rodvv::SolverError (iterations, residual). Cost per Newton iteration: O(N^2) for the
// Jacobian and O(N^3) for the dense LU.
// static_jacobian: exact, symmetric for gravity and a dead end force (to round-off).
#include <cstddef>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/newton.hpp"

namespace rodvv::solvers::superhelix {

VecX static_residual(const RodModel& model, const VecX& q, double load_factor = 1.0);
// 1/2 (q-q0)^T K (q-q0) + lambda (V_gravity - F_end . r_tip) + E_contact, whose gradient is
// static_residual; InputError "end_moment" for a dead end moment (not conservative).
double static_potential(const RodModel& model, const VecX& q, double load_factor = 1.0);
MatX static_jacobian(const RodModel& model, const VecX& q, double load_factor = 1.0);
StaticResult solve_static(const RodModel& model, const StaticOptions& options = {});
// The convergence test's scales (|K|_inf, L, |F_ext(q0)|_inf at full load; newton.hpp) of a validated model.
NewtonScales static_newton_scales(const RodModel& model);

}  // namespace rodvv::solvers::superhelix

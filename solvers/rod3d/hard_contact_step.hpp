#pragma once
// Hard self-contact inside the statics' Newton iteration (statics.hpp; ALGORITHMS.md §4.2 (v), §4.3;
// the rod analogue of elastica2d's Newton-LCP). Not part of the public API.
//
// At an iterate z with elastic-and-load residual r(z) and Jacobian J (the KKT matrix of the inextensible
// rod, plus the pseudo-time mass when that is used), each candidate pair c (segments closer than the
// reach 3h, whose distance d_c no step capped at h/2 per vertex can bring below 2h from outside it)
// has the gap g_c = d_c - 2h and the gap gradient G_c = dd_c/dz (self_contact.hpp: distance_gradient).
// The step and the pair forces lambda solve the linearised equilibrium with the linearised constraint
//     J dz = -r + G^T lambda,     0 <= lambda  _|_  g + G dz >= 0,
// i.e. with dz = dz_free + X lambda (dz_free = -J^-1 r, X = J^-1 G^T) the LCP
//     0 <= lambda  _|_  W lambda + b >= 0,   W = G X (symmetrised),  b = g + G dz_free,
// solved by Lemke's pivoting (contact/lcp.hpp; a few dozen to a few hundred pairs). lambda is the total
// pair force at the new iterate, not an increment: at a fixed point dz = 0 it satisfies r = G^T lambda
// with lambda _|_ g, the equilibrium of the hard contact problem. W is positive semidefinite when the
// rod's stiffness restricted to the inextensibility constraints is (a stable equilibrium, or the
// pseudo-time mass large enough); a W the LCP solvers refuse is a failed step, not an error.
#include <cstddef>
#include <functional>
#include <vector>

#include <Eigen/SparseCore>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d::detail {

// The candidates' reach: 3h (a vertex moves at most h/2 per step, so a pair's distance by at most h).
double hard_contact_reach(const RodModel& model);

// The candidate pairs at `state`, each with the force of the same segment pair in `forces` (0 if absent).
std::vector<ContactPair> candidates_with_forces(const RodModel& model, const RodState& state,
                                                const std::vector<ContactPair>& forces);

// r -= sum_c lambda_c G_c^T over the pairs (their force field is lambda): the residual with the contact
// forces acting on the vertices.
void subtract_contact_forces(const RodModel& model, const std::vector<ContactPair>& pairs, VecX& r);

// The natural-map residual of the complementarity, max_c |min(lambda_c / force_scale, g_c / length_scale)|
// (a negative gap, an interpenetration, counts in full).
double complementarity_measure(const RodModel& model, const std::vector<ContactPair>& pairs, double force_scale,
                               double length_scale);

// The Jacobian of the residual with the pair forces held, plus an augmentation on the pairs in contact:
//     J += -sum_c lambda_c d^2 d_c/dz^2  +  rho sum_{lambda_c > 0} G_c^T G_c.
// The first term is the exact linearisation (the forces' directions turn with the pairs); without it
// Newton is only linear. The second does not move the solution (a step that keeps those pairs in contact
// has G_c dz = 0, so near convergence it vanishes from the step) but makes J positive definite where the
// elastic stiffness alone is not: a knot held together by its contacts is stable only through them, and
// J^-1 - hence W - is then indefinite in the directions they block, where Lemke's method fails. rho is
// given by the caller (statics.cpp: 1000 x the force scale per radius h). Held rows and columns untouched.
void add_contact_stiffness(const RodModel& model, const RodState& state, const std::vector<ContactPair>& pairs,
                           double rho, Eigen::SparseMatrix<double>& jacobian);

struct HardContactStep {
  VecX dz;                         // the step (held dofs 0)
  std::vector<ContactPair> pairs;  // the candidates, force = lambda
  std::size_t lcp_pivots = 0;
};

// The step above. `solve(v)` returns J^-1 v in the problem's units (held rows: identity, so a held dof
// does not move); `residual` is r without contact forces, held rows zero; `held` marks held dofs (their
// columns of G are zero: the supports take those forces). SolverError or InputError from the LCP solver
// when W is not positive semidefinite enough for it: the caller treats the step as failed.
HardContactStep hard_contact_step(const RodModel& model, const std::vector<ContactPair>& candidates,
                                  const std::vector<char>& held, const VecX& residual,
                                  const std::function<VecX(const VecX&)>& solve);

}  // namespace rodvv::solvers::rod3d::detail

#pragma once
// Static equilibrium of the discrete elastic rod (model.hpp, discrete_energy.hpp): Newton on the
// residual r(z) = 0 with the exact banded Jacobian, factorised by a banded LU with partial pivoting
// (O(N) per iteration; the KKT matrix of an inextensible rod is symmetric indefinite, and a dead
// tip moment makes it unsymmetric), a backtracking line search on the scaled residual, and
// continuation. With self-contact (model.hpp, self_contact.hpp) the barrier couples vertices far
// apart along the rod, so the Jacobian is factorised by a sparse LU (COLAMD ordering) instead; a
// Newton step is shortened so that no two segments can pass through each other on its straight path
// (their relative motion stays below their gap less h, or half their distance when in contact; no
// vertex moves more than 2h), since the barrier is seen only at the ends of a step, and a line-search
// trial in which two segments intersect is shortened. Under pseudo-transient continuation a rod whose
// loads all have a potential (the barrier, no dead moments) accepts a step on the decrease of an l1
// merit (energy plus a penalty on the inextensibility constraints; statics.cpp), else on its residual.
//
// Hard self-contact (model.self_contact.law = Hard, self_contact.hpp): the forces are unknowns. Each
// Newton (or pseudo-transient) step solves the linearised equilibrium with the linearised constraints
// d_c >= 2h of every pair closer than 3h as an LCP (Lemke) for the step and the pair forces
// (hard_contact_step.hpp); the Jacobian stays banded (the contacts couple the vertices only through the
// LCP's Schur complement). Converged when the residual with the pair forces meets the test below and
// the complementarity's natural map max |min(lambda / force scale, (d - 2h) / L)| does too. A step whose
// LCP has no solution fails like a step whose factorisation does.
//
// Continuation: the loads (gravity, tip force, tip moment) are scaled by lambda, and the supported
// ends are moved from where `initial` has them to where the model puts them (positions linearly, end
// tangents by a rotation about their common normal, held material angles linearly, so an imposed
// end rotation of many turns is followed turn by turn), lambda going from 0 to 1 in `load_steps`
// steps. A step whose Newton iteration fails is halved (at most `max_halvings` times in a row);
// a step that converges lets the next one grow by 1.5 (never beyond 1 / load_steps).
//
// The angle held at an end: a clamped end's material frame is model.<end>.frame turned by
// model.<end>.rotation about its tangent; a pinned end with hold_twist holds its material angle at
// model.<end>.rotation, measured from the reference director parallel-transported along the rod.
//
// Convergence: every row of r below max(tolerance, 8 N^3 eps max(1, |x|_max / L) [+ 8 eps EA |x| /
// (ebar F) for an extensible rod]) times its scale (the second term is the round-off floor of the
// vertex forces of a nodal rod, whose edge vectors are differences of positions; statics.cpp
// derives and measures it) - forces: the largest of EI/L^2,
// |F|, |M|/L, rho S |g| L and the largest edge tension; moments: that times L; constraint rows: L -
// or a Newton step at round-off (|dz|_inf <= 64 eps L). Failure: rodvv::SolverError naming
// "rod3d statics", the load factor reached, iterations and residual.
#include <cstddef>
#include <vector>

#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

struct StaticOptions {
  std::size_t load_steps = 1;        // >= 1
  std::size_t max_iterations = 60;   // per continuation step, >= 1
  double tolerance = 1e-10;          // relative, in (0, 1)
  std::size_t max_halvings = 16;     // of one continuation step
  // Pseudo-transient continuation instead of the line search (statics.cpp): Newton on
  // (D / tau) dz + r(z + dz) = 0 with the pseudo-time step tau growing as the residual falls, for a
  // start far from equilibrium (a knot to be tied) or a rod with zero or near-zero modes (an
  // isotropic rod turning about its tension axis, a knot sliding along its tails). At large tau it is
  // Newton: like Newton it converges to an UNSTABLE equilibrium when it starts on one (a straight
  // rod twisted past its buckling moment); break the symmetry (an imperfection) to leave it.
  bool pseudo_transient = false;
  double initial_pseudo_time = 1.0;  // tau of the first step, in [1e-6, 1e6]
};

struct StaticResult {
  RodState state;
  // With self-contact, the pairs carrying a force at the equilibrium: the barrier law's (self_contacts),
  // or the hard law's, force = the complementarity's multiplier (below).
  std::vector<ContactPair> contacts;
  std::size_t iterations = 0;  // Newton iterations, all steps
  std::size_t steps = 0;       // continuation steps taken (accepted)
  double residual = 0.0;       // final scaled residual (max over rows)
};

// `initial` must have the model's element count (make_straight_state(model) is the usual start).
StaticResult solve_static(const RodModel& model, const RodState& initial, const StaticOptions& options = {});

// The scaled residual measure of the convergence test above (max over free rows).
double scaled_residual(const RodModel& model, const RodState& state, double load_factor);

// Indices (DofLayout) of the degrees of freedom the supports hold.
std::vector<std::size_t> held_dofs(const RodModel& model);

}  // namespace rodvv::solvers::rod3d

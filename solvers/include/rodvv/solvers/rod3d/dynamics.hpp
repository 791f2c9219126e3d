#pragma once
// Time integration of the discrete elastic rod (model.hpp, discrete_energy.hpp; ALGORITHMS.md §5):
// implicit Euler and implicit midpoint on the same energy, Newton with the banded Jacobian.
//
// State: the configuration z = (positions, material angles; multipliers of an inextensible rod) and
// the velocity v of the positions and angles (DofLayout order), with the lumped mass M of
// linearized.hpp (vertex masses rho S ebar, half at the end vertices; rho I0 ebar on each angle).
// The angle rate is the spin of the cross-section relative to the reference frame, which is carried
// from step to step by time-parallel transport (displaced() transports from the old tangents to the
// new ones, Bergou et al. 2010), so 1/2 rho I0 ebar theta-dot^2 is its kinetic energy.
//
// One step of size h from (z_n, v_n): the unknown y = z_{n+1} - z_n (multiplier entries: the change
// of the multipliers), written in the chart of z_n - the reference frames of z_n transported to the
// trial tangents, the reference twists continued (discrete_energy.hpp chart_residual) - so that the
// angle increment is measured from the time-parallel transported frame, whatever path Newton takes.
//  - implicit Euler:    M (y - h v_n) / h^2 + r(z_n + y) = 0,     v_{n+1} = y / h;
//  - implicit midpoint: 2 M (y - h v_n) / h^2 + r(z_n + y/2) = 0, v_{n+1} = 2 y / h - v_n,
//    with r = grad E + sum_j lambda_j grad c_j - Q (the static residual of discrete_energy.hpp at
//    load factor 1: elastic forces, gravity, the dead tip force and moment), and for an inextensible
//    rod the constraints c_j(z_{n+1}) = |e_j| - ebar = 0 at the end of the step (both methods).
//    In the midpoint rule the constraint force lambda_j grad c_j is taken at the midpoint: it points
//    along e_j(mid) = (e_j(n) + e_j(n+1))/2, so it does the work lambda_j (|e_j(n+1)|^2 -
//    |e_j(n)|^2) / (2 |e_j(mid)|) = 0 over the step: the constraints do no work, and the energy
//    error is that of the midpoint rule on the elastic energy alone.
// Energy behaviour (measured in tests/solvers/test_rod3d_dynamics.cpp): implicit Euler dissipates,
// a mode of frequency omega losing the fraction 1 - 1/(1 + omega^2 h^2) of its energy per step
// (first order in h; matched to 7e-9 on one small-amplitude cantilever mode). The midpoint rule
// conserves a quadratic energy exactly - on the small-amplitude (linearised) rod the energy holds
// to 5e-12 relative over 100 steps, when the start lies on the constraint manifold - and otherwise
// keeps an O(h^2) energy error that oscillates without drift (the swinging rod of
// rod3d/energy-in-time). It is not an energy-conserving discrete gradient for the nonlinear rod.
// Momentum: the internal forces sum to zero for every configuration, so for a rod without supports
// and gravity sum_i m_i v_i is conserved to round-off by both methods (after the first full
// Newton step of each time step, whatever the convergence).
//
// Newton: the exact Jacobian of the step residual - chart_system in the chart of z_n at the
// evaluation point (midpoint: its position and angle columns halved; constraint rows c_j(z_n + y)
// differentiated by hand) plus (2) M / h^2 -, so Newton converges quadratically. Assembling it
// (second-order jets of the 11-dof stencils) costs ~10 residuals, so by default a step keeps its
// factorisation while the residual falls tenfold per full step (the inertia term (2) M / h^2, which
// does not change, dominates it for small h) and refreshes it otherwise.
// Banded LU (elastica2d::BandedLU), O(N) per iteration; backtracking on the scaled residual; a step
// may turn no reference twist by more than pi/4 (the energy's chart).
//
// Convergence: every free row of the step residual below `tolerance` times its scale - force rows:
// the statics force scale (statics.hpp: EI/L^2, |F|, |M|/L, rho S |g| L, the largest tension) or the
// inertial force rho S ebar |v|_max / h if larger; angle rows: that times L, or rho I0 ebar
// |theta-dot|_max / h if larger; constraint rows: L - or a Newton correction at round-off
// (|dy|_inf <= 64 eps L), or one full Newton step taken from a residual at its round-off floor
// (8 N^3 eps max(1, |x|_max / L), the floor of statics.cpp). Failure: rodvv::SolverError naming
// the method, the step number, time, h, the iterations and the residual.
//
// Supports: the held dofs (statics.hpp held_dofs) keep the values of the initial state and zero
// velocity (place the ends first, e.g. with make_straight_state or solve_static). A dead tip moment
// is applied but has no potential: the energy below does not include its work.
#include <cstddef>

#include <Eigen/SparseCore>

#include "rodvv/common/eigen_types.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace rodvv::solvers::rod3d {

enum class TimeIntegrator { ImplicitEuler, ImplicitMidpoint };

const char* integrator_name(TimeIntegrator method);

struct DynamicState {
  RodState rod;
  VecX velocity;           // DofLayout order: vertex velocities, angle rates; 0 on multipliers and held dofs
  double time = 0.0;
  std::size_t steps = 0;   // steps taken (named in a SolverError)
};

// The state `rod` (multipliers set to 0 if an inextensible rod has none) moving with `velocity`
// (DofLayout order; empty: at rest). InputError ("state", "velocity") on a size mismatch, a
// non-finite value, or a non-zero velocity of a held dof or multiplier. Requires twist_inertia > 0.
// A velocity that violates the linearised constraints C v = 0 is not corrected here: the first
// step removes its normal part (an impulse, which changes the energy).
DynamicState make_dynamic_state(const RodModel& model, const RodState& rod, const VecX& velocity = {});

struct DynamicOptions {
  std::size_t max_iterations = 40;  // Newton iterations per step, >= 1
  double tolerance = 1e-12;         // relative residual, in (0, 1)
  bool reuse_jacobian = true;       // keep a step's factorisation while it contracts the residual 10x per iteration
};

struct StepReport {
  std::size_t iterations = 0;      // Newton corrections
  std::size_t factorizations = 0;  // Jacobians assembled and factorised
  double residual = 0.0;           // final scaled residual
};

// One step of size h > 0 (finite). Throws InputError (h, options, model) or SolverError.
DynamicState step(const RodModel& model, const DynamicState& state, double h, TimeIntegrator method,
                  const DynamicOptions& options = {}, StepReport* report = nullptr);

struct DynamicEnergy {
  double kinetic = 0.0;    // 1/2 v.M v (translation and spin)
  double potential = 0.0;  // discrete_energy.hpp energy().potential(): elastic + gravity + tip force
  double total() const noexcept { return kinetic + potential; }
};
DynamicEnergy dynamic_energy(const RodModel& model, const DynamicState& state);

// sum_i m_i v_i.
Vec3 linear_momentum(const RodModel& model, const DynamicState& state);

// The step's residual at the unknown y (DofLayout; held rows 0) and the Newton matrix used at y
// (held rows: identity), for tests: the matrix is the derivative of the residual.
VecX step_residual(const RodModel& model, const DynamicState& state, double h, TimeIntegrator method, const VecX& y);
Eigen::SparseMatrix<double> step_jacobian(const RodModel& model, const DynamicState& state, double h,
                                          TimeIntegrator method, const VecX& y);

}  // namespace rodvv::solvers::rod3d

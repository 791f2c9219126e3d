#pragma once
// Time integrators for the nonlinear pendulum  theta'' = -omega^2 sin(theta)  (PHYSICS.md §2),
// behind one interface: integrate(problem, settings) -> rodvv::Trajectory.
//
// Methods (theoretical global order in brackets):
//   explicit-euler     [1]  own code; not symplectic, energy grows
//   symplectic-euler   [1]  own code; kick (v) then drift (q); symplectic
//   stormer-verlet     [2]  own code; velocity Verlet (kick-drift-kick); symplectic, time reversible
//   rk4                [4]  Boost.Odeint runge_kutta4; not symplectic, energy drifts
//   dopri5             [5]  Boost.Odeint runge_kutta_dopri5, adaptive with dense output; the
//                           resolution is the tolerance (abs = rel), not the step
//   rkn4-mclachlan     [4]  Boost.Odeint symplectic_rkn_sb3a_mclachlan (McLachlan 1995); symplectic
//
// Output grid: t_i = i * dt for i = 0 .. n with n = ceil(t_end / dt) (t_i computed as i * dt, never
// accumulated), so the last recorded time is >= t_end by less than one step. A quotient t_end / dt
// within 4 ulps of an integer counts as that integer (t_end = 2, dt = 0.02 gives n = 100 whatever
// the decimal rounding), so there t_n may undershoot t_end by a few ulps. Fixed-step methods step
// exactly dt; the adaptive method chooses its own steps and samples its dense output on that grid.
// record_every = k keeps every k-th grid point (and always the first and the last).
//
// Bookkeeping: Trajectory.steps = accepted steps (n for the fixed-step methods);
// rhs_evaluations = force evaluations actually made: explicit/symplectic Euler n, Stoermer-Verlet
// n + 1 (the end-of-step force is reused), rk4 4n, rkn4-mclachlan 6n (odeint also evaluates the
// zero-weight last stage), dopri5 1 + 6 per attempted step (FSAL).
// Failures: a non-finite state throws rodvv::SolverError (step count, |theta| + |theta'|); dopri5
// also throws when its step size underflows (below 64 eps t_end) or 500 consecutive steps are
// rejected, reporting the accepted steps and the last normalised error estimate.
#include <cstddef>
#include <span>
#include <string_view>

#include "rodvv/common/trajectory.hpp"

namespace rodvv::solvers::pendulum {

enum class Method { ExplicitEuler, SymplecticEuler, StormerVerlet, RungeKutta4, DormandPrince5, McLachlanRkn4 };

struct MethodInfo {
  Method method;
  std::string_view id;        // stable identifier used in case names and on the command line
  std::string_view name;      // human-readable name
  int order;                  // theoretical global order
  bool symplectic;
  bool adaptive;              // resolution is a tolerance, not a step
  std::string_view citation;  // where the method (or its implementation) comes from
};

const MethodInfo& info(Method method);
std::span<const MethodInfo> all_methods();
// Throws rodvv::InputError naming the known ids when id is unknown.
Method method_from_id(std::string_view id);

struct Problem {
  double omega = 1.0;       // > 0
  double theta0 = 0.0;      // finite
  double theta_dot0 = 0.0;  // finite
  double t_end = 1.0;       // >= 0
};

struct Settings {
  Method method = Method::StormerVerlet;
  double dt = 0.01;           // > 0: the step (fixed-step methods) or the output interval (adaptive)
  double tolerance = 1e-8;    // adaptive only: absolute = relative error tolerance, in (0, 1)
  std::size_t record_every = 1;  // >= 1
};

// Throws rodvv::InputError for omega <= 0, dt <= 0, t_end < 0, NaN anywhere, record_every = 0,
// tolerance outside (0, 1), or more than 1e9 output points.
Trajectory integrate(const Problem& problem, const Settings& settings);

}  // namespace rodvv::solvers::pendulum

#pragma once
// Reference-grade shooting solver for the planar elastica (problem.hpp, PHYSICS.md §0): the same
// Problem as solve_static (EI(s), kappa_hat(s), potential V, the four supports with dead loads),
// solved as a boundary-value problem of the continuous equations rather than a discretisation.
//
// First-order system in s for the state q = (x, y, theta, m, n_x, n_y), m = EI (theta' - kappa_hat):
//   x' = cos theta,  y' = sin theta,  theta' = kappa_hat(s) + m / EI(s),
//   m' = n_x sin theta - n_y cos theta        (moment balance m' + (t x n).e_z = 0),
//   n' = grad V(x, y)                         (force balance n' + f = 0, f = -grad V).
// With a finite axial stiffness EA or shear stiffness GA (the planar Reissner rod, problem.hpp)
// theta is the cross-section angle and x, y follow r' = (1 + n.t/EA) t + (n.N/GA) N, with the moment
// balance m' = -(r' x n).e_z; the solution then carries axial_stiffness, shear_stiffness and the
// shear force n.N, so that H includes the stretch and shear energy (invariants/planar_noether.hpp).
// Ends (n(L) = end force at L, n(0) = -end force at 0, same for m; problem.hpp): every support
// fixes exactly three of the six components at its end,
//   Free    m, n_x, n_y = +-dead load;     Pinned  x, y, m;
//   Clamped x, y, theta;                   Sliding y, n_x, m,
// so the three components not fixed at s = 0 are the unknowns u and the three conditions at s = L
// are the residuals r(u). Newton's method on r(u) = 0 with the exact Jacobian from the variational
// equations S' = (dF/dq) S (S = dq/du, 6 x 3), integrated together with q by the embedded
// Runge-Kutta-Fehlberg 7(8) pair of Boost.Odeint under step-size control (abs and rel tolerance
// below). The Newton step is damped (backtracking on ||r||_2, Armijo 1e-4, halving to 2^-30) and
// computed as the minimum-norm least-squares solution (complete orthogonal decomposition), so an
// unknown the residuals do not see (a rigid translation when no end fixes the position) stays at
// its guess. Once ||r|| <= tolerance, one more full Newton step is taken (kept if it does not
// increase ||r||): with quadratic convergence it brings the mismatch down to the integration error.
// Newton needs a guess in the basin of the wanted branch (from the straight rod it stalls for the
// Mattiasson cantilever at P L^2/EI = 10): use shooting_guess_from on a discrete solution.
// Residuals and unknowns are made dimensionless with L (positions), 1 (angle), F L (moment) and
// F (force), F = max(EI/L^2, |end forces|, |end moments|/L, |guessed n(0)|), EI = max(EI(0),
// EI(L)); convergence is ||r||_inf <= tolerance. The integration error of the boundary values is
// ~ 10-100 x the ODE tolerance in these units, so tolerance must stay above that.
//
// The solution (PlanarRodSolution) is sampled at s_i = i L / N, N = sample_points, by integrating
// the converged initial data once more with steps ending exactly on every s_i: x, y, theta,
// kappa = kappa_hat + m/EI, force_x/y = n, axial_force = n.t, potential V (0 without one),
// bending_stiffness, natural_curvature; the edge arrays stay empty. iterations = Newton steps,
// residual = ||r||_inf of that final integration.
// Errors: rodvv::InputError for bad options (naming the field) or a bad Problem (validate), also
// for EI(s) <= 0 or non-finite EI, kappa_hat met during the integration; rodvv::SolverError (method
// "shooting", Newton iterations, residual) when Newton does not converge within max_iterations,
// the damped step makes no progress, or the integration fails (step-size underflow, too many steps,
// non-finite state at the guess).
#include <Eigen/Core>
#include <cstddef>

#include "rodvv/common/planar_rod.hpp"
#include "rodvv/solvers/elastica2d/problem.hpp"

namespace rodvv::solvers::elastica2d {

struct ShootingOptions {
  double tolerance = 1e-11;          // Newton: ||dimensionless boundary mismatch||_inf; in (0, 1)
  double ode_abs_tolerance = 1e-13;  // per-step error control of RKF78; in (0, 1e-3]
  double ode_rel_tolerance = 1e-13;  // in (0, 1e-3]
  std::size_t max_iterations = 50;   // Newton steps, >= 1
  std::size_t max_ode_steps = 200000;  // accepted steps per integration, >= 1
  std::size_t sample_points = 256;   // N: the solution is sampled at N + 1 nodes; >= 1
};

// The full initial state at s = 0; only the components the start support leaves free are used
// (Free: x, y, theta; Pinned: theta, force; Clamped: moment, force; Sliding: x, theta, force_y).
// moment = m(0) = EI (theta'(0) - kappa_hat(0)); force = n(0), the internal force at s = 0.
struct ShootingGuess {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;
  double moment = 0.0;
  double force_x = 0.0;
  double force_y = 0.0;
};

// The initial state read from node 0 of another solution of the same problem (e.g. solve_static
// at N = 64): this is how a caller picks the branch. Needs at least one node (InputError
// "solution.s" otherwise).
ShootingGuess shooting_guess_from(const PlanarRodSolution& solution, const Problem& problem);

void validate(const ShootingOptions& options);

// What Newton iterates on, at the initial state `guess`: the dimensionless boundary mismatch r at
// s = L (ordered as the end's three conditions: Free m, n_x, n_y; Pinned x, y, m; Clamped x, y,
// theta; Sliding y, n_x, m) and its Jacobian dr/dz from the variational equations, z_k = u_k /
// unknown_scale_k, u = the start's unknown components in the order listed at ShootingGuess.
// Exposed so that a test can check the Jacobian against finite differences. SolverError if the
// integration fails.
struct ShootingResidual {
  Eigen::Vector3d residual;
  Eigen::Matrix3d jacobian;
  Eigen::Vector3d unknown_scale;
};

ShootingResidual shooting_residual(const Problem& problem, const ShootingOptions& options,
                                   const ShootingGuess& guess);

PlanarRodSolution solve_shooting(const Problem& problem, const ShootingOptions& options = {},
                                 const ShootingGuess& guess = {});

}  // namespace rodvv::solvers::elastica2d

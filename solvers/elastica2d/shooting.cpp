// Shooting for the planar elastica (shooting.hpp): RKF 7(8) of Boost.Odeint (Fehlberg 1968, NASA
// TR R-287; Ahnert & Mulansky 2011) on the state and its variational equations, damped Newton on
// the three unknown initial components.
#include "rodvv/solvers/elastica2d/shooting.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Dense>
// GCC 12 reports the copy of a default-constructed stepper's scratch arrays (std::array members
// that odeint fills before reading) as "used uninitialized": a false positive inside Boost.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wuninitialized"
#if !defined(__clang__)  // clang has no -Wmaybe-uninitialized (and no such false positive)
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <boost/numeric/odeint.hpp>
#pragma GCC diagnostic pop

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

namespace odeint = boost::numeric::odeint;
constexpr const char* kMethod = "shooting";

// Component indices of the state q.
enum Component : std::size_t { kX = 0, kY = 1, kTheta = 2, kMoment = 3, kForceX = 4, kForceY = 5 };
constexpr std::size_t kStateSize = 6;
constexpr std::size_t kUnknowns = 3;
// q followed by the sensitivities S = dq/du, column k at [6 + 6 k, 6 + 6 k + 6).
constexpr std::size_t kExtendedSize = kStateSize * (1 + kUnknowns);

using Plain = std::array<double, kStateSize>;
using Extended = std::array<double, kExtendedSize>;

// The integration could not reach its target (not an input error): Newton treats the trial as
// rejected, or reports a SolverError.
struct IntegrationFailure {
  std::string reason;
};

// EI(s) and kappa_hat(s), checked where the integrator samples them.
struct Coefficients {
  double stiffness;
  double natural_curvature;
};

Coefficients coefficients_at(const Problem& problem, double s) {
  const double ei = bending_stiffness_at(problem, s);
  if (!std::isfinite(ei) || ei <= 0.0)
    throw InputError("bending_stiffness", "invalid parameter 'bending_stiffness': EI(" + format_value(s) +
                                              ") = " + format_value(ei) + ", must be finite and > 0");
  const double kh = natural_curvature_at(problem, s);
  if (!std::isfinite(kh))
    throw InputError("natural_curvature", "invalid parameter 'natural_curvature': kappa_hat(" +
                                              format_value(s) + ") = " + format_value(kh) +
                                              ", must be finite");
  return {ei, kh};
}

// Hessian of V: the given one, else central differences of the gradient (as the discrete
// solvers do: step cbrt(eps) scale, error ~ eps^(2/3)); only the Newton Jacobian uses it.
Eigen::Matrix2d potential_hessian(const Potential& v, double px, double py) {
  if (v.hessian) return v.hessian(px, py);
  const double scale = 1.0 + std::max(std::abs(px), std::abs(py));
  const double d = std::cbrt(std::numeric_limits<double>::epsilon()) * scale;
  Eigen::Matrix2d hess;
  hess.col(0) = (v.gradient(px + d, py) - v.gradient(px - d, py)) / (2.0 * d);
  hess.col(1) = (v.gradient(px, py + d) - v.gradient(px, py - d)) / (2.0 * d);
  return 0.5 * (hess + hess.transpose());
}

// 1/EA, 1/GA: 0 for a rigid direction (the elastica).
struct Compliance {
  double axial = 0.0, shear = 0.0;
  explicit Compliance(const Problem& problem)
      : axial(std::isfinite(problem.axial_stiffness) ? 1.0 / problem.axial_stiffness : 0.0),
        shear(std::isfinite(problem.shear_stiffness) ? 1.0 / problem.shear_stiffness : 0.0) {}
};

// The Reissner centreline tangent r' = (1 + a n.t) t + b (n.N) N (a = 1/EA, b = 1/GA; problem.hpp),
// t = (c, sn), N = (-sn, c), and its derivatives with respect to theta, n_x and n_y.
struct ReissnerTangent {
  double x, y;                      // r'
  double x_theta, y_theta;          // d r' / d theta
  double x_nx, x_ny, y_nx, y_ny;    // d r' / d n
};
ReissnerTangent reissner_tangent(const Compliance& k, double c, double sn, double nx, double ny) {
  const double nt = nx * c + ny * sn, nn = -nx * sn + ny * c;  // d nt/d theta = nn, d nn/d theta = -nt
  const double stretch = 1.0 + k.axial * nt, shear = k.shear * nn;
  ReissnerTangent r;
  r.x = stretch * c - shear * sn;
  r.y = stretch * sn + shear * c;
  r.x_theta = k.axial * nn * c - stretch * sn + k.shear * nt * sn - shear * c;
  r.y_theta = k.axial * nn * sn + stretch * c - k.shear * nt * c - shear * sn;
  r.x_nx = k.axial * c * c + k.shear * sn * sn;
  r.x_ny = (k.axial - k.shear) * sn * c;
  r.y_nx = r.x_ny;
  r.y_ny = k.axial * sn * sn + k.shear * c * c;
  return r;
}

// q' = F(s, q) (shooting.hpp) and, for the extended state, S' = (dF/dq) S: r' from reissner_tangent
// (for the elastica, 1/EA = 1/GA = 0 and r' = t) and m' = -(r' x n).e_z = r'_y n_x - r'_x n_y.
struct Rhs {
  const Problem* problem;
  Compliance compliance;

  explicit Rhs(const Problem& p) : problem(&p), compliance(p) {}

  template <class State>
  void operator()(const State& q, State& dq, double s) const {
    const auto [ei, kh] = coefficients_at(*problem, s);
    const double c = std::cos(q[kTheta]), sn = std::sin(q[kTheta]);
    const Potential& v = problem->potential;
    const double nx = q[kForceX], ny = q[kForceY];
    const ReissnerTangent r = reissner_tangent(compliance, c, sn, nx, ny);
    dq[kX] = r.x;
    dq[kY] = r.y;
    dq[kTheta] = kh + q[kMoment] / ei;
    dq[kMoment] = r.y * nx - r.x * ny;
    Eigen::Vector2d grad = Eigen::Vector2d::Zero();
    if (v.active()) grad = v.gradient(q[kX], q[kY]);
    dq[kForceX] = grad.x();
    dq[kForceY] = grad.y();
    if constexpr (std::tuple_size_v<State> == kExtendedSize) {
      Eigen::Matrix2d hess = Eigen::Matrix2d::Zero();
      if (v.active()) hess = potential_hessian(v, q[kX], q[kY]);
      const double m_theta = r.y_theta * nx - r.x_theta * ny;
      const double m_nx = r.y + r.y_nx * nx - r.x_nx * ny;
      const double m_ny = r.y_ny * nx - r.x - r.x_ny * ny;
      for (std::size_t j = 0; j < kUnknowns; ++j) {
        const double* sk = &q[kStateSize * (1 + j)];
        double* dsk = &dq[kStateSize * (1 + j)];
        dsk[kX] = r.x_theta * sk[kTheta] + r.x_nx * sk[kForceX] + r.x_ny * sk[kForceY];
        dsk[kY] = r.y_theta * sk[kTheta] + r.y_nx * sk[kForceX] + r.y_ny * sk[kForceY];
        dsk[kTheta] = sk[kMoment] / ei;
        dsk[kMoment] = m_theta * sk[kTheta] + m_nx * sk[kForceX] + m_ny * sk[kForceY];
        dsk[kForceX] = hess(0, 0) * sk[kX] + hess(0, 1) * sk[kY];
        dsk[kForceY] = hess(1, 0) * sk[kX] + hess(1, 1) * sk[kY];
      }
    }
  }
};

// Integrates q from s = 0 through the increasing targets (the last one is L), with every step
// ending exactly on the next target; observe(i, q) is called at target i.
template <class State, class Observer>
void integrate(const Problem& problem, const ShootingOptions& options, State& q,
               const std::vector<double>& targets, Observer&& observe) {
  using ErrorStepper = odeint::runge_kutta_fehlberg78<State>;
  using Checker = typename odeint::controlled_runge_kutta<ErrorStepper>::error_checker_type;
  odeint::controlled_runge_kutta<ErrorStepper> stepper(
      Checker(options.ode_abs_tolerance, options.ode_rel_tolerance));
  const Rhs rhs(problem);
  const double min_step = 1e-14 * problem.length;
  double s = 0.0;
  double ds = problem.length / 16.0;  // the controller shrinks it at once if needed
  std::size_t steps = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    const double target = targets[i];
    while (s < target) {
      double trial = std::min(ds, target - s);
      bool truncated = trial < ds;
      while (stepper.try_step(rhs, q, s, trial) == odeint::fail) {
        truncated = false;  // the controller's own (smaller) step size rules from here
        if (trial < min_step) throw IntegrationFailure{"step size underflow at s = " + format_value(s)};
      }
      // try_step advanced s by the accepted step and proposed the next one in `trial`; a step
      // shortened only to land on the target keeps the longer proposal for the next interval.
      // Landing within round-off of the target counts as on it.
      ds = truncated ? std::max(ds, trial) : trial;
      if (target - s <= 1e-14 * problem.length) s = target;
      for (double value : q)
        if (!std::isfinite(value)) throw IntegrationFailure{"non-finite state at s = " + format_value(s)};
      if (++steps > options.max_ode_steps)
        throw IntegrationFailure{"more than max_ode_steps = " + std::to_string(options.max_ode_steps) +
                                 " steps"};
    }
    observe(i, q);
  }
}

// Which components each end fixes (shooting.hpp), with their values.
struct BoundaryLayout {
  Plain start_state{};                         // prescribed components at s = 0 (unknowns: guess)
  std::array<std::size_t, kUnknowns> unknown{};  // components of q(0) that Newton solves for
  std::array<std::size_t, kUnknowns> end_index{};  // components of q(L) that are prescribed
  std::array<double, kUnknowns> end_value{};
  Plain scale{};                               // dimensionless units per component
};

BoundaryLayout make_layout(const Problem& problem, const ShootingGuess& guess) {
  BoundaryLayout b;
  b.start_state = {guess.x, guess.y, guess.theta, guess.moment, guess.force_x, guess.force_y};
  const RodEnd& a = problem.start;
  Plain& q0 = b.start_state;
  // At s = 0 the internal force and moment are minus the end load (n(0) = -F_0, m(0) = -M_0).
  switch (a.support) {
    case Support::Free:
      q0[kMoment] = -a.load.moment, q0[kForceX] = -a.load.force_x, q0[kForceY] = -a.load.force_y;
      b.unknown = {kX, kY, kTheta};
      break;
    case Support::Pinned:
      q0[kX] = a.x, q0[kY] = a.y, q0[kMoment] = -a.load.moment;
      b.unknown = {kTheta, kForceX, kForceY};
      break;
    case Support::Clamped:
      q0[kX] = a.x, q0[kY] = a.y, q0[kTheta] = a.angle;
      b.unknown = {kMoment, kForceX, kForceY};
      break;
    case Support::Sliding:
      q0[kY] = a.y, q0[kMoment] = -a.load.moment, q0[kForceX] = -a.load.force_x;
      b.unknown = {kX, kTheta, kForceY};
      break;
  }
  const RodEnd& e = problem.end;  // n(L) = F_L, m(L) = M_L
  switch (e.support) {
    case Support::Free:
      b.end_index = {kMoment, kForceX, kForceY};
      b.end_value = {e.load.moment, e.load.force_x, e.load.force_y};
      break;
    case Support::Pinned:
      b.end_index = {kX, kY, kMoment};
      b.end_value = {e.x, e.y, e.load.moment};
      break;
    case Support::Clamped:
      b.end_index = {kX, kY, kTheta};
      b.end_value = {e.x, e.y, e.angle};
      break;
    case Support::Sliding:
      b.end_index = {kY, kForceX, kMoment};
      b.end_value = {e.y, e.load.force_x, e.load.moment};
      break;
  }
  // Units: force F = max(EI/L^2, |end loads|, |guessed n(0)|), moment F L, so that the mismatch of
  // a heavily loaded rod is measured relative to its loads (its integration error scales with them).
  const double L = problem.length;
  const double ei = std::max(coefficients_at(problem, 0.0).stiffness, coefficients_at(problem, L).stiffness);
  const double force = std::max({ei / (L * L), std::hypot(a.load.force_x, a.load.force_y),
                                 std::hypot(e.load.force_x, e.load.force_y),
                                 std::abs(a.load.moment) / L, std::abs(e.load.moment) / L,
                                 std::hypot(guess.force_x, guess.force_y)});
  b.scale = {L, L, 1.0, force * L, force, force};
  return b;
}

// Residual r (dimensionless) and Jacobian dr/dz (z = u / scale) at the unknowns z.
struct Evaluation {
  Eigen::Vector3d r;
  Eigen::Matrix3d jacobian;
};

Extended initial_extended(const BoundaryLayout& b, const Eigen::Vector3d& z) {
  Extended q{};
  for (std::size_t i = 0; i < kStateSize; ++i) q[i] = b.start_state[i];
  for (std::size_t k = 0; k < kUnknowns; ++k) {
    q[b.unknown[k]] = z[Eigen::Index(k)] * b.scale[b.unknown[k]];
    q[kStateSize * (1 + k) + b.unknown[k]] = 1.0;  // S(0) = du/du
  }
  return q;
}

Eigen::Vector3d end_residual(const BoundaryLayout& b, const double* q_end) {
  Eigen::Vector3d r;
  for (std::size_t j = 0; j < kUnknowns; ++j)
    r[Eigen::Index(j)] = (q_end[b.end_index[j]] - b.end_value[j]) / b.scale[b.end_index[j]];
  return r;
}

Evaluation evaluate(const Problem& problem, const ShootingOptions& options, const BoundaryLayout& b,
                    const Eigen::Vector3d& z) {
  Extended q = initial_extended(b, z);
  integrate(problem, options, q, {problem.length}, [](std::size_t, const Extended&) {});
  Evaluation result;
  result.r = end_residual(b, q.data());
  for (std::size_t j = 0; j < kUnknowns; ++j)
    for (std::size_t k = 0; k < kUnknowns; ++k)
      result.jacobian(Eigen::Index(j), Eigen::Index(k)) = q[kStateSize * (1 + k) + b.end_index[j]] *
                                                          b.scale[b.unknown[k]] / b.scale[b.end_index[j]];
  return result;
}

// The converged initial data integrated once more, sampled at s_i = i L / N.
PlanarRodSolution sample(const Problem& problem, const ShootingOptions& options, const BoundaryLayout& b,
                         const Eigen::Vector3d& z, std::size_t iterations) {
  const std::size_t n = options.sample_points;
  const double L = problem.length;
  std::vector<double> targets(n);
  for (std::size_t i = 1; i <= n; ++i) targets[i - 1] = i == n ? L : L * double(i) / double(n);

  PlanarRodSolution out;
  out.method = "shooting (Boost.Odeint RKF78, Newton with variational equations)";
  out.length = L;
  const Potential& v = problem.potential;
  auto record = [&](double s, const Plain& q) {
    const auto [ei, kh] = coefficients_at(problem, s);
    const double c = std::cos(q[kTheta]), sn = std::sin(q[kTheta]);
    out.s.push_back(s);
    out.x.push_back(q[kX]);
    out.y.push_back(q[kY]);
    out.theta.push_back(q[kTheta]);
    out.kappa.push_back(kh + q[kMoment] / ei);
    out.bending_stiffness.push_back(ei);
    out.natural_curvature.push_back(kh);
    out.potential.push_back(v.active() ? v.value(q[kX], q[kY]) : 0.0);
    out.force_x.push_back(q[kForceX]);
    out.force_y.push_back(q[kForceY]);
    out.axial_force.push_back(q[kForceX] * c + q[kForceY] * sn);
    out.shear_force.push_back(-q[kForceX] * sn + q[kForceY] * c);
  };
  out.axial_stiffness = problem.axial_stiffness;
  out.shear_stiffness = problem.shear_stiffness;
  Plain q = b.start_state;
  for (std::size_t k = 0; k < kUnknowns; ++k) q[b.unknown[k]] = z[Eigen::Index(k)] * b.scale[b.unknown[k]];
  record(0.0, q);
  try {
    integrate(problem, options, q, targets, [&](std::size_t i, const Plain& qi) { record(targets[i], qi); });
  } catch (const IntegrationFailure& failure) {
    throw SolverError(kMethod, "final integration failed: " + failure.reason, iterations,
                      std::numeric_limits<double>::quiet_NaN());
  }
  out.iterations = iterations;
  out.residual = end_residual(b, q.data()).lpNorm<Eigen::Infinity>();
  return out;
}

}  // namespace

void validate(const ShootingOptions& options) {
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  if (!(options.ode_abs_tolerance > 0.0 && options.ode_abs_tolerance <= 1e-3))
    throw InputError("ode_abs_tolerance", "invalid parameter 'ode_abs_tolerance' = " +
                                              format_value(options.ode_abs_tolerance) +
                                              ": must be in (0, 1e-3]");
  if (!(options.ode_rel_tolerance > 0.0 && options.ode_rel_tolerance <= 1e-3))
    throw InputError("ode_rel_tolerance", "invalid parameter 'ode_rel_tolerance' = " +
                                              format_value(options.ode_rel_tolerance) +
                                              ": must be in (0, 1e-3]");
  require_at_least("max_iterations", options.max_iterations, 1);
  require_at_least("max_ode_steps", options.max_ode_steps, 1);
  require_at_least("sample_points", options.sample_points, 1);
}

ShootingGuess shooting_guess_from(const PlanarRodSolution& solution, const Problem& problem) {
  if (solution.s.empty())
    throw InputError("solution.s", "invalid parameter 'solution.s': needs at least one node");
  const auto first = [&](const std::vector<double>& values, const char* name) {
    if (values.empty()) throw InputError(std::string("solution.") + name,
                                         std::string("invalid parameter 'solution.") + name +
                                             "': needs at least one node");
    return values.front();
  };
  ShootingGuess guess;
  guess.x = first(solution.x, "x");
  guess.y = first(solution.y, "y");
  guess.theta = first(solution.theta, "theta");
  const double s0 = solution.s.front();
  const double kappa = first(solution.kappa, "kappa");
  guess.moment = bending_stiffness_at(problem, s0) * (kappa - natural_curvature_at(problem, s0));
  guess.force_x = first(solution.force_x, "force_x");
  guess.force_y = first(solution.force_y, "force_y");
  return guess;
}

ShootingResidual shooting_residual(const Problem& problem, const ShootingOptions& options,
                                   const ShootingGuess& guess) {
  validate(problem);
  validate(options);
  const BoundaryLayout b = make_layout(problem, guess);
  Eigen::Vector3d z;
  ShootingResidual out;
  for (std::size_t k = 0; k < kUnknowns; ++k) {
    out.unknown_scale[Eigen::Index(k)] = b.scale[b.unknown[k]];
    z[Eigen::Index(k)] = b.start_state[b.unknown[k]] / b.scale[b.unknown[k]];
  }
  try {
    const Evaluation e = evaluate(problem, options, b, z);
    out.residual = e.r;
    out.jacobian = e.jacobian;
  } catch (const IntegrationFailure& failure) {
    throw SolverError(kMethod, "integration failed: " + failure.reason, 0,
                      std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

PlanarRodSolution solve_shooting(const Problem& problem, const ShootingOptions& options,
                                 const ShootingGuess& guess) {
  validate(problem);
  validate(options);
  for (double value : {guess.x, guess.y, guess.theta, guess.moment, guess.force_x, guess.force_y})
    require_finite("guess", value);
  const BoundaryLayout b = make_layout(problem, guess);

  Eigen::Vector3d z;
  for (std::size_t k = 0; k < kUnknowns; ++k)
    z[Eigen::Index(k)] = b.start_state[b.unknown[k]] / b.scale[b.unknown[k]];

  Evaluation current;
  try {
    current = evaluate(problem, options, b, z);
  } catch (const IntegrationFailure& failure) {
    throw SolverError(kMethod, "integration from the initial guess failed: " + failure.reason, 0,
                      std::numeric_limits<double>::quiet_NaN());
  }
  std::size_t iterations = 0;
  while (current.r.lpNorm<Eigen::Infinity>() > options.tolerance) {
    if (iterations == options.max_iterations)
      throw SolverError(kMethod, "Newton did not reach the tolerance " + format_value(options.tolerance),
                        iterations, current.r.lpNorm<Eigen::Infinity>());
    // Minimum-norm Newton step: unknowns the residuals do not see stay put.
    const Eigen::Vector3d step = current.jacobian.completeOrthogonalDecomposition().solve(-current.r);
    const double norm = current.r.norm();
    bool accepted = false;
    for (double t = 1.0; t >= 0x1p-30; t *= 0.5) {
      try {
        Evaluation trial = evaluate(problem, options, b, z + t * step);
        if (trial.r.allFinite() && trial.r.norm() <= (1.0 - 1e-4 * t) * norm) {
          z += t * step;
          current = trial;
          accepted = true;
          break;
        }
      } catch (const IntegrationFailure&) {
        // The trial left the region where the ODE can be integrated: shorten the step.
      }
    }
    ++iterations;
    if (!accepted)
      throw SolverError(kMethod, "damped Newton step made no progress (no solution near the guess, or "
                                 "the tolerance is below the integration error)",
                        iterations, current.r.lpNorm<Eigen::Infinity>());
  }
  // One more full Newton step once the tolerance is met: Newton converges quadratically, so this
  // takes the boundary mismatch from <= tolerance down to the integration error (measured: the
  // errors against the closed forms drop from ~1e-12 to ~1e-14). Kept only if it does not
  // increase the mismatch.
  if (iterations < options.max_iterations) {
    try {
      const Eigen::Vector3d step = current.jacobian.completeOrthogonalDecomposition().solve(-current.r);
      const Evaluation trial = evaluate(problem, options, b, z + step);
      if (trial.r.allFinite() && trial.r.norm() <= current.r.norm()) {
        z += step;
        ++iterations;
      }
    } catch (const IntegrationFailure&) {
      // Keep the converged data.
    }
  }
  return sample(problem, options, b, z, iterations);
}

}  // namespace rodvv::solvers::elastica2d

#include "rodvv/solvers/elastica2d/newton.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::elastica2d::detail {

namespace {
constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kArmijo = 1e-4;
constexpr double kMinStep = 0x1p-30;
}  // namespace

using Eigen::VectorXd;

std::string method_name(Scheme scheme) { return "elastica2d-" + std::string(scheme_id(scheme)); }

VectorXd initial_state(const DiscreteLagrangian& lag, const Problem& problem,
                       const InitialGuess& guess) {
  const std::size_t n = lag.elements();
  const double h = lag.element_length();
  VectorXd z = VectorXd::Zero(static_cast<Eigen::Index>(lag.size()));
  const double default_angle = problem.start.support == Support::Clamped ? problem.start.angle : 0.0;
  auto theta = [&](double s) {
    const double value = guess.theta ? guess.theta(s) : default_angle;
    if (!std::isfinite(value))
      throw InputError("guess.theta", "invalid parameter 'guess.theta' = " + format_value(value) +
                                          " at s = " + format_value(s) + ": must be finite");
    return value;
  };
  if (lag.scheme() == Scheme::Polygon) {
    for (std::size_t i = 0; i < n; ++i) z[lag.angle(i)] = theta((static_cast<double>(i) + 0.5) * h);
  } else {
    for (std::size_t i = 0; i <= n; ++i)
      z[lag.angle(i)] = theta(i == n ? problem.length : static_cast<double>(i) * h);
  }
  require_finite("guess.x0", guess.x0);
  require_finite("guess.y0", guess.y0);
  double x0 = guess.x0, y0 = guess.y0;
  switch (problem.start.support) {
    case Support::Pinned:
    case Support::Clamped:
      x0 = problem.start.x;
      y0 = problem.start.y;
      break;
    case Support::Sliding:
      y0 = problem.start.y;
      break;
    case Support::Free:
      break;
  }
  z[lag.x(0)] = x0;
  z[lag.y(0)] = y0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d g = lag.element_chord(z, i);
    z[lag.x(i + 1)] = z[lag.x(i)] + g.x();
    z[lag.y(i + 1)] = z[lag.y(i)] + g.y();
  }
  // Edge forces from the discrete force balance n_{i-1} = n_i - w_i lambda grad V(r_i), integrated
  // from the end force where the end's dead load fixes it (Free: both components; Sliding: x),
  // otherwise from 0. Starting the multipliers at 0 instead would drop the geometric stiffness
  // -n.g'' and leave the KKT matrix singular for, e.g., a rod hanging from a pin.
  const double lambda = lag.load_factor();
  Eigen::Vector2d force(0.0, 0.0);
  if (problem.end.support == Support::Free || problem.end.support == Support::Sliding)
    force.x() = lambda * problem.end.load.force_x;
  if (problem.end.support == Support::Free) force.y() = lambda * problem.end.load.force_y;
  const bool potential = problem.potential.active();
  for (std::size_t k = n; k-- > 0;) {
    if (potential) {
      const double w = (k + 1 == n ? 0.5 : 1.0) * h * lambda;
      force -= w * problem.potential.gradient(z[lag.x(k + 1)], z[lag.y(k + 1)]);
    }
    z[lag.nx(k)] = force.x();
    z[lag.ny(k)] = force.y();
  }
  return z;
}

VectorXd residual_scales(const DiscreteLagrangian& lag) {
  const double L = lag.problem().length, EI = lag.node_stiffness(0);
  VectorXd scale = VectorXd::Ones(static_cast<Eigen::Index>(lag.size()));
  const std::size_t n = lag.elements();
  for (std::size_t i = 0; i <= n; ++i) scale[lag.x(i)] = scale[lag.y(i)] = EI / (L * L);
  for (std::size_t j = 0; j < lag.angle_count(); ++j) scale[lag.angle(j)] = EI / L;
  for (std::size_t e = 0; e < n; ++e) scale[lag.nx(e)] = scale[lag.ny(e)] = L;
  for (std::size_t k = 0; k < lag.rows().size(); ++k) {
    const std::size_t slot = (lag.rows()[k].dof - lag.x(0)) % 5;  // 0, 1: x, y; 2: an angle
    scale[lag.row_multiplier(k)] = slot == 2 ? 1.0 : L;
  }
  return scale;
}

VectorXd unknown_scales(const DiscreteLagrangian& lag) {
  const double energy = lag.node_stiffness(0) / lag.problem().length;  // EI/L
  return residual_scales(lag).cwiseInverse() * energy;
}

void newton(const DiscreteLagrangian& lag, VectorXd& z, const SolverOptions& options,
            NewtonState& state) {
  const std::string method = method_name(lag.scheme());
  const VectorXd scale = residual_scales(lag), unknown = unknown_scales(lag);
  const auto scaled = [&scale](const VectorXd& f) { return f.cwiseQuotient(scale).eval(); };
  for (std::size_t it = 0;; ++it) {
    const VectorXd f = lag.gradient(z);
    const double r = scaled(f).lpNorm<Eigen::Infinity>();
    state.residual = r;
    if (!std::isfinite(r))
      throw SolverError(method, "KKT residual became non-finite", state.iterations, r);
    if (r <= options.tolerance) return;
    check_time_budget(method, state.iterations, r);
    if (it == options.max_iterations)
      throw SolverError(method,
                        "Newton did not converge in " + std::to_string(options.max_iterations) +
                            " iterations (||grad L||_inf = " + format_value(r) + " > tolerance " +
                            format_value(options.tolerance) + ")",
                        state.iterations, r);
    const Eigen::SparseMatrix<double> jac = lag.hessian(z);
    if (!state.lu.factorize(jac))
      throw SolverError(method, "KKT matrix is singular (zero pivot in the banded LU)",
                        state.iterations, r);
    const VectorXd dz = state.lu.solve(-f);
    ++state.iterations;
    if (!dz.allFinite())
      throw SolverError(method, "Newton step is non-finite", state.iterations, r);
    // In the problem's own units (unknown_scales), like the residual.
    if (dz.cwiseQuotient(unknown).lpNorm<Eigen::Infinity>() <=
        64.0 * kEps * (1.0 + z.cwiseQuotient(unknown).lpNorm<Eigen::Infinity>())) {
      z += dz;  // already at round-off: the residual cannot be reduced further
      state.residual = scaled(lag.gradient(z)).lpNorm<Eigen::Infinity>();
      return;
    }
    // Backtracking on the merit ||D grad L||_2 (D = 1/scale): the Newton step is a descent
    // direction for any such diagonal weighting.
    const double merit = scaled(f).norm();
    double alpha = 1.0;
    for (;;) {
      const VectorXd trial = z + alpha * dz;
      const double m = scaled(lag.gradient(trial)).norm();
      if (std::isfinite(m) && m <= (1.0 - kArmijo * alpha) * merit) {
        z = trial;
        break;
      }
      alpha *= 0.5;
      if (alpha < kMinStep)
        throw SolverError(method, "line search failed: no decrease of ||grad L|| along the Newton step",
                          state.iterations, r);
    }
  }
}

PlanarRodSolution fill_solution(const DiscreteLagrangian& lag, const VectorXd& z) {
  const Problem& p = lag.problem();
  const std::size_t n = lag.elements();
  const double h = lag.element_length();
  const bool polygon = lag.scheme() == Scheme::Polygon;
  PlanarRodSolution sol;
  sol.method = method_name(lag.scheme());
  sol.length = p.length;
  const std::size_t nodes = n + 1;
  for (auto* v : {&sol.s, &sol.x, &sol.y, &sol.theta, &sol.kappa, &sol.bending_stiffness,
                  &sol.natural_curvature, &sol.potential, &sol.force_x, &sol.force_y,
                  &sol.axial_force})
    v->assign(nodes, 0.0);
  sol.edge_axial_force.assign(n, 0.0);
  sol.edge_shear_force.assign(n, 0.0);
  sol.shear_force.assign(nodes, 0.0);
  sol.axial_stiffness = p.axial_stiffness;
  sol.shear_stiffness = p.shear_stiffness;

  for (std::size_t i = 0; i <= n; ++i) {
    sol.s[i] = i == n ? p.length : static_cast<double>(i) * h;
    sol.x[i] = z[lag.x(i)];
    sol.y[i] = z[lag.y(i)];
    sol.bending_stiffness[i] = lag.node_stiffness(i);
    sol.natural_curvature[i] = lag.node_natural_curvature(i);
    if (p.potential.active()) sol.potential[i] = p.potential.value(sol.x[i], sol.y[i]);
  }
  auto a = [&](std::size_t j) { return z[lag.angle(j)]; };
  const bool clamp0 = p.start.support == Support::Clamped;
  const bool clamp1 = p.end.support == Support::Clamped;
  // Natural end curvatures: EI (kappa - kappa_hat) = -M_0 at s = 0 and = +M_L at s = L.
  const double natural0 = sol.natural_curvature[0] - p.start.load.moment / sol.bending_stiffness[0];
  const double natural1 = sol.natural_curvature[n] + p.end.load.moment / sol.bending_stiffness[n];
  if (polygon) {
    for (std::size_t i = 1; i < n; ++i) {
      sol.theta[i] = 0.5 * (a(i - 1) + a(i));
      sol.kappa[i] = (a(i) - a(i - 1)) / h;
    }
    if (clamp0) {
      // Clamp moment = derivative of the half-cell clamp term, EI (2 (phi_0 - a) / h - kappa_hat):
      // the discrete moment balance makes it as accurate as the interior moments (O(h^2)).
      sol.kappa[0] = 2.0 * (a(0) - p.start.angle) / h;
      sol.theta[0] = p.start.angle;
    } else {
      sol.kappa[0] = natural0;
      sol.theta[0] = a(0) - 0.5 * h * natural0;
    }
    if (clamp1) {
      sol.kappa[n] = 2.0 * (p.end.angle - a(n - 1)) / h;
      sol.theta[n] = p.end.angle;
    } else {
      sol.kappa[n] = natural1;
      sol.theta[n] = a(n - 1) + 0.5 * h * natural1;
    }
  } else {
    std::vector<double> ke(n);
    for (std::size_t e = 0; e < n; ++e) ke[e] = (a(e + 1) - a(e)) / h;
    for (std::size_t i = 0; i <= n; ++i) sol.theta[i] = a(i);
    for (std::size_t i = 1; i < n; ++i) sol.kappa[i] = 0.5 * (ke[i - 1] + ke[i]);
    // Clamped end: the multiplier of the angle row is the reaction moment (discrete moment
    // balance at the end node): m(0) = mu_0, m(L) = -mu_L.
    sol.kappa[0] = natural0;
    sol.kappa[n] = natural1;
    for (std::size_t k = 0; k < lag.rows().size(); ++k) {
      const double mu = z[lag.row_multiplier(k)];
      if (clamp0 && lag.rows()[k].dof == lag.angle(0))
        sol.kappa[0] = sol.natural_curvature[0] + mu / sol.bending_stiffness[0];
      if (clamp1 && lag.rows()[k].dof == lag.angle(n))
        sol.kappa[n] = sol.natural_curvature[n] - mu / sol.bending_stiffness[n];
    }
  }

  // Internal force: edge multipliers; nodes = mean of the edges; ends moved half an element.
  std::vector<Eigen::Vector2d> edge_force(n);
  for (std::size_t i = 0; i < n; ++i) {
    edge_force[i] = Eigen::Vector2d(z[lag.nx(i)], z[lag.ny(i)]);
    const double angle = polygon ? a(i) : 0.5 * (a(i) + a(i + 1));
    sol.edge_axial_force[i] = edge_force[i].x() * std::cos(angle) + edge_force[i].y() * std::sin(angle);
    sol.edge_shear_force[i] = -edge_force[i].x() * std::sin(angle) + edge_force[i].y() * std::cos(angle);
  }
  for (std::size_t i = 1; i < n; ++i) {
    const Eigen::Vector2d f = 0.5 * (edge_force[i - 1] + edge_force[i]);
    sol.force_x[i] = f.x();
    sol.force_y[i] = f.y();
    sol.axial_force[i] = 0.5 * (sol.edge_axial_force[i - 1] + sol.edge_axial_force[i]);
    sol.shear_force[i] = 0.5 * (sol.edge_shear_force[i - 1] + sol.edge_shear_force[i]);
  }
  Eigen::Vector2d f0 = edge_force[0], f1 = edge_force[n - 1];
  if (p.potential.active()) {  // n_0 = n(0) + (h/2) grad V(r_0);  n(L) = n_{N-1} + (h/2) grad V(r_N)
    f0 -= 0.5 * h * p.potential.gradient(sol.x[0], sol.y[0]);
    f1 += 0.5 * h * p.potential.gradient(sol.x[n], sol.y[n]);
  }
  sol.force_x[0] = f0.x();
  sol.force_y[0] = f0.y();
  sol.force_x[n] = f1.x();
  sol.force_y[n] = f1.y();
  sol.axial_force[0] = f0.x() * std::cos(sol.theta[0]) + f0.y() * std::sin(sol.theta[0]);
  sol.axial_force[n] = f1.x() * std::cos(sol.theta[n]) + f1.y() * std::sin(sol.theta[n]);
  sol.shear_force[0] = -f0.x() * std::sin(sol.theta[0]) + f0.y() * std::cos(sol.theta[0]);
  sol.shear_force[n] = -f1.x() * std::sin(sol.theta[n]) + f1.y() * std::cos(sol.theta[n]);
  return sol;
}

}  // namespace rodvv::solvers::elastica2d::detail

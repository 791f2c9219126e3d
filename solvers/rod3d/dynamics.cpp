#include "rodvv/solvers/rod3d/dynamics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/linearized.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::solvers::rod3d {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kMaxTwistChange = 0.25 * std::numbers::pi;  // per step: the energy's chart needs < pi/2

bool is_multiplier(const DofLayout& layout, std::size_t k) {
  return layout.multipliers && k < layout.size() - 3 && k % layout.stride() == 4;
}
bool is_angle(const DofLayout& layout, std::size_t k) { return k < layout.size() - 3 && k % layout.stride() == 3; }

std::string method_name(TimeIntegrator method) {
  return std::string("rod3d ") + integrator_name(method) + " (Newton, banded LU)";
}

// What one step needs besides the unknown.
struct StepContext {
  const RodModel& model;
  const DynamicState& state;
  double h;
  TimeIntegrator method;
  DofLayout layout;
  VecX mass;
  std::vector<char> held;
  double ell;

  StepContext(const RodModel& m, const DynamicState& s, double step, TimeIntegrator how)
      : model(m), state(s), h(step), method(how), layout(m), mass(lumped_mass(m)), held(layout.size(), 0),
        ell(rest_edge_length(m)) {
    for (std::size_t k : held_dofs(m)) held[k] = 1;
    if (s.rod.elements() != m.elements || s.velocity.size() != Eigen::Index(layout.size()))
      throw InputError("state", "invalid parameter 'state': its sizes do not match the model's " +
                                    std::to_string(m.elements) + " elements (use make_dynamic_state)");
  }
  bool midpoint() const noexcept { return method == TimeIntegrator::ImplicitMidpoint; }
  double inertia_factor() const noexcept { return midpoint() ? 2.0 : 1.0; }
  // Where the forces are evaluated (chart of z_n): z_n + y (Euler) or z_n + y/2 (midpoint), the
  // multipliers at lambda_n + y_lambda in both.
  VecX evaluation_point(const VecX& y) const {
    if (!midpoint()) return y;
    VecX w = y;
    for (std::size_t k = 0; k < layout.size(); ++k)
      if (!is_multiplier(layout, k)) w[Eigen::Index(k)] *= 0.5;
    return w;
  }
};

VecX residual(const StepContext& c, const VecX& y) {
  VecX r = chart_residual(c.model, c.state.rod, c.evaluation_point(y), 1.0);
  r += (c.inertia_factor() / (c.h * c.h)) * c.mass.cwiseProduct(y - c.h * c.state.velocity);
  if (c.midpoint() && c.layout.multipliers)
    for (std::size_t j = 0; j < c.model.elements; ++j) {
      const Vec3 e = (c.state.rod.position[j + 1] + y.segment<3>(Eigen::Index(c.layout.vertex(j + 1)))) -
                     (c.state.rod.position[j] + y.segment<3>(Eigen::Index(c.layout.vertex(j))));
      r[Eigen::Index(c.layout.multiplier(j))] = e.norm() - c.ell;
    }
  for (std::size_t k = 0; k < c.held.size(); ++k)
    if (c.held[k]) r[Eigen::Index(k)] = 0.0;
  return r;
}

Eigen::SparseMatrix<double> jacobian(const StepContext& c, const VecX& y) {
  VecX r;
  Eigen::SparseMatrix<double> J;
  chart_system(c.model, c.state.rod, c.evaluation_point(y), 1.0, r, J);
  std::vector<Eigen::Triplet<double>> triplets;
  triplets.reserve(std::size_t(J.nonZeros()) + c.layout.size() + 6 * c.model.elements);
  const bool midpoint = c.midpoint();
  for (int col = 0; col < J.outerSize(); ++col)
    for (Eigen::SparseMatrix<double>::InnerIterator it(J, col); it; ++it) {
      const auto row = std::size_t(it.row()), k = std::size_t(it.col());
      if (c.held[row]) continue;
      if (midpoint && is_multiplier(c.layout, row)) continue;  // constraint rows at z_n + y, below
      const double scale = (midpoint && !is_multiplier(c.layout, k)) ? 0.5 : 1.0;
      triplets.emplace_back(int(row), int(k), scale * it.value());
    }
  const double factor = c.inertia_factor() / (c.h * c.h);
  for (std::size_t k = 0; k < c.layout.size(); ++k) {
    if (c.held[k]) {
      triplets.emplace_back(int(k), int(k), 1.0);
    } else if (c.mass[Eigen::Index(k)] > 0.0) {
      triplets.emplace_back(int(k), int(k), factor * c.mass[Eigen::Index(k)]);
    }
  }
  if (midpoint && c.layout.multipliers)
    for (std::size_t j = 0; j < c.model.elements; ++j) {
      const std::size_t row = c.layout.multiplier(j);
      if (c.held[row]) continue;
      const std::size_t a = c.layout.vertex(j), b = c.layout.vertex(j + 1);
      const Vec3 t = ((c.state.rod.position[j + 1] + y.segment<3>(Eigen::Index(b))) -
                      (c.state.rod.position[j] + y.segment<3>(Eigen::Index(a))))
                         .normalized();
      for (int q = 0; q < 3; ++q) {
        triplets.emplace_back(int(row), int(b + q), t[q]);
        triplets.emplace_back(int(row), int(a + q), -t[q]);
      }
    }
  const auto n = Eigen::Index(c.layout.size());
  Eigen::SparseMatrix<double> out(n, n);
  out.setFromTriplets(triplets.begin(), triplets.end());
  return out;
}

struct Scales {
  double force = 1.0, moment = 1.0, length = 1.0;
};

Scales residual_scales(const StepContext& c, const VecX& y) {
  const RodModel& m = c.model;
  const double L = m.length;
  double force = m.stiffness.maxCoeff() / (L * L);
  force = std::max(force, dead_load_scale(m, 1.0));
  double speed = 0.0, spin = 0.0;
  for (std::size_t k = 0; k < c.layout.size(); ++k) {
    const double v = std::abs(c.state.velocity[Eigen::Index(k)]);
    if (is_multiplier(c.layout, k)) {
      force = std::max(force, std::abs(c.state.rod.multiplier[k / c.layout.stride()] + y[Eigen::Index(k)]));
    } else if (is_angle(c.layout, k)) {
      spin = std::max(spin, v);
    } else {
      speed = std::max(speed, v);
    }
  }
  force = std::max(force, m.line_density * c.ell * speed / c.h);
  Scales s;
  s.force = force;
  s.moment = std::max(force * L, m.twist_inertia * c.ell * spin / c.h);
  s.length = L;
  return s;
}

double scaled_measure(const StepContext& c, const VecX& r, const Scales& s) {
  double worst = 0.0;
  for (std::size_t k = 0; k < c.layout.size(); ++k) {
    if (c.held[k]) continue;
    const double scale = is_multiplier(c.layout, k) ? s.length : is_angle(c.layout, k) ? s.moment : s.force;
    worst = std::max(worst, std::abs(r[Eigen::Index(k)]) / scale);
  }
  return worst;
}

// The round-off floor of the scaled residual, as in statics.cpp: an edge vector carries the error
// eps |x| of its end positions, the integrated curvature eps |x| N / L, a vertex force
// K kappa_err / ebar^2 relative to K / L^2 grows like N^3 eps |x| / L (measured 1.1 N^3 eps there).
double round_off_floor(const StepContext& c) {
  double extent = c.model.length;
  for (const Vec3& x : c.state.rod.position) extent = std::max(extent, x.cwiseAbs().maxCoeff());
  const double n = double(c.model.elements);
  return 8.0 * kEps * n * n * n * extent / c.model.length;
}

double twist_change(const StepContext& c, const VecX& y) {
  double change = 0.0;
  (void)displaced(c.model, c.state.rod, y, &change);
  return change;
}

void validate_step(const RodModel& model, double h, const DynamicOptions& options) {
  validate(model);
  if (has_self_contact(model) && is_hard(model.self_contact))
    throw InputError("self_contact.law", "invalid parameter 'self_contact.law': the dynamics takes the barrier law "
                                         "only (hard self-contact is solved by the statics)");
  require_positive("h", h);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
}

}  // namespace

const char* integrator_name(TimeIntegrator method) {
  return method == TimeIntegrator::ImplicitEuler ? "implicit Euler" : "implicit midpoint";
}

DynamicState make_dynamic_state(const RodModel& model, const RodState& rod, const VecX& velocity) {
  validate(model);
  require_positive("twist_inertia", model.twist_inertia);
  const DofLayout layout(model);
  if (rod.elements() != model.elements || rod.position.size() != model.elements + 1 ||
      rod.reference_director.size() != model.elements || rod.reference_twist.size() != model.elements + 1)
    throw InputError("state", "invalid parameter 'state': its sizes do not match the model's " +
                                  std::to_string(model.elements) + " elements");
  DynamicState state;
  state.rod = rod;
  if (layout.multipliers && state.rod.multiplier.size() != model.elements) state.rod.multiplier.assign(model.elements, 0.0);
  if (velocity.size() == 0) {
    state.velocity = VecX::Zero(Eigen::Index(layout.size()));
    return state;
  }
  if (velocity.size() != Eigen::Index(layout.size()))
    throw InputError("velocity", "invalid parameter 'velocity': must be empty or hold " + std::to_string(layout.size()) +
                                     " values (DofLayout), got " + std::to_string(velocity.size()));
  std::vector<char> held(layout.size(), 0);
  for (std::size_t k : held_dofs(model)) held[k] = 1;
  for (std::size_t k = 0; k < layout.size(); ++k) {
    const double v = velocity[Eigen::Index(k)];
    require_finite("velocity", v);
    if ((held[k] || is_multiplier(layout, k)) && v != 0.0)
      throw InputError("velocity", "invalid parameter 'velocity': entry " + std::to_string(k) +
                                       " is a held dof or a multiplier and must be 0, got " + format_value(v));
  }
  state.velocity = velocity;
  return state;
}

VecX step_residual(const RodModel& model, const DynamicState& state, double h, TimeIntegrator method, const VecX& y) {
  validate_step(model, h, {});
  const StepContext c(model, state, h, method);
  if (y.size() != Eigen::Index(c.layout.size()))
    throw InputError("y", "invalid parameter 'y': must hold " + std::to_string(c.layout.size()) + " values");
  return residual(c, y);
}

Eigen::SparseMatrix<double> step_jacobian(const RodModel& model, const DynamicState& state, double h,
                                          TimeIntegrator method, const VecX& y) {
  validate_step(model, h, {});
  const StepContext c(model, state, h, method);
  if (y.size() != Eigen::Index(c.layout.size()))
    throw InputError("y", "invalid parameter 'y': must hold " + std::to_string(c.layout.size()) + " values");
  return jacobian(c, y);
}

DynamicState step(const RodModel& model, const DynamicState& state, double h, TimeIntegrator method,
                  const DynamicOptions& options, StepReport* report) {
  validate_step(model, h, options);
  const StepContext c(model, state, h, method);
  const auto n = Eigen::Index(c.layout.size());
  const std::string where = "step " + std::to_string(state.steps + 1) + " (t = " + format_value(state.time) +
                            ", h = " + format_value(h) + ")";
  const std::string budget_method = "rod3d dynamics " + where;  // named once, checked every iteration
  const double floor = 64.0 * kEps * model.length;

  // Predictor: constant velocity (z_n + h v_n), unless it leaves the chart of z_n.
  VecX y = VecX::Zero(n);
  for (std::size_t k = 0; k < c.layout.size(); ++k)
    if (!c.held[k] && !is_multiplier(c.layout, k)) y[Eigen::Index(k)] = h * state.velocity[Eigen::Index(k)];
  if (!(twist_change(c, y) <= kMaxTwistChange)) y.setZero();

  elastica2d::BandedLU lu;
  std::size_t iterations = 0, factorizations = 0;
  bool factorized = false;  // lu holds a Jacobian of this step
  bool fresh = false;       // ... evaluated at the current y
  bool converged = false;
  VecX r = residual(c, y);
  double measure = scaled_measure(c, r, residual_scales(c, y));
  while (true) {
    check_time_budget(budget_method, iterations, measure);
    if (!std::isfinite(measure)) break;
    if (measure <= options.tolerance) {
      converged = true;
      break;
    }
    if (iterations >= options.max_iterations) break;
    // At the round-off floor the residual cannot show further progress: one more full Newton step
    // with a fresh Jacobian, without the line search, and the step is done.
    const bool at_floor = measure <= round_off_floor(c);
    if (at_floor && !fresh) factorized = false;
    if (!factorized) {
      if (!lu.factorize(jacobian(c, y))) break;
      factorized = fresh = true;
      ++factorizations;
    }
    VecX delta = -lu.solve(r);
    for (std::size_t k = 0; k < c.held.size(); ++k)
      if (c.held[k]) delta[Eigen::Index(k)] = 0.0;
    if (!delta.allFinite()) break;
    ++iterations;
    if (at_floor) {
      y += delta;
      r = residual(c, y);
      measure = scaled_measure(c, r, residual_scales(c, y));
      converged = std::isfinite(measure);
      break;
    }
    double alpha = 1.0;
    bool accepted = false;
    const double previous = measure;
    for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
      const VecX trial = y + alpha * delta;
      if (!(twist_change(c, trial) <= kMaxTwistChange)) continue;
      VecX r_trial = residual(c, trial);
      const double m_trial = scaled_measure(c, r_trial, residual_scales(c, trial));
      if (std::isfinite(m_trial) && m_trial <= (1.0 - 1e-4 * alpha) * measure) {
        y = trial;
        r = std::move(r_trial);
        measure = m_trial;
        accepted = true;
        break;
      }
    }
    const double correction = delta.cwiseAbs().maxCoeff();
    if (!accepted) {
      if (!fresh) {  // a Jacobian from an earlier iterate: retry with the current one
        factorized = false;
        continue;
      }
      converged = correction <= floor;  // no decrease, but already at round-off
      break;
    }
    if (alpha * correction <= floor) {
      converged = true;
      break;
    }
    // Keep the factorisation while it contracts the residual tenfold per iteration with full steps.
    fresh = false;
    if (!options.reuse_jacobian || alpha < 1.0 || measure > 0.1 * previous) factorized = false;
  }
  if (report) {
    report->iterations = iterations;
    report->factorizations = factorizations;
    report->residual = measure;
  }
  if (!converged)
    throw SolverError(method_name(method), where + ": Newton did not converge", iterations, measure);

  DynamicState next;
  double change = 0.0;
  next.rod = displaced(model, state.rod, y, &change);
  if (!(change <= kMaxTwistChange))
    throw SolverError(method_name(method),
                      where + ": a reference twist changes by " + format_value(change) +
                          " rad in one step (> pi/4, the energy's chart): reduce h",
                      iterations, measure);
  next.velocity = VecX::Zero(n);
  for (std::size_t k = 0; k < c.layout.size(); ++k) {
    if (c.held[k] || is_multiplier(c.layout, k)) continue;
    const auto i = Eigen::Index(k);
    next.velocity[i] = c.midpoint() ? 2.0 * y[i] / h - state.velocity[i] : y[i] / h;
  }
  next.time = state.time + h;
  next.steps = state.steps + 1;
  return next;
}

DynamicEnergy dynamic_energy(const RodModel& model, const DynamicState& state) {
  const VecX mass = lumped_mass(model);
  if (state.velocity.size() != mass.size())
    throw InputError("state", "invalid parameter 'state': the velocity must hold " + std::to_string(mass.size()) +
                                  " values");
  DynamicEnergy e;
  e.kinetic = 0.5 * state.velocity.dot(mass.cwiseProduct(state.velocity));
  e.potential = energy(model, state.rod).potential();
  return e;
}

Vec3 linear_momentum(const RodModel& model, const DynamicState& state) {
  const VecX mass = lumped_mass(model);
  const DofLayout layout(model);
  if (state.velocity.size() != mass.size())
    throw InputError("state", "invalid parameter 'state': the velocity must hold " + std::to_string(mass.size()) +
                                  " values");
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i <= model.elements; ++i) {
    const auto k = Eigen::Index(layout.vertex(i));
    p += mass[k] * state.velocity.segment<3>(k);
  }
  return p;
}

}  // namespace rodvv::solvers::rod3d

#include "rodvv/solvers/elastica2d/sleeve.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/elastica2d/free_arm.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

using Eigen::Vector2d;
using Eigen::VectorXd;

constexpr double kEps = std::numeric_limits<double>::epsilon();
constexpr double kArmijo = 1e-4;
constexpr double kMinStep = 0x1p-30;
constexpr std::size_t kMaxElements = std::size_t{1} << 24;
const std::string kMethod = "elastica2d-sleeve";

// Arm k has free length l_k = base_k + sign_k u, u being the one length unknown.
struct Slot {
  FreeArm arm;
  double base = 0.0;
  double sign = 1.0;
};

// The joint system in (phi_1, .., phi_K, u): Pi = sum_k Pi_arm_k(phi_k, l_k(u)) + pull * u.
class JointSystem {
 public:
  // The gradient is measured in the problem's own units, the load P and the elastic length
  // ell = sqrt(B / P) that the arms bend over: its angle rows are moments, scaled by B / ell = sqrt(B P),
  // its length row a force, scaled by P, so that one tolerance means the same at any B, P and rod length
  // (an absolute one failed at P = 1e6 and was empty at P = 1e-6; the rod length, mostly inside the
  // sleeve, is no scale of the arms: with it, rod_length = 1e6 asked for 1e-23 of a force).
  JointSystem(std::vector<Slot> slots, double pull, std::size_t elements, double bending_stiffness, double load)
      : slots_(std::move(slots)),
        pull_(pull),
        n_(static_cast<Eigen::Index>(elements)),
        moment_unit_(std::sqrt(bending_stiffness * load)),
        force_unit_(load) {}

  void set_pull(double pull) { pull_ = pull; }
  Eigen::Index angles() const { return n_ * static_cast<Eigen::Index>(slots_.size()); }
  double length(std::size_t k, double u) const { return slots_[k].base + slots_[k].sign * u; }
  const std::vector<Slot>& slots() const { return slots_; }
  VectorXd block(const VectorXd& phi, std::size_t k) const {
    return phi.segment(static_cast<Eigen::Index>(k) * n_, n_);
  }

  struct Eval {
    std::vector<FreeArmDerivatives> arms;
    VectorXd grad_phi;
    double grad_u = 0.0;
  };
  Eval evaluate(const VectorXd& phi, double u) const {
    Eval e;
    e.grad_phi.resize(angles());
    e.grad_u = pull_;
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      e.arms.push_back(free_arm_derivatives(slots_[k].arm, block(phi, k), length(k, u)));
      e.grad_phi.segment(static_cast<Eigen::Index>(k) * n_, n_) = e.arms[k].grad_phi;
      e.grad_u += slots_[k].sign * e.arms[k].grad_l;
    }
    return e;
  }
  // ||gradient||: with the length row (joint) or without it (shape only, u fixed).
  double norm2(const Eval& e, bool joint) const {
    const double g_u = joint ? e.grad_u / force_unit_ : 0.0;
    return std::sqrt(e.grad_phi.squaredNorm() / (moment_unit_ * moment_unit_) + g_u * g_u);
  }
  double norm_inf(const Eval& e, bool joint) const {
    return std::max(e.grad_phi.lpNorm<Eigen::Infinity>() / moment_unit_,
                    joint ? std::abs(e.grad_u) / force_unit_ : 0.0);
  }

  // Newton step: bordered solve of [A b; b^T c] (dphi, du) = -(g_phi, g_u). Returns false if the
  // tridiagonal block is singular. sigma = c - b^T A^{-1} b; joint = false keeps du = 0.
  bool step(const Eval& e, bool joint, VectorXd& dphi, double& du, double& sigma) {
    using T = Eigen::Triplet<double>;
    std::vector<T> triplets;
    VectorXd b(angles());
    double c = 0.0;
    for (std::size_t k = 0; k < slots_.size(); ++k) {
      const Eigen::Index o = static_cast<Eigen::Index>(k) * n_;
      const FreeArmDerivatives& d = e.arms[k];
      for (Eigen::Index i = 0; i < n_; ++i) {
        triplets.emplace_back(o + i, o + i, d.hess_diag[i]);
        if (i + 1 < n_) {
          triplets.emplace_back(o + i, o + i + 1, d.hess_off[i]);
          triplets.emplace_back(o + i + 1, o + i, d.hess_off[i]);
        }
      }
      b.segment(o, n_) = slots_[k].sign * d.hess_phi_l;
      c += d.hess_ll;  // sign^2 = 1
    }
    Eigen::SparseMatrix<double> a(angles(), angles());
    a.setFromTriplets(triplets.begin(), triplets.end());
    if (!lu_.factorize(a)) return false;
    const VectorXd x1 = lu_.solve(-e.grad_phi);
    const VectorXd x2 = lu_.solve(b);
    sigma = c - b.dot(x2);
    if (!joint) {
      du = 0.0;
      dphi = x1;
      return true;
    }
    if (!(std::abs(sigma) > 64.0 * kEps * (std::abs(c) + std::abs(b.dot(x2))))) return false;
    du = (-e.grad_u - b.dot(x1)) / sigma;
    dphi = x1 - du * x2;
    return true;
  }

 private:
  std::vector<Slot> slots_;
  double pull_;
  Eigen::Index n_;
  double moment_unit_, force_unit_;
  BandedLU lu_;
};

struct NewtonResult {
  VectorXd phi;
  double u = 0.0;
  double sigma = 0.0;
  std::size_t iterations = 0;
  double residual = 0.0;
};

// Damped Newton on the shape alone (joint = false, u fixed) or on shape and length jointly.
void newton(JointSystem& system, NewtonResult& state, bool joint, const SleeveSolverOptions& options) {
  for (std::size_t it = 0;; ++it) {
    JointSystem::Eval e = system.evaluate(state.phi, state.u);
    const double r = system.norm_inf(e, joint);
    state.residual = r;
    check_time_budget("elastica2d sleeve Newton", state.iterations, r);
    if (!std::isfinite(r))
      throw SolverError(kMethod, "gradient became non-finite", state.iterations, r);
    if (r <= options.tolerance) return;
    if (it == options.max_iterations)
      throw SolverError(kMethod,
                        "Newton did not converge in " + std::to_string(options.max_iterations) +
                            " iterations (scaled ||grad Pi||_inf = " + format_value(r) + " > tolerance " +
                            format_value(options.tolerance) + ")",
                        state.iterations, r);
    VectorXd dphi;
    double du = 0.0;
    if (!system.step(e, joint, dphi, du, state.sigma))
      throw SolverError(kMethod, "bordered Newton system is singular (zero pivot or Schur complement)",
                        state.iterations, r);
    ++state.iterations;
    if (!dphi.allFinite() || !std::isfinite(du))
      throw SolverError(kMethod, "Newton step is non-finite", state.iterations, r);
    const double size = std::max(state.phi.lpNorm<Eigen::Infinity>(), std::abs(state.u));
    if (std::max(dphi.lpNorm<Eigen::Infinity>(), std::abs(du)) <= 64.0 * kEps * (1.0 + size)) {
      state.phi += dphi;  // already at round-off
      state.u += du;
      state.residual = system.norm_inf(system.evaluate(state.phi, state.u), joint);
      return;
    }
    // Backtracking on ||grad Pi||_2; a trial may not shrink any arm by more than 3/4.
    const double merit = system.norm2(e, joint);
    double alpha = 1.0;
    for (;;) {
      const double u = state.u + alpha * du;
      bool feasible = true;
      for (std::size_t k = 0; k < system.slots().size(); ++k)
        feasible = feasible && system.length(k, u) > 0.25 * system.length(k, state.u);
      if (feasible) {
        const VectorXd phi = state.phi + alpha * dphi;
        const double m = system.norm2(system.evaluate(phi, u), joint);
        if (std::isfinite(m) && m <= (1.0 - kArmijo * alpha) * merit) {
          state.phi = phi;
          state.u = u;
          break;
        }
      }
      alpha *= 0.5;
      if (alpha < kMinStep)
        throw SolverError(kMethod, "line search failed: no decrease of ||grad Pi|| along the Newton step",
                          state.iterations, r);
    }
  }
}

// Shape at the starting length first (a cantilever: a well-posed problem from the straight state),
// then shape and length jointly.
NewtonResult solve_joint(JointSystem& system, double u0, const SleeveSolverOptions& options) {
  NewtonResult state;
  state.u = u0;
  state.phi.resize(system.angles());
  const Eigen::Index n = static_cast<Eigen::Index>(options.elements);
  for (std::size_t k = 0; k < system.slots().size(); ++k)
    state.phi.segment(static_cast<Eigen::Index>(k) * n, n).setConstant(system.slots()[k].arm.exit_angle);
  newton(system, state, false, options);
  newton(system, state, true, options);
  // sigma at the converged state (the last step's value belongs to the state before it).
  VectorXd dphi;
  double du = 0.0;
  system.step(system.evaluate(state.phi, state.u), true, dphi, du, state.sigma);
  return state;
}

ArmEquilibrium equilibrium_of(const FreeArm& arm, const VectorXd& phi, double l) {
  const FreeArmDerivatives d = free_arm_derivatives(arm, phi, l);
  ArmEquilibrium eq;
  eq.shape = free_arm_shape(arm, phi, l);
  const std::size_t n = arm.elements;
  eq.free_length = l;
  eq.exit_angle = arm.exit_angle;
  eq.tip_angle = eq.shape.theta[n];
  eq.exit_moment = arm.bending_stiffness * eq.shape.kappa[0];
  eq.exit_axial_force = eq.shape.axial_force[0];
  eq.configurational_force = -d.grad_l;
  eq.bending_energy = d.bending_energy;
  eq.tip_x = eq.shape.x[n];
  eq.tip_y = eq.shape.y[n];
  return eq;
}

void require_elements(std::size_t elements) {
  if (elements < 2 || elements > kMaxElements)
    throw InputError("elements", "invalid parameter 'elements' = " + std::to_string(elements) +
                                     ": must be in [2, 2^24]");
}

}  // namespace

void validate(const SleeveProblem& problem) {
  require_positive("bending_stiffness", problem.bending_stiffness);
  require_positive("tip_load", problem.tip_load);
  require_open_interval("pull", problem.pull, 0.0, problem.tip_load);
  require_positive("rod_length", problem.rod_length);
}

void validate(const ArmScaleProblem& problem) {
  require_positive("bending_stiffness", problem.bending_stiffness);
  require_open_interval("angle", problem.angle, -0.5 * std::numbers::pi, 0.5 * std::numbers::pi);
  require_positive("weight1", problem.weight1);
  require_positive("weight2", problem.weight2);
  require_positive("rod_length", problem.rod_length);
  require_open_interval("sleeve_length", problem.sleeve_length, 0.0, problem.rod_length);
}

void validate(const SleeveSolverOptions& options) {
  require_elements(options.elements);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  require_at_least("max_iterations", options.max_iterations, 1);
}

SleeveSolution solve_sleeve(const SleeveProblem& problem, const SleeveSolverOptions& options) {
  validate(problem);
  validate(options);
  const double l0 = options.initial_length.value_or(
      std::min(std::sqrt(2.0 * problem.bending_stiffness * problem.pull) / problem.tip_load,
               0.5 * problem.rod_length));
  require_open_interval("initial_length", l0, 0.0, problem.rod_length);

  Slot slot;
  slot.arm.bending_stiffness = problem.bending_stiffness;
  slot.arm.exit = Vector2d::Zero();
  slot.arm.exit_angle = 0.0;
  slot.arm.tip_force = Vector2d(0.0, -problem.tip_load);
  slot.arm.elements = options.elements;
  JointSystem system({slot}, problem.pull, options.elements, problem.bending_stiffness, problem.tip_load);
  NewtonResult r;
  try {
    r = solve_joint(system, l0, options);
  } catch (const SolverError&) {
    // Fallback for S close to P (the free length grows like log(1 / (1 - S/P))): continuation in
    // the pull from S/P = 1/2 with the ratios r_k = 1 - (1 - r)^(k / K), evenly spaced in
    // log(1 - S/P), each step starting from the previous equilibrium.
    if (options.initial_length) throw;
    const double ratio = problem.pull / problem.tip_load;
    const double start = std::min(ratio, 0.5);
    constexpr int kSteps = 16;
    system.set_pull(start * problem.tip_load);
    r = solve_joint(system, std::sqrt(2.0 * problem.bending_stiffness * start * problem.tip_load) /
                                problem.tip_load, options);
    for (int k = 1; k <= kSteps; ++k) {
      const double t = static_cast<double>(k) / kSteps;
      const double rk = 1.0 - std::pow(1.0 - start, 1.0 - t) * std::pow(1.0 - ratio, t);
      system.set_pull(k == kSteps ? problem.pull : rk * problem.tip_load);
      newton(system, r, true, options);
    }
    VectorXd dphi;
    double du = 0.0;
    system.step(system.evaluate(r.phi, r.u), true, dphi, du, r.sigma);
  }
  if (!(r.u < problem.rod_length))
    throw SolverError(kMethod,
                      "the free length " + format_value(r.u) + " reaches the rod length " +
                          format_value(problem.rod_length) + ": the rod leaves the sleeve",
                      r.iterations, r.residual);

  SleeveSolution sol;
  sol.arm = equilibrium_of(slot.arm, r.phi, r.u);
  sol.axial_force_inside = sol.arm.configurational_force;  // -dPi_arm/dl: stationarity in l
  sol.tension_jump = sol.axial_force_inside - sol.arm.exit_axial_force;
  sol.tip_angle_below = -sol.arm.tip_angle;
  sol.length_stiffness = r.sigma;
  sol.iterations = r.iterations;
  sol.residual = r.residual;
  return sol;
}

ArmScaleSolution solve_arm_scale(const ArmScaleProblem& problem, const SleeveSolverOptions& options) {
  validate(problem);
  validate(options);
  const double available = problem.rod_length - problem.sleeve_length;  // l1 + l2
  const double u0 = options.initial_length.value_or(0.5 * available);
  require_open_interval("initial_length", u0, 0.0, available);

  const Vector2d d(std::cos(problem.angle), std::sin(problem.angle));
  Slot s1, s2;
  s1.arm.bending_stiffness = s2.arm.bending_stiffness = problem.bending_stiffness;
  s1.arm.elements = s2.arm.elements = options.elements;
  s1.arm.exit = -0.5 * problem.sleeve_length * d;
  s1.arm.exit_angle = problem.angle + std::numbers::pi;
  s1.arm.tip_force = Vector2d(0.0, -problem.weight1);
  s1.base = 0.0;
  s1.sign = 1.0;
  s2.arm.exit = 0.5 * problem.sleeve_length * d;
  s2.arm.exit_angle = problem.angle;
  s2.arm.tip_force = Vector2d(0.0, -problem.weight2);
  s2.base = available;
  s2.sign = -1.0;
  JointSystem system({s1, s2}, 0.0, options.elements, problem.bending_stiffness,
                     std::max(problem.weight1, problem.weight2));
  const NewtonResult r = solve_joint(system, u0, options);

  ArmScaleSolution sol;
  sol.arm1 = equilibrium_of(s1.arm, system.block(r.phi, 0), system.length(0, r.u));
  sol.arm2 = equilibrium_of(s2.arm, system.block(r.phi, 1), system.length(1, r.u));
  sol.axial_force = sol.arm1.configurational_force;
  sol.axial_force_arm2 = sol.arm2.configurational_force;
  sol.beta1 = sol.arm1.tip_angle - std::numbers::pi;
  sol.beta2 = -sol.arm2.tip_angle;
  sol.sleeve_shift = sol.arm2.free_length - sol.arm1.free_length;
  sol.length_stiffness = r.sigma;
  sol.iterations = r.iterations;
  sol.residual = r.residual;
  return sol;
}

}  // namespace rodvv::solvers::elastica2d

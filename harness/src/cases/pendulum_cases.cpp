// The pendulum family (PHYSICS.md §2): every time integrator of solvers/pendulum against the
// Jacobi-elliptic closed forms of references/pendulum, on five motions, plus the long-time energy
// behaviour that separates symplectic from non-symplectic integrators.
//
// Accuracy cases  pendulum/<motion>/<method>: a sweep over dt (over the tolerance for dopri5).
//   state_max_error      max over compared samples of the phase-space error
//                        sqrt(dtheta^2 + (dtheta'/omega)^2); order p and a bound gated. The global
//                        order of a method is a statement about the whole state: symplectic Euler's
//                        theta alone converges at order 2 when theta(0) = 0 (the first kick
//                        vanishes and its positions coincide with leapfrog's), while theta' stays
//                        first order.
//   theta_max_error      max |theta - theta_exact| (reported)
//   theta_dot_max_error  max |theta' - theta'_exact| (reported)
//   period               mean period from the zero crossings (turns, for rotation) vs 4K(k)/omega
//   energy_max_deviation max |E - E(0)| along the run
// Long-time energy cases  pendulum/long-time-energy/<method>: libration at 90 deg over 1000
//   periods; a bounded energy error (late/early deviation ratio ~ 1) for symplectic methods, a
//   secular drift (ratio >> 1) for RK4 and explicit Euler.
//
// Units. The cases take the pendulum's g and l (pendulum/scales.hpp) and run at omega = sqrt(g/l) =
// 2.7, not 1: at omega = 1 a solver that uses omega where it needs omega^2 (or 1/omega for omega) is
// right. The problem has one time scale, 1/omega, and the cases state everything in it: the step is
// omega dt, the period omega T, rates theta'/omega, energies E/omega^2; the physical inputs in time
// units (the rotation's start rate v0, the separatrix horizon t_end, dopri5's output interval) are
// parameters with windows on their groups with omega (v0/omega, omega t_end, omega dt_out). The
// librations' results are therefore independent of g and l up to round-off, both are unit scales
// (case_info.hpp: Parameter::unit_scale), and a bound measured at the defaults holds at any g and l.
// Not for the rotation and the separatrix, whose v0 and t_end are physical (another g is another
// v0/omega), nor for dopri5: its controller's tolerance applies to theta (rad) and theta' (rad/time)
// alike, so its error per tolerance depends on omega.
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "pendulum/one_step_map.hpp"
#include "pendulum/scales.hpp"
#include "pendulum_levels.hpp"
#include "rodvv/harness/registry.hpp"
#include "rodvv/harness/trajectory_metrics.hpp"
#include "rodvv/invariants/energy.hpp"
#include "rodvv/references/pendulum.hpp"
#include "rodvv/solvers/pendulum/integrators.hpp"

namespace rodvv::harness {

namespace {

namespace ref = rodvv::references;
namespace pend = rodvv::solvers::pendulum;
constexpr double kPi = std::numbers::pi;
constexpr double kBoundedGrowth = 2.0;
constexpr double kDriftGrowth = 10.0;
constexpr double kDefaultOmega = 2.7;  // sqrt(g/l) at the default g and l (pendulum/scales.hpp)
// The separatrix approaches the unstable equilibrium as e^(-omega t), and errors grow as e^(omega t):
// beyond omega t_end = 6 the default levels are no longer asymptotic for every method (measured at
// omega t_end = 8: explicit Euler leaves its window; at 10 its order is 0.50, symplectic Euler's 2.0
// against its order 1; at 12 Stoermer-Verlet 1.68).
constexpr double kSeparatrixHorizon = 6.0;

constexpr const char* kCitation =
    "Jacobi elliptic closed form: DLMF §22.19(i); Byrd & Friedman, Handbook of Elliptic Integrals "
    "(1971); evaluated with GSL gsl_sf_elljac_e (descending Landen transformation near the "
    "separatrix, DLMF 22.7) and K(k) = R_F(0, k'^2, 1) by gsl_sf_ellint_RF_e (DLMF 19.25.1); "
    "checked against a 30-digit mpmath table (PHYSICS.md §2)";

enum class MotionKind { Libration, Rotation, Separatrix };

// The ranges each motion's levels honour with every method (issue 14, class 5: measured with
// `rodvv run` over a grid of values, 2026-11-26). Amplitude: the three librations split (0, 179.5]
// into bands, each of whose levels resolve it (at the libration-30 levels RK4 leaves its order
// window from 120 deg, explicit Euler its resolution from 160; at the libration-90 levels RK4 from
// 150; at the libration-179 levels RK4 reaches round-off below 45 deg and RKN4 fails at 179.9). 180
// itself is the unstable equilibrium: the period is infinite. Rotation: v0/omega from 2.01 (2.001:
// the Euler methods leave their windows near the separatrix) to 10 (RKN4 at 20, Stoermer-Verlet and
// RK4 at 1000: the levels are in units of 1/omega, while a turn takes ~ 2 pi / v0). Horizons: the
// accuracy cases fit orders over a few periods; at 10 periods the libration-90 levels are
// pre-asymptotic for explicit Euler and RK4 (order 3.88), so periods <= 5 and turns <= 30 (100:
// explicit Euler and RK4 fail). Longer runs are the long-time-energy cases. The separatrix horizon:
// omega t_end in [0.5, 6] (dopri5 compares no sample at 0.05; explicit Euler leaves at 8).
struct Range {
  double min, max;
  bool min_open, max_open;
};

struct Motion {
  std::string id;
  MotionKind kind;
  std::string title;
  double amplitude;  // theta0 [deg] (libration), v0 / omega (rotation), unused (separatrix)
  double horizon;    // periods (libration), turns (rotation), omega t_end (separatrix)
  Range amplitude_range;
  Range horizon_range;
};

const std::vector<Motion>& motions() {
  static const std::vector<Motion> list = {
      {"libration-30", MotionKind::Libration, "libration from rest at 30 deg", 30.0, 2.0, {0.0, 90.0, true, false},
       {1.0, 5.0, false, false}},
      {"libration-90", MotionKind::Libration, "libration from rest at 90 deg", 90.0, 2.0, {0.0, 135.0, true, false},
       {1.0, 5.0, false, false}},
      {"libration-179", MotionKind::Libration, "libration from rest at 179 deg", 179.0, 1.0,
       {45.0, 179.5, false, false}, {1.0, 5.0, false, false}},
      {"rotation", MotionKind::Rotation, "rotation with theta'(0) = 3 omega", 3.0, 2.0, {2.01, 10.0, false, false},
       {1.0, 30.0, false, false}},
      {"separatrix", MotionKind::Separatrix, "separatrix, theta'(0) = 2 omega", 0.0, 5.0, {0.0, 0.0, false, false},
       {0.5, kSeparatrixHorizon, false, false}},
  };
  return list;
}

Parameter ranged_parameter(const std::string& name, double value, const Range& range, const char* unit,
                           const char* description) {
  return make_parameter(name, value, range.min, range.max, range.min_open, range.max_open, unit, description);
}

// g and l are unit scales where every other input is dimensionless: the librations with a fixed step.
bool scales_are_units(const Motion& motion, bool adaptive) { return !adaptive && motion.kind == MotionKind::Libration; }

Parameters motion_parameters(const Motion& motion, bool adaptive) {
  Parameters parameters = pendulum_cases::frequency_parameters(scales_are_units(motion, adaptive));
  switch (motion.kind) {
    case MotionKind::Libration:
      parameters.push_back(ranged_parameter("theta0_deg", motion.amplitude, motion.amplitude_range, "deg",
                                            "release angle (from rest)"));
      parameters.push_back(ranged_parameter("periods", motion.horizon, motion.horizon_range, "",
                                            "integration horizon in periods 4K(k)/omega"));
      break;
    case MotionKind::Rotation:
      parameters.push_back(make_parameter("v0", motion.amplitude * kDefaultOmega, 0.0, 1e12, true, false,
                                          "rad/time", "initial rate theta'(0) (> 2 omega for rotation)"));
      parameters.push_back(ranged_parameter("turns", motion.horizon, motion.horizon_range, "",
                                            "integration horizon in full turns"));
      break;
    case MotionKind::Separatrix:
      parameters.push_back(make_parameter("t_end", motion.horizon / kDefaultOmega, 0.0, 1e12, true, false, "time",
                                          "integration horizon"));
      break;
  }
  return parameters;
}

// The windows on the groups with omega of the physical inputs in time units (see Units, and the ranges
// above); dopri5's omega from 0.3 (at 0.1 and 0.027 its order leaves the window on libration-179 and
// rotation; 0.3 .. 1e6 pass on every motion, measured 2026-11-26 with omega a parameter).
void require_motion_windows(Case& c, const Motion& motion, bool adaptive) {
  using pendulum_cases::frequency_group_window;
  if (motion.kind == MotionKind::Rotation)
    cases::require(c, frequency_group_window("v0", -1, motion.amplitude_range.min, motion.amplitude_range.max,
                                             "a rotation, away from the separatrix at 2, where the levels resolve it"));
  if (motion.kind == MotionKind::Separatrix)
    cases::require(c, frequency_group_window("t_end", 1, motion.horizon_range.min, motion.horizon_range.max,
                                             "where the levels of every method are asymptotic"));
  if (adaptive) {
    cases::require(c, frequency_group_window("output_dt", 1, 0.0, 1.0, "dense output at least once per 1/omega"));
    const std::string why = "where dopri5's tolerance, which mixes rad and rad/time, was measured";
    cases::require(c, {"omega = sqrt(g/l) >= 0.3 (" + why + ")", [why](const Parameters& p) {
                         const double omega = pendulum_cases::natural_frequency(p);
                         if (!cases::inside(omega, 0.3, std::numeric_limits<double>::infinity()))
                           throw InputError("g", fmt::format("invalid parameters: omega = sqrt(g/l) = {} must be >= 0.3 ({})",
                                                             format_value(omega), why));
                       }});
  }
}

ref::PendulumMotion reference_motion(const Motion& motion, const Parameters& parameters) {
  const double omega = pendulum_cases::natural_frequency(parameters);
  switch (motion.kind) {
    case MotionKind::Libration:
      return ref::Libration{omega, parameter_value(parameters, "theta0_deg") * kPi / 180.0};
    case MotionKind::Rotation:
      return ref::Rotation{omega, parameter_value(parameters, "v0")};
    case MotionKind::Separatrix:
      return ref::Separatrix{omega};
  }
  throw std::logic_error("unknown motion kind");
}

double horizon_time(const Motion& motion, const Parameters& parameters,
                    const ref::PendulumMotion& exact) {
  switch (motion.kind) {
    case MotionKind::Libration: return parameter_value(parameters, "periods") * *ref::period(exact);
    case MotionKind::Rotation: return parameter_value(parameters, "turns") * *ref::period(exact);
    case MotionKind::Separatrix: return parameter_value(parameters, "t_end");
  }
  throw std::logic_error("unknown motion kind");
}

std::string motion_reference_text(const Motion& motion) {
  switch (motion.kind) {
    case MotionKind::Libration:
      return "sin(theta/2) = k cd(omega t, k), k = sin(theta0/2); period 4K(k)/omega";
    case MotionKind::Rotation:
      return "theta = 2 am(v0 t/2, 2 omega/v0); time per turn 4K(2 omega/v0)/v0";
    case MotionKind::Separatrix:
      return "theta = 2 arcsin(tanh(omega t)), theta' = 2 omega sech(omega t)";
  }
  return {};
}

// The size energy errors are measured against: the energy above rest, (E + omega^2) / omega^2
// (E = theta'^2/2 - omega^2 cos theta), > 0 for every motion the cases start.
double energy_above_rest(const ref::PendulumMotion& motion) {
  const double omega = ref::omega_of(motion);
  return (ref::energy(motion) + omega * omega) / (omega * omega);
}

// The integrator refuses a horizon of more than 1e9 steps as a bad 'dt'; here dt is a level and the
// horizon comes from 'periods' (and the period, which grows without bound as theta0 -> 180 deg), so
// the refusal names them.
Trajectory integrate_horizon(const pend::Problem& problem, const pend::Settings& settings) {
  try {
    return pend::integrate(problem, settings);
  } catch (const InputError& error) {
    if (error.parameter() != "dt") throw;
    throw InputError("periods", fmt::format("invalid parameter 'periods': the horizon t_end = {} takes more than 1e9 "
                                            "steps of dt = {} (omega dt = {}); lower 'periods' or use coarser levels",
                                            format_value(problem.t_end), format_value(settings.dt),
                                            format_value(problem.omega * settings.dt)));
  }
}

MetricSample error_sample(double computed, double reference) {
  return {computed, reference, std::abs(computed - reference)};
}

Solution solve_accuracy_level(const Motion& motion, const pend::MethodInfo& method, const Parameters& parameters,
                              double level) {
  const ref::PendulumMotion exact = reference_motion(motion, parameters);
  const ref::PendulumState start = ref::initial_state(exact);
  const double omega = ref::omega_of(exact);
  const pend::Problem problem{omega, start.theta, start.theta_dot,
                              horizon_time(motion, parameters, exact)};
  pend::Settings settings;
  settings.method = method.method;
  if (method.adaptive) {
    settings.dt = parameter_value(parameters, "output_dt");
    settings.tolerance = level;
  } else {
    settings.dt = level / omega;  // the level is omega dt
  }
  return integrate_horizon(problem, settings);
}

// Reads only the trajectory's samples (t, theta, theta'): a trajectory file from another integrator
// is measured exactly like rodvv's own.
LevelOutput measure_accuracy_level(const Motion& motion, const pend::MethodInfo& method, const Parameters& parameters,
                                   double level, const Solution& solution) {
  const auto& trajectory = solution_as<Trajectory>(solution, "trajectory");
  const ref::PendulumMotion exact = reference_motion(motion, parameters);
  const double omega = ref::omega_of(exact);
  if (trajectory.size() < 2)
    throw InputError("trajectory", "a trajectory needs at least 2 samples, got " + std::to_string(trajectory.size()));
  // The errors are maxima over the whole motion: a trajectory must cover it, from t = 0 to at least
  // the horizon (to a relative 1e-9, a solver's accumulated t += dt; a fixed-step integrator may end
  // a step past it, as rodvv's do).
  const double horizon = horizon_time(motion, parameters, exact);
  if (std::abs(trajectory.t.front()) > 1e-9 * horizon || trajectory.t.back() < horizon * (1.0 - 1e-9))
    throw InputError("trajectory", fmt::format("the trajectory spans t = {:.17g} .. {:.17g}; the case compares "
                                               "t = 0 .. {:.17g} (its horizon at these parameters)",
                                               trajectory.t.front(), trajectory.t.back(), horizon));

  double theta_error = 0.0, rate_error = 0.0, state_error = 0.0;
  // The size the state errors are measured against: the radius of the exact orbit in the phase
  // plane (theta wrapped to [-pi, pi], theta'/omega), which does not grow with the turns of a rotation.
  double orbit_radius = 0.0;
  std::vector<double> times, theta_errors;
  for (std::size_t i : comparison_indices(trajectory.size())) {
    const ref::PendulumState expected = ref::exact_state(exact, trajectory.t[i]);
    orbit_radius = std::max(orbit_radius, std::hypot(std::remainder(expected.theta, 2 * kPi), expected.theta_dot / omega));
    const double error = trajectory.theta[i] - expected.theta;
    const double rate = (trajectory.theta_dot[i] - expected.theta_dot) / omega;
    theta_error = std::max(theta_error, std::abs(error));
    rate_error = std::max(rate_error, std::abs(rate));
    state_error = std::max(state_error, std::hypot(error, rate));
    times.push_back(trajectory.t[i]);
    theta_errors.push_back(error);
  }
  if (!std::isfinite(state_error))
    throw SolverError(std::string(method.id), "non-finite error against the reference", trajectory.steps,
                      state_error);

  LevelOutput output;
  output.metrics["state_max_error"] = {state_error, 0.0, state_error, orbit_radius};
  output.metrics["theta_max_error"] = {theta_error, 0.0, theta_error, orbit_radius};
  output.metrics["theta_dot_max_error"] = {rate_error, 0.0, rate_error, orbit_radius};
  const auto energy = invariants::pendulum_energy_statistics(trajectory, omega);
  const double energy_deviation = energy.max_abs_deviation / (omega * omega);
  output.metrics["energy_max_deviation"] = {energy_deviation, 0.0, energy_deviation,
                                            energy_above_rest(exact)};

  if (const auto period = ref::period(exact)) {
    // Libration crosses theta = 0 twice per period; rotation crosses theta = pi (mod 2 pi) once
    // per turn.
    const bool libration = motion.kind == MotionKind::Libration;
    const auto crossings = crossing_times(trajectory, libration ? 0.0 : kPi, libration ? 0.0 : 2 * kPi);
    if (const auto measured = period_from_crossings(crossings, libration ? 2.0 : 1.0))
      output.metrics["period"] = error_sample(omega * *measured, omega * *period);
  }
  if (method.adaptive) {
    output.metrics["error_over_tolerance"] = {state_error / level, std::nullopt, std::nullopt};
    if (trajectory.rhs_evaluations > 0)
      output.metrics["rhs_evaluations"] = {static_cast<double>(trajectory.rhs_evaluations), std::nullopt,
                                           std::nullopt};
  }
  if (trajectory.steps > 0)
    output.metrics["steps"] = {static_cast<double>(trajectory.steps), std::nullopt, std::nullopt};
  output.series.push_back(thin_series("theta_error", "t", "theta - theta_exact [rad]", times, theta_errors));
  return output;
}

Case accuracy_case(const Motion& motion, const pend::MethodInfo& method) {
  Case c;
  CaseInfo& info = c.info;
  info.name = fmt::format("pendulum/{}/{}", motion.id, method.id);
  info.family = "pendulum";
  info.group = fmt::format("pendulum/{}", motion.id);
  info.title = fmt::format("{}, {}", motion.title, method.name);
  info.physics = "Nonlinear pendulum theta'' = -omega^2 sin(theta), the kinetic analogue of the "
                 "elastica (Kirchhoff); " + motion.title + ".";
  info.reference = motion_reference_text(motion);
  info.citation = kCitation;
  info.method = fmt::format("{} (order {}{}); {}", method.name, method.order,
                            method.symplectic ? ", symplectic" : "", method.citation);
  info.parameters = motion_parameters(motion, method.adaptive);
  const LevelPlan plan = pendulum_level_plan(motion.id, method.id, method.order);
  const auto order = static_cast<double>(method.order);
  if (method.adaptive) {
    info.parameters.push_back(make_parameter("output_dt", 0.005 / kDefaultOmega, 0.0, 1e12, true, false, "time",
                                             "dense-output sampling interval"));
    info.resolution = {"tol", "absolute = relative error tolerance of the step-size controller",
                       ResolutionScale::StepSize, plan.levels, plan.extended_levels};
  } else {
    info.resolution = {"omega_dt", "time step in units of 1/omega", ResolutionScale::StepSize, plan.levels,
                       plan.extended_levels};
  }
  const std::optional<double> metric_order =
      method.adaptive ? std::optional<double>(plan.tolerance_order) : std::optional<double>(order);
  info.metrics = {
      {"state_max_error", MetricKind::Error, "rad",
       "max sqrt(dtheta^2 + (dtheta'/omega)^2) over the compared samples", false, metric_order},
      {"theta_max_error", MetricKind::Error, "rad", "max |theta - theta_exact| over the compared samples",
       false, metric_order},
      {"theta_dot_max_error", MetricKind::Error, "rad", "max |theta' - theta'_exact| / omega", false,
       metric_order},
      {"energy_max_deviation", MetricKind::Invariant, "", "max |E(t) - E(0)| / omega^2", false, metric_order},
  };
  if (motion.kind != MotionKind::Separatrix)
    info.metrics.push_back({"period", MetricKind::Error, "1/omega",
                            "omega T: the mean period from the zero crossings (Hermite-located) vs the exact period",
                            true, metric_order});
  if (method.adaptive) {
    info.metrics.push_back({"error_over_tolerance", MetricKind::Diagnostic, "",
                            "state_max_error / tol", false, std::nullopt});
    info.metrics.push_back({"rhs_evaluations", MetricKind::Diagnostic, "", "force evaluations", false,
                            std::nullopt});
  }
  info.metrics.push_back({"steps", MetricKind::Diagnostic, "", "accepted steps", false, std::nullopt});

  const bool state_gated = plan.order_metric == "state_max_error";
  if (method.adaptive) {
    c.gates.push_back(upper_bound_gate("error_over_tolerance", plan.tolerance_ratio_bound,
                                       GateScope::AllLevels, plan.rationale));
    c.gates.back().measured = true;
    c.gates.push_back(order_gate(plan.order_metric, plan.tolerance_order,
                                 "tolerance proportionality of the Dormand-Prince controller: "
                                 "global error ~ tol"));
  } else {
    c.gates.push_back(order_gate(plan.order_metric, order,
                                 fmt::format("{} is a method of global order {}{}", method.name,
                                             method.order, state_gated ? "" : ". " + plan.note)));
  }
  if (plan.error_constant > 0.0) {
    c.gates.push_back(scaled_upper_bound_gate("state_max_error", plan.error_constant, plan.error_order,
                                              GateScope::FinestLevel, plan.rationale));
    c.gates.back().measured = true;
  }
  if (motion.kind != MotionKind::Separatrix && plan.period_constant > 0.0) {
    c.gates.push_back(scaled_upper_bound_gate(
        "period", plan.period_constant, plan.period_order, GateScope::FinestLevel,
        "period from zero crossings matches 4K(k)/omega; " + plan.rationale));
    c.gates.back().measured = true;
  }
  c.check_parameters = [motion](const Parameters& parameters) {
    (void)ref::energy(reference_motion(motion, parameters));  // references validate the motion
  };
  require_motion_windows(c, motion, method.adaptive);
  split_level(
      c,
      [motion, method](const Parameters& parameters, double level) {
        return solve_accuracy_level(motion, method, parameters, level);
      },
      [motion, method](const Parameters& parameters, double level, const Solution& solution) {
        return measure_accuracy_level(motion, method, parameters, level, solution);
      });
  return c;
}

// ---- long-time energy ---------------------------------------------------------------------------

LevelOutput run_energy_level(const pend::MethodInfo& method, const Parameters& parameters, double omega_dt) {
  const ref::Libration exact{pendulum_cases::natural_frequency(parameters),
                             parameter_value(parameters, "theta0_deg") * kPi / 180.0};
  const double dt = omega_dt / exact.omega;
  const double energy_unit = exact.omega * exact.omega;
  const double periods = parameter_value(parameters, "periods");
  const double t_end = periods * ref::libration_period(exact);
  pend::Settings settings;
  settings.method = method.method;
  settings.dt = dt;
  // Keep at most ~2e5 samples (>= 200 per period at 1000 periods) so long runs stay small in memory;
  // the energy maximum within a period is then sampled to ~1e-4 relative.
  settings.record_every = std::max<std::size_t>(1, static_cast<std::size_t>(t_end / dt / 2e5));
  const Trajectory trajectory = integrate_horizon({exact.omega, exact.theta0, 0.0, t_end}, settings);
  // Early / late windows of one period each: a bounded error gives a ratio ~1, a linear drift a
  // ratio ~ periods.
  const auto stats = invariants::pendulum_energy_statistics(trajectory, exact.omega, 1.0 / periods);
  const auto history = invariants::pendulum_energy_history(trajectory, exact.omega);

  std::vector<double> deviation(history.size());
  for (std::size_t i = 0; i < history.size(); ++i) deviation[i] = (history[i] - stats.initial) / energy_unit;
  LevelOutput output;
  const double max_deviation = stats.max_abs_deviation / energy_unit;
  output.metrics["energy_max_deviation"] = {max_deviation, 0.0, max_deviation, energy_above_rest(exact)};
  const double growth = stats.early_deviation > 0.0 ? stats.late_deviation / stats.early_deviation
                                                    : std::numeric_limits<double>::infinity();
  output.metrics["energy_growth_ratio"] = {growth, std::nullopt, std::nullopt};
  output.metrics["energy_drift_rate"] = {stats.drift_slope / (energy_unit * exact.omega), std::nullopt, std::nullopt};
  output.metrics["steps"] = {static_cast<double>(trajectory.steps), std::nullopt, std::nullopt};
  output.series.push_back(thin_series("energy_error", "t", "(E(t) - E(0)) / omega^2", trajectory.t, deviation));
  return output;
}

Case energy_case(const pend::MethodInfo& method) {
  Case c;
  CaseInfo& info = c.info;
  info.name = fmt::format("pendulum/long-time-energy/{}", method.id);
  info.family = "pendulum";
  info.group = "pendulum/long-time-energy";
  info.title = fmt::format("energy over 1000 periods, {}", method.name);
  info.physics = "Nonlinear pendulum, libration from rest at 90 deg, integrated over 1000 periods.";
  info.reference = "E = 1/2 theta'^2 - omega^2 cos(theta) is conserved exactly; a symplectic method "
                   "conserves a modified energy, so E - E(0) stays bounded (Hairer, Lubich & Wanner "
                   "2006, Thm. IX.8.1); a non-symplectic one drifts secularly.";
  info.citation = "Hairer, Lubich & Wanner, Geometric Numerical Integration, 2nd ed., Springer 2006, ch. IX";
  info.method = fmt::format("{} (order {}{})", method.name, method.order,
                            method.symplectic ? ", symplectic" : ", not symplectic");
  info.parameters = pendulum_cases::frequency_parameters(true);
  info.parameters.insert(info.parameters.end(), {
      // g and l: unit scales (the levels are omega dt, the horizon in periods).
      // Measured like the accuracy cases' ranges: RKN4's energy error is round-off at 0.01 deg, RK4's drift
      // is not yet 10x its early value at 20 periods, and 1e5 periods overran (3e4 passes with every method).
      make_parameter("theta0_deg", 90.0, 1.0, 179.0, false, false, "deg", "release angle"),
      make_parameter("periods", 1000.0, 50.0, 3e4, false, false, "", "integration horizon in periods"),
  });
  const LevelPlan plan = pendulum_level_plan("long-time-energy", method.id, method.order);
  info.resolution = {"omega_dt", "time step in units of 1/omega", ResolutionScale::StepSize, plan.levels,
                     plan.extended_levels};
  const auto order = static_cast<double>(method.order);
  info.metrics = {
      {"energy_max_deviation", MetricKind::Invariant, "", "max |E(t) - E(0)| / omega^2 over the run",
       false, method.symplectic ? std::optional<double>(order) : std::nullopt},
      {"energy_growth_ratio", MetricKind::Diagnostic, "",
       "max |E - E(0)| over the last period / over the first period", false, std::nullopt},
      {"energy_drift_rate", MetricKind::Diagnostic, "", "least-squares slope dE/dt / omega^3",
       false, std::nullopt},
      {"steps", MetricKind::Diagnostic, "", "steps", false, std::nullopt},
  };
  // The contrast: over 1000 periods a bounded error has a growth ratio ~1 and a linear drift one
  // ~1000; the thresholds 2 and 10 separate the two with a wide margin on either side.
  if (method.symplectic) {
    c.gates.push_back(upper_bound_gate("energy_growth_ratio", kBoundedGrowth, GateScope::AllLevels,
                                       "bounded energy error: the last period's deviation is no more "
                                       "than twice the first's"));
    c.gates.push_back(order_gate("energy_max_deviation", order,
                                 "a symplectic method of order p keeps |E - E(0)| = O(dt^p) uniformly in time"));
  } else {
    c.gates.push_back(lower_bound_gate("energy_growth_ratio", kDriftGrowth, GateScope::AllLevels,
                                       "secular drift: the last period's deviation exceeds the first's "
                                       "tenfold"));
  }
  c.check_parameters = [](const Parameters& parameters) {
    (void)ref::libration_period({pendulum_cases::natural_frequency(parameters),
                                 parameter_value(parameters, "theta0_deg") * kPi / 180.0});
  };
  c.run_level = [method](const Parameters& parameters, double level) {
    return run_energy_level(method, parameters, level);
  };
  return c;
}

}  // namespace

void register_pendulum_cases(Registry& registry) {
  for (const Motion& motion : motions())
    for (const pend::MethodInfo& method : pend::all_methods())
      registry.add(accuracy_case(motion, method));
  for (const pend::MethodInfo& method : pend::all_methods())
    if (!method.adaptive) registry.add(energy_case(method));
  pendulum_cases::add_one_step_map_cases(registry);
}

}  // namespace rodvv::harness

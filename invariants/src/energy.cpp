#include "rodvv/invariants/energy.hpp"

#include <cmath>
#include <cstddef>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::invariants {

namespace {

void validate(const Trajectory& trajectory, double omega) {
  require_positive("omega", omega);
  const std::size_t n = trajectory.t.size();
  if (trajectory.theta.size() != n || trajectory.theta_dot.size() != n)
    throw InputError("trajectory", "invalid parameter 'trajectory': arrays of unequal length (t " +
                                       std::to_string(n) + ", theta " +
                                       std::to_string(trajectory.theta.size()) + ", theta_dot " +
                                       std::to_string(trajectory.theta_dot.size()) + ")");
}

}  // namespace

std::vector<double> pendulum_energy_history(const Trajectory& trajectory, double omega) {
  validate(trajectory, omega);
  std::vector<double> energy(trajectory.size());
  for (std::size_t i = 0; i < energy.size(); ++i)
    energy[i] = pendulum_energy(trajectory.theta[i], trajectory.theta_dot[i], omega);
  return energy;
}

EnergyStatistics pendulum_energy_statistics(const Trajectory& trajectory, double omega,
                                            double window) {
  validate(trajectory, omega);
  if (!(window > 0.0 && window <= 0.5))
    throw InputError("window", "invalid parameter 'window' = " + format_value(window) +
                                   ": must be a finite number in (0, 0.5]");
  const std::size_t n = trajectory.size();
  if (n == 0)
    throw InputError("trajectory", "invalid parameter 'trajectory': empty (needs >= 1 sample)");
  const std::vector<double>& t = trajectory.t;
  for (std::size_t i = 0; i < n; ++i) {
    require_finite("trajectory.t", t[i]);
    if (i > 0 && !(t[i] > t[i - 1]))
      throw InputError("trajectory.t", "invalid parameter 'trajectory.t': not strictly increasing at index " +
                                           std::to_string(i) + " (" + format_value(t[i - 1]) + " then " +
                                           format_value(t[i]) + ")");
  }

  const std::vector<double> energy = pendulum_energy_history(trajectory, omega);
  EnergyStatistics stats;
  stats.initial = energy[0];

  // Work with deviations d_i = E_i - E_0: they are small, so the sums below do not lose the drift
  // in the (much larger) mean energy.
  const double span = t[n - 1] - t[0];
  const double early_end = t[0] + window * span;
  const double late_begin = t[n - 1] - window * span;
  double t_mean = 0.0;
  double d_mean = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double d = energy[i] - stats.initial;
    const double ad = std::abs(d);
    if (!std::isfinite(d))
      throw InputError("trajectory", "invalid parameter 'trajectory': non-finite energy at index " +
                                         std::to_string(i));
    if (ad > stats.max_abs_deviation) stats.max_abs_deviation = ad;
    if (t[i] <= early_end && ad > stats.early_deviation) stats.early_deviation = ad;
    if (t[i] >= late_begin && ad > stats.late_deviation) stats.late_deviation = ad;
    t_mean += t[i];
    d_mean += d;
  }
  t_mean /= static_cast<double>(n);
  d_mean /= static_cast<double>(n);

  // Least squares with centred sums (two-pass): slope = sum (t - tm)(d - dm) / sum (t - tm)^2.
  // The one-pass form sum t d - n tm dm cancels catastrophically for long runs (Chan, Golub &
  // LeVeque 1983, Am. Stat. 37:242).
  double s_tt = 0.0;
  double s_td = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double dt = t[i] - t_mean;
    s_tt += dt * dt;
    s_td += dt * ((energy[i] - stats.initial) - d_mean);
  }
  stats.drift_slope = s_tt > 0.0 ? s_td / s_tt : 0.0;  // one sample: no trend
  stats.drift_intercept = stats.initial + (d_mean - stats.drift_slope * t_mean);
  return stats;
}

}  // namespace rodvv::invariants

#include "rodvv/harness/trajectory_metrics.hpp"

#include <cmath>

namespace rodvv::harness {

namespace {

// Cubic Hermite interpolant on [t0, t1] of g(t) = theta(t) - value with slopes from theta'.
struct HermiteSegment {
  double t0, dt, g0, g1, m0, m1;
  double at(double s) const {  // s in [0, 1]
    const double s2 = s * s, s3 = s2 * s;
    return (2 * s3 - 3 * s2 + 1) * g0 + (s3 - 2 * s2 + s) * dt * m0 + (-2 * s3 + 3 * s2) * g1 +
           (s3 - s2) * dt * m1;
  }
  double slope(double s) const {  // d/ds
    const double s2 = s * s;
    return (6 * s2 - 6 * s) * g0 + (3 * s2 - 4 * s + 1) * dt * m0 + (-6 * s2 + 6 * s) * g1 +
           (3 * s2 - 2 * s) * dt * m1;
  }
};

// Root of the segment's interpolant in [0, 1], given g0 and g1 of opposite sign (or g1 == 0):
// Newton steps safeguarded by bisection, to a bracket of a few ulps.
double locate_root(const HermiteSegment& segment) {
  double lo = 0.0, hi = 1.0;
  const bool rising = segment.g0 < 0.0;
  double s = segment.g0 / (segment.g0 - segment.g1);  // secant start
  for (int iteration = 0; iteration < 100 && hi - lo > 4e-16; ++iteration) {
    const double g = segment.at(s);
    if (g == 0.0) return s;
    if ((g < 0.0) == rising) lo = s; else hi = s;
    const double d = segment.slope(s);
    double next = d != 0.0 ? s - g / d : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    s = next;
  }
  return s;
}

}  // namespace

std::vector<double> crossing_times(const Trajectory& trajectory, double offset, double spacing) {
  std::vector<double> times;
  for (std::size_t i = 0; i + 1 < trajectory.size(); ++i) {
    const double a = trajectory.theta[i], b = trajectory.theta[i + 1];
    // Candidate values c = offset + j * spacing in the half-open range between a and b: a crossing
    // that lands exactly on a sample is counted once, by the segment that ends there.
    double first = offset, last = offset;
    if (spacing > 0.0) {
      const double lo = std::min(a, b), hi = std::max(a, b);
      first = offset + std::ceil((lo - offset) / spacing) * spacing;
      last = offset + std::floor((hi - offset) / spacing) * spacing;
    }
    for (double value = first; value <= last; value += (spacing > 0.0 ? spacing : 1.0)) {
      const double g0 = a - value, g1 = b - value;
      if (g0 == 0.0 || !((g0 < 0.0) != (g1 < 0.0) || g1 == 0.0)) {
        if (spacing <= 0.0) break;
        continue;
      }
      const HermiteSegment segment{trajectory.t[i], trajectory.t[i + 1] - trajectory.t[i], g0, g1,
                                   trajectory.theta_dot[i], trajectory.theta_dot[i + 1]};
      times.push_back(segment.t0 + segment.dt * locate_root(segment));
      if (spacing <= 0.0) break;
    }
  }
  return times;
}

std::optional<double> period_from_crossings(const std::vector<double>& times,
                                            double crossings_per_period) {
  if (times.size() < 2) return std::nullopt;
  return (times.back() - times.front()) / static_cast<double>(times.size() - 1) * crossings_per_period;
}

std::vector<std::size_t> comparison_indices(std::size_t samples, std::size_t max_points) {
  std::vector<std::size_t> indices;
  if (samples == 0) return indices;
  std::size_t stride = 1;
  while (samples / stride > max_points) stride *= 2;
  for (std::size_t i = 0; i < samples; i += stride) indices.push_back(i);
  if (indices.back() != samples - 1) indices.push_back(samples - 1);
  return indices;
}

Series thin_series(std::string name, std::string x_label, std::string y_label,
                   const std::vector<double>& x, const std::vector<double>& y, std::size_t max_points) {
  Series series{std::move(name), std::move(x_label), std::move(y_label), {}, {}};
  const std::size_t n = std::min(x.size(), y.size());
  if (n <= max_points || max_points == 0) {
    series.x.assign(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(n));
    series.y.assign(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n));
    return series;
  }
  for (std::size_t bin = 0; bin < max_points; ++bin) {
    const std::size_t begin = bin * n / max_points, end = (bin + 1) * n / max_points;
    std::size_t best = begin;
    for (std::size_t i = begin; i < end; ++i)
      if (std::abs(y[i]) > std::abs(y[best])) best = i;
    series.x.push_back(x[best]);
    series.y.push_back(y[best]);
  }
  return series;
}

}  // namespace rodvv::harness

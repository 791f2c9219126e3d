#include "rodvv/harness/order_fit.hpp"

#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness {

namespace {
bool usable(const std::optional<double>& error) {
  return error && std::isfinite(*error) && *error > 0.0;
}
}  // namespace

OrderFit fit_order(std::span<const double> h, std::span<const std::optional<double>> errors,
                   std::size_t fit_levels) {
  if (h.size() != errors.size())
    throw InputError("errors", "fit_order: " + std::to_string(h.size()) + " mesh sizes but " +
                                   std::to_string(errors.size()) + " errors");
  require_at_least("fit_levels", fit_levels, 2);
  for (double value : h) require_positive("h", value);

  OrderFit fit;
  for (std::size_t i = 0; i + 1 < h.size(); ++i) {
    if (usable(errors[i]) && usable(errors[i + 1]) && h[i] != h[i + 1])
      fit.pairwise.push_back(std::log(*errors[i] / *errors[i + 1]) / std::log(h[i] / h[i + 1]));
    else
      fit.pairwise.push_back(std::nan(""));  // placeholder keeps indices aligned; serialised as null
  }

  if (h.size() < fit_levels) return fit;
  const std::size_t first = h.size() - fit_levels;
  for (std::size_t i = first; i < h.size(); ++i)
    if (!usable(errors[i])) return fit;

  // Ordinary least squares of y = log e on x = log h, with centred sums for stability.
  const auto n = static_cast<double>(fit_levels);
  double mean_x = 0.0, mean_y = 0.0;
  for (std::size_t i = first; i < h.size(); ++i) {
    mean_x += std::log(h[i]);
    mean_y += std::log(*errors[i]);
  }
  mean_x /= n;
  mean_y /= n;
  double sxx = 0.0, sxy = 0.0, syy = 0.0;
  for (std::size_t i = first; i < h.size(); ++i) {
    const double dx = std::log(h[i]) - mean_x;
    const double dy = std::log(*errors[i]) - mean_y;
    sxx += dx * dx;
    sxy += dx * dy;
    syy += dy * dy;
  }
  if (!(sxx > 0.0)) return fit;  // all levels at the same h: no slope
  const double slope = sxy / sxx;
  fit.least_squares = slope;
  // R^2 = 1 - SS_res / SS_tot; with SS_tot = 0 (identical errors) the fit explains nothing.
  const double ss_res = syy - slope * sxy;
  fit.r_squared = syy > 0.0 ? 1.0 - ss_res / syy : 0.0;
  fit.levels_used = fit_levels;
  return fit;
}

}  // namespace rodvv::harness

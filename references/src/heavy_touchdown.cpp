#include "rodvv/references/heavy_touchdown.hpp"

#include <cmath>

#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {

void check(const HeavyTouchdown& rod) {
  require_positive("EI", rod.EI);
  require_positive("w", rod.w);
  require_positive("delta", rod.delta);
}

}  // namespace

double touchdown_clamp_moment(const HeavyTouchdown& rod) {
  check(rod);
  return std::sqrt(2.0 * rod.EI * rod.w * rod.delta);
}

double touchdown_lifted_span(const HeavyTouchdown& rod) {
  check(rod);
  return std::sqrt(std::sqrt(72.0 * rod.EI * rod.delta / rod.w));
}

double touchdown_clamp_force(const HeavyTouchdown& rod) { return 2.0 * rod.w * touchdown_lifted_span(rod) / 3.0; }

double touchdown_height(const HeavyTouchdown& rod, double x) {
  require_finite("x", x);
  const double l = touchdown_lifted_span(rod), xi = l - x;
  if (xi <= 0.0) return 0.0;
  return rod.w * xi * xi * xi * (l / 18.0 - xi / 24.0) / rod.EI;
}

}  // namespace rodvv::references

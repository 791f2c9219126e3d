#include "rodvv/references/heavy_column.hpp"

#include <cmath>

#include "bracketed_root.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

double heavy_column_critical_weight() {
  // On [7, 8.5] the n-th term is below 7e-18 by n = 12 and 2e-37 by n = 20: 40 terms leave nothing.
  // f(7) = 0.080 > 0 > f(8.5) = -0.060: the first root is the only sign change there.
  auto top_slope_at_foot = [](double x) {
    double term = 1.0, sum = 1.0;
    for (int m = 1; m <= 40; ++m) {
      term *= -x / (3.0 * m * (3.0 * m - 1.0));
      sum += term;
    }
    return sum;
  };
  return detail::solve_bracketed("heavy_column_critical_weight", top_slope_at_foot, 7.0, 8.5, top_slope_at_foot(7.0),
                                 top_slope_at_foot(8.5));
}

double heavy_column_critical_length(const HeavyColumn& column) {
  require_positive("EI", column.EI);
  require_positive("w", column.w);
  return std::cbrt(heavy_column_critical_weight() * column.EI / column.w);
}

}  // namespace rodvv::references

#include "rodvv/solvers/elastica2d/arc_geometry.hpp"

#include <cmath>

namespace rodvv::solvers::elastica2d {

SincDerivatives sinc_derivatives(double v) noexcept {
  if (std::abs(v) < 0.5) {
    // sinc(v) = sum_k c_k v^{2k}, c_k = (-1)^k / (2k+1)!; for |v| < 0.5 the k = 10 term is < 1e-26.
    // first  = v * sum_{k>=1} c_k 2k v^{2(k-1)},  second = sum_{k>=1} c_k 2k (2k-1) v^{2(k-1)}.
    const double v2 = v * v;
    double value = 1.0, first_over_v = 0.0, second = 0.0;
    double coefficient = 1.0;  // c_k
    double previous = 1.0;     // v^{2(k-1)}
    for (int k = 1; k <= 10; ++k) {
      const double two_k = 2.0 * k;
      coefficient /= -(two_k * (two_k + 1.0));
      first_over_v += coefficient * two_k * previous;
      second += coefficient * two_k * (two_k - 1.0) * previous;
      previous *= v2;
      value += coefficient * previous;
    }
    return {value, first_over_v * v, second};
  }
  const double s = std::sin(v), c = std::cos(v);
  const double value = s / v;
  const double first = (c - value) / v;            // (v cos v - sin v) / v^2
  const double second = -value - 2.0 * first / v;  // from (v sinc)'' = -v sinc
  return {value, first, second};
}

}  // namespace rodvv::solvers::elastica2d

#include "buckling_threshold.hpp"

#include <cmath>
#include <cstdint>

#include <boost/math/tools/roots.hpp>

#include "rodvv/common/errors.hpp"

namespace rodvv::harness::rod3d_cases {

double critical_load(const std::function<double(double load)>& eigenvalue, double low, double high,
                     const std::string& what) {
  const double f_low = eigenvalue(low), f_high = eigenvalue(high);
  if (!(f_low * f_high < 0.0))
    throw SolverError("critical load (" + what + ")",
                      "the stability eigenvalue does not change sign on the bracket [" + std::to_string(low) + ", " +
                          std::to_string(high) + "]",
                      2, std::min(std::abs(f_low), std::abs(f_high)));
  std::uintmax_t iterations = 60;
  const auto tolerance = [](double a, double b) { return std::abs(a - b) <= 1e-13 * std::abs(a); };
  const auto [a, b] = boost::math::tools::toms748_solve(eigenvalue, low, high, f_low, f_high, tolerance, iterations);
  if (iterations >= 60) throw SolverError("critical load (" + what + ")", "TOMS 748 did not converge", iterations, b - a);
  return 0.5 * (a + b);
}

}  // namespace rodvv::harness::rod3d_cases

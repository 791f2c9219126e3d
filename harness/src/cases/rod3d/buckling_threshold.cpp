#include "buckling_threshold.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

#include <boost/math/tools/roots.hpp>

#include "rodvv/common/errors.hpp"

namespace rodvv::harness::rod3d_cases {

double critical_load(const std::function<double(double load)>& raw_eigenvalue, double low, double high,
                     const std::string& what) {
  // The linearisation refuses a state that is not at rest as a bad 'state'; here the state is the
  // statics' own answer, so that is a numerical failure of this level, not bad input.
  const auto eigenvalue = [&](double load) {
    try {
      return raw_eigenvalue(load);
    } catch (const InputError& error) {
      if (error.parameter() != "state") throw;
      throw SolverError("critical load (" + what + ")",
                        "the equilibrium at load " + std::to_string(load) + " is not at rest enough to linearise: " +
                            error.what(),
                        0, std::numeric_limits<double>::quiet_NaN());
    }
  };
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

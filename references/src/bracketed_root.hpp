#pragma once
// Bracketing root finder shared by the closed-form references (internal header): Boost's TOMS 748
// (Alefeld, Potra & Shi 1995, ACM TOMS 21:327) to a bracket of 4 eps relative width.
#include <boost/math/tools/toms748_solve.hpp>

#include <cmath>
#include <cstdint>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"  // format_value

namespace rodvv::references::detail {

inline constexpr std::uintmax_t kMaxRootIterations = 200;

// The root of f on [a, b], where fa = f(a) and fb = f(b) have opposite signs (checked by the caller);
// returns the midpoint of the final bracket. SolverError (named `method`, with the iterations and
// the residual at the midpoint) if TOMS 748 has not converged after kMaxRootIterations, or if f(a)
// and f(b) do not bracket a root.
template <class F>
double solve_bracketed(const char* method, F f, double a, double b, double fa, double fb) {
  // A bracket without a sign change (a defect upstream, or a NaN) is a numerical failure, not an
  // exception from inside Boost.
  if (!((fa <= 0.0 && fb >= 0.0) || (fa >= 0.0 && fb <= 0.0)))
    throw SolverError(method,
                      std::string(method) + ": no sign change on [" + format_value(a) + ", " + format_value(b) +
                          "] (f = " + format_value(fa) + ", " + format_value(fb) + ")",
                      0, std::abs(fa) < std::abs(fb) ? fa : fb);
  std::uintmax_t iterations = kMaxRootIterations;
  const auto bracket = boost::math::tools::toms748_solve(
      f, a, b, fa, fb, boost::math::tools::eps_tolerance<double>(), iterations);
  const double root = 0.5 * (bracket.first + bracket.second);
  if (iterations >= kMaxRootIterations) {
    const double residual = f(root);
    throw SolverError(method,
                      std::string(method) + ": TOMS 748 did not converge in " +
                          std::to_string(iterations) + " iterations (residual " +
                          format_value(residual) + ")",
                      static_cast<std::size_t>(iterations), residual);
  }
  return root;
}

}  // namespace rodvv::references::detail

#include "rodvv/harness/richardson.hpp"

#include <cmath>
#include <cstdint>

#include <boost/math/tools/roots.hpp>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::harness {

std::optional<RichardsonResult> richardson_gci(const RichardsonInput& in, std::string* why_not) {
  auto decline = [why_not](const std::string& reason) -> std::optional<RichardsonResult> {
    if (why_not) *why_not = reason;
    return std::nullopt;
  };
  require_positive("h1", in.h1);
  if (!(in.h2 > in.h1 && in.h3 > in.h2) || !std::isfinite(in.h3))
    throw InputError("h", "richardson_gci: mesh sizes must increase strictly from fine to coarse, got " +
                              format_value(in.h1) + ", " + format_value(in.h2) + ", " +
                              format_value(in.h3));
  if (!std::isfinite(in.f1) || !std::isfinite(in.f2) || !std::isfinite(in.f3))
    return decline("a level's value is not finite");

  const double r21 = in.h2 / in.h1;
  const double r32 = in.h3 / in.h2;
  const double e21 = in.f2 - in.f1;
  const double e32 = in.f3 - in.f2;
  if (e21 == 0.0 || e32 == 0.0)
    return decline("differences between levels vanish (converged to round-off or exact)");
  const double ratio = e32 / e21;
  if (ratio < 0.0) return decline("oscillatory convergence (level differences change sign)");

  // With f = f_exact + C h^p, e32 / e21 = r21^p (r32^p - 1) / (r21^p - 1) =: G(p). Celik's
  // fixed-point form of this equation can stall for unequal ratios, so solve G(p) = e32/e21 for p
  // by bracketing (TOMS 748) on p in [1e-3, 30]; log G is increasing in p.
  const auto residual = [&](double p) {
    return p * std::log(r21) + std::log(std::expm1(p * std::log(r32))) -
           std::log(std::expm1(p * std::log(r21))) - std::log(ratio);
  };
  constexpr double p_min = 1e-3, p_max = 30.0;
  if (!(residual(p_min) < 0.0 && residual(p_max) > 0.0))
    return decline("observed order outside [0.001, 30]: level differences do not fit C h^p");
  std::uintmax_t iterations = 200;
  const auto bracket = boost::math::tools::toms748_solve(
      residual, p_min, p_max, boost::math::tools::eps_tolerance<double>(50), iterations);
  if (iterations >= 200) return decline("order root-finding did not converge in 200 iterations");
  const double p = 0.5 * (bracket.first + bracket.second);

  RichardsonResult result;
  result.refinement_ratio = r21;
  result.observed_order = p;
  const double r21p = std::pow(r21, p);
  const double r32p = std::pow(r32, p);
  result.extrapolated = (r21p * in.f1 - in.f2) / (r21p - 1.0);
  if (in.f1 == 0.0 || in.f2 == 0.0)
    return decline("relative GCI undefined: the functional is zero at a level");
  result.gci_fine = kGciSafetyFactor * std::abs(e21 / in.f1) / (r21p - 1.0);
  result.gci_coarse = kGciSafetyFactor * std::abs(e32 / in.f2) / (r32p - 1.0);
  result.asymptotic_ratio = result.gci_coarse / (r21p * result.gci_fine);
  return result;
}

}  // namespace rodvv::harness

#include "rodvv/harness/richardson.hpp"

#include <cmath>

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
  const double s = 1.0;

  // Fixed-point iteration for p (Celik et al. 2008, eqs. 3-5). For r21 = r32, q = 0 and the first
  // iterate is exact; otherwise it converges in a handful of iterations in the asymptotic range.
  const double log_ratio = std::log(std::abs(ratio));
  double p = std::abs(log_ratio) / std::log(r21);
  bool settled = false;
  for (int iteration = 0; iteration < 100; ++iteration) {
    const double q = std::log((std::pow(r21, p) - s) / (std::pow(r32, p) - s));
    const double next = std::abs(log_ratio + q) / std::log(r21);
    if (!std::isfinite(next)) return decline("order iteration produced a non-finite value");
    if (std::abs(next - p) <= 1e-12 * std::max(1.0, std::abs(p))) {
      p = next;
      settled = true;
      break;
    }
    p = next;
  }
  if (!settled) return decline("order fixed-point iteration did not settle in 100 iterations");
  if (!(p > 0.0)) return decline("observed order is not positive");

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

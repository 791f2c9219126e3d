#include "rodvv/invariants/planar_noether.hpp"

// Derivation of dH/ds (PHYSICS.md §0, §1.3), V = 0 and n = -P e_x for brevity (the V and general-n
// terms cancel exactly as in §0): H = 1/2 EI (theta'^2 - kh^2) - P cos theta, moment balance
// (EI (theta' - kh))' = -P sin theta, i.e. EI theta'' = EI kh' - P sin theta - EI' (theta' - kh). Then
//   dH/ds = 1/2 EI' (theta'^2 - kh^2) + EI theta' theta'' - EI kh kh' + P sin theta theta'
//         = 1/2 EI' (theta'^2 - kh^2) - EI' theta' (theta' - kh) + EI kh' (theta' - kh)
//         = -1/2 EI' (theta' - kh)^2 + EI kh' (theta' - kh)  = -dL/ds at fixed (theta, theta').

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>
#include <utility>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::invariants {

namespace {

// Neumaier's compensated sum: error O(eps) |sum of |terms||, independent of the number of terms.
class CompensatedSum {
 public:
  void add(double value) {
    const double t = sum_ + value;
    if (std::abs(sum_) >= std::abs(value))
      compensation_ += (sum_ - t) + value;
    else
      compensation_ += (value - t) + sum_;
    sum_ = t;
  }
  double value() const { return sum_ + compensation_; }

 private:
  double sum_ = 0.0;
  double compensation_ = 0.0;
};

void check_array(const std::string& name, const std::vector<double>& values, std::size_t n) {
  if (values.size() != n)
    throw InputError(name, "invalid parameter '" + name + "': " + std::to_string(values.size()) +
                               " values, but solution.s has " + std::to_string(n) +
                               " (arrays of unequal length)");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(values[i]))
      throw InputError(name, "invalid parameter '" + name + "' = " + format_value(values[i]) +
                                 " at index " + std::to_string(i) + ": must be finite");
}

// Validates every field the functions of this file read (see the header).
void validate(const PlanarRodSolution& solution) {
  const std::size_t n = solution.s.size();
  if (n < 2)
    throw InputError("solution.s", "invalid parameter 'solution.s': " + std::to_string(n) +
                                       " nodes, needs >= 2");
  check_array("solution.s", solution.s, n);
  for (std::size_t i = 1; i < n; ++i)
    if (!(solution.s[i] > solution.s[i - 1]))
      throw InputError("solution.s", "invalid parameter 'solution.s': not strictly increasing at index " +
                                         std::to_string(i) + " (" + format_value(solution.s[i - 1]) +
                                         " then " + format_value(solution.s[i]) + ")");
  check_array("solution.kappa", solution.kappa, n);
  check_array("solution.bending_stiffness", solution.bending_stiffness, n);
  for (std::size_t i = 0; i < n; ++i)
    if (!(solution.bending_stiffness[i] > 0.0))
      throw InputError("solution.bending_stiffness",
                       "invalid parameter 'solution.bending_stiffness' = " +
                           format_value(solution.bending_stiffness[i]) + " at index " +
                           std::to_string(i) + ": must be > 0");
  check_array("solution.natural_curvature", solution.natural_curvature, n);
  check_array("solution.axial_force", solution.axial_force, n);
  check_array("solution.potential", solution.potential, n);
  for (const auto& [name, value] : {std::pair{"solution.axial_stiffness", solution.axial_stiffness},
                                    std::pair{"solution.shear_stiffness", solution.shear_stiffness}})
    if (!(value > 0.0))
      throw InputError(name, std::string("invalid parameter '") + name + "' = " + format_value(value) +
                                 ": must be in (0, +inf] (+inf = rigid)");
  if (std::isfinite(solution.shear_stiffness)) check_array("solution.shear_force", solution.shear_force, n);
}

// 1/EA and 1/GA (exactly 0 when rigid); (R) in the header needs n.N only when GA is finite.
struct Compliances {
  double axial = 0.0, shear = 0.0;
  explicit Compliances(const PlanarRodSolution& solution)
      : axial(1.0 / solution.axial_stiffness), shear(1.0 / solution.shear_stiffness) {}
  bool any() const { return axial != 0.0 || shear != 0.0; }
  double energy(const PlanarRodSolution& solution, std::size_t i) const {  // (n.t)^2/2EA + (n.N)^2/2GA
    const double nt = solution.axial_force[i];
    const double nn = shear != 0.0 ? solution.shear_force[i] : 0.0;
    return 0.5 * (axial * nt * nt + shear * nn * nn);
  }
};

std::vector<double> h_unchecked(const PlanarRodSolution& solution) {
  std::vector<double> h(solution.s.size());
  const Compliances compliances(solution);
  for (std::size_t i = 0; i < h.size(); ++i) {
    h[i] = planar_noether_density(solution.bending_stiffness[i], solution.kappa[i],
                                  solution.natural_curvature[i], solution.axial_force[i],
                                  solution.potential[i]);
    if (compliances.any()) h[i] += compliances.energy(solution, i);  // (R)
  }
  return h;
}

double natural_scale_unchecked(const PlanarRodSolution& solution) {
  double scale = 0.0;
  const Compliances compliances(solution);
  for (std::size_t i = 0; i < solution.s.size(); ++i) {
    const double k = solution.kappa[i];
    const double kh = solution.natural_curvature[i];
    double term = 0.5 * solution.bending_stiffness[i] * (k * k + kh * kh) +
                  std::abs(solution.axial_force[i]) + std::abs(solution.potential[i]);
    if (compliances.any()) term += compliances.energy(solution, i);
    if (term > scale) scale = term;
  }
  return scale;
}

// Node values of a coefficient derivative from a callable (empty -> zeros).
std::vector<double> sample(const std::string& name, const ScalarFunction& f,
                           const std::vector<double>& s) {
  std::vector<double> values(s.size(), 0.0);
  if (!f) return values;
  for (std::size_t i = 0; i < s.size(); ++i) {
    values[i] = f(s[i]);
    if (!std::isfinite(values[i]))
      throw InputError(name, "invalid parameter '" + name + "': returned " + format_value(values[i]) +
                                 " at s = " + format_value(s[i]) + " (index " + std::to_string(i) +
                                 "); must be finite");
  }
  return values;
}

// Node values of a coefficient derivative from samples (empty -> zeros).
std::vector<double> sample(const std::string& name, std::span<const double> samples, std::size_t n) {
  if (samples.empty()) return std::vector<double>(n, 0.0);
  std::vector<double> values(samples.begin(), samples.end());
  check_array(name, values, n);
  return values;
}

// Validated solution; derivative arrays of the right length and finite.
std::vector<double> predicted_unchecked(const PlanarRodSolution& solution,
                                        const std::vector<double>& ei_prime,
                                        const std::vector<double>& kh_prime) {
  const std::size_t n = solution.s.size();
  std::vector<double> rate(n);
  for (std::size_t i = 0; i < n; ++i)
    rate[i] = planar_noether_drift_density(solution.bending_stiffness[i], ei_prime[i], solution.kappa[i],
                                           solution.natural_curvature[i], kh_prime[i]);
  std::vector<double> predicted(n, 0.0);
  CompensatedSum integral;
  for (std::size_t i = 1; i < n; ++i) {
    integral.add(0.5 * (solution.s[i] - solution.s[i - 1]) * (rate[i - 1] + rate[i]));
    predicted[i] = integral.value();
  }
  return predicted;
}

HDriftCheck drift_check_unchecked(const PlanarRodSolution& solution,
                                  const std::vector<double>& predicted) {
  const std::vector<double> h = h_unchecked(solution);
  HDriftCheck check;
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double drift = h[i] - h[0];
    const double residual = std::abs(drift - predicted[i]);
    if (residual > check.max_abs_residual) {
      check.max_abs_residual = residual;
      check.worst_index = i;
    }
    check.max_abs_drift = std::max(check.max_abs_drift, std::abs(drift));
    check.max_abs_predicted = std::max(check.max_abs_predicted, std::abs(predicted[i]));
  }
  if (check.max_abs_drift > 0.0)
    check.relative_residual = check.max_abs_residual / check.max_abs_drift;
  else
    check.relative_residual =
        check.max_abs_residual > 0.0 ? std::numeric_limits<double>::infinity() : 0.0;
  const double natural = natural_scale_unchecked(solution);
  check.scale = natural > 0.0 ? natural : 1.0;
  check.residual_over_scale = check.max_abs_residual / check.scale;
  return check;
}

constexpr const char* kEiPrime = "bending_stiffness_derivative";
constexpr const char* kKhPrime = "natural_curvature_derivative";

}  // namespace

std::vector<double> planar_noether_h(const PlanarRodSolution& solution) {
  validate(solution);
  return h_unchecked(solution);
}

double planar_noether_natural_scale(const PlanarRodSolution& solution) {
  validate(solution);
  return natural_scale_unchecked(solution);
}

HSpread planar_noether_spread(const PlanarRodSolution& solution, std::optional<double> scale) {
  validate(solution);
  if (scale) require_positive("scale", *scale);
  const std::vector<double> h = h_unchecked(solution);
  HSpread out;
  CompensatedSum sum;
  for (double value : h) sum.add(value);
  out.mean = sum.value() / static_cast<double>(h.size());
  out.at_start = h.front();
  out.at_end = h.back();
  for (std::size_t i = 0; i < h.size(); ++i) {
    const double deviation = std::abs(h[i] - out.mean);
    if (deviation > out.max_abs_deviation) {
      out.max_abs_deviation = deviation;
      out.worst_index = i;
    }
  }
  if (scale) {
    out.scale = *scale;
  } else {
    const double natural = natural_scale_unchecked(solution);
    out.scale_is_fallback = !(natural > 0.0);
    out.scale = out.scale_is_fallback ? 1.0 : natural;
  }
  out.spread = out.max_abs_deviation / out.scale;
  return out;
}

std::vector<double> planar_noether_predicted_drift(const PlanarRodSolution& solution,
                                                   const ScalarFunction& bending_stiffness_derivative,
                                                   const ScalarFunction& natural_curvature_derivative) {
  validate(solution);
  return predicted_unchecked(solution, sample(kEiPrime, bending_stiffness_derivative, solution.s),
                             sample(kKhPrime, natural_curvature_derivative, solution.s));
}

std::vector<double> planar_noether_predicted_drift(const PlanarRodSolution& solution,
                                                   std::span<const double> bending_stiffness_derivative,
                                                   std::span<const double> natural_curvature_derivative) {
  validate(solution);
  const std::size_t n = solution.s.size();
  return predicted_unchecked(solution, sample(kEiPrime, bending_stiffness_derivative, n),
                             sample(kKhPrime, natural_curvature_derivative, n));
}

HDriftCheck planar_noether_drift_check(const PlanarRodSolution& solution,
                                       const ScalarFunction& bending_stiffness_derivative,
                                       const ScalarFunction& natural_curvature_derivative) {
  return drift_check_unchecked(solution,
                               planar_noether_predicted_drift(solution, bending_stiffness_derivative,
                                                              natural_curvature_derivative));
}

HDriftCheck planar_noether_drift_check(const PlanarRodSolution& solution,
                                       std::span<const double> bending_stiffness_derivative,
                                       std::span<const double> natural_curvature_derivative) {
  return drift_check_unchecked(solution,
                               planar_noether_predicted_drift(solution, bending_stiffness_derivative,
                                                              natural_curvature_derivative));
}

}  // namespace rodvv::invariants

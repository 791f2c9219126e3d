#include "rodvv/references/rod3d.hpp"

#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::references {

namespace {
void validate(const AxialWrenchHelix& helix) {
  require_positive("B", helix.B);
  require_positive("C", helix.C);
  require_positive("radius", helix.radius);
  require_open_interval("pitch_angle", helix.pitch_angle, 0.0, std::numbers::pi / 2);
  require_finite("twisting_moment", helix.twisting_moment);
}

void require_unit(const char* name, const Vec3& v) {
  for (int i = 0; i < 3; ++i) require_finite(name, v[i]);
  if (!(std::abs(v.norm() - 1.0) <= 1e-12))
    throw InputError(name, std::string("invalid parameter '") + name + "': must be a unit vector (|v| = " +
                               format_value(v.norm()) + ")");
}
}  // namespace

AxialWrenchHelixSolution axial_wrench_helix(const AxialWrenchHelix& helix) {
  validate(helix);
  const double sa = std::sin(helix.pitch_angle), ca = std::cos(helix.pitch_angle);
  const double R = helix.radius, Mt = helix.twisting_moment;
  AxialWrenchHelixSolution out;
  out.kappa = sa * sa / R;
  out.tau = sa * ca / R;
  out.darboux = sa / R;
  out.axial_force = (Mt - helix.B * out.tau) * out.darboux;
  out.axial_moment = helix.B * sa * sa * sa / R + Mt * ca;
  out.natural_twist = out.tau - Mt / helix.C;
  out.H = out.axial_force * ca + 0.5 * helix.B * out.kappa * out.kappa + Mt * out.tau - Mt * Mt / (2.0 * helix.C);
  return out;
}

HelixPoint axial_wrench_helix_point(const AxialWrenchHelix& helix, double s) {
  const AxialWrenchHelixSolution sol = axial_wrench_helix(helix);
  require_finite("s", s);
  const double sa = std::sin(helix.pitch_angle), ca = std::cos(helix.pitch_angle);
  const double phi = s * sa / helix.radius, sp = std::sin(phi), cp = std::cos(phi);
  const Vec3 t(-sa * sp, sa * cp, ca), normal(-cp, -sp, 0.0), binormal(ca * sp, -ca * cp, sa);
  HelixPoint point;
  point.position = Vec3(helix.radius * cp, helix.radius * sp, s * ca);
  point.frame.col(0) = t;
  point.frame.col(1) = binormal;
  point.frame.col(2) = -normal;
  point.force = Vec3(0.0, 0.0, sol.axial_force);
  point.moment = helix.B * sol.kappa * binormal + helix.twisting_moment * t;
  return point;
}

double self_weight_tip_deflection(double load_per_length, double L, double EI) {
  require_non_negative("load_per_length", load_per_length);
  require_positive("L", L);
  require_positive("EI", EI);
  return load_per_length * L * L * L * L / (8.0 * EI);
}

double cantilever_beta_l(std::size_t n) {
  require_at_least("n", n, 1);
  // Roots lie within 0.31 of (n - 1/2) pi (n = 1: 1.875 vs 1.571; then within 0.02); cos x + sech x
  // changes sign exactly once on [(n - 1/2) pi - 0.5, (n - 1/2) pi + 0.5]. Bisection to adjacent
  // doubles.
  const double centre = (static_cast<double>(n) - 0.5) * std::numbers::pi;
  double lo = centre - 0.5, hi = centre + 0.5;
  auto f = [](double x) { return std::cos(x) + 1.0 / std::cosh(x); };
  const bool lo_positive = f(lo) > 0.0;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if ((f(mid) > 0.0) == lo_positive)
      lo = mid;
    else
      hi = mid;
  }
  return 0.5 * (lo + hi);
}

double cantilever_frequency(std::size_t n, double EI, double line_density, double L) {
  require_positive("EI", EI);
  require_positive("line_density", line_density);
  require_positive("L", L);
  const double beta = cantilever_beta_l(n);
  return beta * beta * std::sqrt(EI / (line_density * L * L * L * L));
}

RollUpPoint end_moment_roll_up_point(const EndMomentRollUp& rod, double s) {
  require_positive("L", rod.L);
  require_positive("EI", rod.EI);
  require_finite("M", rod.M);
  require_unit("tangent", rod.tangent);
  require_unit("axis", rod.axis);
  if (!(std::abs(rod.tangent.dot(rod.axis)) <= 1e-12))
    throw InputError("axis", "invalid parameter 'axis': must be normal to the tangent");
  require_closed_interval("s", s, 0.0, rod.L);
  const Vec3 normal = rod.axis.cross(rod.tangent);
  const double angle = rod.M * s / rod.EI;
  RollUpPoint point;
  // sin(a)/k and (1 - cos a)/k with k = M/EI, written without division by M: s sinc, s^2 f1 k.
  const double k = rod.M / rod.EI;
  double along, across;
  if (std::abs(angle) < 1e-4) {
    along = s * (1.0 - angle * angle / 6.0);
    across = s * angle * (0.5 - angle * angle / 24.0);
  } else {
    along = std::sin(angle) / k;
    across = 2.0 * std::sin(0.5 * angle) * std::sin(0.5 * angle) / k;
  }
  point.position = rod.root_position + along * rod.tangent + across * normal;
  point.tangent = std::cos(angle) * rod.tangent + std::sin(angle) * normal;
  return point;
}

double end_moment_roll_up_invariant(const EndMomentRollUp& rod) {
  require_positive("EI", rod.EI);
  require_finite("M", rod.M);
  return rod.M * rod.M / (2.0 * rod.EI);
}

}  // namespace rodvv::references

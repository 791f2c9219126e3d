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

ModeShapePoint cantilever_mode_shape(std::size_t n, double x) {
  require_at_least("n", n, 1);
  if (n > 50) throw InputError("n", "invalid n = " + std::to_string(n) + ": the mode number must be in [1, 50]");
  if (!(x >= 0.0 && x <= 1.0))
    throw InputError("x", "invalid x = " + std::to_string(x) + ": the station s / L must be in [0, 1]");
  const double b = cantilever_beta_l(n), d = std::sinh(b) + std::sin(b);
  const double sigma = (std::cosh(b) + std::cos(b)) / d;
  // cosh bx - sigma sinh bx and sinh bx - sigma cosh bx, each over d without the cancelling products.
  const auto hyperbolic = [&](double y) {
    return (std::sinh(b * (1.0 - y)) + std::cosh(b * y) * std::sin(b) - std::sinh(b * y) * std::cos(b)) / d;
  };
  const auto hyperbolic_slope = [&](double y) {
    return (-std::cosh(b * (1.0 - y)) + std::sinh(b * y) * std::sin(b) - std::cosh(b * y) * std::cos(b)) / d;
  };
  const auto phi = [&](double y) { return hyperbolic(y) - std::cos(b * y) + sigma * std::sin(b * y); };
  const double tip = phi(1.0);
  return {phi(x) / tip, b * (hyperbolic_slope(x) + std::sin(b * x) + sigma * std::cos(b * x)) / tip};
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

namespace {
void validate(const SpecialCosseratHelix& rod) {
  require_positive("B", rod.B);
  require_positive("C", rod.C);
  require_positive("GA", rod.GA);
  require_positive("EA", rod.EA);
  for (int i = 0; i < 3; ++i) require_finite("u", rod.u[i]);
  for (int i = 0; i < 3; ++i) require_finite("root_position", rod.root_position[i]);
  // u parallel to n0 (pure twist, including u = 0): a straight twisted rod, any tension is an
  // equilibrium, the helix axis and lambda are undefined.
  if (!(rod.u.tail<2>().norm() > 0.0))
    throw InputError("u", "invalid parameter 'u': must have a bending part (u1, u2) != 0 (otherwise the rod is "
                          "straight: the helix axis and the force lambda are undefined)");
  const Mat3& R = rod.root_frame;
  if (!R.allFinite() || (R.transpose() * R - Mat3::Identity()).norm() > 1e-12 || std::abs(R.determinant() - 1.0) > 1e-12)
    throw InputError("root_frame", "invalid parameter 'root_frame': must be a rotation (|R^T R - I| <= 1e-12, "
                                   "|det R - 1| <= 1e-12)");
}
}  // namespace

SpecialCosseratHelixSolution special_cosserat_helix(const SpecialCosseratHelix& rod) {
  validate(rod);
  const Vec3& u = rod.u;
  const Vec3 stiffness(rod.C, rod.B, rod.B), compliance(1.0 / rod.EA, 1.0 / rod.GA, 1.0 / rod.GA);
  // lambda^2 a + lambda + c = 0 with a = u0 (1/EA - 1/GA), c = (B - C) u0; the root -> -c as a -> 0,
  // lambda = -2 c / (1 + sqrt(1 - 4 a c)) (no cancellation).
  const double a = u[0] * (1.0 / rod.EA - 1.0 / rod.GA), c = (rod.B - rod.C) * u[0];
  const double discriminant = 1.0 - 4.0 * a * c;
  if (!(discriminant >= 0.0))
    throw InputError("u", "invalid parameter 'u': no real force: 1 - 4 u0^2 (1/EA - 1/GA)(B - C) = " +
                              format_value(discriminant) + " must be >= 0");
  SpecialCosseratHelixSolution out;
  out.lambda = -2.0 * c / (1.0 + std::sqrt(discriminant));
  out.strain_v = Vec3::UnitX() + out.lambda * compliance.cwiseProduct(u);
  out.force_body = out.lambda * u;
  out.moment_body = stiffness.cwiseProduct(u);
  out.rate = u.norm();
  const Vec3 axis_body = u / out.rate;
  out.axis = rod.root_frame * axis_body;
  out.advance = out.strain_v.dot(axis_body);
  out.radius = (out.strain_v - out.advance * axis_body).norm() / out.rate;
  out.axis_point = rod.root_position + rod.root_frame * u.cross(out.strain_v) / (out.rate * out.rate);
  out.axial_force = out.lambda * out.rate;
  out.axial_moment = u.dot(out.moment_body) / out.rate;
  out.bending_energy = 0.5 * u.dot(out.moment_body);
  const Vec3 shear = out.strain_v - Vec3::UnitX();
  out.shear_energy = 0.5 * shear.dot(shear.cwiseQuotient(compliance));
  out.H = out.force_body.dot(out.strain_v) + out.moment_body.dot(u) - out.bending_energy - out.shear_energy;
  return out;
}

CosseratHelixPoint special_cosserat_helix_point(const SpecialCosseratHelix& rod, double s) {
  const SpecialCosseratHelixSolution sol = special_cosserat_helix(rod);
  require_finite("s", s);
  const double k = sol.rate, angle = k * s;
  const Vec3 axis_body = rod.u / k;
  const Vec3 v_perp = sol.strain_v - sol.advance * axis_body;
  // int_0^s exp(t [u]x) dt v_perp, with v_perp normal to u: rotation in the plane normal to the axis
  const Vec3 turn = std::sin(angle) / k * v_perp + 2.0 * std::sin(0.5 * angle) * std::sin(0.5 * angle) / k *
                                                        axis_body.cross(v_perp);
  CosseratHelixPoint point;
  const Mat3 local = Eigen::AngleAxisd(angle, axis_body).toRotationMatrix();
  point.frame = rod.root_frame * local;
  point.position = rod.root_position + s * sol.advance * sol.axis + rod.root_frame * turn;
  point.force = point.frame * sol.force_body;
  point.moment = point.frame * sol.moment_body;
  return point;
}

}  // namespace rodvv::references

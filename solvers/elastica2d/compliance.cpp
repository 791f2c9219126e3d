#include "rodvv/solvers/elastica2d/compliance.hpp"

#include <cmath>

#include "rodvv/solvers/elastica2d/arc_geometry.hpp"

namespace rodvv::solvers::elastica2d {

namespace {

// R(psi) = [cos psi, sin psi; sin psi, -cos psi].
Eigen::Matrix2d reflection(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix2d r;
  r << c, s, s, -c;
  return r;
}

// dR/dpsi = [-sin psi, cos psi; cos psi, sin psi] (= R(psi + pi/2)); d^2R/dpsi^2 = -R.
Eigen::Matrix2d reflection_derivative(double psi) {
  const double c = std::cos(psi), s = std::sin(psi);
  Eigen::Matrix2d r;
  r << -s, c, c, s;
  return r;
}

}  // namespace

ElementCompliance element_compliance(Scheme scheme, double a0, double a1, double axial_compliance,
                                     double shear_compliance) noexcept {
  const double alpha = 0.5 * (axial_compliance + shear_compliance);
  const double beta = 0.5 * (axial_compliance - shear_compliance);
  ElementCompliance out;
  const Eigen::Matrix2d zero = Eigen::Matrix2d::Zero();
  if (scheme == Scheme::Polygon) {
    // Q = R(2 phi): dQ = 2 R', d^2Q = -4 R.
    const Eigen::Matrix2d r = reflection(2.0 * a0), rp = reflection_derivative(2.0 * a0);
    out.c = alpha * Eigen::Matrix2d::Identity() + beta * r;
    out.d[0] = 2.0 * beta * rp;
    out.d[1] = zero;
    out.dd[0][0] = -4.0 * beta * r;
    out.dd[0][1] = out.dd[1][0] = out.dd[1][1] = zero;
    return out;
  }
  // Q = sinc(u) R(psi), u = a1 - a0, psi = a0 + a1 (du/da0 = -1, du/da1 = 1, dpsi/dak = 1).
  const SincDerivatives s = sinc_derivatives(a1 - a0);
  const Eigen::Matrix2d r = reflection(a0 + a1), rp = reflection_derivative(a0 + a1);
  out.c = alpha * Eigen::Matrix2d::Identity() + beta * s.value * r;
  out.d[0] = beta * (-s.first * r + s.value * rp);
  out.d[1] = beta * (s.first * r + s.value * rp);
  out.dd[0][0] = beta * ((s.second - s.value) * r - 2.0 * s.first * rp);
  out.dd[1][1] = beta * ((s.second - s.value) * r + 2.0 * s.first * rp);
  out.dd[0][1] = out.dd[1][0] = -beta * (s.second + s.value) * r;
  return out;
}

}  // namespace rodvv::solvers::elastica2d

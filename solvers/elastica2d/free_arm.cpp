#include "rodvv/solvers/elastica2d/free_arm.hpp"

#include <cmath>

namespace rodvv::solvers::elastica2d {

using Eigen::Vector2d;
using Eigen::VectorXd;

FreeArmDerivatives free_arm_derivatives(const FreeArm& arm, const VectorXd& phi, double l) {
  const auto n = static_cast<Eigen::Index>(arm.elements);
  const double h = l / static_cast<double>(n);
  const double k = arm.bending_stiffness / h;  // B / h
  const Vector2d& f = arm.tip_force;
  FreeArmDerivatives d;
  d.grad_phi = VectorXd::Zero(n);
  d.hess_diag = VectorXd::Zero(n);
  d.hess_off = VectorXd::Zero(n - 1);
  d.hess_phi_l = VectorXd::Zero(n);

  // Bending: half-cell clamp term k (phi_0 - a)^2, interior k/2 (phi_i - phi_{i-1})^2.
  VectorXd grad_bend = VectorXd::Zero(n);
  const double c = phi[0] - arm.exit_angle;
  d.bending_energy = k * c * c;
  grad_bend[0] = 2.0 * k * c;
  d.hess_diag[0] = 2.0 * k;
  for (Eigen::Index i = 1; i < n; ++i) {
    const double dphi = phi[i] - phi[i - 1];
    d.bending_energy += 0.5 * k * dphi * dphi;
    grad_bend[i] += k * dphi;
    grad_bend[i - 1] -= k * dphi;
    d.hess_diag[i] += k;
    d.hess_diag[i - 1] += k;
    d.hess_off[i - 1] = -k;
  }

  // Dead tip load: W = -F . (r_tip - e), r_tip - e = h sum t(phi_i).
  Vector2d chord_sum = Vector2d::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const Vector2d t(std::cos(phi[i]), std::sin(phi[i]));
    const Vector2d normal(-t.y(), t.x());
    chord_sum += t;
    const double grad_load = -h * f.dot(normal);  // dW/dphi_i
    d.grad_phi[i] = grad_bend[i] + grad_load;
    d.hess_diag[i] += h * f.dot(t);               // d2W/dphi_i^2
    d.hess_phi_l[i] = (grad_load - grad_bend[i]) / l;
  }
  const Vector2d span = h * chord_sum;  // r_tip - e
  d.tip = arm.exit + span;
  d.energy = d.bending_energy - f.dot(span);
  d.grad_l = -(d.bending_energy + f.dot(span)) / l;
  d.hess_ll = 2.0 * d.bending_energy / (l * l);
  return d;
}

PlanarRodSolution free_arm_shape(const FreeArm& arm, const VectorXd& phi, double l) {
  const std::size_t n = arm.elements;
  const double h = l / static_cast<double>(n);
  const Vector2d& f = arm.tip_force;
  PlanarRodSolution sol;
  sol.method = "elastica2d-sleeve-polygon";
  sol.length = l;
  for (auto* v : {&sol.s, &sol.x, &sol.y, &sol.theta, &sol.kappa, &sol.bending_stiffness,
                  &sol.natural_curvature, &sol.potential, &sol.force_x, &sol.force_y,
                  &sol.axial_force, &sol.shear_force})
    v->assign(n + 1, 0.0);
  sol.edge_axial_force.assign(n, 0.0);
  sol.edge_shear_force.assign(n, 0.0);
  auto a = [&](std::size_t i) { return phi[static_cast<Eigen::Index>(i)]; };

  Vector2d r = arm.exit;
  for (std::size_t i = 0; i <= n; ++i) {
    sol.s[i] = i == n ? l : static_cast<double>(i) * h;
    sol.x[i] = r.x();
    sol.y[i] = r.y();
    if (i < n) r += h * Vector2d(std::cos(a(i)), std::sin(a(i)));
    sol.bending_stiffness[i] = arm.bending_stiffness;
    sol.force_x[i] = f.x();
    sol.force_y[i] = f.y();
  }
  sol.theta[0] = arm.exit_angle;
  sol.kappa[0] = 2.0 * (a(0) - arm.exit_angle) / h;
  for (std::size_t i = 1; i < n; ++i) {
    sol.theta[i] = 0.5 * (a(i - 1) + a(i));
    sol.kappa[i] = (a(i) - a(i - 1)) / h;
  }
  sol.theta[n] = a(n - 1);
  sol.kappa[n] = 0.0;
  auto axial = [&](double angle) { return f.x() * std::cos(angle) + f.y() * std::sin(angle); };
  auto shear = [&](double angle) { return -f.x() * std::sin(angle) + f.y() * std::cos(angle); };
  for (std::size_t i = 0; i <= n; ++i) {
    sol.axial_force[i] = axial(sol.theta[i]);
    sol.shear_force[i] = shear(sol.theta[i]);
  }
  for (std::size_t i = 0; i < n; ++i) {
    sol.edge_axial_force[i] = axial(a(i));
    sol.edge_shear_force[i] = shear(a(i));
  }
  return sol;
}

}  // namespace rodvv::solvers::elastica2d

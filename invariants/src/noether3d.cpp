#include "rodvv/invariants/noether3d.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::invariants {

namespace {

template <class T>
void require_size(const std::vector<T>& values, std::size_t n, const char* field, bool optional = false) {
  if (optional && values.empty()) return;
  if (values.size() != n)
    throw InputError(std::string("solution.") + field,
                     std::string("invalid parameter 'solution.") + field + "': must hold " + std::to_string(n) +
                         " values (one per station), got " + std::to_string(values.size()));
}

void require_finite_vectors(const std::vector<Vec3>& values, const char* field) {
  for (const auto& v : values)
    if (!v.allFinite())
      throw InputError(std::string("solution.") + field,
                       std::string("invalid parameter 'solution.") + field + "': must be finite");
}

double bending_energy(const SpatialRodSolution& sol, std::size_t i) {
  const Vec3 strain = sol.strain_u[i] - sol.natural_strain[i];
  return 0.5 * strain.dot(sol.stiffness[i].cwiseProduct(strain));
}

double shear_energy(const SpatialRodSolution& sol, std::size_t i) {
  return sol.shear_energy.empty() ? 0.0 : sol.shear_energy[i];
}

}  // namespace

void validate_spatial_solution(const SpatialRodSolution& sol) {
  const std::size_t n = sol.s.size();
  if (n == 0) throw InputError("solution.s", "invalid parameter 'solution.s': must hold at least one station");
  require_size(sol.position, n, "position");
  require_size(sol.frame, n, "frame");
  require_size(sol.strain_u, n, "strain_u");
  require_size(sol.strain_v, n, "strain_v");
  require_size(sol.stiffness, n, "stiffness");
  require_size(sol.natural_strain, n, "natural_strain");
  require_size(sol.force_n, n, "force_n");
  require_size(sol.moment_m, n, "moment_m");
  require_size(sol.potential, n, "potential");
  require_size(sol.shear_energy, n, "shear_energy", true);
  for (double s : sol.s) require_finite("solution.s", s);
  for (double v : sol.potential) require_finite("solution.potential", v);
  require_finite_vectors(sol.position, "position");
  require_finite_vectors(sol.strain_u, "strain_u");
  require_finite_vectors(sol.strain_v, "strain_v");
  require_finite_vectors(sol.natural_strain, "natural_strain");
  require_finite_vectors(sol.force_n, "force_n");
  require_finite_vectors(sol.moment_m, "moment_m");
  for (const auto& k : sol.stiffness)
    for (int j = 0; j < 3; ++j) require_positive("solution.stiffness", k[j]);
  for (const auto& R : sol.frame) {
    // A rotation to 1e-8: solvers chain O(N) rotations, each exact to a few eps.
    if (!R.allFinite() || (R.transpose() * R - Mat3::Identity()).norm() > 1e-8 || std::abs(R.determinant() - 1.0) > 1e-8)
      throw InputError("solution.frame", "invalid parameter 'solution.frame': every frame must be a rotation "
                                         "(|R^T R - I| <= 1e-8, |det R - 1| <= 1e-8)");
  }
}

std::vector<double> noether3d_compact(const SpatialRodSolution& sol) {
  validate_spatial_solution(sol);
  std::vector<double> h(sol.s.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Mat3& R = sol.frame[i];
    const Vec3 n_body = R.transpose() * sol.force_n[i], m_body = R.transpose() * sol.moment_m[i];
    h[i] = n_body.dot(sol.strain_v[i]) + m_body.dot(sol.strain_u[i]) - bending_energy(sol, i) -
           shear_energy(sol, i) - sol.potential[i];
  }
  return h;
}

std::vector<double> noether3d_flattened(const SpatialRodSolution& sol) {
  validate_spatial_solution(sol);
  std::vector<double> h(sol.s.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    const Mat3& R = sol.frame[i];
    const Eigen::Quaterniond p(R);  // chart: unit quaternion (w, x)
    const double w = p.w();
    const Vec3 x = p.vec();
    // q' from the fields: r' = R v, p' = 1/2 p (x) (0, u)  (Hamilton product)
    const Vec3& u = sol.strain_u[i];
    const Vec3 r_prime = R * sol.strain_v[i];
    const double w_prime = -0.5 * x.dot(u);
    const Vec3 x_prime = 0.5 * (w * u + x.cross(u));
    // u(p, p') = 2 (w x' - w' x - x cross x'), linear in p'; its Jacobian in p' = (w', x'):
    Eigen::Matrix<double, 3, 4> du_dp;
    du_dp.col(0) = -2.0 * x;
    Mat3 skew_x;
    skew_x << 0.0, -x.z(), x.y(), x.z(), 0.0, -x.x(), -x.y(), x.x(), 0.0;
    du_dp.rightCols<3>() = 2.0 * (w * Mat3::Identity() - skew_x);
    Eigen::Vector4d p_prime;
    p_prime << w_prime, x_prime;
    const Vec3 u_chart = du_dp * p_prime;  // the strain as the chart sees it (= u to round-off)
    const Vec3 strain = u_chart - sol.natural_strain[i];
    const Vec3 dw_du = sol.stiffness[i].cwiseProduct(strain);
    const Eigen::Vector4d dL_dp_prime = du_dp.transpose() * dw_du;
    const Vec3& n = sol.force_n[i];
    const double bending = 0.5 * strain.dot(dw_du);
    // rotation matrix from the chart, for the constraint term n.(r' - R(p) v)
    const Mat3 R_chart = p.toRotationMatrix();
    const double lagrangian = bending + shear_energy(sol, i) + sol.potential[i] +
                              n.dot(r_prime - R_chart * sol.strain_v[i]);
    h[i] = n.dot(r_prime) + dL_dp_prime.dot(p_prime) - lagrangian;
  }
  return h;
}

Noether3dSummary noether3d_summary(const SpatialRodSolution& sol) {
  const auto compact = noether3d_compact(sol);
  const auto flattened = noether3d_flattened(sol);
  Noether3dSummary out;
  for (double v : compact) out.mean += v;
  out.mean /= static_cast<double>(compact.size());
  for (std::size_t i = 0; i < compact.size(); ++i) {
    out.spread = std::max(out.spread, std::abs(compact[i] - out.mean));
    out.form_difference = std::max(out.form_difference, std::abs(compact[i] - flattened[i]));
    const Mat3& R = sol.frame[i];
    const double terms = std::abs((R.transpose() * sol.force_n[i]).dot(sol.strain_v[i])) +
                         std::abs((R.transpose() * sol.moment_m[i]).dot(sol.strain_u[i])) +
                         bending_energy(sol, i) + shear_energy(sol, i) + std::abs(sol.potential[i]);
    out.scale = std::max(out.scale, terms);
  }
  return out;
}

}  // namespace rodvv::invariants

#include "step_guard.hpp"
#include "rodvv/solvers/superhelix/clothoid_dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// J_g qdot at every Gauss point, in O(N) by the root-to-tip velocity recursion (clothoid_kinematics.hpp:
// downstream of an element everything is carried rigidly): with w_Q = (qdot_Q, qdot_{Q+1}),
//   v_g = v_Q + omega_Q x d_g + T_g w_Q,  v_{Q+1} = v_Q + omega_Q x r_Q + T_Q w_Q,
//   omega_{Q+1} = omega_Q + Theta_Q w_Q  (root at rest).
std::vector<Vec3> point_velocities(const ClothoidKinematics& kinematics, const VecX& qdot) {
  const std::size_t per = kinematics.points_per_element();
  std::vector<Vec3> v(kinematics.points().size());
  Vec3 omega = Vec3::Zero(), velocity = Vec3::Zero();
  for (std::size_t e = 0; e < kinematics.elements(); ++e) {
    const Eigen::Matrix<double, 6, 1> w = qdot.segment<6>(static_cast<Eigen::Index>(3 * e));
    for (std::size_t g = 0; g < per; ++g) {
      const ClothoidPoint& point = kinematics.points()[e * per + g];
      v[e * per + g] = velocity + omega.cross(point.offset) + point.local_jacobian * w;
    }
    velocity += omega.cross(kinematics.base_position(e + 1) - kinematics.base_position(e)) +
                kinematics.end_translation_jacobian(e) * w;
    omega += kinematics.end_rotation_jacobian(e) * w;
  }
  return v;
}

void check_state(const RodModel& model, const DynamicState& state) {
  const auto n = static_cast<Eigen::Index>(clothoid_dof_count(model));
  if (state.q.size() != n || state.qdot.size() != n)
    throw InputError("state", "invalid parameter 'state': q and qdot must hold 3 (N + 1) = " + std::to_string(n) +
                                  " values");
  if (!state.q.allFinite() || !state.qdot.allFinite())
    throw InputError("state", "invalid parameter 'state': q and qdot must be finite");
}

}  // namespace

std::vector<Mat3> clothoid_point_rotational_inertias(const RodModel& model, const ClothoidKinematics& kinematics) {
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const std::size_t per = nodes.size();
  const double ell = kinematics.element_length();
  std::vector<Mat3> inertias;
  inertias.reserve(kinematics.points().size());
  for (std::size_t g = 0; g < kinematics.points().size(); ++g) {
    const Mat3& R = kinematics.points()[g].frame;
    inertias.push_back(R * (0.5 * ell * weights[g % per] * model.rotational_inertia).asDiagonal() * R.transpose());
  }
  return inertias;
}

MatX clothoid_mass_matrix(const RodModel& model, const ClothoidKinematics& kinematics) {
  const auto n = static_cast<Eigen::Index>(3 * (kinematics.elements() + 1));
  const bool rotation = !model.rotational_inertia.isZero(0.0);
  const auto inertias = rotation ? clothoid_point_rotational_inertias(model, kinematics) : std::vector<Mat3>{};
  MatX M = MatX::Zero(n, n);
  for (std::size_t g = 0; g < kinematics.points().size(); ++g) {
    const ClothoidPoint& p = kinematics.points()[g];
    const MatX J = kinematics.position_jacobian(p.element, p.sigma);
    M.noalias() += p.mass * J.transpose() * J;
    if (rotation) {
      const MatX Theta = kinematics.rotation_jacobian(p.element, p.sigma);
      M.noalias() += Theta.transpose() * inertias[g] * Theta;
    }
  }
  return M;
}

namespace {

// zeta_g, omega_g, xi_g (world) at every Gauss point: the Featherstone bias recursion of dynamics.hpp
// with the element-local rates of clothoid_element_rates (a = q_Q, b = (q_{Q+1} - q_Q) / ell and their
// rates), in the element frame.
struct ClothoidPointRates {
  Vec3 zeta = Vec3::Zero(), omega = Vec3::Zero(), xi = Vec3::Zero();
};

std::vector<ClothoidPointRates> clothoid_point_rates(const ClothoidKinematics& kinematics, const VecX& qdot,
                                                     const RootState& root) {
  const std::size_t per = kinematics.points_per_element(), n = kinematics.elements();
  std::vector<ClothoidPointRates> rates(kinematics.points().size());
  if (qdot.lpNorm<Eigen::Infinity>() == 0.0 && root.angular_velocity.isZero(0.0) &&
      root.angular_acceleration.isZero(0.0) && root.acceleration.isZero(0.0))
    return rates;
  const double ell = kinematics.element_length();
  const VecX& q = kinematics.q();
  Vec3 omega = root.angular_velocity, alpha = root.angular_acceleration, acc = root.acceleration;
  for (std::size_t e = 0; e < n; ++e) {
    const auto i = static_cast<Eigen::Index>(3 * e);
    const Vec3 a = q.segment<3>(i), b = (q.segment<3>(i + 3) - a) / ell;
    const Vec3 adot = qdot.segment<3>(i), bdot = (qdot.segment<3>(i + 3) - adot) / ell;
    const Mat3& R = kinematics.base_frame(e);
    const Vec3 omega_l = R.transpose() * omega, alpha_l = R.transpose() * alpha, acc_l = R.transpose() * acc;
    const auto carried = [&](const ClothoidRates& local) {
      return Vec3(acc_l + alpha_l.cross(local.r) + omega_l.cross(omega_l.cross(local.r) + 2.0 * local.velocity) +
                  local.bias);
    };
    const auto angular_bias = [&](const ClothoidRates& local) {
      return Vec3(alpha_l + omega_l.cross(local.angular_velocity) + local.angular_bias);
    };
    for (std::size_t g = 0; g < per; ++g) {
      const ClothoidRates local = clothoid_element_rates(a, b, adot, bdot, kinematics.points()[e * per + g].sigma);
      ClothoidPointRates& out = rates[e * per + g];
      out.zeta = R * carried(local);
      out.omega = R * (omega_l + local.angular_velocity);
      out.xi = R * angular_bias(local);
    }
    const ClothoidRates end = clothoid_element_rates(a, b, adot, bdot, ell);
    acc = R * carried(end);
    alpha = R * angular_bias(end);
    omega = R * (omega_l + end.angular_velocity);
  }
  return rates;
}

}  // namespace

std::vector<Vec3> clothoid_bias_accelerations(const RodModel& model, const ClothoidKinematics& kinematics,
                                              const VecX& qdot) {
  (void)model;
  return clothoid_bias_accelerations(kinematics, qdot, RootState{});
}

std::vector<Vec3> clothoid_bias_accelerations(const ClothoidKinematics& kinematics, const VecX& qdot,
                                              const RootState& root) {
  const auto rates = clothoid_point_rates(kinematics, qdot, root);
  std::vector<Vec3> zeta(rates.size());
  for (std::size_t g = 0; g < rates.size(); ++g) zeta[g] = rates[g].zeta;
  return zeta;
}

std::vector<AngularRates> clothoid_angular_rates(const ClothoidKinematics& kinematics, const VecX& qdot,
                                                 const RootState& root) {
  const auto rates = clothoid_point_rates(kinematics, qdot, root);
  std::vector<AngularRates> out(rates.size());
  for (std::size_t g = 0; g < rates.size(); ++g) out[g] = {rates[g].omega, rates[g].xi};
  return out;
}

namespace {

// Dense path on given kinematics (built from the root pose of this step) and point rates.
VecX dense_clothoid_velocity_change(const RodModel& model, const ClothoidKinematics& kin,
                                    const std::vector<ClothoidPointRates>& rates, const DynamicState& state, double h) {
  const MatX K = clothoid_stiffness(model);
  const MatX D = (h * h + h * model.rayleigh_stiffness) * K;
  std::vector<Vec3> bias(rates.size());
  for (std::size_t g = 0; g < rates.size(); ++g) bias[g] = -kin.points()[g].mass * rates[g].zeta;
  // B_n = F_ext - sum_g m_g J_g^T zeta_g - sum_g Theta_g^T (I_g xi_g + omega_g x I_g omega_g)
  // (the bias enters as point forces -m_g zeta_g, the rotational terms through the dense Theta_g)
  VecX B = clothoid_external_force(model, kin) + clothoid_generalised_force(kin, bias, Vec3::Zero(), Vec3::Zero());
  if (!model.rotational_inertia.isZero(0.0)) {
    const auto inertias = clothoid_point_rotational_inertias(model, kin);
    for (std::size_t g = 0; g < rates.size(); ++g) {
      const ClothoidPoint& p = kin.points()[g];
      const Mat3& I = inertias[g];
      B.noalias() -= kin.rotation_jacobian(p.element, p.sigma).transpose() *
                     (I * rates[g].xi + rates[g].omega.cross(I * rates[g].omega));
    }
  }
  const VecX rhs = h * (-K * (state.q - clothoid_natural_strain_vector(model)) + B) - D * state.qdot;
  const MatX A = clothoid_mass_matrix(model, kin) + D;
  return A.ldlt().solve(rhs);
}

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat9 = Eigen::Matrix<double, 9, 9>;
using Vec9 = Eigen::Matrix<double, 9, 1>;
using Mat93 = Eigen::Matrix<double, 9, 3>;
using Mat12 = Eigen::Matrix<double, 12, 12>;
using Vec12 = Eigen::Matrix<double, 12, 1>;
using Mat312 = Eigen::Matrix<double, 3, 12>;
using Mat912 = Eigen::Matrix<double, 9, 12>;

Mat3 skew3(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

// Blocks of the block-tridiagonal K (clothoid_statics.hpp), without forming the dense matrix:
// K_jj = (ell/3) C x (number of elements at node j), K_{j,j+1} = (ell/6) C.
struct TridiagonalStiffness {
  Mat3 end, interior, off;
  std::size_t nodes;
  const Mat3& diagonal(std::size_t j) const { return (j == 0 || j + 1 == nodes) ? end : interior; }
};

TridiagonalStiffness tridiagonal_stiffness(const RodModel& model) {
  const double ell = element_length(model);
  const Mat3 C = model.stiffness.asDiagonal();
  return {(ell / 3.0) * C, (2.0 * ell / 3.0) * C, (ell / 6.0) * C, model.elements + 1};
}

struct NodeElimination {
  Mat3 h_inverse;   // (Z22)^-1
  Mat93 coupling;   // Z12: coupling of the eliminated node to (A_Q, x_Q)
  Vec3 linear;      // z2
};

// The articulated-body recursion for nodal strains (clothoid_dynamics.hpp). Solves
// (M + D) x = b - sum_g J_g^T beta_g + h (J_tip^T F + Theta_tip^T M_end), b = -h K (q - q0) - D qdot,
// exactly, in O(N), as the stationary point of
//   Phi = sum_g (m_g |a_g|^2 / 2 + beta_g . a_g) + x^T D x / 2 - b . x - h (M_end . alpha_N + F . a_N),
// a_g = J_g x = X(d_g) A_Q + T_g (x_Q, x_{Q+1}),  A_{Q+1} = X(r_Q) A_Q + S_Q (x_Q, x_{Q+1}).
VecX recursive_clothoid_velocity_change(const RodModel& model, const ClothoidKinematics& kin,
                                        const std::vector<ClothoidPointRates>& rates, const DynamicState& state,
                                        double h) {
  const std::size_t n = model.elements, per = kin.points_per_element();
  const TridiagonalStiffness K = tridiagonal_stiffness(model);
  const double factor = h * h + h * model.rayleigh_stiffness;  // D = factor K
  const VecX q0 = clothoid_natural_strain_vector(model);
  const bool rotation = !model.rotational_inertia.isZero(0.0);
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);

  // b_j = -h (K (q - q0))_j - (D qdot)_j, block by block.
  VecX b(static_cast<Eigen::Index>(3 * (n + 1)));
  for (std::size_t j = 0; j <= n; ++j) {
    const auto i = static_cast<Eigen::Index>(3 * j);
    Vec3 kq = K.diagonal(j) * (state.q.segment<3>(i) - q0.segment<3>(i));
    Vec3 kv = K.diagonal(j) * state.qdot.segment<3>(i);
    if (j > 0) {
      kq += K.off * (state.q.segment<3>(i - 3) - q0.segment<3>(i - 3));
      kv += K.off * state.qdot.segment<3>(i - 3);
    }
    if (j < n) {
      kq += K.off * (state.q.segment<3>(i + 3) - q0.segment<3>(i + 3));
      kv += K.off * state.qdot.segment<3>(i + 3);
    }
    b.segment<3>(i) = -h * kq - factor * kv;
  }

  // Tip to root: V_{Q+1}(A_{Q+1}, x_{Q+1}) = z^T P z / 2 + p^T z, z in R^9; at the tip only the
  // end wrench (a linear term).
  Mat9 P = Mat9::Zero();
  Vec9 p = Vec9::Zero();
  p.head<3>() = -h * model.end_moment;
  p.segment<3>(3) = -h * model.end_force;
  std::vector<NodeElimination> eliminated(n);
  for (std::size_t e = n; e-- > 0;) {
    // W(y), y = (A_Q, x_Q, x_{Q+1}) in R^12: the element's points ...
    Mat12 Z = Mat12::Zero();
    Vec12 z = Vec12::Zero();
    for (std::size_t g = 0; g < per; ++g) {
      const ClothoidPoint& point = kin.points()[e * per + g];
      Mat312 B;
      B.leftCols<3>() = -skew3(point.offset);
      B.block<3, 3>(0, 3).setIdentity();
      B.rightCols<6>() = point.local_jacobian;
      Z.noalias() += point.mass * B.transpose() * B;
      const ClothoidPointRates& rate = rates[e * per + g];
      z.noalias() += B.transpose() * (h * point.mass * (rate.zeta - model.gravity));
      if (rotation) {
        // the point's angular acceleration alpha_Q + Theta_g (x_Q, x_{Q+1}) (+ xi_g): weight I_g,
        // linear term h (I_g xi_g + omega_g x I_g omega_g)
        const Mat3 I = point.frame * (0.5 * kin.element_length() * weights[g] * model.rotational_inertia).asDiagonal() *
                       point.frame.transpose();
        Mat312 Br = Mat312::Zero();
        Br.leftCols<3>().setIdentity();
        Br.rightCols<6>() = point.local_rotation_jacobian;
        Z.noalias() += Br.transpose() * I * Br;
        z.noalias() += Br.transpose() * (h * (I * rate.xi + rate.omega.cross(I * rate.omega)));
      }
    }
    // ... the downstream value through (A_{Q+1}, x_{Q+1}) = L y ...
    Mat912 L = Mat912::Zero();
    L.topLeftCorner<6, 6>().setIdentity();
    L.block<3, 3>(3, 0) = -skew3(kin.base_position(e + 1) - kin.base_position(e));
    L.block<3, 6>(0, 6) = kin.end_rotation_jacobian(e);
    L.block<3, 6>(3, 6) = kin.end_translation_jacobian(e);
    L.block<3, 3>(6, 9).setIdentity();
    Z.noalias() += L.transpose() * P * L;
    z.noalias() += L.transpose() * p;
    // ... and the implicit stiffness of node e + 1 with its coupling to node e (D is tridiagonal,
    // so node e + 1 couples only to nodes e and e + 2, both already in the quadratic form).
    Z.block<3, 3>(9, 9) += factor * K.diagonal(e + 1);
    Z.block<3, 3>(6, 9) += factor * K.off;
    Z.block<3, 3>(9, 6) += factor * K.off;
    z.segment<3>(9) -= b.segment<3>(static_cast<Eigen::Index>(3 * (e + 1)));
    // Eliminate x_{e+1}: Schur complement onto (A_Q, x_Q).
    NodeElimination& step = eliminated[e];
    step.h_inverse = Z.block<3, 3>(9, 9).inverse();
    step.coupling = Z.block<9, 3>(0, 9);
    step.linear = z.segment<3>(9);
    const Mat93 coupling_hinv = step.coupling * step.h_inverse;
    P = Z.topLeftCorner<9, 9>() - coupling_hinv * step.coupling.transpose();
    // Keep the form exactly symmetric: the map P_{Q+1} -> P_Q amplifies the antisymmetric part of its
    // rounding errors (as the Super-Helix I^A, dynamics.cpp: dense vs recursive 1e-2 at N = 32 with
    // h = 1e-3 before, round-off after); the symmetric part is not amplified.
    P = (0.5 * (P + P.transpose())).eval();
    p = z.head<9>() - coupling_hinv * step.linear;
  }

  // Root (A_0 = 0): node 0.
  VecX dv(b.size());
  const Mat3 H0 = P.block<3, 3>(6, 6) + factor * K.diagonal(0);
  dv.head<3>() = -H0.inverse() * (p.tail<3>() - b.head<3>());
  // Root to tip.
  Eigen::Matrix<double, 6, 1> A = Eigen::Matrix<double, 6, 1>::Zero();
  for (std::size_t e = 0; e < n; ++e) {
    const NodeElimination& step = eliminated[e];
    Vec9 y;
    y << A, dv.segment<3>(static_cast<Eigen::Index>(3 * e));
    const Vec3 x = -step.h_inverse * (step.coupling.transpose() * y + step.linear);
    dv.segment<3>(static_cast<Eigen::Index>(3 * (e + 1))) = x;
    const Eigen::Matrix<double, 6, 1> w = dv.segment<6>(static_cast<Eigen::Index>(3 * e));
    const Vec3 r = kin.base_position(e + 1) - kin.base_position(e);
    A.tail<3>() += A.head<3>().cross(r) + kin.end_translation_jacobian(e) * w;
    A.head<3>() += kin.end_rotation_jacobian(e) * w;
  }
  return dv;
}

}  // namespace

VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h) {
  return clothoid_velocity_change(model, state, h, DynamicsPath::Dense, RootMotion{});
}

VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  return clothoid_velocity_change(model, state, h, path, RootMotion{});
}

VecX clothoid_velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                              const RootMotion& root_motion) {
  validate_clothoid(model);
  require_statics_only_loads_absent(model, "the super-clothoid dynamics");
  require_positive("h", h);
  check_state(model, state);
  require_finite("state.time", state.time);
  const RootState root = root_motion.state_at(model, state.time);
  RodModel moved = model;
  moved.root_position = root.position;
  moved.root_frame = root.frame;
  const ClothoidKinematics kin(moved, state.q);
  const auto rates = clothoid_point_rates(kin, state.qdot, root);
  return path == DynamicsPath::Dense ? dense_clothoid_velocity_change(moved, kin, rates, state, h)
                                     : recursive_clothoid_velocity_change(moved, kin, rates, state, h);
}

DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h) {
  return clothoid_step(model, state, h, DynamicsPath::Dense, RootMotion{});
}

DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  return clothoid_step(model, state, h, path, RootMotion{});
}

DynamicState clothoid_step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                           const RootMotion& root) {
  DynamicState next = state;
  next.qdot = state.qdot + clothoid_velocity_change(model, state, h, path, root);
  next.q = state.q + h * next.qdot;
  next.time = state.time + h;
  detail::require_finite_step(std::string("super-clothoid semi-implicit Euler step (") + (path == DynamicsPath::Dense ? "dense" : "linear-time") + " path)", state, next, h);
  return next;
}

double clothoid_kinetic_energy(const RodModel& model, const ClothoidKinematics& kinematics, const VecX& qdot) {
  double energy = 0.0;
  const auto v = point_velocities(kinematics, qdot);
  for (std::size_t g = 0; g < v.size(); ++g) energy += 0.5 * kinematics.points()[g].mass * v[g].squaredNorm();
  if (model.rotational_inertia.isZero(0.0)) return energy;
  // omega_g = omega_Q + Theta_g w_Q (root at rest), material components R_g^T omega_g.
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const std::size_t per = kinematics.points_per_element();
  const double ell = kinematics.element_length();
  Vec3 omega = Vec3::Zero();
  for (std::size_t e = 0; e < kinematics.elements(); ++e) {
    const Eigen::Matrix<double, 6, 1> w = qdot.segment<6>(static_cast<Eigen::Index>(3 * e));
    for (std::size_t g = 0; g < per; ++g) {
      const ClothoidPoint& point = kinematics.points()[e * per + g];
      const Vec3 material = point.frame.transpose() * (omega + point.local_rotation_jacobian * w);
      energy += 0.25 * ell * weights[g] * material.dot(model.rotational_inertia.cwiseProduct(material));
    }
    omega += kinematics.end_rotation_jacobian(e) * w;
  }
  return energy;
}

double clothoid_total_energy(const RodModel& model, const DynamicState& state) {
  require_statics_only_loads_absent(model, "the super-clothoid total energy");
  check_state(model, state);
  const ClothoidKinematics kin(model, state.q);
  return clothoid_kinetic_energy(model, kin, state.qdot) + clothoid_elastic_energy(model, state.q) +
         clothoid_gravity_energy(model, kin) - model.end_force.dot(kin.tip_position());
}

}  // namespace rodvv::solvers::superhelix

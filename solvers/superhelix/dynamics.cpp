#include "dense_step_system.hpp"
#include "step_guard.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat63 = Eigen::Matrix<double, 6, 3>;
using Mat36 = Eigen::Matrix<double, 3, 6>;

}  // namespace

void detail::check_step_input(const RodModel& model, const DynamicState& state, double h) {
  validate(model);
  require_statics_only_loads_absent(model, "the Super-Helix dynamics");
  require_positive("h", h);
  const auto n = static_cast<Eigen::Index>(dof_count(model));
  if (state.q.size() != n || state.qdot.size() != n)
    throw InputError("state", "invalid parameter 'state': q and qdot must hold 3 N = " + std::to_string(n) +
                                  " values");
  if (!state.q.allFinite()) throw InputError("state.q", "invalid parameter 'state.q': must be finite");
  if (!state.qdot.allFinite()) throw InputError("state.qdot", "invalid parameter 'state.qdot': must be finite");
}

namespace {

using detail::check_step_input;

// What the root-to-tip pass knows about one Gauss point, in the base frame of its element.
struct LocalPointRates {
  ElementRates point;           // offset c, Jacobian dG0, velocity, bias (element.hpp)
  Vec3 zeta = Vec3::Zero();     // translational bias acceleration
  // Filled only when the pass is asked for the rotation (rotational inertia on):
  Mat3 E = Mat3::Identity();    // frame of the point relative to the base: R_g = R_Q E
  Mat3 G = Mat3::Zero();        // rotation per unit q_Q: omega_g = omega_Q + R_Q G qdot_Q
  Vec3 omega = Vec3::Zero();    // angular velocity of the point's frame (with the base's)
  Vec3 xi = Vec3::Zero();       // angular bias acceleration
};

// Root-to-tip pass (O(N), dynamics.hpp): for every element its base frame R_e and end maps, and for
// every Gauss point its local maps (offset, Jacobian in the base frame of its element) and its bias
// accelerations, also in that base frame (world zeta = R_e zeta_local): the base rates are rotated
// into the element frame once per element, so the per-point work is frame-free. With `rotation`
// the points also get their frame, rotation Jacobian, angular velocity and angular bias
// (element_end_rates at the point instead of element_point_rates).
// on_point(e, g, R_e, local); on_element(e, R_e, r_e = p_{e+1} - p_e, Theta_e, T_e) after its points (world).
template <class OnPoint, class OnElement>
void rate_pass(const RodModel& model, const VecX& q, const VecX& qdot, const RootState& root,
               const std::vector<double>& nodes, bool rotation, OnPoint&& on_point, OnElement&& on_element) {
  const double ell = element_length(model);
  Mat3 R = root.frame;
  Vec3 omega = root.angular_velocity, alpha = root.angular_acceleration, acc = root.acceleration;
  LocalPointRates local;
  for (std::size_t e = 0; e < model.elements; ++e) {
    const Vec3 qe = q.segment<3>(3 * e), rate = qdot.segment<3>(3 * e);
    const Vec3 omega_l = R.transpose() * omega, alpha_l = R.transpose() * alpha, acc_l = R.transpose() * acc;
    for (std::size_t g = 0; g < nodes.size(); ++g) {
      const double sigma = 0.5 * ell * (1.0 + nodes[g]);
      if (rotation) {
        const ElementEndRates at = element_end_rates(qe, rate, sigma);
        local.point = at.point;
        local.E = at.E;
        local.G = at.G;
        local.omega = omega_l + at.angular_velocity;
        local.xi = alpha_l + omega_l.cross(at.angular_velocity) + at.angular_bias;
      } else {
        local.point = element_point_rates(qe, rate, sigma);
      }
      local.zeta = acc_l + alpha_l.cross(local.point.offset) +
                   omega_l.cross(omega_l.cross(local.point.offset) + 2.0 * local.point.velocity) + local.point.bias;
      on_point(e, g, R, static_cast<const LocalPointRates&>(local));
    }
    const ElementEndRates end = element_end_rates(qe, rate, ell);
    const Vec3 r = R * end.point.offset;
    on_element(e, R, r, Mat3(R * end.G), Mat3(R * end.point.jacobian));
    const Vec3 acc_end = acc_l + alpha_l.cross(end.point.offset) +
                         omega_l.cross(omega_l.cross(end.point.offset) + 2.0 * end.point.velocity) + end.point.bias;
    acc = R * acc_end;
    alpha = R * (alpha_l + omega_l.cross(end.angular_velocity) + end.angular_bias);
    omega = R * (omega_l + end.angular_velocity);
    R = R * end.E;
  }
}

bool has_rotational_inertia(const RodModel& model) { return !model.rotational_inertia.isZero(0.0); }

// E diag(J) E^T for a rotation E (the rotational inertia density in the frame E is given in).
Mat3 rotate_inertia(const Mat3& E, const Vec3& J) {
  return E * J.asDiagonal() * E.transpose();
}

// World velocity terms of every Gauss point from one rate pass: zeta_g, and with rotational
// inertia omega_g and xi_g.
struct PointRates {
  Vec3 zeta = Vec3::Zero();
  Vec3 omega = Vec3::Zero();
  Vec3 xi = Vec3::Zero();
};

std::vector<PointRates> world_point_rates(const RodModel& model, const VecX& q, const VecX& qdot,
                                          const RootState& root, bool rotation) {
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const std::size_t per = nodes.size();
  std::vector<PointRates> rates(model.elements * per);
  rate_pass(
      model, q, qdot, root, nodes, rotation,
      [&](std::size_t e, std::size_t g, const Mat3& R, const LocalPointRates& local) {
        PointRates& out = rates[e * per + g];
        out.zeta = R * local.zeta;
        if (rotation) {
          out.omega = R * local.omega;
          out.xi = R * local.xi;
        }
      },
      [](std::size_t, const Mat3&, const Vec3&, const Mat3&, const Mat3&) {});
  return rates;
}

RootState fixed_root(const RodModel& model) {
  RootState root;
  root.position = model.root_position;
  root.frame = model.root_frame;
  return root;
}

RodModel model_with_root(const RodModel& model, const RootState& root) {
  RodModel moved = model;
  moved.root_position = root.position;
  moved.root_frame = root.frame;
  return moved;
}

// Right-hand side shared by both paths: h (-K (q - q0)) - D qdot, without the point / tip loads.
VecX elastic_rhs(const RodModel& model, const DynamicState& state, double h, VecX& damping_diagonal) {
  const VecX k = generalised_stiffness(model);
  damping_diagonal = (h * h + h * model.rayleigh_stiffness) * k;
  return -h * k.cwiseProduct(state.q - natural_strain_vector(model)) - damping_diagonal.cwiseProduct(state.qdot);
}

}  // namespace

detail::DenseStepSystem detail::dense_step_system(const RodModel& model_in, const DynamicState& state, double h,
                                                  const RootState& root) {
  const RodModel model = model_with_root(model_in, root);
  const Kinematics kinematics(model, state.q);
  const bool rotation = has_rotational_inertia(model);
  const auto rates = world_point_rates(model, state.q, state.qdot, root, rotation);
  const auto inertias = rotation ? point_rotational_inertias(model, kinematics) : std::vector<Mat3>{};
  const auto n = static_cast<Eigen::Index>(dof_count(model));
  MatX M = MatX::Zero(n, n);
  VecX loads = VecX::Zero(n);
  const auto& points = kinematics.points();
  for (std::size_t g = 0; g < points.size(); ++g) {
    const GaussPoint& point = points[g];
    const MatX J = kinematics.position_jacobian(point.element, point.sigma);
    const auto used = static_cast<Eigen::Index>(3 * (point.element + 1));  // causality: J is zero beyond
    M.topLeftCorner(used, used).noalias() += point.mass * J.leftCols(used).transpose() * J.leftCols(used);
    loads.head(used) += J.leftCols(used).transpose() * (point.mass * (model.gravity - rates[g].zeta));
    if (rotation) {
      // Euler's equation of the cross-section: torque I xi + omega x I omega through Theta_g.
      const MatX Theta = kinematics.rotation_jacobian(point.element, point.sigma);
      const Mat3& I = inertias[g];
      M.topLeftCorner(used, used).noalias() += Theta.leftCols(used).transpose() * I * Theta.leftCols(used);
      const Vec3 spin = I * rates[g].omega;
      loads.head(used) -= Theta.leftCols(used).transpose() * (I * rates[g].xi + rates[g].omega.cross(spin));
    }
  }
  const std::size_t last = model.elements - 1;
  const double ell = element_length(model);
  loads += kinematics.position_jacobian(last, ell).transpose() * model.end_force +
           kinematics.rotation_jacobian(last, ell).transpose() * model.end_moment;
  VecX damping;
  const VecX rhs = elastic_rhs(model, state, h, damping) + h * loads;
  M.diagonal() += damping;
  return {std::move(M), rhs};
}

namespace {

VecX dense_velocity_change(const RodModel& model, const DynamicState& state, double h, const RootState& root) {
  const detail::DenseStepSystem system = detail::dense_step_system(model, state, h, root);
  const Eigen::LDLT<MatX> ldlt(system.matrix);
  if (ldlt.info() != Eigen::Success)
    throw SolverError("superhelix dense step", "LDL^T of M + D failed", 0, 0.0);
  return ldlt.solve(system.rhs);
}

// Per-element data of the articulated-body recursion (ALGORITHMS.md §1.6), filled by the root-to-tip
// rate pass, used by the two later passes. I_el = sum_g I_p(d_g) is kept as its three 3 x 3 parts
// (mass, first moment h = sum m d, rotational part -sum m [d]x^2).
struct ElementBlock {
  Mat3 theta, translation;  // S_Q = [Theta; T]
  Vec3 r;                   // p_{Q+1} - p_Q
  double mass;
  Vec3 first_moment;
  Mat3 rotational;
  Mat63 coupling;  // U_pt = sum m [[d]x T; T], then U_Q
  Mat3 tt;         // sum m T^T T
  Vec6 point_bias;  // sum_g [d x beta; beta]
  Vec3 t_beta;     // sum_g T^T beta
  Mat3 h_inverse;  // H_Q^-1
  Vec3 joint_rhs;  // u_Q
};

// X(r)^T A X(r) for symmetric A = [[A11, A12], [A21, A22]], X(r) = [[I, 0], [-[r]x, I]]:
//   A21' = A21 - A22 [r]x,  A11' = A11 - A12 [r]x + [r]x A21',  A12' = A21'^T,  A22' = A22.
Mat6 shift_inertia(const Mat6& A, const Vec3& r) {
  const Mat3 Rx = skew(r);
  Mat6 out;
  const Mat3 a21 = A.block<3, 3>(3, 0) - A.block<3, 3>(3, 3) * Rx;
  out.block<3, 3>(0, 0) = A.block<3, 3>(0, 0) - A.block<3, 3>(0, 3) * Rx + Rx * a21;
  out.block<3, 3>(3, 0) = a21;
  out.block<3, 3>(0, 3) = a21.transpose();
  out.block<3, 3>(3, 3) = A.block<3, 3>(3, 3);
  return out;
}

VecX recursive_velocity_change(const RodModel& model, const DynamicState& state, double h, const RootState& root) {
  VecX damping;
  const VecX b = elastic_rhs(model, state, h, damping);
  const std::size_t n = model.elements;
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const double ell = element_length(model);
  thread_local std::vector<ElementBlock> blocks;  // reused: no allocation per step once grown
  blocks.resize(n);

  // Pass 1 (root to tip): kinematics, bias accelerations and the element sums, accumulated in the
  // element's base frame (c, J local) and rotated once: [R c]x R J = R [c]x J, -[R c]x^2 = R (|c|^2 I - c c^T) R^T.
  // A point's rotational inertia in the base frame is I_l = (w ell/2) E diag(J) E^T (world R I_l R^T),
  // its rotation Jacobian G (world R G): it adds I_l to the rotational part, I_l G to the top rows of
  // U_pt, G^T I_l G to TT, and the torque h (I_l xi + omega x I_l omega) to the moment and (through
  // G^T) to the joint forces.
  const bool rotation = has_rotational_inertia(model);
  Mat3 rotational = Mat3::Zero(), cross_j = Mat3::Zero(), sum_j = Mat3::Zero();
  Vec3 first_moment = Vec3::Zero(), moment = Vec3::Zero(), force = Vec3::Zero(), gravity_local = Vec3::Zero();
  rate_pass(
      model, state.q, state.qdot, root, nodes, rotation,
      [&](std::size_t e, std::size_t g, const Mat3& R, const LocalPointRates& local) {
        ElementBlock& block = blocks[e];
        if (g == 0) {
          block.mass = 0.0;
          block.tt.setZero();
          block.t_beta.setZero();
          rotational.setZero();
          cross_j.setZero();
          sum_j.setZero();
          first_moment.setZero();
          moment.setZero();
          force.setZero();
          gravity_local = R.transpose() * model.gravity;
        }
        const double w = 0.5 * ell * weights[g];
        const double m = model.line_density * w;
        const Vec3& c = local.point.offset;
        const Mat3& J = local.point.jacobian;
        block.mass += m;
        first_moment += m * c;
        rotational.noalias() -= m * c * c.transpose();
        rotational.diagonal().array() += m * c.squaredNorm();
        for (int j = 0; j < 3; ++j) cross_j.col(j) += m * c.cross(J.col(j));
        sum_j += m * J;
        block.tt.noalias() += m * J.transpose() * J;
        const Vec3 beta = h * m * (local.zeta - gravity_local);
        moment += c.cross(beta);
        force += beta;
        block.t_beta.noalias() += J.transpose() * beta;
        if (rotation) {
          const Mat3 I = rotate_inertia(local.E, w * model.rotational_inertia);
          const Mat3 IG = I * local.G;
          rotational += I;
          cross_j += IG;
          block.tt.noalias() += local.G.transpose() * IG;
          const Vec3 torque = h * (I * local.xi + local.omega.cross(I * local.omega));
          moment += torque;
          block.t_beta.noalias() += local.G.transpose() * torque;
        }
      },
      [&](std::size_t e, const Mat3& R, const Vec3& r, const Mat3& theta, const Mat3& T) {
        ElementBlock& block = blocks[e];
        block.r = r;
        block.theta = theta;
        block.translation = T;
        block.first_moment = R * first_moment;
        block.rotational = R * rotational * R.transpose();
        block.coupling.topRows<3>() = R * cross_j;
        block.coupling.bottomRows<3>() = R * sum_j;
        block.point_bias.head<3>() = R * moment;
        block.point_bias.tail<3>() = R * force;
      });

  // Pass 2 (tip to root): articulated inertias I^A and bias wrenches c (ALGORITHMS.md §1.6).
  Mat6 articulated = Mat6::Zero();  // I^A_{Q+1}
  Vec6 bias;                        // c_{Q+1}: the tip wrench enters with a minus sign (beta = -f)
  bias << -h * model.end_moment, -h * model.end_force;
  for (std::size_t e = n; e-- > 0;) {
    ElementBlock& block = blocks[e];
    Mat63 S;
    S.topRows<3>() = block.theta;
    S.bottomRows<3>() = block.translation;
    const Mat63 IS = articulated * S;
    Mat3 H = block.tt + S.transpose() * IS;
    H.diagonal() += damping.segment<3>(3 * e);
    // U = U_pt + X^T I^A S, with X^T (n; f) = (n + r x f; f)
    Mat63 U = block.coupling + IS;
    for (int j = 0; j < 3; ++j) U.col(j).head<3>() += block.r.cross(IS.col(j).tail<3>());
    const Vec3 u = b.segment<3>(3 * e) - S.transpose() * bias - block.t_beta;
    const Mat3 Hinv = H.inverse();
    const Mat36 HinvUt = Hinv * U.transpose();
    articulated = shift_inertia(articulated, block.r);
    articulated.block<3, 3>(0, 0) += block.rotational;
    articulated.block<3, 3>(0, 3) += skew(block.first_moment);
    articulated.block<3, 3>(3, 0) -= skew(block.first_moment);
    articulated.block<3, 3>(3, 3).diagonal().array() += block.mass;
    articulated.noalias() -= U * HinvUt;
    // Keep I^A exactly symmetric: the map I^A_{Q+1} -> I^A_Q amplifies the antisymmetric part of its
    // rounding errors (measured ~3x per element for a curled rod: at N = 32 the recursion was off by
    // 1e-5 .. 1e-2 relative, for any rotational inertia, while cond(M + D) ~ 1e5); the symmetric part
    // is not amplified, so symmetrising every step keeps I^A at round-off (measured 2e-16 vs long double).
    articulated = (0.5 * (articulated + articulated.transpose())).eval();
    bias.head<3>() += block.r.cross(bias.tail<3>());
    bias += block.point_bias + U * (Hinv * u);
    block.h_inverse = Hinv;
    block.coupling = U;
    block.joint_rhs = u;
  }

  // Pass 3 (root to tip): joint accelerations from A_0 = 0 (the root's motion is inside zeta).
  VecX dv(3 * n);
  Vec3 angular = Vec3::Zero(), linear = Vec3::Zero();
  for (std::size_t e = 0; e < n; ++e) {
    const ElementBlock& block = blocks[e];
    const Vec3 x = block.h_inverse * (block.joint_rhs - block.coupling.topRows<3>().transpose() * angular -
                                      block.coupling.bottomRows<3>().transpose() * linear);
    dv.segment<3>(3 * e) = x;
    // A_{Q+1} = X(r) A_Q + S x, X(r) (alpha; a) = (alpha; a + alpha x r)
    linear += angular.cross(block.r) + block.translation * x;
    angular += block.theta * x;
  }
  return dv;
}

}  // namespace

std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot) {
  return bias_accelerations(model, kinematics, qdot, fixed_root(model));
}

std::vector<Vec3> bias_accelerations(const RodModel& model, const Kinematics& kinematics, const VecX& qdot,
                                     const RootState& root) {
  const auto rates = world_point_rates(model, kinematics.q(), qdot, root, false);
  std::vector<Vec3> zeta(rates.size());
  for (std::size_t g = 0; g < rates.size(); ++g) zeta[g] = rates[g].zeta;
  return zeta;
}

std::vector<AngularRates> angular_rates(const RodModel& model, const Kinematics& kinematics, const VecX& qdot) {
  return angular_rates(model, kinematics, qdot, fixed_root(model));
}

std::vector<AngularRates> angular_rates(const RodModel& model, const Kinematics& kinematics, const VecX& qdot,
                                        const RootState& root) {
  const auto rates = world_point_rates(model, kinematics.q(), qdot, root, true);
  std::vector<AngularRates> out(rates.size());
  for (std::size_t g = 0; g < rates.size(); ++g) out[g] = {rates[g].omega, rates[g].xi};
  return out;
}

std::vector<Mat3> point_rotational_inertias(const RodModel& model, const Kinematics& kinematics) {
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const std::size_t per = nodes.size();
  const double ell = kinematics.element_length();
  std::vector<Mat3> inertias;
  inertias.reserve(kinematics.points().size());
  for (std::size_t g = 0; g < kinematics.points().size(); ++g) {
    const GaussPoint& point = kinematics.points()[g];
    const Mat3 R = kinematics.frame(point.element, point.sigma);
    inertias.push_back(rotate_inertia(R, 0.5 * ell * weights[g % per] * model.rotational_inertia));
  }
  return inertias;
}

MatX mass_matrix(const RodModel& model, const Kinematics& kinematics) {
  const auto n = static_cast<Eigen::Index>(3 * kinematics.elements());
  const bool rotation = has_rotational_inertia(model);
  const auto inertias = rotation ? point_rotational_inertias(model, kinematics) : std::vector<Mat3>{};
  MatX M = MatX::Zero(n, n);
  for (std::size_t g = 0; g < kinematics.points().size(); ++g) {
    const GaussPoint& point = kinematics.points()[g];
    const MatX J = kinematics.position_jacobian(point.element, point.sigma);
    const auto used = static_cast<Eigen::Index>(3 * (point.element + 1));
    M.topLeftCorner(used, used).noalias() += point.mass * J.leftCols(used).transpose() * J.leftCols(used);
    if (rotation) {
      const MatX Theta = kinematics.rotation_jacobian(point.element, point.sigma);
      M.topLeftCorner(used, used).noalias() += Theta.leftCols(used).transpose() * inertias[g] * Theta.leftCols(used);
    }
  }
  return M;
}

VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  return velocity_change(model, state, h, path, RootMotion{});
}

VecX velocity_change(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                     const RootMotion& root_motion) {
  check_step_input(model, state, h);
  require_finite("state.time", state.time);
  const RootState root = root_motion.state_at(model, state.time);
  return path == DynamicsPath::Dense ? dense_velocity_change(model, state, h, root)
                                     : recursive_velocity_change(model, state, h, root);
}

DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path) {
  return step(model, state, h, path, RootMotion{});
}

DynamicState step(const RodModel& model, const DynamicState& state, double h, DynamicsPath path,
                  const RootMotion& root) {
  DynamicState next;
  next.qdot = state.qdot + velocity_change(model, state, h, path, root);
  next.q = state.q + h * next.qdot;
  next.time = state.time + h;
  detail::require_finite_step(std::string("superhelix semi-implicit Euler step (") + (path == DynamicsPath::Dense ? "dense" : "linear-time") + " path)", state, next, h);
  return next;
}

double rotational_kinetic_energy(const RodModel& model, const Kinematics& kinematics, const VecX& qdot) {
  if (!has_rotational_inertia(model)) return 0.0;
  // omega at the points by the O(N) root-to-tip sum (root at rest): omega_g = omega_Q + R_Q G(sigma) qdot_Q,
  // omega_{Q+1} = omega_Q + Theta_Q qdot_Q; the material components R_g^T omega_g with R_g = R_Q E(sigma).
  std::vector<double> nodes, weights;
  gauss_legendre(model.gauss_points, nodes, weights);
  const std::size_t per = nodes.size();
  const double ell = kinematics.element_length();
  double energy = 0.0;
  Vec3 omega = Vec3::Zero();
  for (std::size_t e = 0; e < kinematics.elements(); ++e) {
    const Vec3 qe = kinematics.q().segment<3>(3 * e), rate = qdot.segment<3>(3 * e);
    const Mat3& R = kinematics.base_frame(e);
    for (std::size_t g = 0; g < per; ++g) {
      const ElementMaps maps = element_maps(qe, kinematics.points()[e * per + g].sigma);
      const Vec3 material = maps.E.transpose() * (R.transpose() * omega + maps.G * rate);
      energy += 0.25 * ell * weights[g] * material.dot(model.rotational_inertia.cwiseProduct(material));
    }
    omega += kinematics.end_rotation_jacobian(e) * rate;
  }
  return energy;
}

double kinetic_energy(const RodModel& model, const Kinematics& kinematics, const VecX& qdot) {
  const auto velocities = kinematics.point_velocities(qdot);
  double energy = 0.0;
  for (std::size_t g = 0; g < velocities.size(); ++g)
    energy += 0.5 * kinematics.points()[g].mass * velocities[g].squaredNorm();
  return energy + rotational_kinetic_energy(model, kinematics, qdot);
}

double total_energy(const RodModel& model, const DynamicState& state) {
  require_statics_only_loads_absent(model, "the Super-Helix total energy");
  const Kinematics kinematics(model, state.q);
  return kinetic_energy(model, kinematics, state.qdot) + elastic_energy(model, state.q) +
         gravity_energy(model, kinematics) - model.end_force.dot(kinematics.tip_position());
}

namespace {

// K v = omega^2 M v for a diagonal K > 0 and M >= 0, as the standard symmetric eigenproblem of the
// compliance-scaled mass C = K^{-1/2} M K^{-1/2}: C w = mu w, mu = 1 / omega^2, v = K^{-1/2} w / sqrt(mu)
// (so that v^T M v = 1). The low frequencies are the LARGEST mu, which a symmetric eigensolver gets to
// a backward error eps mu_max = eps / omega_min^2: |d omega_k^2| ~ eps omega_k^4 / omega_min^2, relative
// eps (omega_k / omega_min)^2, free of the conditioning of M (in strain coordinates cond(M) grows as
// N^4 and more: the Cholesky form K v = lambda M v loses eps omega_max^2 on every lambda, 1e-6
// relative on the first bending frequency at N = 256). Ascending omega; a massless direction (mu <= 0
// at round-off) gets omega = +inf and a zero shape.
struct ScaledModes {
  VecX omega;
  MatX shapes;
};
ScaledModes compliance_modes(const VecX& k, const MatX& M, bool vectors) {
  const VecX scale = k.cwiseSqrt().cwiseInverse();
  const MatX C = scale.asDiagonal() * M * scale.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<MatX> solver(C, vectors ? Eigen::ComputeEigenvectors : Eigen::EigenvaluesOnly);
  if (solver.info() != Eigen::Success)
    throw SolverError("superhelix modes", "symmetric eigenproblem of the compliance-scaled mass failed", 0, 0.0);
  const Eigen::Index n = k.size();
  ScaledModes modes;
  modes.omega.resize(n);
  if (vectors) modes.shapes = MatX::Zero(n, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Index j = n - 1 - i;  // largest mu first: lowest omega first
    const double mu = solver.eigenvalues()[j];
    modes.omega[i] = mu > 0.0 ? 1.0 / std::sqrt(mu) : std::numeric_limits<double>::infinity();
    if (vectors && mu > 0.0) modes.shapes.col(i) = scale.asDiagonal() * solver.eigenvectors().col(j) / std::sqrt(mu);
  }
  return modes;
}

}  // namespace

VecX bending_frequencies(const RodModel& model, std::size_t count) {
  validate(model);
  if (count < 1 || count > model.elements)
    throw InputError("count", "invalid parameter 'count' = " + std::to_string(count) +
                                  ": must be an integer in [1, N = " + std::to_string(model.elements) + "]");
  const Kinematics kinematics(model, VecX::Zero(static_cast<Eigen::Index>(dof_count(model))));
  const MatX M = mass_matrix(model, kinematics);
  const VecX k = generalised_stiffness(model);
  const auto n = static_cast<Eigen::Index>(model.elements);
  MatX Mb(n, n);
  VecX kb(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    kb[a] = k[3 * a + 1];
    for (Eigen::Index c = 0; c < n; ++c) Mb(a, c) = M(3 * a + 1, 3 * c + 1);
  }
  // K v = omega^2 M v on the kappa1 coordinates (M is positive definite there on a straight rod).
  return compliance_modes(kb, Mb, false).omega.head(static_cast<Eigen::Index>(count));
}

StraightRodModes straight_rod_modes(const RodModel& model) {
  validate(model);
  if (!(model.rotational_inertia[0] > 0.0))
    throw InputError("rotational_inertia.twist (rho I0)",
                     "invalid parameter 'rotational_inertia.twist (rho I0)' = " + std::to_string(model.rotational_inertia[0]) +
                         ": must be > 0 for the modes of all 3N coordinates (the twist of a straight rod moves no "
                         "point: without rho I0, M is singular)");
  const auto require_zero = [](const std::string& name, const Vec3& v) {
    if (!v.isZero(0.0))
      throw InputError(name, "invalid parameter '" + name +
                                 "': must be 0 for the modes of the straight, unloaded rod (q = 0 is then no equilibrium)");
  };
  require_zero("natural_strain", model.natural_strain);
  for (const Vec3& q0 : model.natural_strain_per_element) require_zero("natural_strain_per_element", q0);
  require_zero("gravity", model.gravity);
  require_zero("end_force", model.end_force);
  require_zero("end_moment", model.end_moment);
  const auto n = static_cast<Eigen::Index>(dof_count(model));
  const Kinematics kinematics(model, VecX::Zero(n));
  const MatX M = mass_matrix(model, kinematics);
  ScaledModes scaled = compliance_modes(generalised_stiffness(model), M, true);
  StraightRodModes modes;
  modes.frequencies = std::move(scaled.omega);
  modes.shapes = std::move(scaled.shapes);
  // The top of the spectrum may reach round-off (mu <= 0: omega = +inf, zero shape, zero share) when the
  // stiffnesses or inertias are many decades apart; the low modes keep their accuracy (above), so this
  // is reported, not refused: a caller that needs a mode checks that its frequency is finite.
  modes.omega_squared_min = modes.frequencies[0] * modes.frequencies[0];
  modes.component_share = MatX::Zero(3, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!std::isfinite(modes.frequencies[k])) continue;
    const auto v = modes.shapes.col(k);
    Vec3 part = Vec3::Zero();
    for (int c = 0; c < 3; ++c)  // v_c^T M_cc v_c over the coordinates of component c
      for (Eigen::Index a = c; a < n; a += 3)
        for (Eigen::Index b = c; b < n; b += 3) part[c] += v[a] * M(a, b) * v[b];
    modes.component_share.col(k) = part / part.sum();
  }
  return modes;
}

}  // namespace rodvv::solvers::superhelix

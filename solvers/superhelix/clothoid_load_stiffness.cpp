#include "rodvv/solvers/superhelix/clothoid_load_stiffness.hpp"

#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

using Mat6 = Eigen::Matrix<double, 6, 6>;

// Element Q's second derivatives at offset sigma in its nodal strains x = (q_Q, q_{Q+1}), base frame:
// rotation_rate[j].col(i) = dTheta_i/dx_j, translation_hessian[j].col(i) = d2r/dx_i dx_j.
struct NodalSecondDerivatives {
  Mat36 rotation_rate[6];
  Mat36 translation_hessian[6];
};

NodalSecondDerivatives nodal_second_derivatives(const VecX& q, std::size_t element, double ell, double sigma) {
  const auto base = static_cast<Eigen::Index>(3 * element);
  const Vec3 a = q.segment<3>(base);
  const Vec3 b = (q.segment<3>(base + 3) - a) / ell;
  const ClothoidSecondDerivatives ab = clothoid_element_second_derivatives(a, b, sigma);
  // (a, b) = C x with a = x_0..2, b = (x_3..5 - x_0..2) / ell: columns X C, then rows sum_j' C_j'j.
  const auto columns = [ell](const Mat36& m) {
    Mat36 out;
    out.leftCols<3>() = m.leftCols<3>() - m.rightCols<3>() / ell;
    out.rightCols<3>() = m.rightCols<3>() / ell;
    return out;
  };
  NodalSecondDerivatives x;
  for (int i = 0; i < 3; ++i) {
    x.rotation_rate[i] = columns(ab.rotation_rate[i] - ab.rotation_rate[i + 3] / ell);
    x.rotation_rate[i + 3] = columns(ab.rotation_rate[i + 3] / ell);
    x.translation_hessian[i] = columns(ab.translation_hessian[i] - ab.translation_hessian[i + 3] / ell);
    x.translation_hessian[i + 3] = columns(ab.translation_hessian[i + 3] / ell);
  }
  return x;
}

}  // namespace

MatX clothoid_generalised_force_jacobian(const ClothoidKinematics& kinematics, const std::vector<Vec3>& point_forces,
                                         const Vec3& tip_force, const Vec3& tip_moment) {
  const std::size_t n = kinematics.elements(), per = kinematics.points_per_element();
  const auto& points = kinematics.points();
  if (!point_forces.empty() && point_forces.size() != points.size())
    throw InputError("point_forces", "invalid parameter 'point_forces': must be empty or hold one force per "
                                     "Gauss point (" + std::to_string(points.size()) + ")");
  const double ell = kinematics.element_length();
  const VecX& q = kinematics.q();
  const auto dofs = static_cast<Eigen::Index>(3 * (n + 1));
  MatX D = MatX::Zero(dofs, dofs);
  // W (columns of element Q) and W + Theta x M_tip, per element (load_stiffness.hpp).
  std::vector<Mat36> downstream(n), downstream_with_moment(n);

  // Suffix sums about p_{Q+1}: resultant, moment (with the tip moment), first moment A = sum d f^T.
  Vec3 resultant = tip_force, moment = tip_moment;
  Mat3 first_moment = Mat3::Zero();  // the tip force acts at p_N itself
  for (std::size_t e = n; e-- > 0;) {
    const Mat36& theta = kinematics.end_rotation_jacobian(e);
    const Mat36& translation = kinematics.end_translation_jacobian(e);
    const Mat3& R = kinematics.base_frame(e);

    // Diagonal block, downstream part.
    const NodalSecondDerivatives end = nodal_second_derivatives(q, e, ell, ell);
    const Mat36 carried = first_moment * theta - first_moment.trace() * theta;  // A Theta_b - tr(A) Theta_b
    Mat6 block = theta.transpose() * carried;
    const Vec3 moment_local = R.transpose() * moment, resultant_local = R.transpose() * resultant;
    for (int j = 0; j < 6; ++j)
      block.col(j) += end.rotation_rate[j].transpose() * moment_local +
                      end.translation_hessian[j].transpose() * resultant_local;
    Mat36 w = carried;
    for (int j = 0; j < 6; ++j) w.col(j) += translation.col(j).cross(resultant);

    // Shift the sums to p_Q, then add the element's own points.
    const Vec3 shift = kinematics.base_position(e + 1) - kinematics.base_position(e);
    first_moment += shift * resultant.transpose();
    moment += shift.cross(resultant);
    for (std::size_t g = 0; !point_forces.empty() && g < per; ++g) {
      const ClothoidPoint& point = points[e * per + g];
      const Vec3& f = point_forces[e * per + g];
      const NodalSecondDerivatives local = nodal_second_derivatives(q, e, ell, point.sigma);
      const Vec3 f_local = R.transpose() * f;
      for (int j = 0; j < 6; ++j) {
        block.col(j) += local.translation_hessian[j].transpose() * f_local;
        w.col(j) += point.local_jacobian.col(j).cross(f);
      }
      first_moment += point.offset * f.transpose();
      moment += point.offset.cross(f);
      resultant += f;
    }
    const auto at = static_cast<Eigen::Index>(3 * e);
    D.block<6, 6>(at, at) += block;
    downstream[e] = w;
    downstream_with_moment[e] = w;
    for (int i = 0; i < 6; ++i) downstream_with_moment[e].col(i) += theta.col(i).cross(tip_moment);
  }
  // Off-diagonal blocks: rows of element P, columns of element Q > P, and the transposed position.
  for (std::size_t P = 0; P < n; ++P) {
    const Mat36& theta_P = kinematics.end_rotation_jacobian(P);
    const auto row = static_cast<Eigen::Index>(3 * P);
    for (std::size_t Q = P + 1; Q < n; ++Q) {
      const auto column = static_cast<Eigen::Index>(3 * Q);
      D.block<6, 6>(row, column).noalias() += theta_P.transpose() * downstream[Q];
      D.block<6, 6>(column, row).noalias() += downstream_with_moment[Q].transpose() * theta_P;
    }
  }
  return D;
}

MatX clothoid_load_stiffness(const RodModel& model, const ClothoidKinematics& kinematics, double load_factor) {
  return clothoid_generalised_force_jacobian(kinematics, clothoid_point_loads(model, kinematics, load_factor),
                                             load_factor * model.end_force, load_factor * model.end_moment);
}

}  // namespace rodvv::solvers::superhelix

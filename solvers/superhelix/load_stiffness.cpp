#include "rodvv/solvers/superhelix/load_stiffness.hpp"

#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"

namespace rodvv::solvers::superhelix {

namespace {

// A dead force at offset sigma of its element, with the point's offset d = r - p_e from the element's
// base and its local position Jacobian (world), grouped by element.
struct LoadedPoint {
  double sigma = 0.0;
  Vec3 force, offset;
  Mat3 local_jacobian;
};
using LoadsPerElement = std::vector<std::vector<LoadedPoint>>;

MatX force_jacobian(const Kinematics& kinematics, const LoadsPerElement& loads, const Vec3& tip_force,
                    const Vec3& tip_moment) {
  const std::size_t n = kinematics.elements();
  const double ell = kinematics.element_length();
  const VecX& q = kinematics.q();
  MatX D = MatX::Zero(Eigen::Index(3 * n), Eigen::Index(3 * n));
  // W_b (column j of element P') and W_a + Theta_a x M, per element (see the header).
  std::vector<Mat3> downstream(n), downstream_with_moment(n);

  // Suffix sums about p_{P+1}: resultant, moment (with the tip moment), first moment A = sum d f^T.
  Vec3 resultant = tip_force, moment = tip_moment;
  Mat3 first_moment = Mat3::Zero();  // the tip force acts at p_N itself
  for (std::size_t e = n; e-- > 0;) {
    const Mat3& theta = kinematics.end_rotation_jacobian(e);
    const Mat3& translation = kinematics.end_translation_jacobian(e);
    const Mat3& R = kinematics.base_frame(e);
    const Vec3 qe = q.segment<3>(Eigen::Index(3 * e));
    const double trace = first_moment.trace();

    // Diagonal block (P = P'), downstream part.
    const ElementSecondDerivatives end = element_second_derivatives(qe, ell);
    const Mat3 carried = first_moment * theta - trace * theta;  // column j: A Theta_b - tr(A) Theta_b
    Mat3 block = theta.transpose() * carried;
    const Vec3 moment_local = R.transpose() * moment, resultant_local = R.transpose() * resultant;
    for (int j = 0; j < 3; ++j) {
      // dTheta_a/dq_j = R dG/dq_j e_i, dT_a/dq_j = R d2(G e0)/dq_i dq_j (column i of offset_hessian[j])
      block.col(j) += end.frame_rate[j].transpose() * moment_local + end.offset_hessian[j].transpose() * resultant_local;
    }
    Mat3 w = carried;
    for (int j = 0; j < 3; ++j) w.col(j) += translation.col(j).cross(resultant);

    // Shift the sums to p_e, then add the element's own points.
    const Vec3 shift = kinematics.base_position(e + 1) - kinematics.base_position(e);
    first_moment += shift * resultant.transpose();
    moment += shift.cross(resultant);
    for (const LoadedPoint& point : loads[e]) {
      const Vec3& f = point.force;
      const ElementSecondDerivatives local = element_second_derivatives(qe, point.sigma);
      const Vec3 f_local = R.transpose() * f;
      for (int j = 0; j < 3; ++j) {
        block.col(j) += local.offset_hessian[j].transpose() * f_local;
        w.col(j) += point.local_jacobian.col(j).cross(f);
      }
      first_moment += point.offset * f.transpose();
      moment += point.offset.cross(f);
      resultant += f;
    }
    D.block<3, 3>(Eigen::Index(3 * e), Eigen::Index(3 * e)) = block;
    downstream[e] = w;
    downstream_with_moment[e] = w;
    for (int i = 0; i < 3; ++i) downstream_with_moment[e].col(i) += theta.col(i).cross(tip_moment);
  }
  // Off-diagonal blocks: rows of element P, columns of element P'.
  for (std::size_t P = 0; P < n; ++P) {
    const Mat3& theta_P = kinematics.end_rotation_jacobian(P);
    for (std::size_t Q = P + 1; Q < n; ++Q) {
      D.block<3, 3>(Eigen::Index(3 * P), Eigen::Index(3 * Q)) = theta_P.transpose() * downstream[Q];
      D.block<3, 3>(Eigen::Index(3 * Q), Eigen::Index(3 * P)) = downstream_with_moment[Q].transpose() * theta_P;
    }
  }
  return D;
}

}  // namespace

MatX generalised_force_jacobian(const Kinematics& kinematics, const std::vector<Vec3>& point_forces,
                                const Vec3& tip_force, const Vec3& tip_moment) {
  const std::size_t per = kinematics.points_per_element();
  LoadsPerElement loads(kinematics.elements());
  for (std::size_t g = 0; g < point_forces.size(); ++g) {
    const GaussPoint& point = kinematics.points()[g];
    loads[g / per].push_back({point.sigma, point_forces[g], point.offset, point.local_jacobian});
  }
  return force_jacobian(kinematics, loads, tip_force, tip_moment);
}

MatX point_load_jacobian(const Kinematics& kinematics, const std::vector<PointLoad>& point_loads) {
  LoadsPerElement loads(kinematics.elements());
  for (const PointLoad& load : point_loads) {
    const Mat3& R = kinematics.base_frame(load.element);
    const PointMaps maps = element_point_maps(kinematics.q().segment<3>(Eigen::Index(3 * load.element)), load.sigma);
    loads.at(load.element).push_back({load.sigma, load.force, R * maps.Ge0, R * maps.dG0});
  }
  return force_jacobian(kinematics, loads, Vec3::Zero(), Vec3::Zero());
}

MatX load_stiffness(const RodModel& model, const Kinematics& kinematics, double load_factor) {
  return generalised_force_jacobian(kinematics, gauss_point_loads(model, kinematics, load_factor),
                                    load_factor * model.end_force, load_factor * model.end_moment);
}

}  // namespace rodvv::solvers::superhelix

#include "rodvv/solvers/superhelix/tip_guide.hpp"

#include "rodvv/solvers/superhelix/load_stiffness.hpp"

namespace rodvv::solvers::superhelix {

namespace {

Vec3 vee(const Mat3& antisymmetric) { return {antisymmetric(2, 1), antisymmetric(0, 2), antisymmetric(1, 0)}; }

Mat3 hat(const Vec3& a) {
  Mat3 m;
  m << 0.0, -a.z(), a.y(), a.z(), 0.0, -a.x(), -a.y(), a.x(), 0.0;
  return m;
}

// The guide's springs at the tip: w = k P (r - point), X = R frame^T, g = k_r vee(X - X^T).
struct GuideState {
  Mat3 P;
  Vec3 w;
  Mat3 X;
  Vec3 g;
};

GuideState state_of(const TipGuide& guide, const Kinematics& kinematics) {
  const Vec3 e = guide.frame.col(0);
  GuideState s;
  s.P = Mat3::Identity() - e * e.transpose();
  s.w = guide.stiffness * (s.P * (kinematics.tip_position() - guide.point));
  s.X = kinematics.tip_frame() * guide.frame.transpose();
  s.g = guide.rotational_stiffness * vee(s.X - s.X.transpose());
  return s;
}

}  // namespace

bool has_tip_guide(const RodModel& model) { return model.tip_guide.stiffness > 0.0; }

TipGuideReaction tip_guide_reaction(const TipGuide& guide, const Kinematics& kinematics) {
  const GuideState s = state_of(guide, kinematics);
  return {-s.w, -s.g};
}

double tip_guide_energy(const TipGuide& guide, const Kinematics& kinematics) {
  const Vec3 e = guide.frame.col(0);
  const Vec3 off_axis = (Mat3::Identity() - e * e.transpose()) * (kinematics.tip_position() - guide.point);
  const double trace = (guide.frame.transpose() * kinematics.tip_frame()).trace();
  return 0.5 * guide.stiffness * off_axis.squaredNorm() + guide.rotational_stiffness * (3.0 - trace);
}

VecX tip_guide_gradient(const TipGuide& guide, const Kinematics& kinematics) {
  const GuideState s = state_of(guide, kinematics);
  const std::size_t last = kinematics.elements() - 1;
  const double ell = kinematics.element_length();
  return kinematics.position_jacobian(last, ell).transpose() * s.w +
         kinematics.rotation_jacobian(last, ell).transpose() * s.g;
}

MatX tip_guide_hessian(const TipGuide& guide, const Kinematics& kinematics) {
  const GuideState s = state_of(guide, kinematics);
  const std::size_t last = kinematics.elements() - 1;
  const double ell = kinematics.element_length();
  const MatX T = kinematics.position_jacobian(last, ell), Theta = kinematics.rotation_jacobian(last, ell);
  Mat3 G;
  for (int i = 0; i < 3; ++i) {
    const Mat3 turn = hat(Vec3::Unit(i));
    G.col(i) = guide.rotational_stiffness * vee(turn * s.X + s.X.transpose() * turn);
  }
  MatX H = generalised_force_jacobian(kinematics, {}, s.w, s.g);
  H.noalias() += guide.stiffness * (T.transpose() * s.P * T);
  H.noalias() += Theta.transpose() * G * Theta;
  return H;
}

}  // namespace rodvv::solvers::superhelix

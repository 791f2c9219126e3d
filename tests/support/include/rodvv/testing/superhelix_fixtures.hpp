// Shared helpers of the Super-Helix / super-clothoid solver tests (tests/solvers/test_superhelix_*.cpp):
// reproducible random coordinate vectors, central-difference position and rotation Jacobians of any
// kinematics class (Kinematics, ClothoidKinematics), and the end-moment roll-up problem whose exact
// answer is a full circle. One copy here instead of one per test file.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cstddef>
#include <numbers>
#include <random>

#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::testing::superhelix {

namespace sh = rodvv::solvers::superhelix;

// n entries uniform in [-amplitude, amplitude], reproducible from seed (std::mt19937).
inline rodvv::VecX random_vector(std::size_t n, double amplitude, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> dist(-amplitude, amplitude);
  rodvv::VecX q(static_cast<Eigen::Index>(n));
  for (auto& v : q) v = dist(gen);
  return q;
}

// Central differences (step h) of the position and of the frame at (element e, arc length sigma)
// with respect to every generalised coordinate. The rotation column is vee(dR R^T), since
// dR = [theta]x R. Kin is constructed as Kin(model, q) and offers position(e, sigma), frame(e, sigma).
struct FiniteDifferenceJacobians {
  rodvv::MatX position, rotation;  // 3 x q.size()
};
template <class Kin>
FiniteDifferenceJacobians finite_difference_jacobians(const sh::RodModel& model, const rodvv::VecX& q,
                                                      std::size_t e, double sigma, double h) {
  const rodvv::Mat3 R = Kin(model, q).frame(e, sigma);
  FiniteDifferenceJacobians fd{rodvv::MatX(3, q.size()), rodvv::MatX(3, q.size())};
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    rodvv::VecX qp = q, qm = q;
    qp[j] += h;
    qm[j] -= h;
    const Kin kp(model, qp), km(model, qm);
    fd.position.col(j) = (kp.position(e, sigma) - km.position(e, sigma)) / (2 * h);
    const rodvv::Mat3 W = (kp.frame(e, sigma) - km.frame(e, sigma)) / (2 * h) * R.transpose();
    fd.rotation.col(j) = rodvv::Vec3(W(2, 1), W(0, 2), W(1, 0));
  }
  return fd;
}

// End-moment roll-up: M = 2 pi EI2 / L about n2 on a rod
// with stiffness (0.7, 1.3, 2.0) bends it into a full circle, u2 = 2 pi / L exactly for any N.
inline sh::RodModel roll_up_model(std::size_t n) {
  sh::RodModel model;
  model.elements = n;
  model.stiffness = rodvv::Vec3(0.7, 1.3, 2.0);
  model.end_moment = rodvv::Vec3(0.0, 0.0, 2 * std::numbers::pi * model.stiffness[2] / model.length);
  return model;
}

// Newton options of the roll-up: the full moment in 4 load steps.
inline sh::StaticOptions roll_up_options() {
  sh::StaticOptions options;
  options.load_steps = 4;
  return options;
}

// A loaded, damped, naturally curved and twisted rod with a tilted root frame: gravity, a dead end
// force and moment (the dynamics tests' common model; callers change single fields).
inline sh::RodModel loaded_model(std::size_t n) {
  sh::RodModel model;
  model.elements = n;
  model.length = 0.8;
  model.stiffness = rodvv::Vec3(0.05, 0.1, 0.13);
  model.natural_strain = rodvv::Vec3(0.5, -1.0, 2.0);
  model.line_density = 0.02;
  model.gravity = rodvv::Vec3(0.0, 0.0, -9.81);
  model.end_force = rodvv::Vec3(0.01, 0.0, 0.02);
  model.end_moment = rodvv::Vec3(0.0, 0.003, 0.0);
  model.rayleigh_stiffness = 0.01;
  model.root_frame =
      Eigen::AngleAxisd(0.4, rodvv::Vec3(0.2, 1.0, -0.3).normalized()).toRotationMatrix();
  return model;
}

}  // namespace rodvv::testing::superhelix

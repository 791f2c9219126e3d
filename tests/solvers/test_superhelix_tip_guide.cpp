// The sliding clamp at the tip of the Super-Helix statics (solvers/superhelix/tip_guide.hpp): its
// gradient and Hessian against central differences of the potential and of the residual (the Hessian's
// two unsymmetric parts must cancel), and equilibria whose exact answer is known: a twisted straight rod
// (uniform twist phi / L, the moment GJ phi / L carried by the clamp), a naturally curved rod held
// straight (the moment EI kappa0), an axial pull that slides freely while a lateral one is carried.
#include <gtest/gtest.h>

#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/solvers/superhelix/tip_guide.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;

constexpr double kLength = 1.7;
const Vec3 kStiffness(0.37, 0.81, 1.23);  // GJ, EI1, EI2: unequal, so that an index slip shows

Mat3 rotation(double angle, const Vec3& axis) { return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix(); }

// Root at an arbitrary pose; the guide's axis is the root tangent's line, through the straight rod's tip.
sh::RodModel guided_rod(std::size_t elements) {
  sh::RodModel model;
  model.length = kLength;
  model.elements = elements;
  model.stiffness = kStiffness;
  model.root_position = Vec3(0.3, -0.2, 0.5);
  model.root_frame = rotation(0.8, Vec3(1, -2, 0.5));
  model.tip_guide.stiffness = 1e3;
  model.tip_guide.rotational_stiffness = 1e2;
  model.tip_guide.point = model.root_position + kLength * model.root_frame.col(0);
  model.tip_guide.frame = model.root_frame;
  return model;
}

// A configuration well off the guide: strains of every sign, gravity and an end force acting.
sh::RodModel loaded(sh::RodModel model) {
  model.gravity = Vec3(0.1, -0.4, 0.3);
  model.end_force = Vec3(0.2, 0.1, -0.3);
  model.natural_strain = Vec3(0.3, -0.5, 0.2);
  return model;
}

VecX strains(std::size_t elements) {
  VecX q(3 * elements);
  for (Eigen::Index i = 0; i < q.size(); ++i) q[i] = 0.4 * std::sin(1.7 * double(i) + 0.3);
  return q;
}

TEST(SuperHelixTipGuide, ResidualIsTheGradientOfThePotential) {
  const sh::RodModel model = loaded(guided_rod(5));
  const VecX q = strains(5);
  const VecX r = sh::static_residual(model, q);
  const double step = 1e-6;
  double worst = 0.0;
  for (Eigen::Index i = 0; i < q.size(); ++i) {
    VecX plus = q, minus = q;
    plus[i] += step;
    minus[i] -= step;
    const double derivative = (sh::static_potential(model, plus) - sh::static_potential(model, minus)) / (2 * step);
    worst = std::max(worst, std::abs(derivative - r[i]));
  }
  // Central differences: truncation ~ step^2 |V'''| and rounding ~ eps |V| / step, both ~1e-9 here.
  EXPECT_LT(worst / r.lpNorm<Eigen::Infinity>(), 1e-7);
}

TEST(SuperHelixTipGuide, HessianMatchesCentralDifferencesAndIsSymmetric) {
  const sh::RodModel model = loaded(guided_rod(5));
  const VecX q = strains(5);
  const sh::Kinematics kinematics(model, q);
  const MatX H = sh::tip_guide_hessian(model.tip_guide, kinematics);
  const double step = 1e-6;
  MatX fd(q.size(), q.size());
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    VecX plus = q, minus = q;
    plus[j] += step;
    minus[j] -= step;
    fd.col(j) = (sh::tip_guide_gradient(model.tip_guide, sh::Kinematics(model, plus)) -
                 sh::tip_guide_gradient(model.tip_guide, sh::Kinematics(model, minus))) /
                (2 * step);
  }
  const double size = H.cwiseAbs().maxCoeff();
  EXPECT_LT((H - fd).cwiseAbs().maxCoeff() / size, 1e-7);
  // Each part alone is unsymmetric (the rotation's second derivative); their sum is the Hessian of E.
  EXPECT_LT((H - H.transpose()).cwiseAbs().maxCoeff() / size, 1e-12);
  // And the whole static Jacobian agrees with central differences of the residual.
  const MatX J = sh::static_jacobian(model, q);
  MatX fd_residual(q.size(), q.size());
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    VecX plus = q, minus = q;
    plus[j] += step;
    minus[j] -= step;
    fd_residual.col(j) = (sh::static_residual(model, plus) - sh::static_residual(model, minus)) / (2 * step);
  }
  EXPECT_LT((J - fd_residual).cwiseAbs().maxCoeff() / J.cwiseAbs().maxCoeff(), 1e-7);
}

TEST(SuperHelixTipGuide, EnergyAndReactionVanishOnTheGuide) {
  const sh::RodModel model = guided_rod(4);
  const sh::Kinematics straight(model, VecX::Zero(12));
  EXPECT_NEAR(sh::tip_guide_energy(model.tip_guide, straight), 0.0, 1e-13);
  const sh::TipGuideReaction reaction = sh::tip_guide_reaction(model.tip_guide, straight);
  EXPECT_LT(reaction.force.norm() + reaction.moment.norm(), 1e-10);
}

// The guide's frame turned by phi about its axis: the rod twists uniformly, tau = phi / L, with the
// moment GJ phi / L; the springs' compliance leaves the tip short of phi by about that moment / (2 k_r).
TEST(SuperHelixTipGuide, TurnedClampTwistsTheRodUniformly) {
  sh::RodModel model = guided_rod(6);
  model.tip_guide.rotational_stiffness = 1e8;
  model.tip_guide.stiffness = 1e8;
  const double phi = 0.9;
  model.tip_guide.frame = model.root_frame * rotation(phi, Vec3::UnitX());
  model.end_force = 2.5 * model.root_frame.col(0);  // an axial pull: the tip slides, nothing changes
  const sh::StaticResult result = sh::solve_static(model);
  const double tau = phi / kLength, moment = kStiffness[0] * tau;
  for (std::size_t e = 0; e < 6; ++e) {
    EXPECT_NEAR(result.q[3 * e], tau, 1e-6 * tau) << e;  // compliance: moment / (2 k_r) / L ~ 1e-9 relative
    EXPECT_NEAR(result.q[3 * e + 1], 0.0, 1e-10);
    EXPECT_NEAR(result.q[3 * e + 2], 0.0, 1e-10);
  }
  const sh::TipGuideReaction reaction = sh::tip_guide_reaction(model.tip_guide, sh::Kinematics(model, result.q));
  EXPECT_NEAR(reaction.moment.dot(model.root_frame.col(0)), moment, 1e-6 * moment);  // m(L) = the applied moment
  EXPECT_LT(reaction.force.norm(), 1e-6);  // the pull is axial: the clamp carries none of it
}

// A rod with natural curvature kappa0 held straight between two clamps: q = 0 up to the compliance,
// the clamp's reaction moment EI1 kappa0 about n1, and n(s) = the dead load minus what the clamp carries.
TEST(SuperHelixTipGuide, NaturallyCurvedRodHeldStraightAndALateralPullCarried) {
  sh::RodModel model = guided_rod(6);
  model.tip_guide.rotational_stiffness = 1e8;
  model.tip_guide.stiffness = 1e8;
  const double kappa0 = 0.6;
  model.natural_strain = Vec3(0.0, kappa0, 0.0);
  const Vec3 lateral = 0.7 * model.root_frame.col(2);
  model.end_force = 1.9 * model.root_frame.col(0) + lateral;
  // From the straight rod, on the guide: from the natural shape (the tip 1 rad off the clamp's frame) the
  // springs, not ramped, make a landscape Newton on |r| does not cross (measured: no convergence in 50).
  sh::StaticOptions options;
  options.initial_q = VecX::Zero(18);
  const sh::StaticResult result = sh::solve_static(model, options);
  // The lateral pull bends the rod between the clamps by ~ F L^2 / EI / k-ish; the curvature stays
  // small: EI kappa0 and F L against the clamp's stiffness.
  EXPECT_LT(result.q.lpNorm<Eigen::Infinity>(), 1e-5);
  const sh::Kinematics kinematics(model, result.q);
  const sh::TipGuideReaction reaction = sh::tip_guide_reaction(model.tip_guide, kinematics);
  EXPECT_NEAR(reaction.force.dot(model.root_frame.col(2)), -0.7, 1e-6);  // the clamp carries the lateral pull
  EXPECT_NEAR(reaction.force.dot(model.root_frame.col(0)), 0.0, 1e-9);   // but none of the axial one
  // The solution's internal force: the end force plus the clamp's reaction, i.e. the axial pull alone.
  const auto solution = sh::make_solution(model, result.q);
  for (const Vec3& n : solution.force_n) EXPECT_LT((n - 1.9 * model.root_frame.col(0)).norm(), 1e-6);
}

TEST(SuperHelixTipGuide, BadInputNamesTheGuideAndStaticsOnly) {
  sh::RodModel model = guided_rod(4);
  model.tip_guide.rotational_stiffness = 0.0;
  EXPECT_THROW(sh::validate(model), rodvv::InputError);
  model = guided_rod(4);
  model.tip_guide.frame = 1.01 * model.tip_guide.frame;
  try {
    sh::validate(model);
    FAIL() << "a frame that is no rotation";
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "tip_guide.frame");
  }
  model = guided_rod(4);
  try {
    sh::require_statics_only_loads_absent(model, "the dynamics");
    FAIL() << "the dynamics take no sliding clamp";
  } catch (const rodvv::InputError& error) {
    EXPECT_EQ(error.parameter(), "tip_guide");
  }
}

}  // namespace

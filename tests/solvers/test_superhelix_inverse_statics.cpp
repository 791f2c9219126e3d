// Inverse statics of the Super-Helix (solvers/superhelix/inverse_statics.hpp): the recovered
// natural strains make the target an equilibrium (checked through the forward residual, the
// forward Newton from elsewhere, and an independent force path), the critical stiffness factor is
// where the forward stability eigenvalue changes sign, and the inputs it refuses.
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/heavy_column.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/inverse_statics.hpp"
#include "rodvv/solvers/superhelix/stability.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

// A hair-like rod at unequal, non-unit scales: clamped pointing up and sideways, curled and twisted,
// gravity and a dead end force.
sh::RodModel hair(std::size_t elements) {
  sh::RodModel model;
  model.elements = elements;
  model.length = 0.9;
  model.stiffness = Vec3(0.35, 0.8, 1.25);
  model.line_density = 0.6;
  model.gravity = Vec3(0.0, 0.0, -2.4);
  model.root_frame = Eigen::AngleAxisd(-1.1, Vec3(0.2, 1.0, 0.3).normalized()).toRotationMatrix();
  model.end_force = Vec3(0.05, -0.1, 0.08);
  return model;
}

VecX curl(std::size_t elements) {
  VecX q(Eigen::Index(3 * elements));
  for (std::size_t e = 0; e < elements; ++e) {
    const double s = (double(e) + 0.5) / double(elements);
    q.segment<3>(Eigen::Index(3 * e)) = Vec3(0.8 - 0.5 * s, 1.6 * std::sin(3.0 * s), 2.2 - 1.4 * s);
  }
  return q;
}

TEST(SuperHelixInverseStatics, RecoveredRestShapeHoldsTheTargetAndNewtonFindsIt) {
  const std::size_t n = 12;
  const sh::RodModel model = hair(n);
  const VecX q = curl(n);
  const sh::InverseStatics inverse = sh::inverse_statics(model, q);
  // One division per entry: the residual is a few eps of the scale.
  EXPECT_LE(inverse.residual, 8 * kEpsilon);
  ASSERT_LT(inverse.critical_stiffness_factor, 1.0) << "the target must be stable at the model's stiffness";
  EXPECT_NEAR(inverse.stability_eigenvalue, 1.0 - inverse.critical_stiffness_factor, 64 * kEpsilon);

  const sh::RodModel rest = sh::model_at_rest_in(model, q);
  ASSERT_EQ(rest.natural_strain_per_element.size(), n);
  // The forward residual at the target (the solver's own path): round-off.
  const VecX r = sh::static_residual(rest, q);
  const double scale = (sh::generalised_stiffness(rest).cwiseProduct(q)).lpNorm<Eigen::Infinity>();
  EXPECT_LE(r.lpNorm<Eigen::Infinity>(), 16 * kEpsilon * scale);
  // The forward statics from the rest shape (load stepping) comes back to the target; Newton stops
  // at its round-off floor, a few eps of the scale through the inverse Jacobian (condition ~ 1e2
  // here): 1e-12 relative leaves a factor ~50.
  sh::StaticOptions options;
  options.load_steps = 4;
  options.tolerance = 1e-15;
  const VecX found = sh::solve_static(rest, options).q;
  EXPECT_LE((found - q).lpNorm<Eigen::Infinity>(), 1e-12 * q.lpNorm<Eigen::Infinity>());
  // The forward stability of the recovered equilibrium agrees with the inverse one.
  EXPECT_NEAR(sh::stability_eigenvalue(rest, q), inverse.stability_eigenvalue, 1e-12);
}

TEST(SuperHelixInverseStatics, CriticalFactorIsWhereTheForwardEigenvalueChangesSign) {
  const std::size_t n = 10;
  sh::RodModel model = hair(n);
  model.gravity = Vec3(0.0, 0.0, -40.0);  // heavy: unstable at the model's stiffness
  const VecX q = curl(n);
  const double critical = sh::inverse_statics(model, q).critical_stiffness_factor;
  ASSERT_GT(critical, 1.0);
  for (double factor : {0.999, 1.001}) {
    const sh::RodModel scaled = sh::model_at_rest_in(model, q, factor * critical);
    const double eigenvalue = sh::stability_eigenvalue(scaled, q);
    // 1 - 1/factor = -+1e-3, far above the eigensolver's round-off
    EXPECT_NEAR(eigenvalue, 1.0 - 1.0 / factor, 1e-9) << factor;
  }
  const sh::RodModel stable = sh::stable_rest_model(model, q, 0.2);
  EXPECT_NEAR(stable.stiffness[1] / model.stiffness[1], 1.2 * critical, 1e-12 * critical);
  EXPECT_GT(sh::stability_eigenvalue(stable, q), 0.0);
  // Light: stable as given, no stiffening.
  const sh::RodModel light = sh::stable_rest_model(hair(n), q, 0.2);
  EXPECT_EQ(light.stiffness, hair(n).stiffness);
}

TEST(SuperHelixInverseStatics, UprightColumnBucklesUnderGreenhillsWeight) {
  // The straight column pointing against gravity: F = 0 (but for the rounding of the tilted frame's
  // vectors, a few eps of w L^2 / EI), so q0 = 0 and the critical stiffness is
  // Greenhill's, w L^3 / EI_min = 7.837 (references/heavy_column.hpp), to O(h^2): ~5e-4 at N = 32.
  sh::RodModel model;
  model.elements = 32;
  model.length = 1.3;
  model.stiffness = Vec3(0.4, 0.9, 1.7);  // buckles about n1 (EI1 = 0.9, the weaker)
  model.line_density = 0.7;
  model.root_frame = Eigen::AngleAxisd(0.6, Vec3(1.0, -0.4, 0.2).normalized()).toRotationMatrix();
  model.gravity = -3.1 * model.root_frame.col(0);
  const VecX straight = VecX::Zero(96);
  const sh::InverseStatics inverse = sh::inverse_statics(model, straight);
  EXPECT_LE(inverse.natural_strain.lpNorm<Eigen::Infinity>(), 64 * kEpsilon * 0.7 * 3.1 * 1.3 / 0.9);
  const double weight = 0.7 * 3.1 * std::pow(1.3, 3) / (inverse.critical_stiffness_factor * 0.9);
  EXPECT_NEAR(weight / rodvv::references::heavy_column_critical_weight(), 1.0, 2e-3);
}

// The dynamics check of inverse/stability-threshold (release at 1.05 and 0.95 x alpha_c from a slight
// bow, growth of |q|_K over 24 sqrt(L/g): <= 5 above, >= 50 below) turns red if alpha_c is 10 % off
// either way: at 1.05 x 0.9 alpha_c the column falls, at 0.95 x 1.1 alpha_c it stands.
TEST(SuperHelixInverseStatics, CriticalFactorTenPercentOffIsSeenByTheDynamics) {
  sh::RodModel model;
  model.elements = 8;
  model.length = 1.3;
  model.stiffness = Vec3(0.54, 0.9, 1.71);
  model.line_density = 0.7;
  model.gravity = Vec3(0.0, 0.0, -3.1);
  model.root_frame = Eigen::AngleAxisd(-0.5 * 3.141592653589793, Vec3::UnitY()).toRotationMatrix();  // upright
  const VecX straight = VecX::Zero(24);
  const double critical = sh::inverse_statics(model, straight).critical_stiffness_factor;
  const auto growth = [&](double factor) {
    const sh::RodModel scaled = sh::model_at_rest_in(model, straight, factor);
    const VecX k = sh::generalised_stiffness(scaled);
    sh::DynamicState state{VecX::Constant(24, 1e-4 / 1.3), VecX::Zero(24), 0.0};
    for (int e = 0; e < 8; ++e) state.q[3 * e] = 0.0;
    const double start = std::sqrt(state.q.dot(k.cwiseProduct(state.q)));
    const double swing = std::sqrt(1.3 / 3.1);
    double largest = 1.0;
    for (int i = 0; i < 24 * 500; ++i) {
      state = sh::step(scaled, state, swing / 500, sh::DynamicsPath::Recursive);
      largest = std::max(largest, std::sqrt(state.q.dot(k.cwiseProduct(state.q))) / start);
    }
    return largest;
  };
  EXPECT_LE(growth(1.05 * critical), 5.0);
  EXPECT_GE(growth(0.95 * critical), 50.0);
  EXPECT_GT(growth(1.05 * 0.9 * critical), 5.0) << "alpha_c 10 % low: the 'stable' column falls";
  EXPECT_LT(growth(0.95 * 1.1 * critical), 50.0) << "alpha_c 10 % high: the 'unstable' column stands";
}

TEST(SuperHelixInverseStatics, RefusesWhatItCannotDo) {
  const sh::RodModel model = hair(6);
  const VecX q = curl(6);
  const auto parameter_of = [](auto&& call) {
    try {
      call();
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter_of([&] { sh::inverse_statics(model, q); }), "none");
  EXPECT_EQ(parameter_of([&] { sh::inverse_statics(model, VecX::Zero(5)); }), "q");
  VecX bad = q;
  bad[3] = std::nan("");
  EXPECT_EQ(parameter_of([&] { sh::natural_strain_for(model, bad); }), "q");
  EXPECT_EQ(parameter_of([&] { sh::stable_rest_model(model, q, 0.0); }), "margin");
  EXPECT_EQ(parameter_of([&] { sh::stable_rest_model(model, q, 12.0); }), "margin");
  EXPECT_EQ(parameter_of([&] { sh::model_at_rest_in(model, q, -1.0); }), "stiffness_factor");
  sh::RodModel moment = model;
  moment.end_moment = Vec3(0.2, -0.1, 0.3);
  EXPECT_EQ(parameter_of([&] { sh::inverse_statics(moment, q); }), "end_moment");
  EXPECT_EQ(parameter_of([&] { sh::natural_strain_for(moment, q); }), "none");  // q0 is still defined
}

TEST(SuperHelixInverseStatics, NaturalStrainVectorRoundTrips) {
  sh::RodModel model = hair(6);
  const VecX q0 = curl(6);
  sh::set_natural_strain_vector(model, q0);
  EXPECT_EQ(sh::natural_strain_vector(model), q0);
  EXPECT_THROW(sh::set_natural_strain_vector(model, VecX::Zero(17)), rodvv::InputError);
}

}  // namespace

// Inverse statics with frictional contact (solvers/superhelix/inverse_contact.hpp): the SOCQP's KKT
// conditions rebuilt here from the kinematics' point Jacobians (r in K_mu, W r + b in K_mu*,
// orthogonal), the round trip through the forward statics with the forces as dead point forces (the
// tip-to-root wrench pass, another path than the dense Jacobians), a force put at the wrong point
// seen by that round trip, and the inputs refused.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

// A curled rod at unequal scales and contacts at every other Gauss point against a ball whose
// centre lies below the rod (normals roughly upwards).
struct Problem {
  sh::RodModel model;
  VecX q;
  std::vector<sh::RodContact> contacts;
};

Problem problem() {
  Problem p;
  p.model.elements = 6;
  p.model.length = 0.8;
  p.model.stiffness = Vec3(0.3, 0.7, 1.1);
  p.model.line_density = 0.4;
  p.model.gravity = Vec3(0.1, 0.0, -5.0);
  p.model.gauss_points = 2;
  p.q.resize(18);
  for (int e = 0; e < 6; ++e) p.q.segment<3>(3 * e) = Vec3(0.4, 0.3 * std::sin(e), 1.2 - 0.1 * e);
  const sh::Kinematics kinematics(p.model, p.q);
  const Vec3 centre = Vec3(0.3, 0.2, -1.0);
  for (std::size_t g = 0; g < kinematics.points().size(); g += 2)
    p.contacts.push_back({g, (kinematics.points()[g].position - centre).normalized(), 0.4});
  return p;
}

TEST(SuperHelixInverseContact, SolvesTheSocqpAndHoldsTheTargetThroughTheWrenchPass) {
  const Problem p = problem();
  sh::InverseContactOptions options;
  options.gamma = 1e-2;
  const sh::InverseContactResult result = sh::inverse_statics_with_contacts(p.model, p.q, p.contacts, options);
  EXPECT_LE(result.residual, options.solver.tolerance);
  EXPECT_LE(result.cone_violation, 1e-15);
  // KKT rebuilt from the point Jacobians.
  const sh::Kinematics kinematics(p.model, p.q);
  const VecX k = sh::generalised_stiffness(p.model);
  const auto m = Eigen::Index(p.contacts.size());
  MatX H(3 * m, 18);
  for (Eigen::Index c = 0; c < m; ++c) {
    const auto& point = kinematics.points()[p.contacts[std::size_t(c)].point];
    H.middleRows(3 * c, 3) = result.frames[std::size_t(c)].transpose() * kinematics.position_jacobian(point.element, point.sigma);
  }
  const MatX A = H * k.cwiseInverse().asDiagonal();
  MatX W = A * A.transpose();
  W.diagonal().array() += 2.0 * options.gamma * W.trace() / double(3 * m);
  const VecX z = -sh::external_generalised_force(p.model, kinematics).cwiseQuotient(k);  // q0bar = q
  const VecX u = W * result.local_forces - A * z;
  double worst = 0.0;
  for (Eigen::Index c = 0; c < m; ++c) {
    const Vec3 r = result.local_forces.segment<3>(3 * c), v = u.segment<3>(3 * c);
    worst = std::max({worst, 0.4 * std::hypot(v[1], v[2]) - v[0], std::abs(r.dot(v)) / (r.norm() + 1e-300)});
  }
  EXPECT_LE(worst, 1e-9 * (A * z).norm());  // the Gauss-Seidel's tolerance, relative to b
  // Round trip: the forward residual at q (round-off) and Newton from the rest shape.
  const sh::RodModel rest = sh::contact_model(p.model, p.contacts, result);
  const double scale = (k.cwiseProduct(p.q)).lpNorm<Eigen::Infinity>();
  EXPECT_LE(sh::static_residual(rest, p.q).lpNorm<Eigen::Infinity>(), 64 * kEpsilon * scale);
  sh::StaticOptions newton;
  newton.load_steps = 4;
  newton.tolerance = 1e-15;
  EXPECT_LE((sh::solve_static(rest, newton).q - p.q).lpNorm<Eigen::Infinity>(), 1e-12 * p.q.lpNorm<Eigen::Infinity>());

  // The same forces one Gauss point further along: the round trip sees it.
  std::vector<sh::RodContact> shifted = p.contacts;
  for (auto& c : shifted) ++c.point;
  const sh::RodModel wrong = sh::contact_model(p.model, shifted, result);
  EXPECT_GT(sh::static_residual(wrong, p.q).lpNorm<Eigen::Infinity>(), 1e6 * kEpsilon * scale);
}

TEST(SuperHelixInverseContact, RefusesWhatItCannotDo) {
  const Problem p = problem();
  const auto parameter_of = [](auto&& call) {
    try {
      call();
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  const auto with = [&](auto change) {
    Problem copy = p;
    sh::InverseContactOptions options;
    change(copy, options);
    return parameter_of([&] { sh::inverse_statics_with_contacts(copy.model, copy.q, copy.contacts, options); });
  };
  EXPECT_EQ(with([](Problem&, sh::InverseContactOptions&) {}), "none");
  EXPECT_EQ(with([](Problem& c, sh::InverseContactOptions&) { c.contacts[1].mu = 0.0; }), "mu");
  EXPECT_EQ(with([](Problem&, sh::InverseContactOptions& o) { o.gamma = -1.0; }), "gamma");
  EXPECT_EQ(with([](Problem& c, sh::InverseContactOptions&) { c.contacts[0].normal *= 1.01; }), "contacts");
  EXPECT_EQ(with([](Problem& c, sh::InverseContactOptions&) { c.contacts[0].point = 12; }), "contacts");
  EXPECT_EQ(with([](Problem&, sh::InverseContactOptions& o) { o.preferred_rest = VecX::Zero(5); }), "preferred_rest");
  EXPECT_EQ(with([](Problem& c, sh::InverseContactOptions&) { c.q = VecX::Zero(4); }), "q");
  // Dead point forces are statics only.
  sh::RodModel forced = p.model;
  forced.point_forces.assign(12, Vec3(0.0, 0.0, 0.1));
  EXPECT_EQ(parameter_of([&] { sh::validate(forced); }), "none");
  EXPECT_EQ(parameter_of([&] { sh::step(forced, {p.q, VecX::Zero(18), 0.0}, 1e-3, sh::DynamicsPath::Recursive); }),
            "point_forces");
  // The solution struct carries them in n(s): each station sees the forces beyond it (half of one on it).
  const auto with_forces = sh::make_solution(forced, p.q), without = sh::make_solution(p.model, p.q);
  const sh::Kinematics kinematics(forced, p.q);
  const double ell = sh::element_length(forced);
  for (std::size_t i = 0; i < with_forces.s.size(); ++i) {
    Vec3 beyond = Vec3::Zero();
    for (std::size_t g = 0; g < kinematics.points().size(); ++g) {
      const double s_g = double(kinematics.points()[g].element) * ell + kinematics.points()[g].sigma;
      beyond += (s_g > with_forces.s[i] ? 1.0 : s_g == with_forces.s[i] ? 0.5 : 0.0) * forced.point_forces[g];
    }
    EXPECT_LE((with_forces.force_n[i] - without.force_n[i] - beyond).norm(), 1e-15) << "station " << i;
  }
  forced.point_forces.resize(5);
  EXPECT_EQ(parameter_of([&] { sh::validate(forced); }), "point_forces");
}

}  // namespace

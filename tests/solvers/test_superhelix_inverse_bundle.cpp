// Inverse statics of a bundle (solvers/superhelix/inverse_bundle.hpp): one strand on an obstacle is
// inverse_contact.hpp's problem (the same SOCQP, dense there, factored here); strands touching each
// other are checked by the SOCQP's KKT conditions rebuilt here from the point Jacobians of the whole
// bundle stacked in one q, by each strand's round trip through the wrench pass (another path than the
// Jacobians), by a reaction of the wrong sign seen by that round trip, and the inputs refused.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <utility>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/inverse_bundle.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

// Three curled strands of one shape, at unequal scales (stiffnesses, line densities), stacked: strands 1
// and 2 lie on strand 0, their roots (and so every pair of Gauss points of one
// index) 0.01 apart along tilted directions u1 and u2 (the contacts' normals, as the geometry gives
// them); strand 0 also on a ball at every other Gauss point, strand 2 on the ball at its tip and on
// itself (two of its points, the normal along the line between them). The forces are what the inverse
// chooses.
struct Bundle {
  std::vector<sh::RodModel> strands;
  std::vector<VecX> q;
  std::vector<sh::BundleContact> contacts;
};

const Vec3 kU1 = Vec3(0.3, 0.1, 1.0).normalized(), kU2 = Vec3(-0.2, 0.3, 1.0).normalized();

Bundle bundle() {
  Bundle b;
  const std::vector<Vec3> roots{Vec3::Zero(), 0.01 * kU1, 0.01 * kU2};
  for (int s = 0; s < 3; ++s) {
    sh::RodModel m;
    m.elements = 5;
    m.length = 0.9;
    m.stiffness = Vec3(0.3, 0.7, 1.1) * (1.0 + 0.5 * s);
    m.line_density = 0.4 + 0.1 * s;
    m.gravity = Vec3(0.1, 0.0, -5.0);
    m.gauss_points = 2;
    m.root_position = roots[std::size_t(s)];
    VecX q(Eigen::Index(3 * m.elements));
    for (Eigen::Index e = 0; e < Eigen::Index(m.elements); ++e)
      q.segment<3>(3 * e) = Vec3(0.4, 0.3 * std::sin(double(e)), 1.2 - 0.1 * double(e));
    b.strands.push_back(m);
    b.q.push_back(q);
  }
  const Vec3 centre(0.3, 0.2, -1.0);
  const sh::Kinematics k0(b.strands[0], b.q[0]), k2(b.strands[2], b.q[2]);
  const auto towards = [](const Vec3& from, const Vec3& to) { return (to - from).normalized(); };
  for (std::size_t g = 0; g < k0.points().size(); g += 2)
    b.contacts.push_back({0, g, sh::kObstacle, 0, towards(centre, k0.points()[g].position), 0.4});
  for (std::size_t g = 1; g < 10; g += 3) b.contacts.push_back({1, g, 0, g, kU1, 0.5});
  for (std::size_t g = 2; g < 10; g += 3) b.contacts.push_back({2, g, 0, g, kU2, 0.3});
  b.contacts.push_back({2, 9, sh::kObstacle, 0, towards(centre, k2.points()[9].position), 0.4});
  b.contacts.push_back({2, 1, 2, 7, towards(k2.points()[7].position, k2.points()[1].position), 0.6});
  return b;
}

sh::InverseBundleOptions options() {
  sh::InverseBundleOptions o;
  o.gamma = 1e-2;
  o.solver.tolerance = 1e-12;
  return o;
}

TEST(SuperHelixInverseBundle, OneStrandOnAnObstacleIsInverseContactsProblem) {
  Bundle b = bundle();
  b.strands.resize(1);
  b.q.resize(1);
  std::vector<sh::RodContact> single;
  std::vector<sh::BundleContact> on_obstacle;
  for (const auto& c : b.contacts)
    if (c.strand == 0 && c.other_strand == sh::kObstacle) {
      single.push_back({c.point, c.normal, c.mu});
      on_obstacle.push_back(c);
    }
  sh::InverseContactOptions dense_options;
  dense_options.gamma = options().gamma;
  dense_options.solver = options().solver;
  const auto dense = sh::inverse_statics_with_contacts(b.strands[0], b.q[0], single, dense_options);
  const auto factored = sh::inverse_statics_of_bundle(b.strands, b.q, on_obstacle, options());
  // The same sweeps on the same operator, up to the rounding of its products.
  EXPECT_LE((factored.local_forces - dense.local_forces).norm(), 1e-10 * dense.local_forces.norm());
  EXPECT_LE((factored.natural_strain[0] - dense.natural_strain).norm(), 1e-10 * dense.natural_strain.norm());
}

TEST(SuperHelixInverseBundle, SolvesTheSocqpOfTheWholeBundleAndHoldsEveryStrand) {
  const Bundle b = bundle();
  const sh::InverseBundleOptions o = options();
  const sh::InverseBundleResult result = sh::inverse_statics_of_bundle(b.strands, b.q, b.contacts, o);
  EXPECT_LE(result.residual, o.solver.tolerance);
  EXPECT_LE(result.cone_violation, 1e-15);

  // KKT rebuilt on the stacked q = (q_0, q_1, q_2): H with +rows on `strand`, -rows on the other.
  std::vector<Eigen::Index> offset{0};
  for (const auto& m : b.strands) offset.push_back(offset.back() + Eigen::Index(3 * m.elements));
  const auto m = Eigen::Index(b.contacts.size());
  MatX H = MatX::Zero(3 * m, offset.back());
  VecX k(offset.back()), F(offset.back());
  std::vector<sh::Kinematics> kinematics;
  for (std::size_t s = 0; s < b.strands.size(); ++s) {
    kinematics.emplace_back(b.strands[s], b.q[s]);
    k.segment(offset[s], offset[s + 1] - offset[s]) = sh::generalised_stiffness(b.strands[s]);
    F.segment(offset[s], offset[s + 1] - offset[s]) = sh::external_generalised_force(b.strands[s], kinematics[s]);
  }
  const auto jacobian = [&](std::size_t s, std::size_t g) {
    const auto& point = kinematics[s].points()[g];
    return kinematics[s].position_jacobian(point.element, point.sigma);
  };
  for (Eigen::Index c = 0; c < m; ++c) {
    const auto& contact = b.contacts[std::size_t(c)];
    const Mat3 frame = sh::contact_frame(contact.normal);
    H.block(3 * c, offset[contact.strand], 3, offset[contact.strand + 1] - offset[contact.strand]) +=
        frame.transpose() * jacobian(contact.strand, contact.point);
    if (contact.other_strand != sh::kObstacle)
      H.block(3 * c, offset[contact.other_strand], 3, offset[contact.other_strand + 1] - offset[contact.other_strand]) -=
          frame.transpose() * jacobian(contact.other_strand, contact.other_point);
  }
  const MatX A = H * k.cwiseInverse().asDiagonal();
  MatX W = A * A.transpose();
  W.diagonal().array() += 2.0 * o.gamma * W.trace() / double(3 * m);
  const VecX b_socqp = A * F.cwiseQuotient(k);
  const VecX u = W * result.local_forces + b_socqp;
  double worst = 0.0;
  for (Eigen::Index c = 0; c < m; ++c) {
    const double mu = b.contacts[std::size_t(c)].mu;
    const Vec3 r = result.local_forces.segment<3>(3 * c), v = u.segment<3>(3 * c);
    worst = std::max({worst, mu * std::hypot(v[1], v[2]) - v[0], std::abs(r.dot(v)) / (r.norm() + 1e-300)});
  }
  EXPECT_LE(worst, 1e-10 * b_socqp.norm());  // the Gauss-Seidel's tolerance, relative to b
  // Each kind of contact between strands (1 on 0, 2 on 0, 2 on itself) carries a force somewhere: the
  // checks below see both of its sides.
  std::map<std::pair<std::size_t, std::size_t>, int> loaded;
  for (Eigen::Index c = 0; c < m; ++c) {
    const auto& contact = b.contacts[std::size_t(c)];
    if (contact.other_strand != sh::kObstacle)
      loaded[{contact.strand, contact.other_strand}] += result.local_forces.segment<3>(3 * c).norm() > 0.0;
  }
  for (const auto& [pair, count] : loaded) EXPECT_GE(count, 1) << pair.first << " on " << pair.second;
  EXPECT_EQ(loaded.size(), 3u);

  // Round trip, strand by strand, through the wrench pass: the residual at q is round-off.
  const std::vector<sh::RodModel> rest = sh::bundle_rest_models(b.strands, b.contacts, result);
  for (std::size_t s = 0; s < rest.size(); ++s) {
    const double scale = (sh::generalised_stiffness(rest[s]).cwiseProduct(b.q[s])).lpNorm<Eigen::Infinity>();
    EXPECT_LE(sh::static_residual(rest[s], b.q[s]).lpNorm<Eigen::Infinity>(), 64 * kEpsilon * scale) << "strand " << s;
  }
  // A reaction of the wrong sign on the strand below: strand 0 is no longer held.
  std::vector<sh::RodModel> wrong = rest;
  for (std::size_t c = 0; c < b.contacts.size(); ++c) {
    const auto& contact = b.contacts[c];
    if (contact.other_strand == sh::kObstacle || contact.other_strand == contact.strand) continue;
    wrong[contact.other_strand].point_forces[contact.other_point] +=
        2.0 * result.frames[c] * result.local_forces.segment<3>(Eigen::Index(3 * c));
  }
  const double scale = (sh::generalised_stiffness(rest[0]).cwiseProduct(b.q[0])).lpNorm<Eigen::Infinity>();
  EXPECT_GT(sh::static_residual(wrong[0], b.q[0]).lpNorm<Eigen::Infinity>(), 1e6 * kEpsilon * scale);
}

TEST(SuperHelixInverseBundle, RefusesWhatItCannotDo) {
  const Bundle b = bundle();
  const auto with = [&](auto change) {
    Bundle copy = b;
    sh::InverseBundleOptions o;
    change(copy, o);
    try {
      sh::inverse_statics_of_bundle(copy.strands, copy.q, copy.contacts, o);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  using O = sh::InverseBundleOptions;
  EXPECT_EQ(with([](Bundle&, O&) {}), "none");
  EXPECT_EQ(with([](Bundle& c, O&) { c.q.pop_back(); }), "q");
  EXPECT_EQ(with([](Bundle& c, O&) { c.q[1] = VecX::Zero(4); }), "q");
  EXPECT_EQ(with([](Bundle& c, O&) { c.strands[2].length = -1.0; }), "length");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[0].strand = 3; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[0].point = 10; }), "contacts");  // strand 0: 5 x 2 points
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[5].other_strand = 5; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[5].other_point = 100; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts.back().other_point = c.contacts.back().point; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[1].normal *= 1.01; }), "contacts");
  // between strands, the normal must be the direction between the two points
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[5].normal = Vec3(0.0, 0.6, 0.8); }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[5].normal = -c.contacts[5].normal; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.strands[1].root_position = c.strands[0].root_position; }), "contacts");
  EXPECT_EQ(with([](Bundle& c, O&) { c.contacts[1].mu = 0.0; }), "mu");
  EXPECT_EQ(with([](Bundle&, O& o) { o.gamma = 0.0; }), "gamma");
  // bundle_rest_models takes only this bundle's result
  const auto result = sh::inverse_statics_of_bundle(b.strands, b.q, b.contacts);
  std::vector<sh::BundleContact> fewer(b.contacts.begin(), b.contacts.end() - 1);
  EXPECT_THROW(sh::bundle_rest_models(b.strands, fewer, result), rodvv::InputError);
}

}  // namespace

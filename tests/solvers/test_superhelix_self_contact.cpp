// Self-contact of the Super-Helix on its helical arcs (solvers/superhelix/self_contact.hpp), against
// oracles that share none of its search: the closed-form distance between consecutive turns of a
// circular helix (a 1-D minimisation in the turn offset), a dense sampling of every element pair
// (nothing missed, nothing closer than what the narrow phase returns), the all-pairs search (the
// broad phase loses no pair), and central differences of the barrier energy (the generalised force).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

constexpr double kLength = 1.3;

sh::RodModel rod(std::size_t elements) {
  sh::RodModel model;
  model.length = kLength;
  model.elements = elements;
  model.root_position = Vec3(0.2, -0.1, 0.4);
  model.root_frame = Eigen::AngleAxisd(0.7, Vec3(1, 2, -1).normalized()).toRotationMatrix();
  return model;
}

// A uniform Super-Helix q = (tau, kappa1, kappa2) is a circular helix of curvature |(kappa1, kappa2)|
// and torsion tau: radius a = kappa / |q|^2, axial advance b = tau / |q|^2 per radian about the axis,
// |q| radians per unit arclength. 2.5 turns of pitch 2 pi b = 0.05 on L = 1.3.
struct TightHelix {
  double omega = 2.5 * 2.0 * std::numbers::pi / kLength;
  double b = 0.05 / (2.0 * std::numbers::pi);
  double tau = b * omega * omega;
  double kappa = std::sqrt(omega * omega - tau * tau);
  double a = kappa / (omega * omega);
  VecX q(std::size_t elements) const {
    VecX strains(3 * elements);
    for (std::size_t e = 0; e < elements; ++e) strains.segment<3>(3 * e) = Vec3(tau, kappa * std::cos(0.3), kappa * std::sin(0.3));
    return strains;
  }
  // Distance from a point to the next turn: min over delta of 4 a^2 sin^2(delta/2) + b^2 (2 pi + delta)^2,
  // by Newton on its derivative 2 a^2 sin(delta) + 2 b^2 (2 pi + delta) from delta = 0.
  double turn_offset() const {
    double delta = 0.0;
    for (int i = 0; i < 50; ++i)
      delta -= (a * a * std::sin(delta) + b * b * (2 * std::numbers::pi + delta)) / (a * a * std::cos(delta) + b * b);
    return delta;
  }
  double turn_distance() const {
    const double delta = turn_offset();
    return std::sqrt(4 * a * a * std::pow(std::sin(delta / 2), 2) + b * b * std::pow(2 * std::numbers::pi + delta, 2));
  }
};

// Strains that fold a rod onto itself in 3-D with varying curvature and twist.
VecX tangled(std::size_t elements, double phase) {
  VecX q(3 * elements);
  for (std::size_t e = 0; e < elements; ++e) {
    const double s = (static_cast<double>(e) + 0.5) / static_cast<double>(elements);
    q.segment<3>(3 * e) = Vec3(2.0 * std::sin(3 * s + phase), 14.0 + 4.0 * std::cos(5 * s + phase), 3.0 * std::sin(7 * s - phase));
  }
  return q;
}

// Dense sampling oracle: for every pair of elements more than m apart, the smallest distance between
// 41 x 41 points of the two arcs.
double sampled_distance(const sh::Kinematics& kinematics, std::size_t P, std::size_t Q, int samples = 41) {
  const double ell = kinematics.element_length();
  std::vector<Vec3> a(samples), b(samples);
  for (int i = 0; i < samples; ++i) {
    a[i] = kinematics.position(P, ell * i / (samples - 1));
    b[i] = kinematics.position(Q, ell * i / (samples - 1));
  }
  double best = INFINITY;
  for (const auto& x : a)
    for (const auto& y : b) best = std::min(best, (x - y).norm());
  return best;
}

TEST(SuperHelixSelfContact, ConsecutiveTurnsOfAHelixAreAtTheClosedFormDistance) {
  const TightHelix helix;
  const std::size_t n = 24;
  const sh::Kinematics kinematics(rod(n), helix.q(n));
  const sh::SelfContact contact{0.03, 2.0e4};  // 2h = 0.06 > the turn distance 0.0496
  const double d_turn = helix.turn_distance();
  ASSERT_LT(d_turn, 2 * contact.radius);
  const auto contacts = sh::self_contacts(kinematics, contact);
  ASSERT_FALSE(contacts.empty());
  // Every point of the helix is d_turn from the next turn, which lies (2 pi + delta) / |q| further on.
  const double ell = kinematics.element_length(), shift = (2 * std::numbers::pi + helix.turn_offset()) / helix.omega;
  std::vector<double> nearest(n, INFINITY);
  for (const auto& pair : contacts) {
    EXPECT_GE(pair.distance, d_turn * (1 - 64 * kEpsilon)) << pair.first << " " << pair.second;
    EXPECT_NEAR(pair.distance, (pair.p - pair.q).norm(), 16 * kEpsilon);
    EXPECT_NEAR(pair.force, contact.stiffness * std::pow(2 * contact.radius - pair.distance, 2), 1e-12 * pair.force);
    nearest[pair.first] = std::min(nearest[pair.first], pair.distance);
  }
  std::size_t checked = 0;
  for (std::size_t e = 0; e < n; ++e) {
    if (static_cast<double>(e + 1) * ell + shift > kLength) continue;  // its partner leaves the rod
    // The partner's arc is reached at an interior point of the pair: the minimum is the helix's.
    EXPECT_NEAR(nearest[e], d_turn, 1e-11 * d_turn) << "element " << e;
    ++checked;
  }
  EXPECT_GE(checked, 10u);
}

TEST(SuperHelixSelfContact, NothingMissedAndNothingCloserThanDenseSamplingOfTangledRods) {
  for (const double phase : {0.0, 0.9, 2.1}) {
    const std::size_t n = 30;
    const sh::Kinematics kinematics(rod(n), tangled(n, phase));
    const sh::SelfContact contact{0.02, 1.0e3};
    const auto contacts = sh::self_contacts(kinematics, contact);
    const std::size_t m = sh::contact_excluded_elements(contact.radius, kinematics.element_length());
    // A grid of spacing ell / 40 on each arc has a point within ell / 80 (arclength) of each closest
    // point: its minimum exceeds the true distance by at most ell / 40.
    const double sampling = 2.0 * kinematics.element_length() / 40.0;
    std::size_t in_contact = 0;
    for (std::size_t P = 0; P < n; ++P)
      for (std::size_t Q = P + m + 1; Q < n; ++Q) {
        const double sampled = sampled_distance(kinematics, P, Q);
        const sh::ArcContact* found = nullptr;
        for (const auto& pair : contacts)
          if (pair.first == P && pair.second == Q) found = &pair;
        if (found) {
          ++in_contact;
          EXPECT_LE(found->distance, sampled * (1 + 1e-12)) << phase << ": " << P << " " << Q;
          EXPECT_LT(found->distance, 2 * contact.radius);
        } else {
          EXPECT_GE(sampled, 2 * contact.radius) << "missed " << P << " " << Q << " phase " << phase;
        }
        if (sampled < 2 * contact.radius - sampling) {
          EXPECT_TRUE(found) << P << " " << Q;
        }
      }
    EXPECT_GE(in_contact, 3u) << "phase " << phase << ": the configuration must touch itself";
  }
}

TEST(SuperHelixSelfContact, BroadPhaseFindsExactlyTheAllPairsContacts) {
  for (const double phase : {0.0, 0.9, 2.1}) {
    const std::size_t n = 40;
    const sh::Kinematics kinematics(rod(n), tangled(n, phase));
    const sh::SelfContact contact{0.025, 1.0e3};
    const auto fast = sh::self_contacts(kinematics, contact), all = sh::self_contacts_all_pairs(kinematics, contact);
    ASSERT_EQ(fast.size(), all.size()) << phase;
    ASSERT_FALSE(fast.empty());
    for (std::size_t i = 0; i < fast.size(); ++i) {
      EXPECT_EQ(fast[i].first, all[i].first);
      EXPECT_EQ(fast[i].second, all[i].second);
      EXPECT_EQ(fast[i].distance, all[i].distance);  // the same start, the same Newton: identical
    }
  }
  const TightHelix helix;
  const sh::Kinematics kinematics(rod(24), helix.q(24));
  EXPECT_EQ(sh::self_contacts(kinematics, {0.03, 1.0}).size(), sh::self_contacts_all_pairs(kinematics, {0.03, 1.0}).size());
}

TEST(SuperHelixSelfContact, GeneralizedForceIsMinusTheEnergyGradient) {
  const std::size_t n = 20;
  const sh::RodModel model = rod(n);
  const sh::SelfContact contact{0.02, 3.0e3};
  const VecX q = tangled(n, 0.9);
  auto energy = [&](const VecX& at) {
    const sh::Kinematics k(model, at);
    return sh::self_contact_energy(contact, sh::self_contacts(k, contact));
  };
  const sh::Kinematics kinematics(model, q);
  const auto contacts = sh::self_contacts(kinematics, contact);
  ASSERT_GE(contacts.size(), 2u);
  const VecX force = sh::self_contact_generalized_force(kinematics, contacts);
  // Central differences, step 1e-6 in strains of size ~10: truncation h^2 |E'''| / 6 and rounding
  // eps |E| / h, both ~1e-10 |E'| here; gate 1e-6 of the largest component.
  const double h = 1e-6;
  VecX difference(q.size());
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    VecX plus = q, minus = q;
    plus(j) += h;
    minus(j) -= h;
    difference(j) = -(energy(plus) - energy(minus)) / (2 * h);
  }
  EXPECT_LE((force - difference).cwiseAbs().maxCoeff(), 1e-6 * force.cwiseAbs().maxCoeff());
  // The sign: a normal flipped in the force turns it into +gradient.
  EXPECT_GT((force + difference).cwiseAbs().maxCoeff(), 0.5 * force.cwiseAbs().maxCoeff());
}

TEST(SuperHelixSelfContact, HessianMatchesCentralDifferencesOfTheGeneralizedForce) {
  for (const double phase : {0.9, 2.1}) {
    const std::size_t n = 16;
    const sh::RodModel model = rod(n);
    const sh::SelfContact contact{0.02, 3.0e3};
    const VecX q = tangled(n, phase);
    const sh::Kinematics kinematics(model, q);
    const auto contacts = sh::self_contacts(kinematics, contact);
    ASSERT_GE(contacts.size(), 1u) << phase;
    const rodvv::MatX hessian = sh::self_contact_hessian(kinematics, contact, contacts);
    // -dQ/dq by central differences of Q with the contacts re-found at q +- h (step 1e-6: truncation
    // and rounding both ~1e-10 of the largest entry; gate 1e-6 of it).
    const double h = 1e-6;
    rodvv::MatX difference(q.size(), q.size());
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      VecX plus = q, minus = q;
      plus(j) += h;
      minus(j) -= h;
      const sh::Kinematics kp(model, plus), km(model, minus);
      difference.col(j) = -(sh::self_contact_generalized_force(kp, sh::self_contacts(kp, contact)) -
                            sh::self_contact_generalized_force(km, sh::self_contacts(km, contact))) / (2 * h);
    }
    const double scale = hessian.cwiseAbs().maxCoeff();
    EXPECT_LE((hessian - difference).cwiseAbs().maxCoeff(), 1e-6 * scale) << "phase " << phase;
    EXPECT_LE((hessian - hessian.transpose()).cwiseAbs().maxCoeff(), 1e-9 * scale);
  }
}

// A rod whose rest shape (the tangled strains above) passes through itself at crossings: the statics
// with self-contact separates the crossings to where the barrier balances the bending.
TEST(SuperHelixSelfContact, StaticsSeparatesARestShapeThatCrossesItself) {
  const std::size_t n = 24;
  sh::RodModel model = rod(n);
  model.stiffness = Vec3(0.7, 1.3, 2.1);
  const VecX rest = tangled(n, 0.9);
  for (std::size_t e = 0; e < n; ++e) model.natural_strain_per_element.push_back(rest.segment<3>(3 * static_cast<Eigen::Index>(e)));
  model.self_contact = {0.02, 1.0e5};
  double rest_closest = INFINITY;
  for (const auto& pair : sh::self_contacts(sh::Kinematics(model, rest), model.self_contact))
    rest_closest = std::min(rest_closest, pair.distance);
  const sh::StaticResult result = sh::solve_static(model);
  const sh::Kinematics kinematics(model, result.q);
  const auto contacts = sh::self_contacts(kinematics, model.self_contact);
  ASSERT_FALSE(contacts.empty());
  double closest = INFINITY;
  for (const auto& pair : contacts) closest = std::min(closest, pair.distance);
  EXPECT_GT(closest, 1.4 * rest_closest);  // 0.0210 at rest, 0.0301 at equilibrium (N = 24)
  EXPECT_LT(closest, 2 * model.self_contact.radius);
  // Stationary: the residual at the solver's tolerance, and the exact Jacobian (contact Hessian
  // included) against central differences of the residual at the solution (1e-6 of its largest entry).
  EXPECT_LE(sh::static_residual(model, result.q).cwiseAbs().maxCoeff(), 1e-10);
  const rodvv::MatX jacobian = sh::static_jacobian(model, result.q);
  rodvv::MatX difference(jacobian.rows(), jacobian.cols());
  const double h = 1e-6;
  for (Eigen::Index j = 0; j < result.q.size(); ++j) {
    VecX plus = result.q, minus = result.q;
    plus(j) += h;
    minus(j) -= h;
    difference.col(j) = (sh::static_residual(model, plus) - sh::static_residual(model, minus)) / (2 * h);
  }
  EXPECT_LE((jacobian - difference).cwiseAbs().maxCoeff(), 1e-6 * jacobian.cwiseAbs().maxCoeff());
  // Without contact the same rod stays at its rest shape.
  model.self_contact = {};
  EXPECT_LE((sh::solve_static(model).q - rest).cwiseAbs().maxCoeff(), 0.0);
}

TEST(SuperHelixSelfContact, StraightRodHasNoContactAndBadInputIsNamed) {
  const sh::Kinematics straight(rod(16), VecX::Zero(48));
  EXPECT_TRUE(sh::self_contacts(straight, {0.05, 1.0}).empty());
  EXPECT_TRUE(sh::self_contacts(straight, {0.4, 1.0}).empty());  // thick: m grows with h / ell
  try {
    (void)sh::self_contacts(straight, {0.0, 1.0});
    ADD_FAILURE() << "radius 0 accepted";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "radius");
  }
  try {
    (void)sh::self_contacts(straight, {0.01, -1.0});
    ADD_FAILURE() << "negative stiffness accepted";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "stiffness");
  }
  sh::RodModel model = rod(8);
  model.self_contact = {0.01, 0.0};
  EXPECT_THROW(sh::solve_static(model), rodvv::InputError);  // self_contact.stiffness
  model.self_contact = {0.01, 1.0};
  try {
    (void)sh::total_energy(model, {VecX::Zero(24), VecX::Zero(24)});
    ADD_FAILURE() << "the dynamics' energy ignored the self-contact";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "self_contact");
  }
}

}  // namespace

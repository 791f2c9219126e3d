// Self-contact of the Super-Helix on its helical arcs (solvers/superhelix/self_contact.hpp), against
// oracles that share none of its search: the closed-form distance between consecutive turns of a
// circular helix (a 1-D minimisation in the turn offset), a dense sampling of every element pair
// (nothing missed, nothing closer than what the narrow phase returns), the all-pairs search (the
// broad phase loses no pair), and central differences of the barrier energy (the generalised force).
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <numbers>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/model.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "rodvv/testing/tolerance.hpp"
#include "superhelix_contact_fixtures.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;
using namespace superhelix_contact_fixtures;

// Dense sampling oracle: the smallest distance from a point to 41 points of an element's arc.
double sampled_distance(const sh::Kinematics& kinematics, const Vec3& point, std::size_t element, int samples = 41) {
  double best = INFINITY;
  for (int i = 0; i < samples; ++i)
    best = std::min(best, (point - kinematics.position(element, kinematics.element_length() * i / (samples - 1))).norm());
  return best;
}

TEST(SuperHelixSelfContact, PointsOfAHelixTouchTheNeighbouringTurnsAtTheClosedFormDistance) {
  const TightHelix helix;
  const std::size_t n = 24;
  const sh::Kinematics kinematics(rod(n), helix.q(n));
  const sh::SelfContact contact{0.03, 2.0e4};  // 2h = 0.06 > the turn distance 0.0498; two turns 0.1 apart
  const double d_turn = helix.turn_distance();
  ASSERT_LT(d_turn, 2 * contact.radius);
  const auto contacts = sh::self_contacts(kinematics, contact);
  ASSERT_FALSE(contacts.empty());
  // Every point of the helix is d_turn from the next turn and from the previous one, whose feet lie
  // (2 pi + delta) / |q| further on and back: each Gauss point with both inside the rod touches twice
  // there. Where the partner lies beyond an end of the rod, the foot is that end (a constrained
  // minimum), farther than d_turn.
  const double ell = kinematics.element_length(), shift = (2 * std::numbers::pi + helix.turn_offset()) / helix.omega;
  std::map<std::pair<std::size_t, double>, int> touches;
  double weights = 0.0;
  std::size_t at_ends = 0;
  for (const auto& pair : contacts) {
    EXPECT_NEAR(pair.distance, (pair.p - pair.q).norm(), 16 * kEpsilon);
    EXPECT_NEAR(pair.force, pair.weight * contact.stiffness * std::pow(2 * contact.radius - pair.distance, 2),
                1e-12 * pair.force);
    const double s = static_cast<double>(pair.first) * ell + pair.s;
    const double foot = static_cast<double>(pair.second) * ell + pair.t;
    if (foot == 0.0 || foot == kLength) {
      EXPECT_GT(pair.distance, d_turn) << "an end foot";
      EXPECT_LT(std::abs(foot - s), shift);
      ++at_ends;
      continue;
    }
    EXPECT_NEAR(pair.distance, d_turn, 1e-11 * d_turn) << pair.first << " " << pair.s << " -> " << pair.second;
    EXPECT_NEAR(std::abs(foot - s), shift, 1e-9) << "the foot is on the neighbouring turn";
    ++touches[{pair.first, pair.s}];
    weights += pair.weight;
  }
  EXPECT_GE(at_ends, 2u);
  std::size_t both = 0;
  for (const auto& gauss : kinematics.points()) {
    const double s = static_cast<double>(gauss.element) * ell + gauss.sigma;
    const int expected = (s + shift < kLength ? 1 : 0) + (s - shift > 0.0 ? 1 : 0);
    const auto found = touches.find({gauss.element, gauss.sigma});
    EXPECT_EQ(found == touches.end() ? 0 : found->second, expected) << s;
    both += expected == 2 ? 1 : 0;
  }
  EXPECT_GE(both, 20u);
  // Half a weight per side: the interior contacts' weights add up to the length in contact, L - shift
  // counted from each side, to the quadrature's error at the ends of the contact region (one element).
  EXPECT_NEAR(weights, kLength - shift, ell);
}

TEST(SuperHelixSelfContact, NothingMissedAndNothingCloserThanDenseSamplingOfTangledRods) {
  for (const double phase : {0.0, 0.9, 2.1}) {
    const std::size_t n = 30;
    const sh::Kinematics kinematics(rod(n), tangled(n, phase));
    const sh::SelfContact contact{0.02, 1.0e3};
    const auto contacts = sh::self_contacts(kinematics, contact);
    const std::size_t m = sh::contact_excluded_elements(contact.radius, kinematics.element_length());
    // 41 samples per arc: one within ell / 80 of any foot, so the sampled minimum exceeds the true
    // distance by at most ell / 80.
    const double sampling = kinematics.element_length() / 80.0;
    std::size_t touching = 0;
    for (const auto& gauss : kinematics.points()) {
      double nearest = INFINITY;
      for (std::size_t Q = 0; Q < n; ++Q)
        if (Q + m < gauss.element || Q > gauss.element + m)
          nearest = std::min(nearest, sampled_distance(kinematics, gauss.position, Q));
      double found = INFINITY;
      for (const auto& pair : contacts)
        if (pair.first == gauss.element && pair.s == gauss.sigma) {
          found = std::min(found, pair.distance);
          EXPECT_GE(pair.distance, nearest - sampling) << "closer than the curve";
          EXPECT_LT(pair.distance, 2 * contact.radius);
        }
      if (nearest < 2 * contact.radius - sampling) {
        EXPECT_LE(found, nearest * (1 + 1e-12)) << "missed: element " << gauss.element << " phase " << phase;
        ++touching;
      }
    }
    EXPECT_GE(touching, 6u) << "phase " << phase << ": the configuration must touch itself";
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
      EXPECT_EQ(fast[i].s, all[i].s);
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
  model.self_contact = {0.02, 1.0e7};
  double rest_closest = INFINITY;
  for (const auto& pair : sh::self_contacts(sh::Kinematics(model, rest), model.self_contact))
    rest_closest = std::min(rest_closest, pair.distance);
  const sh::StaticResult result = sh::solve_static(model);
  const sh::Kinematics kinematics(model, result.q);
  const auto contacts = sh::self_contacts(kinematics, model.self_contact);
  ASSERT_FALSE(contacts.empty());
  double closest = INFINITY;
  for (const auto& pair : contacts) closest = std::min(closest, pair.distance);
  EXPECT_GT(closest, 1.4 * rest_closest);  // 0.0193 at rest, 0.0348 at equilibrium (N = 24)
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
  // Out of iterations: a SolverError naming the method, its iterations and the residual.
  sh::StaticOptions two;
  two.max_iterations = 2;
  try {
    (void)sh::solve_static(model, two);
    ADD_FAILURE() << "two iterations converged";
  } catch (const rodvv::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("superhelix potential Newton"), std::string::npos) << e.what();
    EXPECT_EQ(e.iterations(), 2u);
    EXPECT_GT(e.residual(), 0.0);
  }
  // Without contact the same rod stays at its rest shape.
  model.self_contact = {};
  EXPECT_LE((sh::solve_static(model).q - rest).cwiseAbs().maxCoeff(), 0.0);
}

// A coil spring whose rest pitch (0.05) is below the contact distance 2h = 0.06: line contacts between
// its turns, which the potential Newton resolves as quadratically as the crossings above; the turns
// end up within the barrier's overlap of 2h.
TEST(SuperHelixSelfContact, StaticsPushesTheTurnsOfAnOverlappingSpringApart) {
  const TightHelix helix;
  for (const std::size_t n : {24, 48}) {
    sh::RodModel model = rod(n);
    model.stiffness = Vec3(0.7, 1.3, 2.1);
    model.natural_strain = helix.q(1);
    model.self_contact = {0.03, 1.0e7};
    const sh::StaticResult result = sh::solve_static(model);
    EXPECT_LE(result.iterations, 20u);
    double closest = INFINITY;
    for (const auto& pair : sh::self_contacts(sh::Kinematics(model, result.q), model.self_contact))
      closest = std::min(closest, pair.distance);
    EXPECT_GT(closest, 0.055) << n;  // the rest shape's 0.0498, pushed towards 2h = 0.06
    EXPECT_LT(closest, 0.06) << n;
    EXPECT_LT(sh::static_potential(model, result.q), sh::static_potential(model, helix.q(n)));
  }
}

// The spring at equilibrium: uniform natural strain, no loads, frictionless line contacts between its
// turns, so H (PHYSICS.md §1.2) is one constant along the whole rod, through the contacts, when the
// solution struct carries the contact forces in n(s) and the field V_eff = 1/2 sum psi(d) in V.
// Measured spread over the stations / max |m| |u|: 5.3e-3, 6.7e-4, 9.0e-5 at N = 24, 48, 96 (order
// 2.97, 2.90); with the full field (the nodal rod's pair-potential form) 2.9e-3 at N = 96, and it
// stalls there (as without the field).
TEST(SuperHelixSelfContact, NoetherQuantityIsConstantThroughTheSpringsLineContacts) {
  const TightHelix helix;
  std::vector<double> spreads;
  for (const std::size_t n : {24, 48, 96}) {
    sh::RodModel model = rod(n);
    model.stiffness = Vec3(0.7, 1.3, 2.1);
    model.natural_strain = helix.q(1);
    model.self_contact = {0.03, 1.0e7};
    const rodvv::SpatialRodSolution solution = sh::make_solution(model, sh::solve_static(model).q);
    const std::vector<double> compact = rodvv::invariants::noether3d_compact(solution);
    const std::vector<double> flattened = rodvv::invariants::noether3d_flattened(solution);
    // The size of the terms H is made of: |m| |u| (the moment's work on the strain).
    double scale = 0.0;
    for (std::size_t i = 0; i < compact.size(); ++i)
      scale = std::max(scale, solution.moment_m[i].norm() * solution.strain_u[i].norm());
    double lo = INFINITY, hi = -INFINITY, lo_full = INFINITY, hi_full = -INFINITY;
    for (std::size_t i = 0; i < compact.size(); ++i) {
      lo = std::min(lo, compact[i]);
      hi = std::max(hi, compact[i]);
      const double full = compact[i] - solution.potential[i];  // V_eff doubled (no gravity: V = V_eff)
      lo_full = std::min(lo_full, full);
      hi_full = std::max(hi_full, full);
      EXPECT_NEAR(compact[i], flattened[i], 1e-12 * scale);
    }
    spreads.push_back((hi - lo) / scale);
    if (n == 96) {
      EXPECT_LT(spreads.back(), 1.8e-4);  // measured 9.0e-5, x 2
      EXPECT_GT((hi_full - lo_full) / scale, 10.0 * spreads.back()) << "the field's factor 1/2 is what H needs";
    }
  }
  EXPECT_LT(spreads[1], 0.25 * spreads[0]);  // at least second order between the levels
  EXPECT_LT(spreads[2], 0.25 * spreads[1]);
}

// The potential's gradient is the residual (central differences; gravity, an end force and contact).
TEST(SuperHelixSelfContact, StaticPotentialGradientIsTheResidual) {
  const std::size_t n = 12;
  sh::RodModel model = rod(n);
  model.stiffness = Vec3(0.7, 1.3, 2.1);
  model.gravity = Vec3(0.3, -9.0, 1.0);
  model.line_density = 0.02;
  model.end_force = Vec3(0.05, 0.1, -0.2);
  model.self_contact = {0.02, 1.0e6};
  const VecX q = tangled(n, 0.9);
  ASSERT_FALSE(sh::self_contacts(sh::Kinematics(model, q), model.self_contact).empty());
  const VecX residual = sh::static_residual(model, q, 0.7);
  VecX difference(q.size());
  const double h = 1e-6;
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    VecX plus = q, minus = q;
    plus(j) += h;
    minus(j) -= h;
    difference(j) = (sh::static_potential(model, plus, 0.7) - sh::static_potential(model, minus, 0.7)) / (2 * h);
  }
  EXPECT_LE((residual - difference).cwiseAbs().maxCoeff(), 1e-6 * residual.cwiseAbs().maxCoeff());
  model.end_moment = Vec3(0.0, 0.1, 0.0);
  EXPECT_THROW((void)sh::static_potential(model, q), rodvv::InputError);
  EXPECT_THROW((void)sh::solve_static(model), rodvv::InputError);  // no potential to minimise
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

// Hard self-contact of the Super-Helix (solvers/superhelix/hard_self_contact.hpp): d >= 2h at the Gauss
// points by complementarity inside Newton. Oracles that share none of its steps: the equilibrium
// r(q) = sum lambda_c dd_c/dq with the gradients taken by central differences of each contact's distance
// (the foot found again at every perturbed q), the barrier statics (another solver: Newton on a potential)
// whose solutions approach the hard one as the barrier stiffens, and the Noether quantity H (constant
// through frictionless contact).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/superhelix/arc_pair_contact.hpp"
#include "rodvv/solvers/superhelix/hard_self_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "superhelix_contact_fixtures.hpp"

namespace {

using namespace superhelix_contact_fixtures;
using rodvv::MatX;

constexpr double kTolerance = 1e-11;  // the hard statics' equilibrium measure in these tests

sh::RodModel hard(sh::RodModel model, double radius) {
  model.self_contact = {radius, 0.0, sh::ContactLaw::Hard};
  return model;
}

// The spring of the barrier tests (rest pitch 0.05) with hard contact of radius 0.03 (2h = 0.06).
sh::RodModel hard_spring(std::size_t n) {
  const TightHelix helix;
  sh::RodModel model = rod(n);
  model.stiffness = Vec3(0.7, 1.3, 2.1);
  model.natural_strain = helix.q(1);
  return hard(model, 0.03);
}

// The tangled rest shape of the barrier tests, crossing itself, with hard contact of radius 0.02.
sh::RodModel hard_tangle(std::size_t n) {
  sh::RodModel model = rod(n);
  model.stiffness = Vec3(0.7, 1.3, 2.1);
  const VecX rest = tangled(n, 0.9);
  for (std::size_t e = 0; e < n; ++e)
    model.natural_strain_per_element.push_back(rest.segment<3>(3 * static_cast<Eigen::Index>(e)));
  return hard(model, 0.02);
}

// From `start` (empty: the rest shape).
sh::HardContactStatics solve(const sh::RodModel& model, const VecX& start = {}) {
  sh::StaticOptions options;
  options.tolerance = kTolerance;
  options.max_iterations = 400;
  options.initial_q = start;
  return sh::solve_static_with_hard_contact(model, options);
}

// The tangle's rest shape passes through itself (closest 0.0193 < h): the hard statics starts from the
// barrier's equilibrium (closest 0.0348).
sh::HardContactStatics solve_tangle(const sh::RodModel& model) {
  sh::RodModel barrier = model;
  barrier.self_contact = {model.self_contact.radius, 1.0e7};
  return solve(model, sh::solve_static(barrier).q);
}

// The distance between a contact's two points (first, s) and (second, t) at q, s and t held: by the
// envelope theorem its gradient at the solution is that of the closest points' distance, with no search.
double contact_distance(const sh::RodModel& model, const VecX& q, const sh::ArcContact& c) {
  const sh::Kinematics kinematics(model, q);
  return (kinematics.position(c.first, c.s) - kinematics.position(c.second, c.t)).norm();
}

// r(q) - sum lambda_c dd_c/dq with the gradients by central differences (step 1e-6).
VecX unbalanced_by_differences(const sh::RodModel& model, const sh::HardContactStatics& result) {
  const VecX& q = result.statics.q;
  VecX unbalanced = sh::static_residual(model, q);
  const double step = 1e-6;
  for (const auto& c : result.contacts) {
    if (c.force == 0.0) continue;
    for (Eigen::Index j = 0; j < q.size(); ++j) {
      VecX plus = q, minus = q;
      plus(j) += step;
      minus(j) -= step;
      unbalanced(j) -= c.force * (contact_distance(model, plus, c) - contact_distance(model, minus, c)) / (2 * step);
    }
  }
  return unbalanced;
}

// A spring coiled tighter than its thickness allows: the hard contact holds its turns at exactly 2h.
TEST(SuperHelixHardSelfContact, HoldsTheTurnsOfAnOverlappingSpringAtTheContactDistance) {
  for (const std::size_t n : {24, 48}) {
    const sh::RodModel model = hard_spring(n);
    const sh::HardContactStatics result = solve(model);
    EXPECT_LE(result.statics.residual, kTolerance) << n;
    std::size_t loaded = 0;
    for (const auto& c : result.contacts) {
      EXPECT_GE(c.force, 0.0);
      // No overlap beyond the tolerance (gaps measured against L), and a force only where the gap closes.
      EXPECT_GE(c.distance - 0.06, -kTolerance * kLength) << c.first << " " << c.s;
      if (c.force > 0.0) {
        ++loaded;
        EXPECT_NEAR(c.distance, 0.06, kTolerance * kLength) << c.first << " " << c.s;
      }
    }
    // Measured: 4 closest-point pairs carry the spring's turns apart at N = 24 and 48: a hard contact holds
    // the coil at points, with the turns free between them.
    EXPECT_GE(loaded, 2u) << n;
    // The equilibrium with the gradients of the distances by differences: 1e-7 of the residual's scale
    // (the differences' truncation, h^2 |d'''| ~ 1e-12 relative, times the forces).
    const VecX unbalanced = unbalanced_by_differences(model, result);
    const double scale = sh::static_residual(model, result.statics.q).cwiseAbs().maxCoeff();
    EXPECT_LE(unbalanced.cwiseAbs().maxCoeff(), 1e-7 * scale) << n;
  }
}

// H is one constant along the spring, through its hard line contacts, when the solution struct carries
// the multipliers in n(s) (no field: the hard law has no energy). The forces act at closest points, normal
// to both tangents, so only the midpoint stations' O(h^2) is left: measured spread / max |m| |u| 4.95e-3,
// 1.93e-3, 4.85e-4 at N = 12, 24, 48 (order 1.36, 1.99; 1.26e-4 at N = 96, but 3 minutes there: ~1000
// candidate pairs within the reach 3h of the coil's turns go into every LCP). With the forces at the
// barrier's Gauss points and feet instead (tried first), 2.0e-3, 3.1e-3, 7.4e-3 at N = 24, 48, 96: each
// force's component along its own rod's tangent makes H jump, and those jumps grow as the forces
// concentrate.
TEST(SuperHelixHardSelfContact, NoetherQuantityIsConstantThroughHardContacts) {
  std::vector<double> spreads;
  for (const std::size_t n : {12, 24, 48}) {
    const sh::RodModel model = hard_spring(n);
    const sh::HardContactStatics result = solve(model);
    ASSERT_LE(result.statics.residual, kTolerance);
    const rodvv::SpatialRodSolution solution = sh::make_solution(model, result.statics.q, result.contacts);
    const std::vector<double> compact = rodvv::invariants::noether3d_compact(solution);
    double scale = 0.0, lo = INFINITY, hi = -INFINITY;
    for (std::size_t i = 0; i < compact.size(); ++i) {
      scale = std::max(scale, solution.moment_m[i].norm() * solution.strain_u[i].norm());
      lo = std::min(lo, compact[i]);
      hi = std::max(hi, compact[i]);
    }
    spreads.push_back((hi - lo) / scale);
  }
  EXPECT_LT(spreads[1], 0.5 * spreads[0]);  // order above 1 on the coarse pair (measured 1.36) ...
  EXPECT_LT(spreads[2], 0.3 * spreads[1]);  // ... and above 1.7 on the fine one (measured 1.99)
  EXPECT_LT(spreads[2], 1e-3);              // measured 4.85e-4, x 2
}

// The barrier's equilibria (another solver) approach the hard one as the barrier stiffens: the
// overlap of a line contact carrying p per length is (p / k)^(1/2), of a crossing (F / k)^(2/5)
// (knot/trefoil-barrier-limit's derivation), so each fourfold stiffening cuts the distance by
// 4^-0.4 .. 4^-0.5 = 0.57 .. 0.5 once the active set is the hard one's.
TEST(SuperHelixHardSelfContact, BarrierEquilibriaConvergeToTheHardOne) {
  const std::size_t n = 24;
  const sh::RodModel model = hard_tangle(n);
  const sh::HardContactStatics result = solve_tangle(model);
  ASSERT_FALSE(result.contacts.empty());
  std::vector<double> distances;
  for (const double k : {1e7, 4e7, 1.6e8, 6.4e8}) {
    sh::RodModel barrier = model;
    barrier.self_contact = {0.02, k};
    sh::StaticOptions options;
    options.tolerance = 1e-12;
    options.max_iterations = 400;
    const VecX q = sh::solve_static(barrier, options).q;
    distances.push_back((q - result.statics.q).cwiseAbs().maxCoeff() / result.statics.q.cwiseAbs().maxCoeff());
  }
  // Measured 0.0182, 0.0114, 0.00679, 0.00404: ratios 0.63, 0.60, 0.59, toward the crossings' 0.57. The
  // window is the theory's [0.5, 0.57] widened to the first, pre-asymptotic, ratio; a hard solution off the
  // barrier's limit would leave the ratios at 1.
  for (std::size_t i = 1; i < distances.size(); ++i) {
    EXPECT_LT(distances[i], 0.7 * distances[i - 1]) << i;
    EXPECT_GT(distances[i], 0.45 * distances[i - 1]) << i;
  }
  EXPECT_LT(distances.back(), 0.01);
}

// The hard law's Hessian is the geometric stiffness of the held forces: central differences of the
// generalised force with each contact's force held (matched by its Gauss point and foot element).
TEST(SuperHelixHardSelfContact, HessianIsTheHeldForcesStiffness) {
  const std::size_t n = 24;
  const sh::RodModel model = hard_tangle(n);
  const sh::HardContactStatics result = solve_tangle(model);
  const VecX& q = result.statics.q;
  const auto force_at = [&](const VecX& x) {
    const sh::Kinematics kinematics(model, x);
    auto contacts = sh::closest_arc_pairs(kinematics, model.self_contact, 3.0 * model.self_contact.radius);
    for (auto& c : contacts) {
      c.force = 0.0;
      for (const auto& held : result.contacts)
        if (held.first == c.first && held.second == c.second) c.force = held.force;
    }
    return sh::self_contact_generalized_force(kinematics, contacts);
  };
  const MatX hessian = sh::closest_pair_force_stiffness(sh::Kinematics(model, q), result.contacts);
  MatX difference(q.size(), q.size());
  const double step = 1e-6;
  for (Eigen::Index j = 0; j < q.size(); ++j) {
    VecX plus = q, minus = q;
    plus(j) += step;
    minus(j) -= step;
    difference.col(j) = -(force_at(plus) - force_at(minus)) / (2 * step);  // E's Hessian: minus the force's
  }
  const double scale = hessian.cwiseAbs().maxCoeff();
  ASSERT_GT(scale, 0.0);
  EXPECT_LE((hessian - difference).cwiseAbs().maxCoeff(), 1e-6 * scale);
}

TEST(SuperHelixHardSelfContact, RefusalsNameTheParameter) {
  const auto parameter_of = [](auto&& call) -> std::string {
    try {
      call();
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return "(accepted)";
  };
  sh::RodModel model = hard_spring(12);
  model.self_contact.stiffness = 5.0;  // the hard law has no barrier
  EXPECT_EQ(parameter_of([&] { sh::validate(model); }), "self_contact.stiffness");
  model = hard_spring(12);
  EXPECT_EQ(parameter_of([&] { (void)sh::solve_static(model); }), "self_contact.law");
  EXPECT_EQ(parameter_of([&] { (void)sh::make_solution(model, VecX::Zero(36)); }), "self_contact.law");
  model.end_moment = Vec3(0.0, 0.1, 0.0);
  EXPECT_EQ(parameter_of([&] { (void)sh::solve_static_with_hard_contact(model); }), "end_moment");
  sh::RodModel barrier = rod(12);
  barrier.self_contact = {0.03, 1e4};
  EXPECT_EQ(parameter_of([&] { (void)sh::solve_static_with_hard_contact(barrier); }), "self_contact.law");
  EXPECT_EQ(parameter_of([&] { (void)sh::make_solution(barrier, VecX::Zero(36), std::vector<sh::ArcContact>{}); }), "self_contact.law");
  const sh::Kinematics straight(rod(12), VecX::Zero(36));
  EXPECT_EQ(parameter_of([&] { (void)sh::contact_element_pairs(straight, {0.03, 1.0}, 0.05); }), "reach");
  // Out of iterations: a SolverError naming the method, its iterations and the measure.
  sh::StaticOptions two;
  two.max_iterations = 2;
  try {
    (void)sh::solve_static_with_hard_contact(hard_spring(24), two);
    ADD_FAILURE() << "two iterations converged";
  } catch (const rodvv::SolverError& e) {
    EXPECT_NE(std::string(e.what()).find("Newton-LCP"), std::string::npos) << e.what();
    EXPECT_EQ(e.iterations(), 2u);
    EXPECT_GT(e.residual(), 0.0);
  }
}

}  // namespace

// The nodal rod's self-contact barrier (solvers/rod3d/self_contact.hpp): exact gradient and Hessian
// against finite differences in every active set of the closest points, force and moment balance,
// and the pairs it reports.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <iostream>
#include <random>
#include <string>
#include <vector>

#include <numbers>

#include <Eigen/Geometry>
#include <Eigen/SparseCore>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/rod3d/model.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"

namespace {

using rodvv::Vec3;
namespace rod = rodvv::solvers::rod3d;

// A polyline that comes back on itself: along x, a half turn of radius 0.06 in the (x, y) plane,
// back along -x at height z_offset, so segments of the two strands face each other at a distance
// of about 2 x 0.06 (crossing at an angle when `skew` != 0). Edge length ~0.05.
std::vector<Vec3> hairpin(double skew, double z_offset) {
  std::vector<Vec3> x;
  for (int i = 0; i <= 20; ++i) x.push_back(Vec3(0.05 * i, 0.0, 0.0));
  for (int i = 1; i < 8; ++i) {
    const double a = 3.14159265358979 * i / 8;
    x.push_back(Vec3(1.0 + 0.06 * std::sin(a), 0.06 * (1 - std::cos(a)), 0.0));
  }
  for (int i = 0; i <= 20; ++i) x.push_back(Vec3(1.0 - 0.05 * i, 0.12 + skew * 0.05 * i, z_offset));
  return x;
}

const rod::SelfContact kContact{0.065, 3.0e4};  // 2h = 0.13 > the strands' 0.12 separation
constexpr double kEdge = 0.05;

double energy_at(const std::vector<Vec3>& x) { return rod::self_contact_energy(kContact, x, kEdge); }

// The parameter a model's validation names, or "none".
std::string parameter_of(const rod::RodModel& m) {
  try {
    rod::validate(m);
  } catch (const rodvv::InputError& e) {
    return e.parameter();
  }
  return "none";
}

TEST(Rod3dSelfContact, GradientAndHessianMatchFiniteDifferences) {
  std::mt19937 rng(3);
  std::normal_distribution<double> g(0.0, 1.0);
  int checked = 0;
  for (double skew : {0.0, 0.03, -0.05}) {
    for (double z : {0.0, 0.02}) {
      std::vector<Vec3> x = hairpin(skew, z);
      for (auto& p : x) p += 2e-3 * Vec3(g(rng), g(rng), g(rng));  // generic: all active sets occur
      const auto pairs = rod::self_contacts(kContact, x, kEdge);
      ASSERT_FALSE(pairs.empty());
      std::vector<Vec3> gradient;
      std::vector<Eigen::Triplet<double>> triplets;
      rod::self_contact_derivatives(kContact, x, kEdge, gradient, &triplets);
      // Without the Hessian the gradient comes from the envelope theorem, not the jets: the same to round-off.
      std::vector<Vec3> envelope_gradient;
      rod::self_contact_derivatives(kContact, x, kEdge, envelope_gradient, nullptr);
      double gradient_scale = 0.0, paths_differ = 0.0;
      for (std::size_t i = 0; i < x.size(); ++i) {
        gradient_scale = std::max(gradient_scale, gradient[i].norm());
        paths_differ = std::max(paths_differ, (gradient[i] - envelope_gradient[i]).norm());
      }
      EXPECT_LE(paths_differ, 64 * std::numeric_limits<double>::epsilon() * gradient_scale) << skew << " " << z;
      const int n = int(3 * x.size());
      Eigen::SparseMatrix<double> H(n, n);
      H.setFromTriplets(triplets.begin(), triplets.end());
      // Central differences with step 1e-7: truncation h^2 |d^3 E| and round-off eps |E| / h are both
      // ~1e-9 relative to the largest entry here (measured <= 3.3e-10). A step of 1e-6 crosses an
      // active-set boundary of one pair (a closest point reaching a segment end, where d is only C^1)
      // in one configuration: Hessian error 4e-3 there. Bound 1e-7 relative: 300 x the measured.
      const double step = 1e-7;
      double g_scale = 0.0, h_scale = 0.0, g_error = 0.0, h_error = 0.0;
      for (int a = 0; a < n; ++a) {
        std::vector<Vec3> plus = x, minus = x;
        plus[a / 3][a % 3] += step;
        minus[a / 3][a % 3] -= step;
        const double fd = (energy_at(plus) - energy_at(minus)) / (2 * step);
        g_scale = std::max(g_scale, std::abs(gradient[a / 3][a % 3]));
        g_error = std::max(g_error, std::abs(fd - gradient[a / 3][a % 3]));
        std::vector<Vec3> gp, gm;
        rod::self_contact_derivatives(kContact, plus, kEdge, gp, nullptr);
        rod::self_contact_derivatives(kContact, minus, kEdge, gm, nullptr);
        for (int b = 0; b < n; ++b) {
          const double fd_h = (gp[b / 3][b % 3] - gm[b / 3][b % 3]) / (2 * step);
          h_scale = std::max(h_scale, std::abs(H.coeff(b, a)));
          h_error = std::max(h_error, std::abs(fd_h - H.coeff(b, a)));
        }
      }
      EXPECT_LE(g_error, 1e-7 * g_scale) << skew << " " << z;
      EXPECT_LE(h_error, 1e-7 * h_scale) << skew << " " << z;
      std::cout << "[ summary  ] skew " << skew << " z " << z << " pairs " << pairs.size() << " g " << g_error / g_scale << " h " << h_error / h_scale << "\n";
      ++checked;
    }
  }
  EXPECT_EQ(checked, 6);
}

TEST(Rod3dSelfContact, ForcesBalanceAndPointAlongTheNormal) {
  const std::vector<Vec3> x = hairpin(0.03, 0.01);
  const auto pairs = rod::self_contacts(kContact, x, kEdge);
  ASSERT_FALSE(pairs.empty());
  std::vector<Vec3> gradient;
  rod::self_contact_derivatives(kContact, x, kEdge, gradient, nullptr);
  // Internal forces: zero net force and moment (the pair force acts along the line of its points).
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();
  double scale = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    force += gradient[i];
    moment += x[i].cross(gradient[i]);
    scale = std::max(scale, gradient[i].norm());
  }
  EXPECT_LE(force.norm(), 1e-13 * scale);
  EXPECT_LE(moment.norm(), 1e-13 * scale);
  for (const auto& pair : pairs) {
    EXPECT_LT(pair.distance, 2 * kContact.radius);
    EXPECT_NEAR(pair.force, kContact.stiffness * std::pow(2 * kContact.radius - pair.distance, 2), 1e-12 * pair.force);
    EXPECT_NEAR(pair.normal.norm(), 1.0, 1e-15);
    EXPECT_GT(pair.second - pair.first, rod::contact_excluded_neighbours(kContact.radius, kEdge));
  }
  // One pair alone: the gradient on the first segment's vertices is -force normal split (1 - s, s).
  const std::vector<Vec3> cross{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 5, 0), Vec3(0.3, 5, 0), Vec3(0.3, -1, 0.1),
                                Vec3(0.3, -2, 0.1)};
  const auto single = rod::self_contacts(kContact, cross, 1.0);
  ASSERT_EQ(single.size(), 1u);
  EXPECT_EQ(single[0].first, 0u);
  EXPECT_EQ(single[0].second, 3u);
  rod::self_contact_derivatives(kContact, cross, 1.0, gradient, nullptr);
  EXPECT_LE((gradient[0] + (1 - single[0].s) * single[0].force * single[0].normal).norm(), 1e-12 * single[0].force);
  EXPECT_LE((gradient[1] + single[0].s * single[0].force * single[0].normal).norm(), 1e-12 * single[0].force);
}

TEST(Rod3dSelfContact, ExcludedNeighboursAndBadInput) {
  EXPECT_EQ(rod::contact_excluded_neighbours(0.01, 0.1), 1u);
  EXPECT_EQ(rod::contact_excluded_neighbours(0.1, 0.1), 4u);  // ceil(pi) = 4
  EXPECT_THROW(rod::self_contacts({0.0, 1.0}, hairpin(0, 0), kEdge), rodvv::InputError);
  EXPECT_THROW(rod::self_contacts({0.1, -1.0}, hairpin(0, 0), kEdge), rodvv::InputError);
  EXPECT_THROW(rod::self_contacts({0.1, 1.0}, hairpin(0, 0), 0.0), rodvv::InputError);
  // Segments that pass through each other are not a contact the barrier can resolve: SolverError.
  const std::vector<Vec3> crossing{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 5, 0), Vec3(0.5, 5, 0), Vec3(0.5, -1, 0),
                                   Vec3(0.5, -2, 0)};
  EXPECT_THROW(rod::self_contacts(kContact, crossing, 1.0), rodvv::SolverError);
  // In a rod model: both numbers positive, and a radius that leaves some pair of segments able to touch.
  rod::RodModel m;
  m.elements = 20;
  m.length = 2.0;  // ebar = 0.1
  m.self_contact = {0.05, 1e5};
  EXPECT_EQ(parameter_of(m), "none");
  m.self_contact = {0.05, 0.0};
  EXPECT_EQ(parameter_of(m), "self_contact.stiffness");
  m.self_contact = {-0.05, 1e5};
  EXPECT_EQ(parameter_of(m), "self_contact.radius");
  m.self_contact = {0.6, 1e5};  // pi h / ebar = 18.8 -> 19 excluded neighbours of 20 edges
  EXPECT_EQ(parameter_of(m), "self_contact.radius");
}

// Two straight strands joined far away: A along x (z = 0, x in [0, 1]), out to (5, 0, 0), over to
// (0.5, -5, height) and back along y as B (x = 0.5, y in [-0.5, 0.5]) at `height`, so that B crosses
// A's middle. B's vertices are the last 21.
std::vector<Vec3> crossing_strands(double height) {
  std::vector<Vec3> x;
  for (int i = 0; i <= 20; ++i) x.push_back(Vec3(0.05 * i, 0.0, 0.0));
  x.push_back(Vec3(5.0, 0.0, 0.0));
  x.push_back(Vec3(0.5, -5.0, height));
  for (int i = 0; i <= 20; ++i) x.push_back(Vec3(0.5, -0.5 + 0.05 * i, height));
  return x;
}

TEST(Rod3dSelfContact, StepFractionStopsPassThroughNotRigidMotion) {
  const double h = kContact.radius, d0 = 0.2;  // B 0.2 above A: apart (2h = 0.13)
  const auto x = crossing_strands(d0);
  // B pushed straight down through A to the mirror height: both end points of the step are 0.2 apart,
  // so a barrier seen only there would not notice that B went through A half way. (The segment joining
  // B to the fixed vertex before it stretches, and keeps 0.3 - h from B's 6th segment on: a looser bound.)
  std::vector<Vec3> u(x.size(), Vec3::Zero());
  for (std::size_t i = x.size() - 21; i < x.size(); ++i) u[i] = Vec3(0.0, 0.0, -2.0 * d0);
  const double alpha = rod::pass_through_free_fraction(kContact, x, u, kEdge);
  // The closest pair is head-on: after the fraction the gap is exactly h, so d0 - 2 d0 alpha = h.
  EXPECT_NEAR(alpha, (d0 - h) / (2.0 * d0), 1e-15);
  // Any rigid motion of the whole rod, however long, is free.
  EXPECT_EQ(rod::pass_through_free_fraction(kContact, x, std::vector<Vec3>(x.size(), Vec3(3.0, -7.0, 20.0)), kEdge),
            1.0);
  // A step that stays clear (B lowered to 2h + 0.01, still above h from A): not shortened.
  std::vector<Vec3> clear(x.size(), Vec3::Zero());
  for (std::size_t i = x.size() - 21; i < x.size(); ++i) clear[i] = Vec3(0.0, 0.0, -(d0 - 2.0 * h - 0.01));
  EXPECT_EQ(rod::pass_through_free_fraction(kContact, x, clear, kEdge), 1.0);
  // In contact (0.1 < 2h apart), pushed together by 0.1: half the distance is the room, so alpha = 1/2.
  const auto touching = crossing_strands(0.1);
  std::vector<Vec3> push(touching.size(), Vec3::Zero());
  for (std::size_t i = touching.size() - 21; i < touching.size(); ++i) push[i] = Vec3(0.0, 0.0, -0.1);
  EXPECT_NEAR(rod::pass_through_free_fraction(kContact, touching, push, kEdge), 0.5, 1e-15);
  // Bad input names u.
  try {
    rod::pass_through_free_fraction(kContact, x, std::vector<Vec3>(3, Vec3::Zero()), kEdge);
    ADD_FAILURE() << "no InputError for a wrong number of displacements";
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "u");
  }
  u[0].x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(rod::pass_through_free_fraction(kContact, x, u, kEdge), rodvv::InputError);
}

}  // namespace

#include "rodvv/invariants/noether3d.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/dynamics.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "rodvv/solvers/rod3d/state.hpp"

namespace {

// A racket: both ends clamped side by side (root at the origin along +x, tip at (0, 3h, 0) pointing
// back along -x), both tilted towards the other strand, so the rod makes a loop whose two strands
// press on each other in its neck: the barrier holds them apart. Started as a half circle (with
// untilted clamps), the clamps are moved and turned by the continuation. No external load but the clamps and the contact, so H(s)
// is constant along the whole rod, contact region included, up to the barrier's own field V_eff
// (PHYSICS.md §1.2), which vanishes as k -> infinity.
struct Racket {
  rod::RodModel model;
  rod::RodState start;
};

Racket racket(std::size_t elements, double stiffness) {
  const double L = 2.0, h = 0.02;
  Racket r;
  auto& m = r.model;
  m.elements = elements;
  m.length = L;
  m.stiffness = Vec3(0.7, 1.0, 1.3);
  m.self_contact = {h, stiffness};
  m.root.support = rod::EndSupport::Clamped;
  m.root.position = Vec3::Zero();
  // The clamps tilt both strands towards each other by beta: they cross 3h / (2 tan beta) = 0.044
  // beyond the clamps (4 edges at N = 200) unless the barrier holds them apart.
  const double beta = 0.6;
  m.root.frame = Eigen::AngleAxisd(beta, Vec3::UnitZ()).toRotationMatrix();  // t = (cos, sin, 0), m1, m2 = e_z
  m.tip.support = rod::EndSupport::Clamped;
  m.tip.position = Vec3(0.0, 3.0 * h, 0.0);
  m.tip.frame = Eigen::AngleAxisd(std::numbers::pi - beta, Vec3::UnitZ()).toRotationMatrix();  // t = (-cos, sin, 0)
  // A half circle of length L from the root, turning left: with both ends clamped it is an exact
  // equilibrium (constant curvature, zero force), from which the continuation brings the tip in.
  const double radius = L / std::numbers::pi;
  std::vector<Vec3> x(elements + 1);
  for (std::size_t i = 0; i <= elements; ++i) {
    const double a = rod::vertex_arclength(m, i) / radius;
    x[i] = Vec3(radius * std::sin(a), radius * (1 - std::cos(a)), 0);
  }
  r.start = rod::make_state(x, Vec3(0, 1, 0), std::vector<double>(elements, 0.0));
  r.start.multiplier.assign(elements, 0.0);
  return r;
}

TEST(Rod3dSelfContact, RacketEquilibriumKeepsHThroughTheContact) {
  // Measured at N = 100 (k = 1e6, 1e7, 1e8): 15, 10, 7 pairs; largest overlap 6.7e-3, 3.0e-3,
  // 1.1e-3 (~ sqrt(f/k)); H spread / scale 1.83e-2, 1.40e-2, 1.28e-2, i.e. set by the resolution
  // once the barrier is stiff (N = 200, k = 1e8: 4.3e-3). Bound: 2 x the largest measured spread; a
  // wrong contact normal, force or Hessian breaks the balance of n.t and the curvature across the
  // neck and moves H by O(1) there.
  double previous_overlap = 1.0;
  for (double k : {1e6, 1e7, 1e8}) {
    const Racket r = racket(100, k);
    rod::StaticOptions options;
    options.load_steps = 8;
    const auto result = rod::solve_static(r.model, r.start, options);
    const auto pairs = rod::self_contacts(r.model.self_contact, result.state.position, rod::rest_edge_length(r.model));
    ASSERT_FALSE(pairs.empty()) << k;
    double overlap = 0.0, force = 0.0;
    for (const auto& p : pairs) {
      overlap = std::max(overlap, 2 * r.model.self_contact.radius - p.distance);
      force = std::max(force, p.force);
    }
    EXPECT_LT(overlap, 0.5 * previous_overlap) << k;  // ~ sqrt(f/k): each decade of k at least halves it
    previous_overlap = overlap;
    const auto summary = rodvv::invariants::noether3d_summary(rod::make_solution(r.model, result.state));
    EXPECT_LE(summary.spread, 2 * 1.83e-2 * summary.scale) << k;
    std::cout << "[ summary  ] k " << k << ": " << pairs.size() << " pairs, largest overlap " << overlap
              << ", largest pair force " << force << ", H spread / scale " << summary.spread / summary.scale
              << ", iterations " << result.iterations << " in " << result.steps << " steps\n";
  }
}

}  // namespace

namespace {

// The racket with hard contact (self_contact.hpp: law Hard; statics.hpp: Newton-LCP): the constraint
// d >= 2h itself. A polyline's tube has creases at the vertices, so a strand sliding along another
// meets equilibria O(ebar^2) apart and the hard problem has several; each barrier equilibrium is
// therefore hardened (the hard statics started from it), and checked:
//  - the barrier's equilibria tend to their hardened ones (here one and the same: 2 pairs carry 598.67)
//    as k -> infinity. Not like the overlap: in the neck the strands are nearly parallel, the barrier
//    spreads the load over a patch of half-width a = sqrt(2 rho delta) (7 to 15 pairs) where the hard
//    contact puts it on 2 pairs, and the shapes differ by that spread, ~ a ~ k^(-1/5) (a line force
//    k delta^2 over the patch carries F ~ k delta^(5/2): knot/trefoil-barrier-limit's comment). So each
//    decade of k multiplies the largest vertex distance by about 10^(-1/5) = 0.63: measured 0.52, 0.60
//    (0.37 h, 0.19 h, 0.11 h at k = 1e6, 1e7, 1e8); bound 0.7 per decade;
//  - the KKT conditions recomputed here from the returned pairs: every force > 0, every pair at the
//    contact distance to the solver's tolerance, and the elastic residual balanced by the pair forces
//    along their normals (static_residual = sum f grad d on the free vertices);
//  - H is as constant through the neck as with the barrier.
TEST(Rod3dSelfContact, HardContactIsTheBarriersLimit) {
  rod::StaticOptions options;
  options.load_steps = 8;
  double previous = 1e300;
  for (double k : {1e6, 1e7, 1e8}) {
    const Racket soft = racket(100, k);
    const auto barrier = rod::solve_static(soft.model, soft.start, options);
    rod::RodModel model = soft.model;
    model.self_contact = {model.self_contact.radius, 0.0, rod::ContactLaw::Hard};
    const auto hard = rod::solve_static(model, barrier.state);
    ASSERT_FALSE(hard.contacts.empty()) << k;
    const double h = model.self_contact.radius;
    double distance = 0.0;
    for (std::size_t i = 0; i <= model.elements; ++i)
      distance = std::max(distance, (barrier.state.position[i] - hard.state.position[i]).norm());
    EXPECT_LT(distance, 0.7 * previous) << k;
    previous = distance;

    const double length_tolerance = 2 * options.tolerance * model.length;  // the constraint rows' scale (statics.hpp)
    std::vector<Vec3> contact_force(model.elements + 1, Vec3::Zero());
    double total = 0.0;
    for (const auto& pair : hard.contacts) {
      EXPECT_GT(pair.force, 0.0);
      EXPECT_NEAR(pair.distance, 2 * h, length_tolerance) << pair.first << ", " << pair.second;
      const auto gradient = rod::distance_gradient(pair);
      const auto vertex = rod::pair_vertices(pair);
      for (std::size_t a = 0; a < 4; ++a) contact_force[vertex[a]] += pair.force * gradient[a];
      total += pair.force;
    }
    // Balance on the free vertices (the clamps hold vertices 0, 1, N - 1, N), in the statics' force scale.
    const rod::DofLayout layout(model);
    const auto residual = rod::static_residual(model, hard.state, 1.0);
    double force_scale = model.stiffness.maxCoeff() / (model.length * model.length);
    for (double tension : hard.state.multiplier) force_scale = std::max(force_scale, std::abs(tension));
    double imbalance = 0.0;
    for (std::size_t i = 2; i + 2 <= model.elements; ++i)
      imbalance = std::max(imbalance, (residual.segment<3>(Eigen::Index(layout.vertex(i))) - contact_force[i]).norm());
    EXPECT_LE(imbalance, options.tolerance * force_scale) << k;
    const auto summary = rodvv::invariants::noether3d_summary(rod::make_solution(model, hard.state));
    EXPECT_LE(summary.spread, 2 * 1.83e-2 * summary.scale) << k;
    std::cout << "[ summary  ] k " << k << ": largest vertex distance to its hardened equilibrium / h " << distance / h
              << "; hard: " << hard.contacts.size() << " pairs, total force " << total << ", imbalance "
              << imbalance / force_scale << ", H spread / scale " << summary.spread / summary.scale << ", "
              << hard.iterations << " iterations\n";
  }
}

TEST(Rod3dSelfContact, HardContactBadInput) {
  Racket r = racket(40, 0.0);
  r.model.self_contact = {0.02, 0.0, rod::ContactLaw::Hard};
  EXPECT_EQ(parameter_of(r.model), "none");
  r.model.self_contact.stiffness = 1e6;  // a barrier stiffness with the hard law: refused, not ignored
  EXPECT_EQ(parameter_of(r.model), "self_contact.stiffness");
  // The hard law has no energy: nothing for the dynamics to integrate.
  r.model.self_contact.stiffness = 0.0;
  const auto state = rod::make_dynamic_state(r.model, r.start, {});
  EXPECT_THROW(rod::step(r.model, state, 1e-3, rod::TimeIntegrator::ImplicitEuler), rodvv::InputError);
  EXPECT_EQ(rod::self_contact_energy(r.model.self_contact, r.start.position, rod::rest_edge_length(r.model)), 0.0);
}

}  // namespace

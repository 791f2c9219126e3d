// The knot cases pass at their default levels; their gates turn red on a wrong claim or an inconsistent
// H; the tying procedure ties what it says (a trefoil holds together under the pull, the same closure
// with one half twist - the unknot - comes undone and pulls straight; a laid ply sits on its curve, and
// its gates tell the plectoneme's tension law from a wrong one and a wrong stiffness).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "../../harness/src/cases/knot/contact_profile.hpp"
#include "../../harness/src/cases/knot/nodal_trefoil.hpp"
#include "../../harness/src/cases/knot/plectoneme_tying.hpp"
#include "../../harness/src/cases/knot/superhelix_on_curve.hpp"
#include "../../harness/src/cases/knot/trefoil_tying.hpp"
#include "case_test_support.hpp"
#include "rodvv/harness/convergence.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/references/knot_and_ply.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::testing::failing_gates;
using rodvv::testing::regated;
using rodvv::testing::run_at_default_levels;
namespace rod = rodvv::solvers::rod3d;
namespace knot = rodvv::harness::knot_cases;

const Case& named(const std::string& name) { return rodvv::testing::named_case(name); }

Vec3 braid_end(const knot::BraidClosure& braid) { return knot::braid_closure_curve(braid).back(); }

TEST(KnotCases, TrefoilPassesAtDefaultLevels) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  const auto result = run_at_default_levels(named("knot/trefoil-nodal"));
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  EXPECT_FALSE(result.gates.empty());
  EXPECT_EQ(rodvv::testing::case_names_of_family("knot").size(), 11u);
  // The report's contact-force profile beside H(s): zero on the tails, positive in the braid.
  const auto& series = result.levels.back().series;
  const auto profile = std::find_if(series.begin(), series.end(), [](const Series& s) { return s.name == "contact force p(s)"; });
  ASSERT_NE(profile, series.end());
  EXPECT_EQ(profile->y.front(), 0.0);
  EXPECT_EQ(profile->y.back(), 0.0);
  EXPECT_GT(*std::max_element(profile->y.begin(), profile->y.end()), 0.0);
}

// One pair, force 2 along e_z between segment 0 (at s = 0.25) and segment 3 (at t = 0.5) of a 4-edge rod
// of length 2 (free ends: ebar = 0.5): vertex forces 1.5, 0.5 on the first segment's ends, 1, 1 on the
// second's, per length / 0.5.
TEST(KnotContactProfile, SplitsEachPairByItsClosestPointParameters) {
  rod::RodModel model;
  model.elements = 4;
  model.length = 2.0;
  rod::ContactPair pair;
  pair.first = 0;
  pair.second = 3;
  pair.s = 0.25;
  pair.t = 0.5;
  pair.force = 2.0;
  pair.normal = Vec3::UnitZ();
  const Series p = knot::contact_force_series(model, {pair});
  ASSERT_EQ(p.y.size(), 5u);
  const std::vector<double> expected{3.0, 1.0, 0.0, 2.0, 2.0};
  for (std::size_t i = 0; i < 5; ++i) {
    EXPECT_DOUBLE_EQ(p.x[i], 0.5 * double(i));
    EXPECT_DOUBLE_EQ(p.y[i], expected[i]) << i;
  }
}

// Claimed at second order, the first-order H error fails its order gate; an error three times larger
// (what a contact force with a tangential part, or a lumping twice as coarse, would give) fails the
// magnitude gate.
TEST(KnotCases, WrongOrderOrTripledErrorIsRed) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  const SweepResult ran = run_at_default_levels(named("knot/trefoil-nodal"));  // solved once, gated twice
  rodvv::testing::expect_wrong_order_claims_fail(named("knot/trefoil-nodal"), ran, "H_deviation", {2.0});
  const auto tripled = regated(named("knot/trefoil-nodal"), ran, [](const Parameters&, auto& metrics) {
    *metrics.at("H_deviation").error *= 3.0;
  });
  EXPECT_FALSE(tripled.passed());
}

// The loose-knot limit: 1/2 B kappa_B^2 / T -> 1 as eps^2. A relation off by 1 % (a tension or a stiffness
// misread by 1 %) adds 0.01 to every level's excess: the order falls to about 1.4, out of its window.
TEST(KnotCases, LoosenessStudyPassesAndARelationOffByOnePercentIsRed) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  const Case& study = named("knot/trefoil-looseness-superhelix");
  const auto result = run_at_default_levels(study);
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  // Each level's point of the report's figure of the relations over the looseness is its own measurement.
  for (const auto& level : result.levels) {
    const auto point = std::find_if(level.series.begin(), level.series.end(), [](const Series& s) {
      return s.name == "loose-knot relations over the looseness|levels: 1/2 B kappa_B^2 / T where t is "
                       "perpendicular to the pull";
    });
    ASSERT_NE(point, level.series.end()) << level.level;
    EXPECT_EQ(point->x, std::vector<double>{level.level});
    EXPECT_EQ(point->y, std::vector<double>{level.metrics.at("perpendicular_ratio").computed});
  }
  const auto wrong = regated(study, result, [](const Parameters&, auto& metrics) {
    const double ratio = 1.01 * metrics.at("perpendicular_ratio").computed;
    metrics["perpendicular_excess"] = {ratio - 1.0, 0.0, ratio - 1.0, 1.0};
  });
  EXPECT_FALSE(wrong.passed());
  ASSERT_TRUE(wrong.gates.front().measured.has_value());
  EXPECT_LT(*wrong.gates.front().measured, 1.6);
}

// As the barrier stiffens the overlap vanishes at the order the contact's geometry sets (1/2 for the nodal
// rod's point forces, 2/5 .. 1/2 for the Super-Helix's line force); an overlap that fell as the compliance
// itself (order 1: a linear penalty's) is red on either rod.
TEST(KnotCases, BarrierLimitPassesAndALinearPenaltysOrderIsRed) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  for (const char* name : {"knot/trefoil-barrier-limit-nodal", "knot/trefoil-barrier-limit-superhelix"}) {
    const auto result = run_at_default_levels(named(name));
    EXPECT_TRUE(result.passed()) << name << failing_gates(result);
    Case linear = named(name);
    linear.gates = {order_gate("overlap", 1.0, "a linear penalty's overlap ~ F / k")};
    EXPECT_FALSE(regated(linear, result).passed()) << name;
  }
}

knot::PulledKnot pulled(int half_twists);  // below

// With hard contact the trefoil passes its gates, among them no overlap beyond the statics' gap tolerance
// (1e-9 L); the overlap the barrier leaves at the same level (about 2.5 % of 2h: some 1e5 tolerances) is red.
TEST(KnotCases, HardTrefoilPassesAndTheBarriersOverlapIsRed) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  const auto result = run_at_default_levels(named("knot/trefoil-hard-nodal"));
  EXPECT_TRUE(result.passed()) << failing_gates(result);
  EXPECT_EQ(result.gates.size(), 4u);  // order, magnitude, overlap, resolution
  Case soft = named("knot/trefoil-hard-nodal");
  const double length = pulled(3).model.length, h = 0.05;  // the knot's defaults (the helper below)
  soft.run_level = [length, h](const Parameters& p, double level) {
    const auto knot_parameters = knot::trefoil_knot(p, std::nullopt, 500.0);
    LevelOutput out = knot::relax_nodal_trefoil(knot_parameters, std::size_t(level));
    const double overlap = out.metrics.at("deepest_overlap").computed * 2 * h;
    out.metrics["overlap_over_tolerance"] = {overlap / (1e-9 * length), 0.0, overlap / (1e-9 * length), 1.0};
    return out;
  };
  EXPECT_FALSE(run_at_default_levels(soft).passed());
}

// The Super-Helix's hard trefoil passes its gates. Its H at the elements holding the point forces is the
// lumping's O(h) spike (superhelix_point_force_lumping.hpp) plus O(h^2): with the spike left in (no model:
// H_lumping_miss = the raw H_deviation, whose order scatters with where the forces fall in their elements:
// 0.091, 0.011, 0.029 at N = 50, 100, 200) the miss's gates are red; so is a deviation between the
// contacts three times larger (a force with a part along its rod, a tension misread).
TEST(KnotCases, HardSuperHelixTrefoilPassesAndAnUnexplainedSpikeIsRed) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  const Case& hard = named("knot/trefoil-hard-superhelix");
  SweepResult right;
  for (const double level : {50.0, 100.0, 200.0}) {  // the default levels, solved once; the variants edit them
    LevelResult result;
    result.level = level;
    result.h = 1.0 / level;
    result.metrics = hard.run_level(hard.info.parameters, level).metrics;
    right.levels.push_back(result);
  }
  right.analyses = analyse_metrics(hard.info.metrics, right.levels);
  for (const auto& gate : hard.gates) {
    if (gate.kind != GateKind::Regression) {
      EXPECT_TRUE(evaluate_gate(gate, right).passed) << gate.name << evaluate_gate(gate, right).reason;
    }
  }
  auto red_gates = [&](const SweepResult& sweep, const std::string& metric) {
    std::size_t red = 0;
    for (const auto& gate : hard.gates)
      if (gate.metric == metric && !evaluate_gate(gate, sweep).passed) ++red;
    return red;
  };
  SweepResult unexplained = right, tripled = right;
  for (std::size_t i = 0; i < right.levels.size(); ++i) {
    unexplained.levels[i].metrics["H_lumping_miss"] = right.levels[i].metrics.at("H_deviation");
    *tripled.levels[i].metrics["H_deviation_between_contacts"].error *= 3.0;
  }
  for (SweepResult* variant : {&unexplained, &tripled}) variant->analyses = analyse_metrics(hard.info.metrics, variant->levels);
  EXPECT_GE(red_gates(unexplained, "H_lumping_miss"), 2u);  // order and magnitude
  EXPECT_GE(red_gates(tripled, "H_deviation_between_contacts"), 1u);
}

// The rod of the case's construction at N = 100 (lambda = sqrt(B/T) = 0.5, h = 0.05).
knot::PulledKnot pulled(int half_twists) {
  const double B = 1.3, T = 5.2, lambda = 0.5, h = 0.05;
  const knot::TiedRod tied = knot::tie_braid_closure({half_twists, 1.25 * h, 10 * h, 0.6 * lambda, 3 * h, 6 * lambda}, 100);
  return knot::pull_tied_rod(tied, B, 0.9, T, {h, 500 * T / (h * h)});
}

TEST(KnotTying, VerticesSitOnTheCurveAtEqualStepsWithoutOverlap) {
  const knot::PulledKnot p = pulled(3);
  const double ebar = rod::rest_edge_length(p.model);
  // Chords of arcs of length ebar: never longer, and shorter only where the curve bends (curvature at
  // most 1 / (1.25 h) on the braid: chord >= ebar (1 - (ebar kappa)^2 / 24) >= 0.93 ebar here).
  for (std::size_t j = 0; j < p.model.elements; ++j) {
    const double chord = (p.start.position[j + 1] - p.start.position[j]).norm();
    EXPECT_LE(chord, ebar * (1 + 1e-12)) << j;
    EXPECT_GE(chord, 0.9 * ebar) << j;
  }
  EXPECT_TRUE(rod::self_contacts(p.model.self_contact, p.start.position, ebar).empty());
  EXPECT_THROW(knot::tie_braid_closure({2, 0.1, 1, 1, 0.1, 1}, 100), rodvv::InputError);
  EXPECT_THROW(knot::tie_braid_closure({3, 0.0, 1, 1, 0.1, 1}, 100), rodvv::InputError);
}

TEST(KnotTying, TrefoilHoldsAndTheUnknotComesUndone) {
  rod::StaticOptions options;
  options.pseudo_transient = true;
  options.max_iterations = 20000;
  options.tolerance = 1e-9;
  for (int half_twists : {3, 1}) {
    const knot::PulledKnot p = pulled(half_twists);
    const auto result = rod::solve_static(p.model, p.start, options);
    const auto pairs = rod::self_contacts(p.model.self_contact, result.state.position, rod::rest_edge_length(p.model));
    const double reach = (result.state.position.back() - result.state.position.front()).x() / p.model.length;
    if (half_twists == 3) {
      // Measured: 11 pairs; the knot takes up about 5 lambda = 2.5 of the rod's 14.2.
      EXPECT_GE(pairs.size(), 5u);
      EXPECT_LT(reach, 0.9);
    } else {
      // Undone: nothing touches, and the rod is straight but for the end tension's O(eps) sag: none here.
      EXPECT_TRUE(pairs.empty());
      EXPECT_GT(reach, 1.0 - 1e-6);
    }
  }
}

// The Super-Helix laid on a circle of radius R (sampled densely): every element is the circle's own arc,
// kappa = 1/R about the binormal and no twist, to the dense polyline's chord error (Delta s)^2 / (8 R).
TEST(KnotTying, SuperHelixLaidOnACircleIsTheCircle) {
  const double R = 0.7;
  std::vector<Vec3> circle;
  const int samples = 20000;
  for (int i = 0; i <= samples; ++i) {
    const double phi = 1.5 * 3.14159265358979 * i / samples;  // three quarters of a turn
    circle.emplace_back(0.3 + R * std::sin(phi), -0.2 + R * (1.0 - std::cos(phi)), 0.5);
  }
  const knot::LaidSuperHelix laid = knot::superhelix_on_curve(circle, 12, Vec3::UnitZ());
  const double chord_error = std::pow(1.5 * 3.14159265358979 * R / samples, 2) / (8.0 * R);
  EXPECT_LE(laid.max_miss, 4.0 * chord_error);
  for (int e = 0; e < 12; ++e) {
    EXPECT_NEAR(laid.q(3 * e), 0.0, 1e-6) << e;                    // no twist
    EXPECT_NEAR(std::hypot(laid.q(3 * e + 1), laid.q(3 * e + 2)), 1.0 / R, 1e-5) << e;
  }
  EXPECT_NEAR(laid.length, 1.5 * 3.14159265358979 * R, 1e-8);
  EXPECT_THROW(knot::superhelix_on_curve(circle, 12, Vec3::UnitX()), rodvv::InputError);  // normal along the tangent
}

// The Super-Helix on the trefoil case's braid closure: element ends within the miss the case reports
// (0.31 h at N = 100, measured), and no strand closer to another than the contact distance.
TEST(KnotTying, SuperHelixLaidOnTheBraidClosureFollowsIt) {
  const double lambda = 0.5, h = 0.05;
  const knot::BraidClosure braid{3, 1.25 * h, 10 * h, 0.6 * lambda, 3 * h, 2 * lambda};
  const knot::LaidSuperHelix laid = knot::superhelix_on_curve(knot::braid_closure_curve(braid), 100, Vec3::UnitZ());
  EXPECT_LT(laid.max_miss, 0.35 * h);
  rodvv::solvers::superhelix::RodModel model;
  model.elements = 100;
  model.length = laid.length;
  model.root_position = laid.root_position;
  model.root_frame = laid.root_frame;
  const rodvv::solvers::superhelix::Kinematics kinematics(model, laid.q);
  EXPECT_TRUE(rodvv::solvers::superhelix::self_contacts(kinematics, {h, 1.0}).empty());
  EXPECT_NEAR((kinematics.tip_position() - laid.root_position).x(), (braid_end(braid) - laid.root_position).x(), 0.35 * h);
}

// ---- the plectoneme ------------------------------------------------------------------------------

TEST(PlyLaying, VerticesSitOnTheLaidCurveAndTheEndsAreHeldAsDocumented) {
  const double h = 0.05, theta = 15.0 * 3.14159265358979 / 180.0;
  const knot::TiedRod laid = knot::lay_plectoneme({h, theta, 120 * h, 4 * h, 8 * h, 2 * h, 40 * h}, 400);
  const knot::PulledPly p = knot::pull_laid_ply(laid, 1.1, 1.3, 0.9, 3.9, {h, 500 * 3.9 / (h * h)});
  const double ebar = rod::rest_edge_length(p.model);
  for (std::size_t j = 0; j < p.model.elements; ++j) {
    const double chord = (p.start.position[j + 1] - p.start.position[j]).norm();
    EXPECT_LE(chord, ebar * (1 + 1e-12)) << j;
    EXPECT_GE(chord, 0.9 * ebar) << j;  // the tightest bend, the junction arcs (radius 4 h): >= 0.99 ebar
  }
  // The tails on the x-axis, the root's at x < 0, the tip's (a coordinate axis, so that it can slide) at x > 0.
  EXPECT_EQ(p.model.tip.frame.col(0), Vec3::UnitX());
  EXPECT_TRUE(p.model.tip.slides);
  EXPECT_LT(p.model.root.position.x(), 0.0);
  EXPECT_GT(p.model.tip.position.x(), 0.0);
  EXPECT_EQ(p.model.end_force, Vec3(3.9, 0, 0));
  // The strands are laid touching (2R = 2h): the chords of each helix dip inside it by at most
  // ebar^2 kappa / 8 (kappa = sin^2 theta / R), so the two strands' chords come closer than 2h by at most
  // twice that, to leading order in ebar kappa (measured 6.735e-4 against 6.716e-4 here: 5 % allowed for the
  // higher orders).
  double deepest = 0.0;
  for (const auto& c : rod::self_contacts(p.model.self_contact, p.start.position, ebar))
    deepest = std::max(deepest, 2 * h - c.distance);
  const double kappa = std::pow(std::sin(theta), 2) / h;
  EXPECT_LT(deepest, 1.05 * 2.0 * ebar * ebar * kappa / 8.0);
  // The twist: the tip's material frame is turned by 1.1 rad per length along the rod from the root's
  // transported frame, i.e. its twist about the tangent per edge is 1.1 ebar.
  EXPECT_NEAR(p.start.angle[1] - p.start.angle[0], 1.1 * ebar, 1e-14);
  // The tip's clamp holds that twist with all its turns (about 2 here): its frame is the reference director's
  // (angle 0) and its rotation the laid angle, so the start meets the clamp exactly and the statics' end path
  // has nothing to unwind (a frame with the twist in it and no rotation fixes the angle modulo 2 pi only).
  const std::size_t n = p.model.elements;
  EXPECT_GT(p.model.tip.rotation, 4.0 * 3.14159265358979);
  EXPECT_EQ(p.model.tip.rotation, p.start.angle[n - 1]);
  const Mat3 turned = Eigen::AngleAxisd(p.model.tip.rotation, p.model.tip.frame.col(0)).toRotationMatrix() *
                      p.model.tip.frame;
  EXPECT_LT((turned - rod::material_frame(p.start, n - 1)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_THROW(knot::lay_plectoneme({h, 0.8, 1, 1, 1, 0, 1}, 100), rodvv::InputError);  // theta >= pi/4
  EXPECT_THROW(knot::lay_plectoneme({0.0, theta, 1, 1, 1, 0, 1}, 100), rodvv::InputError);
  EXPECT_THROW(knot::pull_laid_ply(laid, std::nan(""), 1.3, 0.9, 3.9, {h, 1}), rodvv::InputError);
}

// The plectoneme case's coarsest level (N = 200, about 1 s; the case itself runs under `rodvv run` and
// ctest): its tension gate, evaluated on that level alone (a bound C h at h = 1/200: 0.027, measured
// -0.0126), passes; the tension law with the 2 of (1 + 2 / cos 2 theta) halved, at the same measured R and
// theta, and the right law with a bending stiffness 10 % off (what a solver with a wrong B would be
// compared with) fail it. (The bound at N = 800, 0.68 % against the measured 0.25 %, sees a stiffness
// error of 0.5 %.)
TEST(PlectonemeCases, TheTensionGateTellsTheLawFromAWrongOneAndAWrongStiffness) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  namespace ref = rodvv::references;
  const Case& c = named("knot/plectoneme-nodal");
  SweepResult right;
  LevelResult level;
  level.level = 200.0;
  level.h = 1.0 / 200.0;
  level.metrics = c.run_level(c.info.parameters, 200.0).metrics;  // solved once; the variants edit it
  right.levels.push_back(level);
  const auto gate = std::find_if(c.gates.begin(), c.gates.end(), [](const GateSpec& g) { return g.metric == "tension_law"; });
  ASSERT_NE(gate, c.gates.end());
  EXPECT_TRUE(evaluate_gate(*gate, right).passed) << evaluate_gate(*gate, right).reason;
  const double B = parameter_value(c.info.parameters, "B"), h = parameter_value(c.info.parameters, "radius");
  const auto& m = level.metrics;
  const double R = m.at("ply_radius").computed * h, theta = m.at("helix_angle").computed * 3.14159265358979 / 180.0;
  const double T = m.at("tail_tension").computed, s2 = std::sin(theta) * std::sin(theta);
  const double halved_law = B / (R * R) * 0.5 * s2 * s2 * (1.0 + 1.0 / std::cos(2 * theta));
  const double stiffer_law = ref::plectoneme({1.10 * B, R, theta, 0, 0}).tail_tension;
  for (const double law : {halved_law, stiffer_law}) {
    SweepResult wrong = right;
    wrong.levels[0].metrics["tension_law"] = {T / law - 1.0, 0.0, std::abs(T / law - 1.0)};
    EXPECT_FALSE(evaluate_gate(*gate, wrong).passed) << law;
  }
}

// The angle study (knot/plectoneme-angles-nodal, 10 .. 35 degrees, about 45 s), solved once: it passes, every
// level adds its measured point to the tension law's figure, and its tension gates turn red, at the same
// measured R, theta and T_ext, against the law with the 2 of (1 + 2 / cos 2 theta) halved and against the
// right law with a bending stiffness 10 % off (measured errors at most 0.022 against the bounds 0.044, 0.1).
TEST(PlectonemeCases, TheAngleStudyTellsTheTensionLawFromAWrongOneAndAWrongStiffness) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  namespace ref = rodvv::references;
  const Case& c = named("knot/plectoneme-angles-nodal");
  const SweepResult right = run_at_default_levels(c);
  EXPECT_TRUE(right.passed()) << failing_gates(right);
  ASSERT_EQ(right.levels.size(), 6u);
  for (const auto& level : right.levels) {
    const auto point = std::find_if(level.series.begin(), level.series.end(), [](const Series& s) {
      return s.name.rfind("tension law over the helix angle|levels: ", 0) == 0;
    });
    ASSERT_NE(point, level.series.end()) << level.level;
    ASSERT_EQ(point->x.size(), 1u);
    EXPECT_NEAR(point->x[0], level.level, 0.5);  // the measured theta, laid at the level's angle
  }
  const double B = parameter_value(c.info.parameters, "B"), h = parameter_value(c.info.parameters, "radius");
  const auto against = [&](auto law) {
    return [=](const Parameters&, std::map<std::string, MetricSample>& m) {
      const double R = m.at("ply_radius").computed * h, theta = m.at("helix_angle").computed * 3.14159265358979 / 180.0;
      const double T = m.at("tail_tension").computed, e = T / law(R, theta) - 1.0;
      m["tension_law"] = {e, 0.0, std::abs(e)};
    };
  };
  const auto halved_law = [&](double R, double theta) {
    const double s2 = std::sin(theta) * std::sin(theta);
    return B / (R * R) * 0.5 * s2 * s2 * (1.0 + 1.0 / std::cos(2 * theta));
  };
  const auto stiffer_law = [&](double R, double theta) {
    return ref::plectoneme({1.10 * B, R, theta, 0, 0}).tail_tension;
  };
  const auto right_law = [&](double R, double theta) { return ref::plectoneme({B, R, theta, 0, 0}).tail_tension; };
  EXPECT_TRUE(regated(c, right, against(right_law)).passed());  // the edit itself changes nothing
  EXPECT_FALSE(regated(c, right, against(halved_law)).passed());
  EXPECT_FALSE(regated(c, right, against(stiffer_law)).passed());
}

// The ply formed by twisting (knot/plectoneme-twisted-nodal, about 20 s): the rod was turned by the overtwist
// times Greenhill's buckling rotation 2 sqrt(B T_ext) L / C, computed here apart from the case; the helix angle
// it chose is the one the tension law gives for T_ext (the law inverted here by bisection, within 0.3 degrees:
// measured 0.04 .. 0.11); its gates pass, and the tension gates go red against the law with the 2 of
// (1 + 2 / cos 2 theta) halved and against the right law with B 10 % off.
TEST(PlectonemeCases, TheTwistFormedPlyChoosesTheTensionLawsAngle) {
  RODVV_RELEASE_PRESET_ONLY("EveryCase.CoarsestLevelRunsAndGivesFiniteMetrics");
  namespace ref = rodvv::references;
  const double pi = 3.14159265358979;
  const Case& c = named("knot/plectoneme-twisted-nodal");
  const SweepResult right = run_at_default_levels(c);
  EXPECT_TRUE(right.passed()) << failing_gates(right);
  ASSERT_EQ(right.levels.size(), 3u);
  const auto& p = c.info.parameters;
  const double B = parameter_value(p, "B"), C = parameter_value(p, "C"), h = parameter_value(p, "radius");
  const double T = parameter_value(p, "tension") * B / (h * h), L = 300.0 * h;
  const double turns = parameter_value(p, "overtwist") * 2.0 * std::sqrt(B * T) * L / C / (2.0 * pi);
  double low = 0.01, high = 0.7;  // theta with ref::plectoneme's tail tension = T (it grows with theta)
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (low + high);
    (ref::plectoneme({B, h, mid, 0, 0}).tail_tension < T ? low : high) = mid;
  }
  for (const auto& level : right.levels) {
    EXPECT_NEAR(level.metrics.at("end_rotation_turns").computed, turns, 1e-12 * turns) << level.level;
    EXPECT_NEAR(level.metrics.at("helix_angle").computed, low * 180.0 / pi, 0.3) << level.level;
    // n . t on the tail is T_ext cos(tilt): the tail leaves the pull's axis by well under 0.04 rad (measured
    // n . t / T_ext - 1 = -4e-5 at the corners)
    EXPECT_NEAR(level.metrics.at("tail_tension").computed, T, 1e-3 * T) << level.level;
  }
  const auto against = [&](auto law) {
    return [=](const Parameters&, std::map<std::string, MetricSample>& m) {
      const double R = m.at("ply_radius").computed * h, theta = m.at("helix_angle").computed * pi / 180.0;
      const double e = m.at("tail_tension").computed / law(R, theta) - 1.0;
      m["tension_law"] = {e, 0.0, std::abs(e)};
    };
  };
  const auto halved_law = [&](double R, double theta) {
    const double s2 = std::sin(theta) * std::sin(theta);
    return B / (R * R) * 0.5 * s2 * s2 * (1.0 + 1.0 / std::cos(2 * theta));
  };
  const auto stiffer_law = [&](double R, double theta) { return ref::plectoneme({1.10 * B, R, theta, 0, 0}).tail_tension; };
  const auto right_law = [&](double R, double theta) { return ref::plectoneme({B, R, theta, 0, 0}).tail_tension; };
  EXPECT_TRUE(regated(c, right, against(right_law)).passed());  // the edit itself changes nothing
  EXPECT_FALSE(regated(c, right, against(halved_law)).passed());
  EXPECT_FALSE(regated(c, right, against(stiffer_law)).passed());
}

}  // namespace


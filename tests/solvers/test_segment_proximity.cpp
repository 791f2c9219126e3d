// Segment proximity for self-contact (solvers/contact/segment_proximity.hpp): closest points of two
// segments against an independent oracle, and the sort-and-sweep broad phase against all pairs.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/contact/segment_proximity.hpp"

namespace {

using rodvv::Vec3;
namespace contact = rodvv::solvers::contact;

// Oracle: the distance from the point P(s) to segment B is exact by a clamped projection, and it is a
// convex function of s (distance from a point moving on a line to a convex set), so golden-section
// search on s in [0, 1] converges to the global minimum; 200 iterations shrink the bracket by
// 0.618^200 ~ 1e-42. Shares no code with closest_points.
double point_segment_distance(const Vec3& p, const Vec3& b0, const Vec3& b1) {
  const Vec3 d = b1 - b0;
  const double len2 = d.squaredNorm();
  const double t = len2 > 0 ? std::clamp((p - b0).dot(d) / len2, 0.0, 1.0) : 0.0;
  return (p - (b0 + t * d)).norm();
}
double oracle_distance(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const auto f = [&](double s) { return point_segment_distance(a0 + s * (a1 - a0), b0, b1); };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.0, hi = 1.0;
  for (int k = 0; k < 200; ++k) {
    const double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
    (f(x1) <= f(x2) ? hi : lo) = (f(x1) <= f(x2) ? x2 : x1);
  }
  return std::min({f(0.0), f(1.0), f(0.5 * (lo + hi))});
}

TEST(SegmentProximity, ClosestPointsMatchTheOracle) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_point = [&] { return Vec3(u(rng), u(rng), u(rng)); };
  double worst = 0.0;
  for (int trial = 0; trial < 4000; ++trial) {
    Vec3 a0 = random_point(), a1 = random_point(), b0 = random_point(), b1 = random_point();
    if (trial % 4 == 1) b1 = b0 + 0.7 * (a1 - a0);                 // parallel
    if (trial % 4 == 2) b1 = b0 + (a1 - a0) * (1 + 1e-13);         // nearly parallel
    if (trial % 4 == 3) { b0 = a0 + 0.3 * (a1 - a0); b1 = a0 + 1.4 * (a1 - a0); }  // collinear, overlapping
    const auto c = contact::closest_points(a0, a1, b0, b1);
    // The returned points lie on the segments at the returned parameters, and their distance is the
    // minimum: the oracle's golden-section minimum is within ~eps of it (both are distances of
    // O(1) points: 1e-12 allows the oracle's sqrt of a flat minimum, ~sqrt(eps) in s but eps in f).
    ASSERT_GE(c.s, 0.0);
    ASSERT_LE(c.s, 1.0);
    ASSERT_GE(c.t, 0.0);
    ASSERT_LE(c.t, 1.0);
    EXPECT_LE((c.p - (a0 + c.s * (a1 - a0))).norm(), 1e-15);
    const double oracle = oracle_distance(a0, a1, b0, b1);
    worst = std::max(worst, std::abs(c.distance - oracle));
    EXPECT_NEAR(c.distance, oracle, 1e-12) << trial;
  }
  std::cout << "[ summary  ] worst |distance - oracle| " << worst << "\n";
}

TEST(SegmentProximity, KnownConfigurations) {
  // crossing at right angles, 0.3 apart
  auto c = contact::closest_points(Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0.2, -1, 0.3), Vec3(0.2, 1, 0.3));
  EXPECT_NEAR(c.distance, 0.3, 1e-16);
  EXPECT_NEAR(c.s, 0.6, 1e-16);
  EXPECT_NEAR(c.t, 0.5, 1e-16);
  // end to end, collinear, gap 0.5
  c = contact::closest_points(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1.5, 0, 0), Vec3(3, 0, 0));
  EXPECT_DOUBLE_EQ(c.distance, 0.5);
  EXPECT_EQ(c.s, 1.0);
  EXPECT_EQ(c.t, 0.0);
  // degenerate: a point and a segment, two points
  c = contact::closest_points(Vec3(0.5, 2, 0), Vec3(0.5, 2, 0), Vec3(0, 0, 0), Vec3(1, 0, 0));
  EXPECT_DOUBLE_EQ(c.distance, 2.0);
  EXPECT_DOUBLE_EQ(c.t, 0.5);
  c = contact::closest_points(Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(3, 4, 0), Vec3(3, 4, 0));
  EXPECT_DOUBLE_EQ(c.distance, 5.0);
}

// Polylines that fold back on themselves: a random walk, a tight helix (neighbouring turns in contact)
// and a two-strand ply, each at several cutoffs, with and without index exclusion.
std::vector<std::vector<Vec3>> test_polylines() {
  std::vector<std::vector<Vec3>> lines;
  std::mt19937 rng(11);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Vec3> walk{Vec3::Zero()};
  for (int i = 0; i < 400; ++i) walk.push_back(walk.back() + 0.1 * Vec3(g(rng), g(rng), g(rng)).normalized());
  lines.push_back(walk);
  std::vector<Vec3> helix;
  for (int i = 0; i <= 300; ++i) helix.push_back(Vec3(std::cos(0.2 * i), std::sin(0.2 * i), 0.021 * i));
  lines.push_back(helix);
  std::vector<Vec3> ply;  // down one strand, round a loop, back up the other
  for (int i = 0; i <= 200; ++i) ply.push_back(Vec3(0.05 * std::cos(0.3 * i), 0.05 * std::sin(0.3 * i), 0.02 * i));
  for (int i = 200; i >= 0; --i) ply.push_back(Vec3(-0.05 * std::cos(0.3 * i), -0.05 * std::sin(0.3 * i), 0.02 * i + 1e-3));
  lines.push_back(ply);
  return lines;
}

TEST(SegmentProximity, BroadPhaseFindsExactlyTheAllPairsSet) {
  std::size_t total = 0;
  for (const auto& line : test_polylines())
    for (double cutoff : {0.0, 0.02, 0.1, 0.25, 1.0})
      for (std::size_t excluded : {1u, 3u}) {
        const auto fast = contact::segments_within(line, cutoff, excluded);
        const auto slow = contact::segments_within_all_pairs(line, cutoff, excluded);
        ASSERT_EQ(fast.size(), slow.size()) << cutoff << " " << excluded;
        for (std::size_t k = 0; k < fast.size(); ++k) {
          EXPECT_EQ(fast[k], slow[k]);
          EXPECT_EQ(fast[k].closest.distance, slow[k].closest.distance);
        }
        total += fast.size();
      }
  EXPECT_GT(total, 1000u);  // the test polylines do fold onto themselves
}

TEST(SegmentProximity, ParallelStrandsAtExactlyTheCutoff) {
  // Two parallel strands exactly 0.1 apart across y: their uninflated boxes do not overlap on y, so
  // only the cutoff/2 inflation of each box lets the sweep see the pair; the distance test is closed.
  const std::vector<Vec3> hairpin{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 0.1, 0), Vec3(0, 0.1, 0)};
  const auto pairs = contact::segments_within(hairpin, 0.1, 1);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 0u);
  EXPECT_EQ(pairs[0].second, 2u);
  EXPECT_TRUE(contact::segments_within(hairpin, 0.0999, 1).empty());
}

TEST(SegmentProximity, BadInputNamesTheParameter) {
  EXPECT_THROW(contact::segments_within({Vec3::Zero()}, 0.1), rodvv::InputError);
  EXPECT_THROW(contact::segments_within({Vec3::Zero(), Vec3(NAN, 0, 0)}, 0.1), rodvv::InputError);
  EXPECT_THROW(contact::segments_within({Vec3::Zero(), Vec3::Ones()}, -1.0), rodvv::InputError);
  try {
    contact::segments_within({Vec3::Zero(), Vec3::Ones()}, INFINITY);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "cutoff");
  }
}

}  // namespace

#pragma once
// Proximity of the segments of a rod's centreline polyline, for self-contact (ALGORITHMS.md §4): the
// closest points of two segments (narrow phase) and the pairs of non-adjacent segments closer than a
// cutoff (broad phase), shared by every rod that detects self-contact on chords.
//
// Closest points. Segments P(s) = a0 + s (a1 - a0), Q(t) = b0 + t (b1 - b0), s, t in [0, 1];
// |P(s) - Q(t)|^2 is a convex quadratic on the unit square. With d1 = a1 - a0, d2 = b1 - b0,
// r = a0 - b0 and A = d1.d1, B = d1.d2, E = d2.d2, C = d1.r, F = d2.r, its unconstrained minimiser
// solves [A -B; -B E] (s, t) = (-C, F). Clamping s to [0, 1], taking the best t for it
// (t = (B s + F)/E), and, if that t leaves [0, 1], clamping it and re-taking the best s for it, gives
// the constrained minimiser: for a convex quadratic the partial minimiser over one variable is
// exact after the other is fixed at its optimal face (Lumelsky 1985, Inf. Proc. Letters 21:55).
// Parallel segments (A E - B^2 <= 64 eps A E) have a segment of minimisers: s = 0 is taken first
// and the rest follows the same rule, which still returns a minimiser. A zero-length segment is a
// point (its parameter 0).
//
// Broad phase: sort and sweep (Baraff 1992; Cohen et al. 1995, I-COLLIDE) along the axis of largest
// extent: each segment's bounding box, inflated by cutoff/2, is an interval on that axis; after
// sorting by interval start, one sweep finds every pair whose intervals overlap, and the other two
// axes and then the exact distance filter them. Cost O(N log N + K), K the overlapping pairs (for a
// rod, O(N) unless it is folded many times along the sweep axis). Segments i and j with |i - j| <=
// excluded_neighbours are never reported (they share a vertex, or lie within the contact distance
// along the rod by construction).
#include <cstddef>
#include <vector>

#include "rodvv/common/eigen_types.hpp"

namespace rodvv::solvers::contact {

struct SegmentClosestPoints {
  double s = 0.0, t = 0.0;  // parameters on the first and the second segment, in [0, 1]
  Vec3 p = Vec3::Zero(), q = Vec3::Zero();  // the closest points
  double distance = 0.0;                    // |p - q|
};

SegmentClosestPoints closest_points(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1);

struct SegmentPair {
  std::size_t first = 0, second = 0;  // segment indices, first < second (segment i joins vertex i to i + 1)
  SegmentClosestPoints closest;
  bool operator==(const SegmentPair& other) const { return first == other.first && second == other.second; }
};

// The pairs of segments of the open polyline `vertices` (segment i: vertices[i] to vertices[i + 1])
// at distance <= cutoff with second - first > excluded_neighbours, sorted by (first, second).
// InputError: fewer than 2 vertices, a non-finite vertex, cutoff not finite and >= 0.
std::vector<SegmentPair> segments_within(const std::vector<Vec3>& vertices, double cutoff,
                                         std::size_t excluded_neighbours = 1);

// The same by testing all pairs (O(N^2)): the oracle of the broad phase's tests, and the cheaper path
// for a handful of segments.
std::vector<SegmentPair> segments_within_all_pairs(const std::vector<Vec3>& vertices, double cutoff,
                                                   std::size_t excluded_neighbours = 1);

}  // namespace rodvv::solvers::contact

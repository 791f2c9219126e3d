#include "rodvv/solvers/contact/segment_proximity.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"

namespace rodvv::solvers::contact {

namespace {

double clamp01(double x) { return std::clamp(x, 0.0, 1.0); }

void validate(const std::vector<Vec3>& vertices, double cutoff) {
  if (vertices.size() < 2)
    throw InputError("vertices", "invalid parameter 'vertices': a polyline needs at least 2 vertices, got " +
                                     std::to_string(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
    if (!vertices[i].allFinite())
      throw InputError("vertices", "invalid parameter 'vertices': vertex " + std::to_string(i) + " is not finite");
  if (!(std::isfinite(cutoff) && cutoff >= 0.0))
    throw InputError("cutoff", "invalid parameter 'cutoff' = " + format_value(cutoff) + ": must be finite and >= 0");
}

SegmentPair pair_of(const std::vector<Vec3>& x, std::size_t i, std::size_t j) {
  return {i, j, closest_points(x[i], x[i + 1], x[j], x[j + 1])};
}

}  // namespace

SegmentClosestPoints closest_points(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  const Vec3 d1 = a1 - a0, d2 = b1 - b0, r = a0 - b0;
  const double A = d1.squaredNorm(), E = d2.squaredNorm(), B = d1.dot(d2), C = d1.dot(r), F = d2.dot(r);
  constexpr double kEps = std::numeric_limits<double>::epsilon();
  double s = 0.0, t = 0.0;
  if (A == 0.0 && E == 0.0) {
    // two points
  } else if (A == 0.0) {
    t = clamp01(F / E);
  } else if (E == 0.0) {
    s = clamp01(-C / A);
  } else {
    const double det = A * E - B * B;  // >= 0 (Cauchy-Schwarz); ~0 for parallel segments
    s = det > 64.0 * kEps * A * E ? clamp01((B * F - C * E) / det) : 0.0;
    t = (B * s + F) / E;
    if (t < 0.0) {
      t = 0.0;
      s = clamp01(-C / A);
    } else if (t > 1.0) {
      t = 1.0;
      s = clamp01((B - C) / A);
    }
  }
  SegmentClosestPoints out;
  out.s = s;
  out.t = t;
  out.p = a0 + s * d1;
  out.q = b0 + t * d2;
  out.distance = (out.p - out.q).norm();
  return out;
}

std::vector<SegmentPair> segments_within_all_pairs(const std::vector<Vec3>& vertices, double cutoff,
                                                   std::size_t excluded_neighbours) {
  validate(vertices, cutoff);
  const std::size_t n = vertices.size() - 1;
  std::vector<SegmentPair> pairs;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + excluded_neighbours + 1; j < n; ++j) {
      SegmentPair pair = pair_of(vertices, i, j);
      if (pair.closest.distance <= cutoff) pairs.push_back(pair);
    }
  return pairs;
}

std::vector<SegmentPair> segments_within(const std::vector<Vec3>& vertices, double cutoff,
                                         std::size_t excluded_neighbours) {
  validate(vertices, cutoff);
  const std::size_t n = vertices.size() - 1;
  std::vector<Vec3> low(n), high(n);
  Vec3 lowest = Vec3::Constant(std::numeric_limits<double>::infinity()), highest = -lowest;
  for (std::size_t i = 0; i < n; ++i) {
    low[i] = vertices[i].cwiseMin(vertices[i + 1]).array() - 0.5 * cutoff;
    high[i] = vertices[i].cwiseMax(vertices[i + 1]).array() + 0.5 * cutoff;
    lowest = lowest.cwiseMin(low[i]);
    highest = highest.cwiseMax(high[i]);
  }
  Eigen::Index axis = 0;
  (highest - lowest).maxCoeff(&axis);
  std::vector<std::size_t> order(n);
  for (std::size_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return low[a][axis] < low[b][axis] || (low[a][axis] == low[b][axis] && a < b);
  });
  std::vector<SegmentPair> pairs;
  std::vector<std::size_t> active;  // segments whose interval may still overlap later starts
  for (std::size_t k : order) {
    const double start = low[k][axis];
    // Boxes are closed intervals: a pair touching at exactly `start` overlaps (<=, not <).
    std::erase_if(active, [&](std::size_t a) { return high[a][axis] < start; });
    for (std::size_t a : active) {
      const std::size_t i = std::min(a, k), j = std::max(a, k);
      if (j - i <= excluded_neighbours) continue;
      if (((low[a].array() > high[k].array()) || (low[k].array() > high[a].array())).any()) continue;
      SegmentPair pair = pair_of(vertices, i, j);
      if (pair.closest.distance <= cutoff) pairs.push_back(pair);
    }
    active.push_back(k);
  }
  std::sort(pairs.begin(), pairs.end(), [](const SegmentPair& x, const SegmentPair& y) {
    return x.first < y.first || (x.first == y.first && x.second < y.second);
  });
  return pairs;
}

}  // namespace rodvv::solvers::contact

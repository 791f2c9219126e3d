#include "rodvv/solvers/rod3d/self_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/cubic_barrier.hpp"
#include "rodvv/solvers/contact/segment_proximity.hpp"
#include "taylor2.hpp"

namespace rodvv::solvers::rod3d {

namespace {

contact::CubicBarrier barrier(const SelfContact& contact) { return {contact.radius, contact.stiffness}; }

constexpr int kPairDofs = 12;  // a0, a1, b0, b1
using PairJet = taylor2::Jet<kPairDofs, 2>;

void validate(const SelfContact& contact, double edge_length) {
  require_positive("radius", contact.radius);
  if (is_hard(contact)) {
    if (contact.stiffness != 0.0)
      throw InputError("stiffness", "invalid parameter 'stiffness' = " + format_value(contact.stiffness) +
                                        ": must be 0 with the hard contact law (it has no barrier)");
  } else {
    require_positive("stiffness", contact.stiffness);
  }
  require_positive("edge_length", edge_length);
}

struct JetVector {
  std::array<PairJet, 3> c;
};
JetVector operator-(const JetVector& a, const JetVector& b) {
  return {{a.c[0] - b.c[0], a.c[1] - b.c[1], a.c[2] - b.c[2]}};
}
PairJet dot(const JetVector& a, const JetVector& b) { return a.c[0] * b.c[0] + a.c[1] * b.c[1] + a.c[2] * b.c[2]; }

// The pair distance as a jet in the 12 endpoint coordinates, within the active set of `closest`:
// a parameter at exactly 0 or 1 is held there, an interior one follows its normal equation.
PairJet distance_jet(const std::array<Vec3, 4>& ends, const contact::SegmentClosestPoints& closest) {
  std::array<JetVector, 4> p;
  for (int k = 0; k < 4; ++k)
    for (int c = 0; c < 3; ++c) p[k].c[c] = PairJet::variable(ends[k][c], 3 * k + c);
  const JetVector d1 = p[1] - p[0], d2 = p[3] - p[2], r = p[0] - p[2];
  const PairJet A = dot(d1, d1), B = dot(d1, d2), E = dot(d2, d2), C = dot(d1, r), F = dot(d2, r);
  const bool s_free = closest.s > 0.0 && closest.s < 1.0, t_free = closest.t > 0.0 && closest.t < 1.0;
  PairJet s(closest.s), t(closest.t);
  if (s_free && t_free) {
    const PairJet det = A * E - B * B;
    s = (B * F - C * E) / det;
    t = (A * F - B * C) / det;
  } else if (t_free) {
    t = (B * s + F) / E;
  } else if (s_free) {
    s = (B * t - C) / A;
  }
  JetVector gap;
  for (int c = 0; c < 3; ++c) gap.c[c] = r.c[c] + s * d1.c[c] - t * d2.c[c];
  return sqrt(dot(gap, gap));
}

std::vector<ContactPair> find_contacts(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length,
                                       double reach) {
  validate(contact, edge_length);
  std::vector<ContactPair> pairs;
  for (const auto& near : contact::segments_within(x, reach, contact_excluded_neighbours(contact.radius, edge_length))) {
    const auto& cp = near.closest;
    if (!(cp.distance < reach)) continue;
    if (!(cp.distance > 0.0))
      throw SolverError("rod3d self-contact", "segments " + std::to_string(near.first) + " and " +
                                                  std::to_string(near.second) + " intersect (distance 0)",
                        0, 0.0);
    ContactPair pair;
    pair.first = near.first;
    pair.second = near.second;
    pair.s = cp.s;
    pair.t = cp.t;
    pair.distance = cp.distance;
    pair.normal = (cp.p - cp.q) / cp.distance;
    pair.force = is_hard(contact) ? 0.0 : barrier(contact).force(cp.distance);
    pairs.push_back(pair);
  }
  return pairs;
}

}  // namespace

std::size_t contact_excluded_neighbours(double radius, double edge_length) {
  require_positive("radius", radius);
  require_positive("edge_length", edge_length);
  return std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(std::numbers::pi * radius / edge_length)));
}

std::vector<ContactPair> self_contacts(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length) {
  return find_contacts(contact, x, edge_length, 2.0 * contact.radius);
}

std::vector<ContactPair> contact_candidates(const SelfContact& contact, const std::vector<Vec3>& x,
                                            double edge_length, double reach) {
  if (!(reach >= 2.0 * contact.radius) || !std::isfinite(reach))
    throw InputError("reach", "invalid parameter 'reach' = " + format_value(reach) +
                                  ": must be finite and at least the contact distance 2h = " +
                                  format_value(2.0 * contact.radius));
  return find_contacts(contact, x, edge_length, reach);
}

double pass_through_free_fraction(const SelfContact& contact, const std::vector<Vec3>& x, const std::vector<Vec3>& u,
                                  double edge_length) {
  validate(contact, edge_length);
  if (u.size() != x.size())
    throw InputError("u", "invalid parameter 'u': " + std::to_string(u.size()) + " displacements for " +
                              std::to_string(x.size()) + " vertices");
  double largest = 0.0;
  for (const Vec3& ui : u) {
    if (!ui.allFinite()) throw InputError("u", "invalid parameter 'u': a displacement is not finite");
    largest = std::max(largest, ui.norm());
  }
  const double h = contact.radius;
  // Pairs farther apart than 2h + 2 max |u| cannot come within h of each other.
  double alpha = 1.0;
  for (const auto& pair :
       contact::segments_within(x, 2.0 * h + 2.0 * largest, contact_excluded_neighbours(h, edge_length))) {
    double w = 0.0;
    for (std::size_t a : {pair.first, pair.first + 1})
      for (std::size_t b : {pair.second, pair.second + 1}) w = std::max(w, (u[a] - u[b]).norm());
    const double d = pair.closest.distance;
    const double room = d >= 2.0 * h ? d - h : 0.5 * d;
    if (alpha * w > room) alpha = room / w;
  }
  return alpha;
}

std::array<Vec3, 4> distance_gradient(const ContactPair& pair) {
  const Vec3& n = pair.normal;
  return {(1.0 - pair.s) * n, pair.s * n, -(1.0 - pair.t) * n, -pair.t * n};
}

void contact_force_hessian(const std::vector<Vec3>& x, const std::vector<ContactPair>& pairs,
                           std::vector<Eigen::Triplet<double>>& hessian) {
  for (const auto& pair : pairs) {
    if (pair.force == 0.0) continue;
    const auto vertex = pair_vertices(pair);
    contact::SegmentClosestPoints closest;
    closest.s = pair.s;
    closest.t = pair.t;
    const PairJet d = distance_jet({x[vertex[0]], x[vertex[1]], x[vertex[2]], x[vertex[3]]}, closest);
    for (int a = 0; a < kPairDofs; ++a)
      for (int b = 0; b < kPairDofs; ++b) {
        const double value = -pair.force * d.hessian(a, b);
        if (value != 0.0)
          hessian.emplace_back(int(3 * vertex[a / 3] + a % 3), int(3 * vertex[b / 3] + b % 3), value);
      }
  }
}

double contact_pair_energy(const SelfContact& contact, double distance) {
  return is_hard(contact) ? 0.0 : barrier(contact).energy(distance);
}

double self_contact_energy(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length) {
  if (is_hard(contact)) return 0.0;
  double energy = 0.0;
  for (const auto& pair : self_contacts(contact, x, edge_length)) energy += contact_pair_energy(contact, pair.distance);
  return energy;
}

void self_contact_derivatives(const SelfContact& contact, const std::vector<Vec3>& x, double edge_length,
                              std::vector<Vec3>& gradient, std::vector<Eigen::Triplet<double>>* hessian) {
  gradient.assign(x.size(), Vec3::Zero());
  if (is_hard(contact)) return;  // no energy: the forces are the statics' unknowns
  const contact::CubicBarrier law = barrier(contact);
  for (const auto& pair : self_contacts(contact, x, edge_length)) {
    const auto vertex = pair_vertices(pair);
    if (!hessian) {  // the gradient alone: the envelope theorem's, no jets (a residual is 2x cheaper)
      const auto gradient_d = distance_gradient(pair);
      for (int k = 0; k < 4; ++k) gradient[vertex[k]] -= pair.force * gradient_d[k];
      continue;
    }
    const std::array<Vec3, 4> ends{x[vertex[0]], x[vertex[1]], x[vertex[2]], x[vertex[3]]};
    contact::SegmentClosestPoints closest;
    closest.s = pair.s;
    closest.t = pair.t;
    const PairJet d = distance_jet(ends, closest);
    const double d_phi = -law.force(d.v), dd_phi = law.force_rate(d.v);
    for (int a = 0; a < kPairDofs; ++a) gradient[vertex[a / 3]][a % 3] += d_phi * d.g[a];
    for (int a = 0; a < kPairDofs; ++a)
      for (int b = 0; b < kPairDofs; ++b) {
        const double value = dd_phi * d.g[a] * d.g[b] + d_phi * d.hessian(a, b);
        if (value != 0.0)
          hessian->emplace_back(int(3 * vertex[a / 3] + a % 3), int(3 * vertex[b / 3] + b % 3), value);
      }
  }
}

}  // namespace rodvv::solvers::rod3d

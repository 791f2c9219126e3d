#include "rodvv/solvers/superhelix/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/cubic_barrier.hpp"
#include "rodvv/solvers/contact/segment_proximity.hpp"
#include "rodvv/solvers/superhelix/arc_pair_contact.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"

#include "arc_point.hpp"
#include "signed_outer_products.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr double kChordSagittaFraction = 0.1;  // delta <= h / 10 (header: broad phase)
constexpr std::size_t kMaxChordsPerElement = 32;
constexpr int kMaxNewtonIterations = 60;
constexpr double kStepRoundOff = 4.0 * std::numeric_limits<double>::epsilon();

using detail::arc_point;
using detail::ArcPoint;

double curvature(const Kinematics& kinematics, std::size_t e) {
  const auto i = static_cast<Eigen::Index>(3 * e);
  return std::hypot(kinematics.q()(i + 1), kinematics.q()(i + 2));
}

// The chord polyline (c chords per element) and its sagitta bound delta.
struct ChordPolyline {
  std::size_t chords_per_element = 1;
  double sagitta = 0.0;
  std::vector<Vec3> vertices;
};
ChordPolyline chord_polyline(const Kinematics& kinematics, double radius) {
  const std::size_t n = kinematics.elements();
  const double ell = kinematics.element_length();
  double kappa_max = 0.0;
  for (std::size_t e = 0; e < n; ++e) kappa_max = std::max(kappa_max, curvature(kinematics, e));
  ChordPolyline polyline;
  // kappa (ell / c)^2 / 8 <= h / 10  <=>  c >= ell sqrt(kappa / (0.8 h))
  const double needed = std::ceil(ell * std::sqrt(kappa_max / (8.0 * kChordSagittaFraction * radius)));
  polyline.chords_per_element =
      std::clamp<std::size_t>(needed < 1.0 ? 1 : static_cast<std::size_t>(std::min(needed, 1e6)), 1,
                              kMaxChordsPerElement);
  const double chord = ell / static_cast<double>(polyline.chords_per_element);
  polyline.sagitta = kappa_max * chord * chord / 8.0;
  polyline.vertices.reserve(n * polyline.chords_per_element + 1);
  for (std::size_t e = 0; e < n; ++e)
    for (std::size_t j = 0; j < polyline.chords_per_element; ++j)
      polyline.vertices.push_back(kinematics.position(e, static_cast<double>(j) * chord));
  polyline.vertices.push_back(kinematics.tip_position());
  return polyline;
}

// The candidate element pairs (P < Q) of the broad phase.
using Candidates = std::vector<std::pair<std::size_t, std::size_t>>;

bool is_local_minimum_of_curve(const ArcFoot& foot, double ell, std::size_t element, std::size_t elements) {
  if (foot.t > 0.0 && foot.t < ell) return true;
  // An element end is a minimum of the whole curve only at the rod's ends (header: a junction's
  // minimum belongs to the element where the distance keeps falling).
  return (foot.t <= 0.0 && element == 0) || (foot.t >= ell && element + 1 == elements);
}

// The foot of `point` on the arc of `element` from the start t0 when it is in contact (closer than 2h)
// and a local minimum of the distance to the whole curve; nothing otherwise.
std::optional<ArcFoot> foot_in_contact(const Kinematics& kinematics, const SelfContact& contact, const Vec3& point,
                                       std::size_t element, double t0) {
  const ArcFoot foot = foot_on_arc(kinematics, point, element, t0);
  if (foot.distance < 2.0 * contact.radius &&
      is_local_minimum_of_curve(foot, kinematics.element_length(), element, kinematics.elements()))
    return foot;
  return std::nullopt;
}

// The contacts of the Gauss points of `point_element` with the arc of `foot_element`.
void add_contacts(const Kinematics& kinematics, const SelfContact& contact, const ChordPolyline& polyline,
                  const std::vector<double>& weights, std::size_t point_element, std::size_t foot_element,
                  std::vector<ArcContact>& contacts) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  const double ell = kinematics.element_length();
  const std::size_t per = kinematics.points_per_element(), c = polyline.chords_per_element;
  for (std::size_t g = 0; g < per; ++g) {
    const GaussPoint& point = kinematics.points()[point_element * per + g];
    // Start at the nearest chord vertex of the foot's element (in its basin: chords are short
    // against the arc's radius of curvature).
    std::size_t nearest = 0;
    for (std::size_t j = 1; j <= c; ++j)
      if ((polyline.vertices[foot_element * c + j] - point.position).squaredNorm() <
          (polyline.vertices[foot_element * c + nearest] - point.position).squaredNorm())
        nearest = j;
    const std::optional<ArcFoot> found = foot_in_contact(kinematics, contact, point.position, foot_element,
                                                         ell * static_cast<double>(nearest) / static_cast<double>(c));
    if (!found) continue;
    const ArcFoot& foot = *found;
    if (!(foot.distance > 0.0))
      throw SolverError("superhelix self-contact",
                        "a Gauss point of element " + std::to_string(point_element) + " lies on the centreline of element " +
                            std::to_string(foot_element) + " (distance 0)",
                        static_cast<std::size_t>(foot.iterations), 0.0);
    ArcContact pair;
    pair.first = point_element;
    pair.second = foot_element;
    pair.s = point.sigma;
    pair.t = foot.t;
    pair.weight = 0.25 * weights[g] * ell;  // w ell / 2 on this side, half of it
    pair.p = point.position;
    pair.q = foot.position;
    pair.distance = foot.distance;
    pair.normal = (pair.p - pair.q) / foot.distance;
    pair.force = pair.weight * law.force(foot.distance);
    contacts.push_back(pair);
  }
}

std::vector<ArcContact> resolve(const Kinematics& kinematics, const SelfContact& contact,
                                const ChordPolyline& polyline, Candidates candidates) {
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  std::vector<double> nodes, weights;
  gauss_legendre(kinematics.points_per_element(), nodes, weights);
  std::vector<ArcContact> contacts;
  for (const auto& [P, Q] : candidates) {
    add_contacts(kinematics, contact, polyline, weights, P, Q, contacts);
    add_contacts(kinematics, contact, polyline, weights, Q, P, contacts);
  }
  std::sort(contacts.begin(), contacts.end(), [](const ArcContact& a, const ArcContact& b) {
    return std::tie(a.first, a.s, a.second) < std::tie(b.first, b.s, b.second);
  });
  return contacts;
}

}  // namespace

void validate(const SelfContact& contact) { validate_self_contact(contact, ""); }

std::size_t contact_excluded_elements(double radius, double element_length) {
  require_positive("radius", radius);
  require_positive("element_length", element_length);
  const double m = std::ceil(std::numbers::pi * radius / element_length);
  if (!(m < 1e9))
    throw InputError("radius", "invalid parameter 'radius': pi h / ell = " + format_value(m) +
                                   " elements; the radius must be small against the rod");
  return std::max<std::size_t>(1, static_cast<std::size_t>(m));
}

ArcFoot foot_on_arc(const Kinematics& kinematics, const Vec3& point, std::size_t element, double t0) {
  const double ell = kinematics.element_length();
  double t = std::clamp(t0, 0.0, ell);
  ArcPoint b = arc_point(kinematics, element, t);
  Vec3 gap = point - b.r;
  double f = 0.5 * gap.squaredNorm();
  ArcFoot foot;
  for (int iteration = 1; iteration <= kMaxNewtonIterations; ++iteration) {
    foot.iterations = iteration;
    // f(t) = 1/2 |point - r(t)|^2: f' = -gap . n0, f'' = 1 - gap . n0' (|n0| = 1).
    const double g = -gap.dot(b.tangent), H = 1.0 - gap.dot(b.tangent_rate);
    if ((t <= 0.0 && g >= 0.0) || (t >= ell && g <= 0.0)) break;  // at an end, pushed outwards: KKT
    // Newton where f is convex, else a gradient step (f'' ~ 1 in these units).
    const double step = H > 0.0 ? -g / H : -g;
    if (std::abs(step) <= kStepRoundOff * ell) break;
    double alpha = 1.0;
    bool moved = false;
    for (int halving = 0; halving < 50; ++halving, alpha *= 0.5) {
      const double trial = std::clamp(t + alpha * step, 0.0, ell);
      const double taken = g * (trial - t);
      if (!(taken < 0.0)) continue;
      const ArcPoint tb = arc_point(kinematics, element, trial);
      const Vec3 trial_gap = point - tb.r;
      const double trial_f = 0.5 * trial_gap.squaredNorm();
      // Near the foot f's decrease drowns in its rounding (eps f) long before t is at round-off:
      // there a full Newton step is taken when it reduces |f'| instead.
      const bool final_step =
          halving == 0 && std::abs(step) <= 1e-6 * ell && std::abs(trial_gap.dot(tb.tangent)) < std::abs(g);
      if (final_step || trial_f <= f + 1e-4 * taken) {
        moved = true;
        t = trial;
        b = tb;
        gap = trial_gap;
        f = trial_f;
        break;
      }
    }
    if (!moved) break;  // no decrease left at round-off
  }
  foot.t = t;
  foot.position = b.r;
  foot.distance = gap.norm();
  return foot;
}

std::vector<ArcContact> self_contacts(const Kinematics& kinematics, const SelfContact& contact) {
  validate(contact);
  const double reach = 2.0 * contact.radius;
  if (is_hard(contact)) return closest_arc_pairs(kinematics, contact, reach);
  return resolve(kinematics, contact, chord_polyline(kinematics, contact.radius),
                 contact_element_pairs(kinematics, contact, reach));
}

std::vector<std::pair<std::size_t, std::size_t>> contact_element_pairs(const Kinematics& kinematics,
                                                                       const SelfContact& contact, double reach) {
  validate(contact);
  if (!(reach >= 2.0 * contact.radius && reach < std::numeric_limits<double>::infinity()))
    throw InputError("reach", "invalid parameter 'reach' = " + format_value(reach) +
                                  ": must be finite and at least the contact distance 2h = " +
                                  format_value(2.0 * contact.radius));
  const std::size_t excluded = contact_excluded_elements(contact.radius, kinematics.element_length());
  const ChordPolyline polyline = chord_polyline(kinematics, contact.radius);
  const std::size_t c = polyline.chords_per_element;
  // Chords of elements more than `excluded` apart are more than excluded * c chords apart.
  Candidates candidates;
  for (const auto& near : contact::segments_within(polyline.vertices, reach + 2.0 * polyline.sagitta, excluded * c))
    if (near.second / c - near.first / c > excluded) candidates.emplace_back(near.first / c, near.second / c);
  std::sort(candidates.begin(), candidates.end());
  candidates.erase(std::unique(candidates.begin(), candidates.end()), candidates.end());
  return candidates;
}

std::vector<ArcContact> self_contacts_all_pairs(const Kinematics& kinematics, const SelfContact& contact) {
  validate(contact);
  const std::size_t n = kinematics.elements();
  const std::size_t excluded = contact_excluded_elements(contact.radius, kinematics.element_length());
  Candidates candidates;
  for (std::size_t P = 0; P < n; ++P)
    for (std::size_t Q = P + excluded + 1; Q < n; ++Q) candidates.emplace_back(P, Q);
  return resolve(kinematics, contact, chord_polyline(kinematics, contact.radius), std::move(candidates));
}

double self_contact_energy(const SelfContact& contact, const std::vector<ArcContact>& contacts) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  double energy = 0.0;
  for (const auto& pair : contacts) energy += pair.weight * law.energy(pair.distance);
  return energy;
}

VecX self_contact_generalized_force(const Kinematics& kinematics, const std::vector<ArcContact>& contacts) {
  VecX force = VecX::Zero(3 * static_cast<Eigen::Index>(kinematics.elements()));
  for (const auto& pair : contacts) {
    force.noalias() += pair.force * (kinematics.position_jacobian(pair.first, pair.s).transpose() * pair.normal);
    force.noalias() -= pair.force * (kinematics.position_jacobian(pair.second, pair.t).transpose() * pair.normal);
  }
  return force;
}

double contact_field(const Kinematics& kinematics, const SelfContact& contact, std::size_t element, double sigma) {
  validate(contact);
  if (is_hard(contact)) return 0.0;  // no barrier, no field: the forces act through n(s) alone
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  const std::size_t n = kinematics.elements();
  const double ell = kinematics.element_length();
  const std::size_t excluded = contact_excluded_elements(contact.radius, ell);
  const Vec3 point = kinematics.position(element, sigma);
  constexpr int kStarts = 4;  // the foot search starts at the nearest of 5 points of the arc
  double field = 0.0;
  for (std::size_t Q = 0; Q < n; ++Q) {
    if (Q + excluded >= element && Q <= element + excluded) continue;
    // An arc lies within ell / 2 (arclength) of its midpoint.
    if ((kinematics.position(Q, 0.5 * ell) - point).norm() > 0.5 * ell + 2.0 * contact.radius) continue;
    double start = 0.0, nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j <= kStarts; ++j) {
      const double t = ell * j / kStarts, distance = (kinematics.position(Q, t) - point).norm();
      if (distance < nearest) {
        nearest = distance;
        start = t;
      }
    }
    if (const auto foot = foot_in_contact(kinematics, contact, point, Q, start))
      field += 0.5 * law.energy(foot->distance);
  }
  return field;
}

MatX self_contact_hessian(const Kinematics& kinematics, const SelfContact& contact,
                          const std::vector<ArcContact>& contacts) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  const double ell = kinematics.element_length();
  const auto size = 3 * static_cast<Eigen::Index>(kinematics.elements());
  // Every term but the held loads' is a weighted outer product u w u^T of a vector u = J^T v (J: 3 x 3N):
  // phi'' (J^T n)(J^T n)^T, the normal's rotation -f/d J^T (I - n n^T) J = -f/d sum over an orthonormal
  // pair b1, b2 perpendicular to n of (J^T b)(J^T b)^T, and the foot's motion +f/D_tt D_qt D_qt^T. They are
  // summed by two symmetric rank-k updates (signed_outer_products.hpp), one product instead of four dense
  // outer products per contact.
  detail::SignedOuterProducts terms;
  // -f n . d2(Delta)/dq2 is the dead-load stiffness of the forces -f n at the point and +f n at the
  // foot (F = sum J^T f is linear in f).
  std::vector<PointLoad> held;
  for (const auto& pair : contacts) {
    const double d = pair.distance, f = pair.force, stiffness = pair.weight * law.force_rate(d);
    const Vec3& n = pair.normal;
    const MatX J = kinematics.position_jacobian(pair.first, pair.s) - kinematics.position_jacobian(pair.second, pair.t);
    const Vec3 b1 = n.unitOrthogonal(), b2 = n.cross(b1);
    terms.add(J.transpose() * n, stiffness);
    terms.add(J.transpose() * b1, -f / d);
    terms.add(J.transpose() * b2, -f / d);
    held.push_back({pair.first, pair.s, -f * n});
    held.push_back({pair.second, pair.t, f * n});
    if (!(pair.t > 0.0 && pair.t < ell)) continue;  // a foot at an end of the rod stays there
    // The foot's motion: + f D_qt D_tt^-1 D_tq (the distance's curvature -D_qt D_tt^-1 D_tq, times -f).
    const ArcPoint Q = arc_point(kinematics, pair.second, pair.t);
    const double Dtt = (1.0 - std::pow(n.dot(Q.tangent), 2)) / d - n.dot(Q.tangent_rate);
    if (!(Dtt > 0.0)) continue;
    const Vec3 across = Q.tangent - n.dot(Q.tangent) * n;  // (I - n n^T) T_Q
    const VecX Dqt = -(J.transpose() * across) / d -
                     kinematics.rotation_jacobian(pair.second, pair.t).transpose() * Q.tangent.cross(n);
    terms.add(Dqt, f / Dtt);
  }
  MatX hessian = terms.sum(size);
  hessian += point_load_jacobian(kinematics, held);
  return hessian;
}

}  // namespace rodvv::solvers::superhelix

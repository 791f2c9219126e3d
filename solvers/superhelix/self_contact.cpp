#include "rodvv/solvers/superhelix/self_contact.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <utility>

#include <Eigen/Eigenvalues>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/cubic_barrier.hpp"
#include "rodvv/solvers/contact/segment_proximity.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr double kChordSagittaFraction = 0.1;  // delta <= h / 10 (header: broad phase)
constexpr std::size_t kMaxChordsPerElement = 32;
constexpr int kMaxNewtonIterations = 60;

// Position, tangent n0 and its derivative R (q x e0) of element e at offset sigma.
struct ArcPoint {
  Vec3 r, tangent, tangent_rate;
};
ArcPoint arc_point(const Kinematics& kinematics, std::size_t e, double sigma) {
  const Mat3 R = kinematics.frame(e, sigma);
  const Vec3 q = kinematics.q().segment<3>(3 * static_cast<Eigen::Index>(e));
  return {kinematics.position(e, sigma), R.col(0), R * q.cross(Vec3::UnitX())};
}

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

// A candidate element pair with its start point (the closest chord points).
struct Candidate {
  double chord_distance = std::numeric_limits<double>::infinity();
  double s = 0.0, t = 0.0;
};
using CandidateMap = std::map<std::pair<std::size_t, std::size_t>, Candidate>;

void offer(CandidateMap& candidates, const ChordPolyline& polyline, double ell, std::size_t chord_a,
           std::size_t chord_b, const contact::SegmentClosestPoints& closest) {
  const std::size_t c = polyline.chords_per_element;
  const double chord = ell / static_cast<double>(c);
  Candidate& candidate = candidates[{chord_a / c, chord_b / c}];
  if (closest.distance < candidate.chord_distance) {
    candidate.chord_distance = closest.distance;
    candidate.s = (static_cast<double>(chord_a % c) + closest.s) * chord;
    candidate.t = (static_cast<double>(chord_b % c) + closest.t) * chord;
  }
}

std::vector<ArcContact> resolve(const Kinematics& kinematics, const SelfContact& contact,
                                const CandidateMap& candidates) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  std::vector<ArcContact> contacts;
  for (const auto& [elements, candidate] : candidates) {
    const ArcClosestPoints closest =
        closest_points_on_arcs(kinematics, elements.first, elements.second, candidate.s, candidate.t);
    if (!(closest.distance < 2.0 * contact.radius)) continue;
    if (!(closest.distance > 0.0))
      throw SolverError("superhelix self-contact",
                        "the arcs of elements " + std::to_string(elements.first) + " and " +
                            std::to_string(elements.second) + " intersect (distance 0)",
                        closest.iterations, 0.0);
    ArcContact pair;
    pair.first = elements.first;
    pair.second = elements.second;
    pair.s = closest.s;
    pair.t = closest.t;
    pair.p = closest.p;
    pair.q = closest.q;
    pair.distance = closest.distance;
    pair.normal = (closest.p - closest.q) / closest.distance;
    pair.force = law.force(closest.distance);
    contacts.push_back(pair);
  }
  return contacts;  // std::map iterates in (first, second) order
}

}  // namespace

void validate(const SelfContact& contact) {
  require_positive("radius", contact.radius);
  require_positive("stiffness", contact.stiffness);
}

std::size_t contact_excluded_elements(double radius, double element_length) {
  require_positive("radius", radius);
  require_positive("element_length", element_length);
  const double m = std::ceil(std::numbers::pi * radius / element_length);
  if (!(m < 1e9)) throw InputError("radius", "pi h / ell = " + std::to_string(m) + ": the radius is not small against the element length");
  return std::max<std::size_t>(1, static_cast<std::size_t>(m));
}

ArcClosestPoints closest_points_on_arcs(const Kinematics& kinematics, std::size_t first, std::size_t second,
                                        double s0, double t0) {
  const double ell = kinematics.element_length();
  double x[2] = {std::clamp(s0, 0.0, ell), std::clamp(t0, 0.0, ell)};
  ArcPoint a = arc_point(kinematics, first, x[0]), b = arc_point(kinematics, second, x[1]);
  Vec3 gap = a.r - b.r;
  double f = 0.5 * gap.squaredNorm();
  ArcClosestPoints result;
  for (int iteration = 1; iteration <= kMaxNewtonIterations; ++iteration) {
    result.iterations = iteration;
    // f = 1/2 |r_a(s) - r_b(t)|^2: gradient (gap.n0_a, -gap.n0_b); Hessian with |n0| = 1.
    const double g[2] = {gap.dot(a.tangent), -gap.dot(b.tangent)};
    const double cross = -a.tangent.dot(b.tangent);
    const double H[2][2] = {{1.0 + gap.dot(a.tangent_rate), cross}, {cross, 1.0 - gap.dot(b.tangent_rate)}};
    // A parameter at a bound whose gradient pushes it outwards stays fixed (projected Newton).
    bool free[2];
    for (int i = 0; i < 2; ++i) free[i] = !((x[i] <= 0.0 && g[i] > 0.0) || (x[i] >= ell && g[i] < 0.0));
    // Newton step on the free parameters with the Hessian's eigenvalues made positive (|lambda|,
    // at least 1e-10 of the largest): a valley of parallel arcs (lambda ~ 0 along it) stays a
    // descent direction instead of a singular solve.
    Eigen::Matrix2d hessian;
    hessian << (free[0] ? H[0][0] : 1.0), (free[0] && free[1] ? H[0][1] : 0.0),
        (free[0] && free[1] ? H[1][0] : 0.0), (free[1] ? H[1][1] : 1.0);
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(hessian);
    const Eigen::Vector2d lambda = eigen.eigenvalues().cwiseAbs();
    const double floor = 1e-10 * std::max(1.0, lambda.maxCoeff());
    const Eigen::Vector2d gradient(free[0] ? g[0] : 0.0, free[1] ? g[1] : 0.0);
    const Eigen::Vector2d step = -eigen.eigenvectors() *
                                 ((eigen.eigenvectors().transpose() * gradient).array() / lambda.array().max(floor)).matrix();
    if (step.cwiseAbs().sum() <= 4.0 * std::numeric_limits<double>::epsilon() * ell) break;
    // Backtracking along the projected path, Armijo 1e-4 on the displacement actually taken.
    double alpha = 1.0;
    bool moved = false;
    for (int halving = 0; halving < 50; ++halving, alpha *= 0.5) {
      const double trial[2] = {std::clamp(x[0] + alpha * step[0], 0.0, ell),
                               std::clamp(x[1] + alpha * step[1], 0.0, ell)};
      const double taken = g[0] * (trial[0] - x[0]) + g[1] * (trial[1] - x[1]);
      if (!(taken < 0.0)) continue;
      const ArcPoint ta = arc_point(kinematics, first, trial[0]), tb = arc_point(kinematics, second, trial[1]);
      const Vec3 trial_gap = ta.r - tb.r;
      const double trial_f = 0.5 * trial_gap.squaredNorm();
      // Near the minimiser f's decrease drowns in its rounding (eps f) long before z is at round-off:
      // there a full Newton step is taken when it reduces the gradient instead.
      const bool final_steps = halving == 0 && step.cwiseAbs().maxCoeff() <= 1e-6 * ell &&
                               std::hypot(trial_gap.dot(ta.tangent) * (free[0] ? 1.0 : 0.0),
                                          trial_gap.dot(tb.tangent) * (free[1] ? 1.0 : 0.0)) <
                                   std::hypot(g[0] * (free[0] ? 1.0 : 0.0), g[1] * (free[1] ? 1.0 : 0.0));
      if (final_steps || trial_f <= f + 1e-4 * taken) {
        moved = true;
        x[0] = trial[0];
        x[1] = trial[1];
        a = ta;
        b = tb;
        gap = trial_gap;
        f = trial_f;
        break;
      }
    }
    if (!moved) break;  // no decrease left at round-off
  }
  result.s = x[0];
  result.t = x[1];
  result.p = a.r;
  result.q = b.r;
  result.distance = gap.norm();
  return result;
}

std::vector<ArcContact> self_contacts(const Kinematics& kinematics, const SelfContact& contact) {
  validate(contact);
  const double ell = kinematics.element_length();
  const std::size_t excluded = contact_excluded_elements(contact.radius, ell);
  const ChordPolyline polyline = chord_polyline(kinematics, contact.radius);
  const std::size_t c = polyline.chords_per_element;
  // Chords of elements more than `excluded` apart are more than excluded * c chords apart.
  CandidateMap candidates;
  for (const auto& near : contact::segments_within(polyline.vertices, 2.0 * contact.radius + 2.0 * polyline.sagitta,
                                                   excluded * c)) {
    if (near.second / c - near.first / c <= excluded) continue;
    offer(candidates, polyline, ell, near.first, near.second, near.closest);
  }
  return resolve(kinematics, contact, candidates);
}

std::vector<ArcContact> self_contacts_all_pairs(const Kinematics& kinematics, const SelfContact& contact) {
  validate(contact);
  const double ell = kinematics.element_length();
  const std::size_t n = kinematics.elements(), excluded = contact_excluded_elements(contact.radius, ell);
  const ChordPolyline polyline = chord_polyline(kinematics, contact.radius);
  const std::size_t c = polyline.chords_per_element;
  CandidateMap candidates;
  for (std::size_t i = 0; i < n * c; ++i)
    for (std::size_t j = (i / c + excluded + 1) * c; j < n * c; ++j)
      offer(candidates, polyline, ell, i, j,
            contact::closest_points(polyline.vertices[i], polyline.vertices[i + 1], polyline.vertices[j],
                                    polyline.vertices[j + 1]));
  return resolve(kinematics, contact, candidates);
}

double self_contact_energy(const SelfContact& contact, const std::vector<ArcContact>& contacts) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  double energy = 0.0;
  for (const auto& pair : contacts) energy += law.energy(pair.distance);
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

MatX self_contact_hessian(const Kinematics& kinematics, const SelfContact& contact,
                          const std::vector<ArcContact>& contacts) {
  const contact::CubicBarrier law{contact.radius, contact.stiffness};
  const double ell = kinematics.element_length();
  const auto size = 3 * static_cast<Eigen::Index>(kinematics.elements());
  MatX hessian = MatX::Zero(size, size);
  // phi' n . d2(Delta)/dq2 is the dead-load stiffness of the forces phi' n = -force n at the first
  // point and +force n at the second (F = sum J^T f is linear in f).
  std::vector<PointLoad> held;
  for (const auto& pair : contacts) {
    const double d = pair.distance, d_phi = -pair.force, dd_phi = law.force_rate(d);
    const Vec3& n = pair.normal;
    const ArcPoint P = arc_point(kinematics, pair.first, pair.s), Q = arc_point(kinematics, pair.second, pair.t);
    const MatX J = kinematics.position_jacobian(pair.first, pair.s) - kinematics.position_jacobian(pair.second, pair.t);
    const Mat3 transverse = Mat3::Identity() - n * n.transpose();
    const VecX gradient = J.transpose() * n;  // dd/dq
    const MatX JT = transverse * J;           // (I - n n^T) J_Delta
    hessian.noalias() += dd_phi * gradient * gradient.transpose();
    hessian.noalias() += (d_phi / d) * (J.transpose() * JT);
    held.push_back({pair.first, pair.s, -pair.force * n});
    held.push_back({pair.second, pair.t, pair.force * n});
    // Minus the closest points' motion: D_qz D_zz^+ D_zq over the free parameters (implicit function
    // theorem on the stationarity of the distance in z = (s, t)).
    const bool free_s = pair.s > 0.0 && pair.s < ell, free_t = pair.t > 0.0 && pair.t < ell;
    if (!free_s && !free_t) continue;
    MatX Dqz(size, 2);
    Dqz.col(0) = JT.transpose() * P.tangent / d +
                 kinematics.rotation_jacobian(pair.first, pair.s).transpose() * P.tangent.cross(n);
    Dqz.col(1) = -(JT.transpose() * Q.tangent) / d -
                 kinematics.rotation_jacobian(pair.second, pair.t).transpose() * Q.tangent.cross(n);
    Eigen::Matrix2d Dzz;
    Dzz(0, 0) = (1.0 - std::pow(n.dot(P.tangent), 2)) / d + n.dot(P.tangent_rate);
    Dzz(1, 1) = (1.0 - std::pow(n.dot(Q.tangent), 2)) / d - n.dot(Q.tangent_rate);
    Dzz(0, 1) = Dzz(1, 0) = -(P.tangent.dot(Q.tangent) - n.dot(P.tangent) * n.dot(Q.tangent)) / d;
    if (!free_s || !free_t) {  // one parameter at its bound: a 1 x 1 problem in the other
      const int i = free_s ? 0 : 1;
      if (Dzz(i, i) > 0.0) hessian.noalias() -= (d_phi / Dzz(i, i)) * Dqz.col(i) * Dqz.col(i).transpose();
      continue;
    }
    // Pseudo-inverse: arcs parallel along a valley of minimisers (D_zz singular) move nothing there.
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen(Dzz);
    const double cutoff = 1e-10 * eigen.eigenvalues().cwiseAbs().maxCoeff();
    for (int k = 0; k < 2; ++k) {
      const double lambda = eigen.eigenvalues()(k);
      if (!(std::abs(lambda) > cutoff)) continue;
      const VecX u = Dqz * eigen.eigenvectors().col(k);
      hessian.noalias() -= (d_phi / lambda) * u * u.transpose();
    }
  }
  hessian += point_load_jacobian(kinematics, held);
  return hessian;
}

}  // namespace rodvv::solvers::superhelix

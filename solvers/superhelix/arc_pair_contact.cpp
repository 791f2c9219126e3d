#include "rodvv/solvers/superhelix/arc_pair_contact.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"

#include "arc_point.hpp"
#include "signed_outer_products.hpp"

namespace rodvv::solvers::superhelix {

namespace {

using detail::arc_point;
using detail::ArcPoint;
using Vec2 = Eigen::Vector2d;
using Mat2 = Eigen::Matrix2d;

constexpr int kMaxNewtonIterations = 100;
constexpr double kCurvatureFloor = 1e-6;  // D's Hessian in (s, t) is ~1 (|T| = 1) away from parallel arcs
constexpr double kStepRoundOff = 4.0 * std::numeric_limits<double>::epsilon();
constexpr double kSlideFloor = 1e-8;  // D_xx's eigenvalues at or below kSlideFloor / d: parallel strands (header)
constexpr std::size_t kSeedsPerElement = 4;  // the start: the nearest of 5 x 5 points of the two arcs

struct PairPoint {
  ArcPoint P, Q;
  Vec3 gap;  // r_P - r_Q
  double f = 0.0;  // 1/2 |gap|^2
};

PairPoint pair_point(const Kinematics& kinematics, std::size_t P, std::size_t Q, const Vec2& x) {
  PairPoint point{arc_point(kinematics, P, x[0]), arc_point(kinematics, Q, x[1]), Vec3::Zero(), 0.0};
  point.gap = point.P.r - point.Q.r;
  point.f = 0.5 * point.gap.squaredNorm();
  return point;
}

// The local minimum of D(s, t) on [0, ell]^2 from x0: projected Newton (variables at a bound with the
// gradient pushing out are held there, the step projected onto the box), backtracking (Armijo 1e-4).
Vec2 closest_points(const Kinematics& kinematics, std::size_t P, std::size_t Q, Vec2 x) {
  const double ell = kinematics.element_length();
  PairPoint here = pair_point(kinematics, P, Q, x);
  for (int iteration = 0; iteration < kMaxNewtonIterations; ++iteration) {
    // D_s = gap . T_P, D_t = -gap . T_Q; D_ss = 1 + gap . T_P', D_tt = 1 - gap . T_Q', D_st = -T_P . T_Q.
    const Vec2 g(here.gap.dot(here.P.tangent), -here.gap.dot(here.Q.tangent));
    Mat2 H;
    H << 1.0 + here.gap.dot(here.P.tangent_rate), -here.P.tangent.dot(here.Q.tangent),
        -here.P.tangent.dot(here.Q.tangent), 1.0 - here.gap.dot(here.Q.tangent_rate);
    bool held[2];
    for (int k = 0; k < 2; ++k) held[k] = (x[k] <= 0.0 && g[k] >= 0.0) || (x[k] >= ell && g[k] <= 0.0);
    // Newton on the free variables with the Hessian's eigenvalues taken by magnitude and at least
    // kCurvatureFloor (a saddle-free Newton step): two nearly parallel arcs make D a long valley along
    // their common sliding (T_P . T_Q ~ +-1, H nearly singular or slightly indefinite), where gradient
    // steps zigzag without end; the box then stops the long step, and the held variable's 1-D Newton
    // finishes.
    Vec2 step = Vec2::Zero();
    if (!held[0] && !held[1]) {
      const Eigen::SelfAdjointEigenSolver<Mat2> eigen(H);
      const Vec2 magnitude = eigen.eigenvalues().cwiseAbs().cwiseMax(kCurvatureFloor);
      step = -eigen.eigenvectors() * (eigen.eigenvectors().transpose() * g).cwiseQuotient(magnitude);
    } else {
      for (int k = 0; k < 2; ++k)
        if (!held[k]) step[k] = -g[k] / std::max(std::abs(H(k, k)), kCurvatureFloor);
    }
    if (step.cwiseAbs().maxCoeff() <= kStepRoundOff * ell) break;
    const auto free_part = [&](const Vec2& v) {
      return std::max(held[0] ? 0.0 : std::abs(v[0]), held[1] ? 0.0 : std::abs(v[1]));
    };
    double alpha = 1.0;
    bool moved = false;
    for (int halving = 0; halving < 50; ++halving, alpha *= 0.5) {
      const Vec2 trial = (x + alpha * step).cwiseMax(0.0).cwiseMin(ell);
      const double taken = g.dot(trial - x);
      if (!(taken < 0.0)) continue;
      const PairPoint there = pair_point(kinematics, P, Q, trial);
      // Near the minimum D's decrease drowns in its rounding: a full step that reduces the free part of
      // grad D is taken (a held variable's component stays large at the bound).
      const Vec2 trial_g(there.gap.dot(there.P.tangent), -there.gap.dot(there.Q.tangent));
      const bool final_step =
          halving == 0 && step.cwiseAbs().maxCoeff() <= 1e-6 * ell && free_part(trial_g) < free_part(g);
      if (final_step || there.f <= here.f + 1e-4 * taken) {
        x = trial;
        here = there;
        moved = true;
        break;
      }
    }
    if (!moved) break;
  }
  return x;
}

}  // namespace

std::vector<ArcContact> closest_arc_pairs(const Kinematics& kinematics, const SelfContact& contact, double reach,
                                          const std::vector<ArcContact>& previous) {
  const double ell = kinematics.element_length();
  std::vector<ArcContact> contacts;
  auto known = previous.begin();
  for (const auto& [P, Q] : contact_element_pairs(kinematics, contact, reach)) {
    // The start: the pair's closest points in `previous` (sorted like the pairs), so that an iteration
    // follows the same minimum; else the nearest pair of 5 evenly spaced points on each arc.
    while (known != previous.end() && std::make_pair(known->first, known->second) < std::make_pair(P, Q)) ++known;
    const bool seeded = known != previous.end() && known->first == P && known->second == Q;
    Vec2 start = seeded ? Vec2(known->s, known->t) : Vec2(0.0, 0.0);
    double nearest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i <= kSeedsPerElement && !seeded; ++i)
      for (std::size_t j = 0; j <= kSeedsPerElement; ++j) {
        const double s = ell * static_cast<double>(i) / kSeedsPerElement, t = ell * static_cast<double>(j) / kSeedsPerElement;
        const double distance = (kinematics.position(P, s) - kinematics.position(Q, t)).squaredNorm();
        if (distance < nearest) {
          nearest = distance;
          start = Vec2(s, t);
        }
      }
    const Vec2 x = closest_points(kinematics, P, Q, start);
    ArcContact pair;
    pair.first = P;
    pair.second = Q;
    pair.s = x[0];
    pair.t = x[1];
    pair.p = kinematics.position(P, x[0]);
    pair.q = kinematics.position(Q, x[1]);
    pair.distance = (pair.p - pair.q).norm();
    if (!(pair.distance < reach)) continue;
    if (!(pair.distance > 0.0))
      throw SolverError("superhelix self-contact",
                        "the centrelines of elements " + std::to_string(P) + " and " + std::to_string(Q) +
                            " intersect (distance 0)",
                        0, 0.0);
    pair.normal = (pair.p - pair.q) / pair.distance;
    contacts.push_back(pair);
  }
  return contacts;
}

MatX closest_pair_force_stiffness(const Kinematics& kinematics, const std::vector<ArcContact>& contacts) {
  const double ell = kinematics.element_length();
  const std::size_t n = kinematics.elements();
  const auto size = 3 * static_cast<Eigen::Index>(n);
  // As in self_contact_hessian: the outer-product terms summed by signed_outer_products.hpp, the held loads'
  // dead-load stiffness by point_load_jacobian.
  detail::SignedOuterProducts terms;
  std::vector<PointLoad> held;
  for (const auto& c : contacts) {
    const double d = c.distance, f = c.force;
    if (f == 0.0) continue;
    const Vec3& nrm = c.normal;
    const MatX J = kinematics.position_jacobian(c.first, c.s) - kinematics.position_jacobian(c.second, c.t);
    const Vec3 b1 = nrm.unitOrthogonal(), b2 = nrm.cross(b1);
    terms.add(J.transpose() * b1, -f / d);  // the normal's rotation: -f J^T (I - n n^T) J / d
    terms.add(J.transpose() * b2, -f / d);
    held.push_back({c.first, c.s, -f * nrm});  // -f n . d2(Delta)/dq2
    held.push_back({c.second, c.t, f * nrm});
    // The closest points' motion: + f D_qx D_xx^-1 D_xq over the free ones of x = (s, t).
    const ArcPoint A = arc_point(kinematics, c.first, c.s), B = arc_point(kinematics, c.second, c.t);
    const bool free_s = c.s > 0.0 && c.s < ell, free_t = c.t > 0.0 && c.t < ell;
    // d_s = n . T_P, d_t = -n . T_Q; D_ss = (1 - (n.T_P)^2)/d + n.T_P', D_tt = (1 - (n.T_Q)^2)/d - n.T_Q',
    // D_st = -(T_P.T_Q - (n.T_P)(n.T_Q))/d; D_qs = J^T (I - n n^T) T_P / d + Theta_P^T (T_P x n), and
    // D_qt = -J^T (I - n n^T) T_Q / d - Theta_Q^T (T_Q x n).
    const double nP = nrm.dot(A.tangent), nQ = nrm.dot(B.tangent);
    Mat2 Dxx;
    Dxx << (1.0 - nP * nP) / d + nrm.dot(A.tangent_rate), -(A.tangent.dot(B.tangent) - nP * nQ) / d,
        -(A.tangent.dot(B.tangent) - nP * nQ) / d, (1.0 - nQ * nQ) / d - nrm.dot(B.tangent_rate);
    MatX Dqx(size, 2);
    Dqx.col(0) = J.transpose() * (A.tangent - nP * nrm) / d +
                 kinematics.rotation_jacobian(c.first, c.s).transpose() * A.tangent.cross(nrm);
    Dqx.col(1) = -(J.transpose() * (B.tangent - nQ * nrm)) / d -
                 kinematics.rotation_jacobian(c.second, c.t).transpose() * B.tangent.cross(nrm);
    if (free_s && free_t) {
      const Eigen::SelfAdjointEigenSolver<Mat2> eigen(Dxx);
      // A direction with D_xx's eigenvalue at or below kSlideFloor / d (parallel strands) is dropped.
      for (int k = 0; k < 2; ++k)
        if (eigen.eigenvalues()[k] > kSlideFloor / d)
          terms.add(Dqx * eigen.eigenvectors().col(k), f / eigen.eigenvalues()[k]);
    } else if (free_s || free_t) {
      const int k = free_s ? 0 : 1;
      if (Dxx(k, k) > kSlideFloor / d) terms.add(Dqx.col(k), f / Dxx(k, k));
    }
  }
  MatX stiffness = terms.sum(size);
  if (!held.empty()) stiffness += point_load_jacobian(kinematics, held);
  return stiffness;
}

}  // namespace rodvv::solvers::superhelix

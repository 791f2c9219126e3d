#include "rodvv/solvers/superhelix/bundle_frictional_statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <tuple>
#include <utility>

#include "contact_active_set.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/load_stiffness.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr const char* kMethod = "superhelix frictional statics";
constexpr std::size_t kNoStrand = std::numeric_limits<std::size_t>::max();

// The foot of a point on a strand's centreline: the material point (element, sigma) nearest it.
struct Foot {
  std::size_t element = 0;
  double sigma = 0.0;
  Vec3 position, tangent;
};

// A candidate contact at the current iterate: strand's Gauss point `point` against obstacle `obstacle`,
// or (obstacle = kNoStrand) against its foot on strand `other_strand`.
struct Candidate {
  std::size_t strand, point, obstacle, other_strand;
  Foot foot;
  ObstacleProximity proximity;  // for a rod pair: gap, normal, dn/d(x_a - x_b)
  Mat3 frame;
  Vec3 force;  // r_k, local
};
using ForceKey = std::tuple<std::size_t, std::size_t, std::size_t, std::size_t>;
ForceKey key(const Candidate& c) { return {c.strand, c.point, c.obstacle, c.other_strand}; }

// The foot of x on the strand's centreline by the projection iteration s += (x - r(s)) . t(s) over the arc
// length s (Newton's without the curvature term, which converges at the rate |x - r| kappa: fast for
// strands in contact, |x - r| kappa << 1), from the nearest Gauss point, crossing element ends and stopping
// at the rod's ends; to 1e-14 L, at most 100 iterations (at a rod's end it stops there).
Foot foot_on(const Kinematics& kinematics, const Vec3& x) {
  const double ell = kinematics.element_length(), L = ell * double(kinematics.elements());
  const auto& points = kinematics.points();
  std::size_t nearest = 0;
  for (std::size_t g = 1; g < points.size(); ++g)
    if ((points[g].position - x).squaredNorm() < (points[nearest].position - x).squaredNorm()) nearest = g;
  double arc = ell * double(points[nearest].element) + points[nearest].sigma;
  Foot foot;
  for (int iteration = 0; iteration < 100; ++iteration) {
    foot.element = std::min(std::size_t(arc / ell), kinematics.elements() - 1);
    foot.sigma = arc - ell * double(foot.element);
    foot.position = kinematics.position(foot.element, foot.sigma);
    foot.tangent = kinematics.frame(foot.element, foot.sigma).col(0);
    const double next = std::clamp(arc + (x - foot.position).dot(foot.tangent), 0.0, L);
    if (std::abs(next - arc) <= 1e-14 * L) break;
    arc = next;
  }
  return foot;
}

std::vector<Vec3> point_positions(const Kinematics& kinematics) {
  std::vector<Vec3> positions;
  for (const auto& point : kinematics.points()) positions.push_back(point.position);
  return positions;
}

void check_previous(const std::vector<RodModel>& strands, const std::vector<RigidObstacle>& obstacles,
                    const BundleFrictionalResult& previous) {
  if (previous.strands.size() != strands.size())
    throw InputError("previous", "invalid parameter 'previous': holds " + std::to_string(previous.strands.size()) +
                                     " strands, must hold one per strand (" + std::to_string(strands.size()) + ")");
  for (std::size_t s = 0; s < strands.size(); ++s) {
    const RodModel& model = strands[s];
    const FrictionalStaticResult& p = previous.strands[s];
    const std::size_t points = model.elements * model.gauss_points;
    const bool fits =
        p.q.size() == Eigen::Index(dof_count(model)) && p.q.allFinite() && p.points.size() == points &&
        std::all_of(p.points.begin(), p.points.end(), [](const Vec3& x) { return x.allFinite(); }) &&
        std::all_of(p.contacts.begin(), p.contacts.end(), [&](const FrictionalContact& c) {
          return c.point < points && c.obstacle < obstacles.size() && c.local_force.allFinite();
        });
    if (!fits)
      throw InputError("previous", "invalid parameter 'previous': strand " + std::to_string(s) + " must hold q (3 N = " +
                                       std::to_string(dof_count(model)) + " finite values), one finite Gauss point "
                                       "position per Gauss point (" + std::to_string(points) +
                                       ") and contacts naming existing points and obstacles");
    if (!p.root_position.allFinite() || !p.root_frame.allFinite() ||
        !((p.root_frame.transpose() * p.root_frame - Mat3::Identity()).cwiseAbs().maxCoeff() <= 1e-10))
      throw InputError("previous", "invalid parameter 'previous': strand " + std::to_string(s) +
                                       " must hold its root's placement (a finite position and a rotation to 1e-10)");
  }
  for (const RodRodContact& c : previous.rod_contacts)
    if (c.strand >= strands.size() || c.point >= strands[c.strand].elements * strands[c.strand].gauss_points ||
        c.other_strand >= strands.size() || c.strand == c.other_strand || !c.local_force.allFinite())
      throw InputError("previous", "invalid parameter 'previous': a rod contact must join an existing Gauss point to "
                                   "another existing strand and carry a finite force");
}

// An axis-aligned box holding a strand's centreline: its Gauss points' box grown by one element length (every
// point of the centreline is within an element's arc length of its own element's Gauss points).
std::pair<Vec3, Vec3> bounding_box(const Kinematics& kinematics) {
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const auto& point : kinematics.points()) {
    lo = lo.cwiseMin(point.position);
    hi = hi.cwiseMax(point.position);
  }
  const Vec3 margin = Vec3::Constant(kinematics.element_length());
  return {lo - margin, hi + margin};
}

}  // namespace

BundleFrictionalResult bundle_frictional_start(const std::vector<RodModel>& strands, const std::vector<VecX>& q) {
  if (strands.empty() || q.size() != strands.size())
    throw InputError("strands", "invalid parameter 'strands': must be at least one, with one q each (" +
                                    std::to_string(strands.size()) + " strands, " + std::to_string(q.size()) + " q)");
  BundleFrictionalResult start;
  for (std::size_t s = 0; s < strands.size(); ++s) start.strands.push_back(frictional_start(strands[s], q[s]));
  return start;
}

BundleFrictionalResult solve_bundle_frictional_increment(const std::vector<RodModel>& strands,
                                                         const std::vector<RigidObstacle>& obstacles,
                                                         const RodRodContactLaw& law,
                                                         const BundleFrictionalResult& previous,
                                                         const FrictionalStaticOptions& options) {
  if (strands.empty()) throw InputError("strands", "invalid parameter 'strands': must hold at least one strand");
  for (const RodModel& model : strands) {
    validate(model);
    if (!model.point_forces.empty())
      throw InputError("point_forces", "invalid parameter 'point_forces': frictional statics computes the forces at "
                                       "the Gauss points itself; must be empty");
    if (model.self_contact.radius > 0.0)
      throw InputError("self_contact", "invalid parameter 'self_contact': frictional statics takes rigid obstacles "
                                       "and other strands only; self_contact.radius must be 0");
  }
  validate_obstacles(obstacles);
  if (!(std::isfinite(law.distance) && law.distance >= 0.0 && std::isfinite(law.mu) && law.mu >= 0.0))
    throw InputError("law", "invalid parameter 'law': distance " + format_value(law.distance) + " and mu " +
                                format_value(law.mu) + " must be finite and >= 0");
  check_previous(strands, obstacles, previous);
  require_non_negative("contact_distance", options.contact_distance);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);

  const std::size_t S = strands.size();
  std::vector<Eigen::Index> offset(S + 1, 0);  // strand s's coordinates in the stacked q
  for (std::size_t s = 0; s < S; ++s) offset[s + 1] = offset[s] + Eigen::Index(dof_count(strands[s]));
  const Eigen::Index n = offset[S];
  VecX k(n);  // the stacked generalised stiffness (the Levenberg shift's scale)
  std::vector<double> k_max(S), load_scale(S), reach(S);
  double rho_0 = 0.0;
  for (std::size_t s = 0; s < S; ++s) {
    const RodModel& model = strands[s];
    const double ell = element_length(model);
    reach[s] = options.contact_distance > 0.0 ? options.contact_distance : ell;
    k.segment(offset[s], offset[s + 1] - offset[s]) = generalised_stiffness(model);
    k_max[s] = k.segment(offset[s], offset[s + 1] - offset[s]).lpNorm<Eigen::Infinity>();
    rho_0 = std::max(rho_0, k_max[s] / (ell * ell));
    load_scale[s] = external_generalised_force(model, Kinematics(model, natural_strain_vector(model)))
                        .lpNorm<Eigen::Infinity>();
  }
  std::map<ForceKey, Vec3> forces;  // r_k by contact
  for (std::size_t s = 0; s < S; ++s)
    for (const auto& c : previous.strands[s].contacts) forces[{s, c.point, c.obstacle, 0}] = c.local_force;
  for (const auto& c : previous.rod_contacts) forces[{c.strand, c.point, kNoStrand, c.other_strand}] = c.local_force;
  // The strands at the previous equilibrium: where a foot's material point was.
  std::vector<Kinematics> before;
  for (std::size_t s = 0; s < S && law.distance > 0.0; ++s) {
    RodModel placed = strands[s];
    placed.root_position = previous.strands[s].root_position;
    placed.root_frame = previous.strands[s].root_frame;
    before.emplace_back(placed, previous.strands[s].q);
  }

  BundleFrictionalResult result;
  result.strands.resize(S);
  for (std::size_t s = 0; s < S; ++s) result.strands[s].q = previous.strands[s].q;
  std::vector<RodModel> loaded = strands;  // the forces r_k as dead point loads
  std::vector<double> last_step(S, std::numeric_limits<double>::infinity());
  for (std::size_t iteration = 0;; ++iteration) {
    std::vector<Kinematics> kinematics;
    for (std::size_t s = 0; s < S; ++s) {
      kinematics.emplace_back(strands[s], result.strands[s].q);
      loaded[s].point_forces.assign(strands[s].elements * strands[s].gauss_points, Vec3::Zero());
    }
    std::vector<Candidate> candidates;
    result.penetration = 0.0;
    const auto add_candidate = [&](Candidate c) {
      result.penetration = std::max(result.penetration, -c.proximity.gap);
      const double within =
          c.obstacle == kNoStrand ? std::max(reach[c.strand], reach[c.other_strand]) : reach[c.strand];
      if (c.proximity.gap > within) return;
      c.frame = contact_frame(c.proximity.normal);
      const auto known = forces.find(key(c));
      c.force = known == forces.end() ? Vec3::Zero() : known->second;
      loaded[c.strand].point_forces[c.point] += c.frame * c.force;
      candidates.push_back(std::move(c));
    };
    for (std::size_t s = 0; s < S; ++s)
      for (std::size_t g = 0; g < kinematics[s].points().size(); ++g)
        for (std::size_t o = 0; o < obstacles.size(); ++o)
          add_candidate({s, g, o, 0, {}, obstacle_proximity(obstacles[o], kinematics[s].points()[g].position), {}, {}});
    if (law.distance > 0.0) {
      std::vector<std::pair<Vec3, Vec3>> boxes;
      for (const auto& kin : kinematics) boxes.push_back(bounding_box(kin));
      for (std::size_t a = 0; a < S; ++a)
        for (std::size_t b = a + 1; b < S; ++b) {
          const double within = std::max(reach[a], reach[b]);
          const Vec3 apart = (boxes[a].first - boxes[b].second).cwiseMax(boxes[b].first - boxes[a].second);
          if (apart.maxCoeff() > law.distance + within) continue;  // the boxes are farther apart than the reach
          for (std::size_t g = 0; g < kinematics[a].points().size(); ++g) {
            const Vec3& x = kinematics[a].points()[g].position;
            if (((boxes[b].first - x).cwiseMax(x - boxes[b].second)).maxCoeff() > law.distance + within) continue;
            const Foot foot = foot_on(kinematics[b], x);
            const Vec3 between = x - foot.position;
            const double d = between.norm();
            if (!(d > 0.0))
              throw SolverError(kMethod, "a Gauss point lies on another strand's centreline: no normal there", iteration,
                                result.residual);
            ObstacleProximity proximity;
            proximity.gap = d - law.distance;
            proximity.normal = between / d;
            // n turns as x_g moves across b only: along b's tangent t the foot follows (the curvature's share,
            // d kappa, is left out: small for strands in contact)
            proximity.normal_gradient = (Mat3::Identity() - proximity.normal * proximity.normal.transpose() -
                                         foot.tangent * foot.tangent.transpose()) /
                                        d;
            add_candidate({a, g, kNoStrand, b, foot, proximity, {}, {}});
          }
        }
    }

    // The reactions -frame r at the feet as generalised forces J_b(foot)^T (-frame r) (dense: a foot is no
    // Gauss point).
    VecX foot_load = VecX::Zero(n);
    for (const Candidate& c : candidates)
      if (c.obstacle == kNoStrand && c.force != Vec3::Zero()) {
        const auto b = c.other_strand;
        foot_load.segment(offset[b], offset[b + 1] - offset[b]).noalias() -=
            kinematics[b].position_jacobian(c.foot.element, c.foot.sigma).transpose() * (c.frame * c.force);
      }
    // Every strand's residual, relative to its own scale (frictional_statics.hpp).
    VecX residual(n);
    result.residual = 0.0;
    bool step_small = true;
    for (std::size_t s = 0; s < S; ++s) {
      const VecX& q = result.strands[s].q;
      const Eigen::Index size = offset[s + 1] - offset[s];
      residual.segment(offset[s], size) = static_residual(loaded[s], q) - foot_load.segment(offset[s], size);
      // J^T f of the contact forces alone, by the tip-to-root wrench pass (loads.hpp, O(N)).
      const VecX contact_load = generalised_force(kinematics[s], loaded[s].point_forces, Vec3::Zero(), Vec3::Zero()) +
                                foot_load.segment(offset[s], size);
      const double scale = std::max({k_max[s] * q.lpNorm<Eigen::Infinity>(), k_max[s] / strands[s].length,
                                     load_scale[s], contact_load.lpNorm<Eigen::Infinity>()});
      result.residual =
          std::max(result.residual, residual.segment(offset[s], size).lpNorm<Eigen::Infinity>() / scale);
      step_small = step_small && last_step[s] * strands[s].length <=
                                     options.tolerance * (1.0 + q.lpNorm<Eigen::Infinity>() * strands[s].length);
    }
    // The relative motion of a candidate's point(s) since the previous equilibrium, in the world.
    const auto moved = [&](const Candidate& c) {
      const Vec3 own = kinematics[c.strand].points()[c.point].position - previous.strands[c.strand].points[c.point];
      if (c.obstacle != kNoStrand) return own;
      return Vec3(own - (c.foot.position - before[c.other_strand].position(c.foot.element, c.foot.sigma)));
    };
    if (iteration > 0 && result.residual <= options.tolerance && step_small) {
      for (std::size_t s = 0; s < S; ++s) {
        FrictionalStaticResult& strand = result.strands[s];
        strand.points = point_positions(kinematics[s]);
        strand.root_position = strands[s].root_position;
        strand.root_frame = strands[s].root_frame;
        strand.iterations = result.iterations;
        strand.residual = result.residual;
        strand.contact_residual = result.contact_residual;
        strand.penetration = result.penetration;
      }
      for (const auto& c : candidates) {
        const Vec3 dx = moved(c);
        const Vec3 slip(c.proximity.gap, c.frame.col(1).dot(dx), c.frame.col(2).dot(dx));
        if (c.obstacle != kNoStrand)
          result.strands[c.strand].contacts.push_back(
              {c.point, c.obstacle, c.proximity.gap, c.frame, c.force, c.frame * c.force, slip});
        else
          result.rod_contacts.push_back({c.strand, c.point, c.other_strand, c.foot.element, c.foot.sigma,
                                         c.foot.position, c.proximity.gap, c.frame, c.force, c.frame * c.force, slip});
      }
      return result;
    }
    if (iteration >= options.max_iterations)
      throw SolverError(kMethod, "no convergence in " + std::to_string(options.max_iterations) + " iterations (step " +
                                     format_value(*std::max_element(last_step.begin(), last_step.end())) + ")",
                        iteration, result.residual);
    check_time_budget(kMethod, iteration, result.residual);

    // Tangent stiffness: the dead point loads' (static_jacobian, per strand) and the normal forces' turning.
    MatX A = MatX::Zero(n, n);
    std::vector<std::vector<PointLoad>> foot_loads(S);  // the reactions at the feet, as dead loads
    for (const Candidate& c : candidates)
      if (c.obstacle == kNoStrand) foot_loads[c.other_strand].push_back({c.foot.element, c.foot.sigma, -(c.frame * c.force)});
    for (std::size_t s = 0; s < S; ++s) {
      const Eigen::Index size = offset[s + 1] - offset[s];
      A.block(offset[s], offset[s], size, size) = static_jacobian(loaded[s], result.strands[s].q);
      // their lever arms (load_stiffness.hpp: the static Jacobian is K - dF/dq)
      if (!foot_loads[s].empty())
        A.block(offset[s], offset[s], size, size) -= point_load_jacobian(kinematics[s], foot_loads[s]);
    }
    const auto m = Eigen::Index(candidates.size());
    MatX H = MatX::Zero(3 * m, n);
    VecX w(3 * m), r_k(3 * m), mu(m);
    std::vector<Eigen::Index> normal_rows, sticking;  // the contacts with a force; those strictly in their cone
    for (Eigen::Index c = 0; c < m; ++c) {
      const Candidate& candidate = candidates[std::size_t(c)];
      // J_g, or J_rel = (J_a, -J_b) for a rod pair, over the stacked coordinates
      MatX J = MatX::Zero(3, n);
      const auto& point = kinematics[candidate.strand].points()[candidate.point];
      const auto a = candidate.strand;
      J.middleCols(offset[a], offset[a + 1] - offset[a]) =
          kinematics[a].position_jacobian(point.element, point.sigma);
      if (candidate.obstacle == kNoStrand) {
        const auto b = candidate.other_strand;
        J.middleCols(offset[b], offset[b + 1] - offset[b]) =
            -kinematics[b].position_jacobian(candidate.foot.element, candidate.foot.sigma);
      }
      A.noalias() -= J.transpose() * (candidate.force[0] * candidate.proximity.normal_gradient) * J;
      if (candidate.obstacle == kNoStrand && candidate.force != Vec3::Zero()) {
        // n stays perpendicular to b's tangent t: as t turns (dt/dq_j = Theta_j x t, Theta b's rotation
        // Jacobian at the foot), n turns with it, dn = -t (t x n)^T Theta dq_b, and the foot slides along b
        // by d sigma* = t . (J_rel dq) + d (t x n)^T Theta dq_b. The first turns the force (+frame r on a,
        // -frame r on b); the second moves the reaction f_b = -frame r along b: d(J_b(sigma*)^T f_b) =
        // (dJ_b/dsigma)^T f_b d sigma*, with (dJ_b/dsigma)^T f_b = Theta^T (t x f_b).
        const auto b = candidate.other_strand;
        const double d = candidate.proximity.gap + law.distance;
        const Vec3& t = candidate.foot.tangent;
        const Vec3& normal = candidate.proximity.normal;
        MatX Theta = MatX::Zero(3, n);
        Theta.middleCols(offset[b], offset[b + 1] - offset[b]) =
            kinematics[b].rotation_jacobian(candidate.foot.element, candidate.foot.sigma);
        const Eigen::RowVectorXd tilt = t.cross(normal).transpose() * Theta;  // (t x n)^T Theta
        A.noalias() += J.transpose() * (candidate.force[0] * t) * tilt;
        const Vec3 f_b = -(candidate.frame * candidate.force);
        const VecX lever = Theta.transpose() * t.cross(f_b);
        A.noalias() -= lever * (t.transpose() * J + d * tilt);
      }
      H.middleRows(3 * c, 3) = candidate.frame.transpose() * J;
      const Vec3 dx = moved(candidate);
      w.segment<3>(3 * c) = Vec3(candidate.proximity.gap, candidate.frame.col(1).dot(dx), candidate.frame.col(2).dot(dx));
      r_k.segment<3>(3 * c) = candidate.force;
      mu[c] = candidate.obstacle == kNoStrand ? law.mu : obstacles[candidate.obstacle].mu;
      if (candidate.force[0] > 0.0) {
        normal_rows.push_back(3 * c);
        if (candidate.force.tail<2>().norm() < mu[c] * candidate.force[0]) sticking.push_back(c);
      }
    }
    // The step's matrix (frictional_statics.hpp): A, else augmented on the normal rows of the contacts that
    // carry a force, else also on the tangential rows of those that stick (their slip stays 0: a strand
    // resting on another is unstable across it without them, where the normal turns at r_N / d, d the
    // strands' distance), else shifted.
    const auto rows_of = [&](const std::vector<Eigen::Index>& rows) {
      MatX G(Eigen::Index(rows.size()), n);
      VecX g(G.rows());
      for (Eigen::Index i = 0; i < G.rows(); ++i) {
        G.row(i) = H.row(rows[std::size_t(i)]);
        g[i] = w[rows[std::size_t(i)]];
      }
      return detail::augmentation_of(G, g);
    };
    std::vector<Eigen::Index> held_rows = normal_rows;
    for (const Eigen::Index c : sticking) held_rows.insert(held_rows.end(), {3 * c + 1, 3 * c + 2});
    std::vector<detail::Augmentation> augmentations{rows_of(normal_rows)};
    if (!sticking.empty()) augmentations.push_back(rows_of(held_rows));
    const detail::StepMatrix step_matrix(A, augmentations, rho_0, k, kMethod, iteration + 1, result.residual);
    const VecX free_step = -step_matrix.solve(residual + step_matrix.augmented_rhs());
    VecX step = free_step;
    VecX r = r_k;
    if (m > 0) {
      const MatX Y = step_matrix.solve(H.transpose());  // A^-1 H^T
      MatX W = H * Y;
      const VecX b = w + H * free_step - W * r_k;
      W = 0.5 * (W + W.transpose()).eval();  // A is symmetric but for rounding and a dead end moment's part
      // A point whose tangential motion is locked to first order (on a straight stretch from the clamp of
      // an inextensible rod) has a singular Delassus block. A compliance of 1e-12 of the largest diagonal
      // keeps every block positive definite; at the fixed point it moves the gaps and slips by 1e-12 of
      // the displacements a unit force makes (below the Newton tolerance).
      W.diagonal().array() += 1e-12 * W.diagonal().maxCoeff();
      if (const auto settled = detail::active_set_contact_solve(W, b, mu, r_k)) {
        r = *settled;
        result.contact_residual = contact::cone_residual(W, b, mu, r, contact::ConeLaw::Coulomb);
      } else {
        const contact::ConeSolution solution =
            contact::solve_cone_complementarity(W, b, mu, contact::ConeLaw::Coulomb, options.cone);
        r = solution.r;
        result.contact_residual = solution.residual;
      }
      step += Y * (r - r_k);
    }
    if (!step.allFinite())
      throw SolverError(kMethod, "a non-finite Newton step (singular tangent stiffness)", iteration + 1, result.residual);
    forces.clear();
    for (Eigen::Index c = 0; c < m; ++c) forces[key(candidates[std::size_t(c)])] = r.segment<3>(3 * c);
    for (std::size_t s = 0; s < S; ++s) {
      const auto segment = step.segment(offset[s], offset[s + 1] - offset[s]);
      result.strands[s].q += segment;
      last_step[s] = segment.lpNorm<Eigen::Infinity>();
    }
    result.iterations = iteration + 1;
  }
}

}  // namespace rodvv::solvers::superhelix

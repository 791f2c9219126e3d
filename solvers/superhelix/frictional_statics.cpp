#include "rodvv/solvers/superhelix/frictional_statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr const char* kMethod = "superhelix frictional statics";

bool unit(const Vec3& v) { return v.allFinite() && std::abs(v.norm() - 1.0) <= 1e-10; }

// A candidate contact at a Gauss point, at the current iterate.
struct Candidate {
  std::size_t point, obstacle;
  ObstacleProximity proximity;
  Mat3 frame;
  Vec3 force;  // r_k, local
};

// The contact problem u = W r + b under Signorini-Coulomb by a primal-dual active set: each contact open
// (r = 0), sticking (u = 0) or sliding (u_N = 0, r_T = -mu r_N s with the slip direction s frozen), the
// statuses guessed from u at the guess r (closed if r_N > 0 or u_N < 0; sliding if its slip is not 0),
// the linear system of the statuses solved (dense LU), the statuses corrected where the result breaks its
// law (r_N < 0: open; u_N < 0: closed; |r_T| > mu r_N: sliding against r_T; slip against s: sticking) and
// s turned to the new slip, until nothing changes: all violated statuses at once for 30 rounds, then one at
// a time, the least index first (Murty's rule, finite for the frictionless LCP, W positive definite), up to
// 8 m more rounds. Newton's iterations converge together with the slip directions. It returns nothing
// when the statuses have not settled: the block Gauss-Seidel takes over. The Gauss-Seidel alone slows down
// as contacts along one inextensible strand multiply (W couples them all: 10^5 sweeps do not reach 1e-12 at
// 40 contacts of the capstan).
std::optional<VecX> active_set_contact_solve(const MatX& W, const VecX& b, const VecX& mu, const VecX& guess) {
  enum class Status { Open, Stick, Slide };
  const Eigen::Index m = mu.size();
  const double force_scale = std::max(guess.lpNorm<Eigen::Infinity>(), b.lpNorm<Eigen::Infinity>() /
                                                                            W.diagonal().maxCoeff());
  const double slip_scale = std::max(b.lpNorm<Eigen::Infinity>(), W.diagonal().maxCoeff() * force_scale);
  const double tol = 1e-10;
  std::vector<Status> status(static_cast<std::size_t>(m));
  std::vector<Vec2> direction(static_cast<std::size_t>(m), Vec2::Zero());
  VecX u = W * guess + b;
  for (Eigen::Index c = 0; c < m; ++c) {
    const Vec2 slip = u.segment<2>(3 * c + 1);
    const bool closed = guess[3 * c] > 0.0 || u[3 * c] < 0.0;
    const bool sliding = mu[c] > 0.0 && slip.norm() > tol * slip_scale;
    status[std::size_t(c)] = !closed ? Status::Open : sliding ? Status::Slide : Status::Stick;
    if (sliding) direction[std::size_t(c)] = slip.normalized();
    if (closed && mu[c] == 0.0) status[std::size_t(c)] = Status::Slide;  // frictionless: r_T = 0
  }
  // Rounds: all violated statuses flipped at once first (30 rounds); if that cycles, one at a time, the
  // least index first (Murty's least-index rule, finite for the frictionless LCP with W positive definite).
  const int rounds = 30 + 8 * int(m);
  // The rows of W (slips, a compliance times forces) are divided by W's largest diagonal entry, so that they
  // are forces like the rows r = 0 and r_T + mu r_N s = 0 beside them: the LU's pivoting then does not depend
  // on the problem's force unit (unscaled, the hanging fold converged at one unit of force and not at 0.3 of it).
  const double compliance = W.diagonal().maxCoeff();
  for (int round = 0; round < rounds; ++round) {
    const bool one_at_a_time = round >= 30;
    bool flipped = false;
    MatX system = MatX::Zero(3 * m, 3 * m);
    VecX rhs = VecX::Zero(3 * m);
    for (Eigen::Index c = 0; c < m; ++c) {
      const auto i = 3 * c;
      switch (status[std::size_t(c)]) {
        case Status::Open:
          system.block<3, 3>(i, i).setIdentity();
          break;
        case Status::Stick:
          system.middleRows(i, 3) = W.middleRows(i, 3) / compliance;
          rhs.segment<3>(i) = -b.segment<3>(i) / compliance;
          break;
        case Status::Slide: {
          system.row(i) = W.row(i) / compliance;
          rhs[i] = -b[i] / compliance;
          const Vec2& s = direction[std::size_t(c)];  // r_T + mu r_N s = 0
          system(i + 1, i + 1) = 1.0, system(i + 1, i) = mu[c] * s[0];
          system(i + 2, i + 2) = 1.0, system(i + 2, i) = mu[c] * s[1];
          break;
        }
      }
    }
    const Eigen::PartialPivLU<MatX> lu(system);
    const VecX r = lu.solve(rhs);
    if (!r.allFinite()) return std::nullopt;
    u = W * r + b;
    bool changed = false;
    for (Eigen::Index c = 0; c < m; ++c) {
      Status& st = status[std::size_t(c)];
      if (one_at_a_time && flipped) continue;
      const double r_N = r[3 * c], u_N = u[3 * c];
      const Vec2 r_T = r.segment<2>(3 * c + 1), slip = u.segment<2>(3 * c + 1);
      Status next = st;
      if (st == Status::Open) {
        if (u_N < -tol * slip_scale) next = mu[c] > 0.0 ? Status::Stick : Status::Slide;
      } else if (r_N < -tol * force_scale) {
        next = Status::Open;
      } else if (st == Status::Stick && r_T.norm() > mu[c] * r_N + tol * force_scale) {
        next = Status::Slide;
        direction[std::size_t(c)] = -r_T.normalized();
      } else if (st == Status::Slide && mu[c] > 0.0) {
        Vec2& s = direction[std::size_t(c)];
        if (slip.dot(s) < -tol * slip_scale) {
          next = Status::Stick;
        } else if (slip.norm() > tol * slip_scale && (slip.normalized() - s).norm() > tol) {
          s = slip.normalized();  // the slip turned: slide along it
          changed = true;
        }
      }
      flipped = flipped || next != st;
      changed = changed || next != st;
      st = next;
    }
    if (!changed) return r;
  }
  return std::nullopt;
}

}  // namespace

void validate_obstacles(const std::vector<RigidObstacle>& obstacles) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    const RigidObstacle& o = obstacles[i];
    const std::string which = "invalid parameter 'obstacles': obstacle " + std::to_string(i);
    if (!o.point.allFinite()) throw InputError("obstacles", which + " has a point that is not finite");
    if (o.shape != RigidObstacle::Shape::Ball && !unit(o.direction))
      throw InputError("obstacles", which + " must have a finite unit direction (|d| - 1 within 1e-10)");
    if (o.shape == RigidObstacle::Shape::Edge && !(unit(o.side) && std::abs(o.side.dot(o.direction)) <= 1e-10))
      throw InputError("obstacles", which + " (an edge) must have a finite unit side orthogonal to its direction "
                                            "(within 1e-10)");
    if (o.shape != RigidObstacle::Shape::Plane && !(std::isfinite(o.radius) && o.radius > 0.0))
      throw InputError("obstacles", which + " has radius " + format_value(o.radius) + ": must be finite and > 0");
    if (!(std::isfinite(o.mu) && o.mu >= 0.0))
      throw InputError("obstacles", which + " has mu " + format_value(o.mu) + ": must be finite and >= 0");
  }
}

ObstacleProximity obstacle_proximity(const RigidObstacle& obstacle, const Vec3& x) {
  ObstacleProximity result;
  const Vec3 offset = x - obstacle.point;
  switch (obstacle.shape) {
    case RigidObstacle::Shape::Plane:
      result.gap = obstacle.direction.dot(offset);
      result.normal = obstacle.direction;
      return result;
    case RigidObstacle::Shape::Ball:
    case RigidObstacle::Shape::Cylinder: {
      const bool cylinder = obstacle.shape == RigidObstacle::Shape::Cylinder;
      const Mat3 off_axis =
          cylinder ? Mat3(Mat3::Identity() - obstacle.direction * obstacle.direction.transpose()) : Mat3::Identity();
      const Vec3 radial = off_axis * offset;
      const double distance = radial.norm();
      if (!(distance > 0.0))
        throw SolverError(kMethod, "a Gauss point lies on the obstacle's centre or axis: no normal there", 0, 0.0);
      result.gap = distance - obstacle.radius;
      result.normal = radial / distance;
      result.normal_gradient = (off_axis - result.normal * result.normal.transpose()) / distance;
      return result;
    }
    case RigidObstacle::Shape::Edge: {
      // Coordinates across the two faces; beyond both, the rounding (a cylinder about the edge's axis).
      const double up = obstacle.direction.dot(offset), out = obstacle.side.dot(offset);
      if (up > 0.0 && out > 0.0) {
        const Vec3 radial = up * obstacle.direction + out * obstacle.side;
        const double distance = std::hypot(up, out);
        const Mat3 off_axis =
            obstacle.direction * obstacle.direction.transpose() + obstacle.side * obstacle.side.transpose();
        result.gap = distance - obstacle.radius;
        result.normal = radial / distance;
        result.normal_gradient = (off_axis - result.normal * result.normal.transpose()) / distance;
      } else {  // over a face (or inside, where the nearer face's distance is the larger coordinate)
        const bool top = up >= out;
        result.gap = (top ? up : out) - obstacle.radius;
        result.normal = top ? obstacle.direction : obstacle.side;
      }
      return result;
    }
  }
  return result;
}

namespace {

std::vector<Vec3> point_positions(const Kinematics& kinematics) {
  std::vector<Vec3> positions;
  for (const auto& point : kinematics.points()) positions.push_back(point.position);
  return positions;
}

void check_previous(const RodModel& model, const std::vector<RigidObstacle>& obstacles,
                    const FrictionalStaticResult& previous) {
  const std::size_t points = model.elements * model.gauss_points;
  const bool fits =
      previous.q.size() == Eigen::Index(dof_count(model)) && previous.q.allFinite() &&
      previous.points.size() == points &&
      std::all_of(previous.points.begin(), previous.points.end(), [](const Vec3& x) { return x.allFinite(); }) &&
      std::all_of(previous.contacts.begin(), previous.contacts.end(), [&](const FrictionalContact& c) {
        return c.point < points && c.obstacle < obstacles.size() && c.local_force.allFinite();
      });
  if (!fits)
    throw InputError("previous", "invalid parameter 'previous': must hold q (3 N = " + std::to_string(dof_count(model)) +
                                     " finite values), one finite Gauss point position per Gauss point (" +
                                     std::to_string(points) + ") and contacts naming existing points and obstacles");
}

}  // namespace

FrictionalStaticResult frictional_start(const RodModel& model, const VecX& q) {
  validate(model);
  FrictionalStaticResult start;
  start.q = q;
  start.points = point_positions(Kinematics(model, q));  // checks q
  return start;
}

FrictionalStaticResult solve_frictional_increment(const RodModel& model, const std::vector<RigidObstacle>& obstacles,
                                                  const FrictionalStaticResult& previous,
                                                  const FrictionalStaticOptions& options) {
  validate(model);
  if (!model.point_forces.empty())
    throw InputError("point_forces", "invalid parameter 'point_forces': frictional statics computes the forces at the "
                                     "Gauss points itself; must be empty");
  if (model.self_contact.radius > 0.0)
    throw InputError("self_contact", "invalid parameter 'self_contact': frictional statics takes rigid obstacles "
                                     "only; self_contact.radius must be 0");
  validate_obstacles(obstacles);
  check_previous(model, obstacles, previous);
  require_non_negative("contact_distance", options.contact_distance);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  const std::size_t points = model.elements * model.gauss_points;
  const double ell = element_length(model);
  const double reach = options.contact_distance > 0.0 ? options.contact_distance : ell;

  const VecX k = generalised_stiffness(model);
  const double k_max = k.lpNorm<Eigen::Infinity>(), rho_0 = k_max / (ell * ell);
  const double load_scale =
      external_generalised_force(model, Kinematics(model, natural_strain_vector(model))).lpNorm<Eigen::Infinity>();
  std::map<std::pair<std::size_t, std::size_t>, Vec3> forces;  // r_k by (point, obstacle)
  for (const auto& c : previous.contacts) forces[{c.point, c.obstacle}] = c.local_force;

  FrictionalStaticResult result;
  result.q = previous.q;
  RodModel loaded = model;  // the forces r_k as dead point loads
  loaded.point_forces.assign(points, Vec3::Zero());
  double last_step = std::numeric_limits<double>::infinity();
  for (std::size_t iteration = 0;; ++iteration) {
    const Kinematics kinematics(model, result.q);
    std::vector<Candidate> candidates;
    std::fill(loaded.point_forces.begin(), loaded.point_forces.end(), Vec3::Zero());
    result.penetration = 0.0;
    for (std::size_t g = 0; g < points; ++g)
      for (std::size_t o = 0; o < obstacles.size(); ++o) {
        const ObstacleProximity proximity = obstacle_proximity(obstacles[o], kinematics.points()[g].position);
        result.penetration = std::max(result.penetration, -proximity.gap);
        if (proximity.gap > reach) continue;
        const auto known = forces.find({g, o});
        Candidate c{g, o, proximity, contact_frame(proximity.normal),
                    known == forces.end() ? Vec3::Zero() : known->second};
        loaded.point_forces[g] += c.frame * c.force;
        candidates.push_back(std::move(c));
      }
    const VecX residual = static_residual(loaded, result.q);
    // J^T f of the contact forces alone, by the tip-to-root wrench pass (loads.hpp, O(N)).
    const VecX contact_load = generalised_force(kinematics, loaded.point_forces, Vec3::Zero(), Vec3::Zero());
    const double scale = std::max({k_max * result.q.lpNorm<Eigen::Infinity>(), k_max / model.length, load_scale,
                                   contact_load.lpNorm<Eigen::Infinity>()});
    result.residual = residual.lpNorm<Eigen::Infinity>() / scale;
    const bool step_small =
        last_step * model.length <= options.tolerance * (1.0 + result.q.lpNorm<Eigen::Infinity>() * model.length);
    if (iteration > 0 && result.residual <= options.tolerance && step_small) {
      result.points = point_positions(kinematics);
      for (const auto& c : candidates) {
        const Vec3 moved = kinematics.points()[c.point].position - previous.points[c.point];
        result.contacts.push_back({c.point, c.obstacle, c.proximity.gap, c.frame, c.force, c.frame * c.force,
                                   Vec3(c.proximity.gap, c.frame.col(1).dot(moved), c.frame.col(2).dot(moved))});
      }
      return result;
    }
    if (iteration >= options.max_iterations)
      throw SolverError(kMethod, "no convergence in " + std::to_string(options.max_iterations) + " iterations (step " +
                                     format_value(last_step) + ")",
                        iteration, result.residual);
    check_time_budget(kMethod, iteration, result.residual);

    // Tangent stiffness: the dead point loads' (static_jacobian) and the normal forces' turning.
    MatX A = static_jacobian(loaded, result.q);
    const auto m = Eigen::Index(candidates.size());
    MatX H(3 * m, result.q.size());
    VecX w(3 * m), r_k(3 * m), mu(m);
    std::vector<Eigen::Index> active;
    for (Eigen::Index c = 0; c < m; ++c) {
      const Candidate& candidate = candidates[std::size_t(c)];
      const auto& point = kinematics.points()[candidate.point];
      const MatX J = kinematics.position_jacobian(point.element, point.sigma);
      A.noalias() -= J.transpose() * (candidate.force[0] * candidate.proximity.normal_gradient) * J;
      H.middleRows(3 * c, 3) = candidate.frame.transpose() * J;
      const Vec3 moved = point.position - previous.points[candidate.point];
      w.segment<3>(3 * c) =
          Vec3(candidate.proximity.gap, candidate.frame.col(1).dot(moved), candidate.frame.col(2).dot(moved));
      r_k.segment<3>(3 * c) = candidate.force;
      mu[c] = obstacles[candidate.obstacle].mu;
      if (candidate.force[0] > 0.0) active.push_back(c);
    }
    // The step's matrix (header): A, else the augmented A + rho G^T G, else with a Levenberg shift.
    MatX G(Eigen::Index(active.size()), result.q.size());
    VecX g(G.rows());
    for (Eigen::Index a = 0; a < G.rows(); ++a) {
      G.row(a) = H.row(3 * active[std::size_t(a)]);
      g[a] = w[3 * active[std::size_t(a)]];
    }
    const MatX augmentation = G.transpose() * G;
    Eigen::LLT<MatX> cholesky;  // of the symmetric part of the last matrix tried
    const auto positive_definite = [&cholesky](const MatX& M) {
      cholesky.compute(0.5 * (M + M.transpose()));
      return cholesky.info() == Eigen::Success;
    };
    double rho = 0.0;
    MatX A_step = A;
    bool definite = positive_definite(A_step);
    for (double trial = rho_0; !definite && G.rows() > 0 && trial <= 1e6 * rho_0; trial *= 10.0)
      if ((definite = positive_definite(A_step = A + trial * augmentation))) rho = trial;
    for (double sigma = 1e-6; !definite; sigma *= 10.0) {
      if (sigma > 1e12)
        throw SolverError(kMethod, "no positive definite shift of the tangent stiffness", iteration + 1, result.residual);
      rho = G.rows() > 0 ? rho_0 : 0.0;
      A_step = A + rho * augmentation;
      A_step.diagonal() += sigma * k;
      definite = positive_definite(A_step);
    }
    // Solves with the Cholesky factor when the matrix is symmetric to round-off (gravity, dead end forces,
    // the normal forces' turning: half the work of an LU, the factor already made); else (a dead end
    // moment) by LU. Either way the fixed point is the same (dq = 0).
    const bool symmetric =
        (A_step - A_step.transpose()).cwiseAbs().maxCoeff() <= 1e-12 * A_step.cwiseAbs().maxCoeff();
    Eigen::PartialPivLU<MatX> lu;
    if (!symmetric) lu.compute(A_step);
    const auto solve = [&](const MatX& rhs) -> MatX {
      return symmetric ? MatX(cholesky.solve(rhs)) : MatX(lu.solve(rhs));
    };
    const VecX free_step = -solve(residual + rho * (G.transpose() * g));
    VecX step = free_step;
    VecX r = r_k;
    if (m > 0) {
      const MatX Y = solve(H.transpose());  // A^-1 H^T
      MatX W = H * Y;
      const VecX b = w + H * free_step - W * r_k;
      W = 0.5 * (W + W.transpose()).eval();  // A is symmetric but for rounding and a dead end moment's part
      // A point whose tangential motion is locked to first order (on a straight stretch from the clamp of
      // an inextensible rod) has a singular Delassus block. A compliance of 1e-12 of the largest diagonal
      // keeps every block positive definite; at the fixed point it moves the gaps and slips by 1e-12 of
      // the displacements a unit force makes (below the Newton tolerance).
      W.diagonal().array() += 1e-12 * W.diagonal().maxCoeff();
      if (const auto settled = active_set_contact_solve(W, b, mu, r_k)) {
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
    for (Eigen::Index c = 0; c < m; ++c)
      forces[{candidates[std::size_t(c)].point, candidates[std::size_t(c)].obstacle}] = r.segment<3>(3 * c);
    result.q += step;
    last_step = step.lpNorm<Eigen::Infinity>();
    result.iterations = iteration + 1;
  }
}

}  // namespace rodvv::solvers::superhelix

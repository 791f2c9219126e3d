#include "rodvv/solvers/superhelix/hard_self_contact.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/lcp.hpp"
#include "rodvv/solvers/superhelix/arc_pair_contact.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/loads.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::solvers::superhelix {

namespace {

constexpr const char* kMethod = "superhelix Newton-LCP (hard self-contact)";

// The augmentation rho of the contacts that carry a force, in units of F / h per unit G^T G (the nodal
// rod's choice, rod3d/statics.cpp: a barrier of stiffness k at the force F is 2 sqrt(k F) stiff, so
// 1000 F / h is the barrier k ~ 2.5e5 F / h^2, far stiffer than the knots' 500 T / h^2).
constexpr double kContactAugmentation = 1000.0;
// The Levenberg shift's range, in units of K (statics.cpp uses the same for the barrier).
constexpr double kFirstShift = 1e-6;
constexpr double kLargestShift = 1e12;
// Lemke's verified solution: its natural-map residual at most this times max|b| (contact/lcp.hpp).
constexpr double kLcpAccuracy = 1e-9;

// The candidates at `kinematics` (sorted by their element pair), each with the force the same element
// pair carries in `forces` (also sorted), 0 if absent.
std::vector<ArcContact> candidates_with_forces(const Kinematics& kinematics, const SelfContact& contact,
                                               const std::vector<ArcContact>& forces) {
  auto candidates = closest_arc_pairs(kinematics, contact, 3.0 * contact.radius, forces);
  const auto key = [](const ArcContact& c) { return std::make_pair(c.first, c.second); };
  auto known = forces.begin();
  for (auto& candidate : candidates) {
    while (known != forces.end() && key(*known) < key(candidate)) ++known;
    candidate.force = (known != forces.end() && key(*known) == key(candidate)) ? known->force : 0.0;
  }
  return candidates;
}

// G_c^T = (dr_P/dq(s) - dr_Q/dq(t))^T n: the gap's gradient.
VecX gap_gradient(const Kinematics& kinematics, const ArcContact& c) {
  return (kinematics.position_jacobian(c.first, c.s) - kinematics.position_jacobian(c.second, c.t)).transpose() *
         c.normal;
}

struct Scales {
  double residual = 1.0;  // S
  double force = 1.0;     // F
  double length = 1.0;    // L
};

// The equilibrium measure of the header at a configuration with residual r (no contact forces) and the
// candidates' forces.
double equilibrium_measure(const Kinematics& kinematics, const VecX& r, const std::vector<ArcContact>& contacts,
                           double contact_distance, const Scales& scales) {
  const VecX unbalanced = r - self_contact_generalized_force(kinematics, contacts);
  double worst = unbalanced.lpNorm<Eigen::Infinity>() / scales.residual;
  for (const auto& c : contacts)
    worst = std::max(worst, std::abs(std::min(c.force / scales.force, (c.distance - contact_distance) / scales.length)));
  return worst;
}

// A configuration: its kinematics, residual without contact, candidates (with forces) and measure.
struct Iterate {
  Kinematics kinematics;
  VecX residual;
  std::vector<ArcContact> contacts;
  double measure = 0.0;
};

// The iterate at q with the forces `forces` carried to its candidates; nothing when a candidate is closer
// than h (a strand pushed through another: too long a step for the linearisation) or the contacts are
// singular (a Gauss point on another centreline).
std::optional<Iterate> iterate_at(const RodModel& model, const VecX& q, double load_factor,
                                  const std::vector<ArcContact>& forces, const Scales& scales) {
  Kinematics kinematics(model, q);
  std::vector<ArcContact> contacts;
  try {
    contacts = candidates_with_forces(kinematics, model.self_contact, forces);
  } catch (const SolverError&) {
    return std::nullopt;
  }
  for (const auto& c : contacts)
    if (c.distance < model.self_contact.radius) return std::nullopt;
  VecX r = static_residual(model, q, load_factor);
  const double measure =
      equilibrium_measure(kinematics, r, contacts, 2.0 * model.self_contact.radius, scales);
  if (!std::isfinite(measure)) return std::nullopt;
  return Iterate{std::move(kinematics), std::move(r), std::move(contacts), measure};
}

// The linearised step of the header at `here` with the shift mu: dq and the candidates with the LCP's
// forces; nothing when A + mu K is not positive definite or Lemke finds no accurate solution.
struct Step {
  VecX dq;
  std::vector<ArcContact> contacts;
  std::size_t pivots = 0;
};
std::optional<Step> newton_lcp_step(const RodModel& model, const Iterate& here, double load_factor, double shift,
                                    const Scales& scales) {
  const VecX& q = here.kinematics.q();
  const SelfContact& contact = model.self_contact;
  const double rho = kContactAugmentation * scales.force / contact.radius;
  const auto m = static_cast<Eigen::Index>(here.contacts.size());
  MatX G(m, q.size());
  for (Eigen::Index c = 0; c < m; ++c) G.row(c) = gap_gradient(here.kinematics, here.contacts[std::size_t(c)]).transpose();
  MatX A = static_jacobian(model, q, load_factor);
  A += closest_pair_force_stiffness(here.kinematics, here.contacts);  // the held forces' stiffness
  for (Eigen::Index c = 0; c < m; ++c)
    if (here.contacts[std::size_t(c)].force > 0.0) A.noalias() += rho * G.row(c).transpose() * G.row(c);
  A.diagonal() += shift * generalised_stiffness(model);
  const Eigen::LLT<MatX> cholesky(A);
  if (cholesky.info() != Eigen::Success) return std::nullopt;
  Step step;
  step.dq = -cholesky.solve(here.residual);
  step.contacts = here.contacts;
  if (m == 0) return step;
  const MatX X = cholesky.solve(G.transpose());
  MatX W = G * X;
  W = 0.5 * (W + W.transpose()).eval();  // symmetric in exact arithmetic (A is)
  VecX b(m);
  const double contact_distance = 2.0 * contact.radius;
  for (Eigen::Index c = 0; c < m; ++c)
    b[c] = here.contacts[std::size_t(c)].distance - contact_distance + G.row(c).dot(step.dq);
  contact::LcpSolution lcp;
  try {
    lcp = contact::solve_lcp_verified(W, b, contact::LcpMethod::Lemke, {}, kLcpAccuracy);
  } catch (const SolverError&) {  // a ray or the pivot limit: no solution of this linearisation
    return std::nullopt;
  } catch (const InputError&) {  // W refused (not positive semidefinite to round-off)
    return std::nullopt;
  }
  step.dq.noalias() += X * lcp.lambda;
  for (Eigen::Index c = 0; c < m; ++c) step.contacts[std::size_t(c)].force = lcp.lambda[c];
  step.pivots = lcp.iterations;
  return step;
}

}  // namespace

double hard_contact_force_scale(const RodModel& model) {
  const double stiffness = model.stiffness.maxCoeff();
  return std::max({model.end_force.norm(), model.line_density * model.gravity.norm() * model.length,
                   stiffness / (model.length * model.length)});
}

HardContactStatics solve_static_with_hard_contact(const RodModel& model, const StaticOptions& options) {
  validate(model);  // a hard law has a radius > 0
  if (!is_hard(model.self_contact))
    throw InputError("self_contact.law", "invalid parameter 'self_contact.law': solve_static_with_hard_contact "
                                         "needs hard self-contact (law Hard, radius > 0)");
  if (!model.end_moment.isZero(0.0))
    throw InputError("end_moment", "invalid parameter 'end_moment': a dead end moment is not conservative "
                                   "(Ziegler); must be 0 with hard self-contact");
  const NewtonScales newton_scales = static_newton_scales(model);
  HardContactStatics result;
  result.statics.q = newton_start(options, natural_strain_vector(model));
  const double max_motion = 0.5 * model.self_contact.radius;  // per step (header; the reach is 3h)
  Scales scales;
  scales.force = hard_contact_force_scale(model);
  scales.length = model.length;
  std::vector<ArcContact> forces;
  double measure = 0.0;
  for (std::size_t load_step = 1; load_step <= options.load_steps; ++load_step) {
    const double lambda = static_cast<double>(load_step) / static_cast<double>(options.load_steps);
    scales.residual = newton_scales.residual_scale(result.statics.q);
    std::optional<Iterate> here = iterate_at(model, result.statics.q, lambda, forces, scales);
    if (!here)
      throw SolverError(kMethod, "the start has two arcs closer than h (their centrelines within a radius): not a state to start from",
                        result.statics.iterations, 0.0);
    double shift = 0.0;  // the Levenberg shift mu, in units of K
    bool converged = false;
    for (std::size_t iteration = 0; iteration < options.max_iterations; ++iteration) {
      measure = here->measure;
      check_time_budget(kMethod, result.statics.iterations, measure);
      if (measure <= options.tolerance) {
        converged = true;
        break;
      }
      ++result.statics.iterations;
      const auto raise_shift = [&](double factor) {
        shift = std::max(kFirstShift, factor * shift);
        if (shift > kLargestShift)
          throw SolverError(kMethod, "no step found even with the largest Levenberg shift at load factor " +
                                         format_value(lambda),
                            result.statics.iterations, measure);
      };
      std::optional<Step> step = newton_lcp_step(model, *here, lambda, shift, scales);
      if (!step) {
        raise_shift(4.0);
        continue;
      }
      result.lcp_pivots += step->pivots;
      const double full_motion =
          largest_point_motion(here->kinematics, Kinematics(model, result.statics.q + step->dq));
      double alpha = full_motion > max_motion ? 0.99 * max_motion / full_motion : 1.0;
      const bool capped = alpha < 1.0;
      // The yardstick: the measure here, and here under the step's own forces (header).
      const double yardstick = std::max(
          measure, equilibrium_measure(here->kinematics, here->residual, step->contacts,
                                       2.0 * model.self_contact.radius, scales));
      // Pseudo-transient continuation (Kelley & Keyes 1998; the nodal rod's, rod3d/statics.cpp): the shift
      // is the inverse pseudo-time step. A step is taken whole (cut to the motion cap) if its measure stays
      // within 10 x the yardstick; one that lowered the measure and was not cut lowers the shift by the
      // measure's ratio (switched evolution relaxation, clamped to [1.2, 10]), a cut one raises it by the
      // cut (at most 10 x: the next step about as long as the cap allows); a failed one raises it 4 x.
      std::optional<Iterate> trial =
          iterate_at(model, result.statics.q + alpha * step->dq, lambda, step->contacts, scales);
      if (!trial || !(trial->measure <= 10.0 * yardstick)) {
        // At round-off the measure cannot show progress: a step at round-off from a measure within
        // 1e3 x the tolerance is convergence (newton.hpp's floor).
        if (newton_scales.round_off_step(step->dq, result.statics.q) && measure <= 1e3 * options.tolerance) {
          converged = true;
          break;
        }
        raise_shift(4.0);
        continue;
      }
      const bool progress = !capped && trial->measure < measure;
      result.statics.q = trial->kinematics.q();
      here = std::move(trial);
      scales.residual = newton_scales.residual_scale(result.statics.q);
      here->measure = equilibrium_measure(here->kinematics, here->residual, here->contacts,
                                          2.0 * model.self_contact.radius, scales);
      if (progress) {
        shift /= std::clamp(measure / here->measure, 1.2, 10.0);
        if (shift < kFirstShift) shift = 0.0;  // Newton itself
      } else if (capped) {
        raise_shift(1.0 / std::max(0.1, alpha));
      }
    }
    measure = here->measure;
    if (!converged)
      throw SolverError(kMethod, "no convergence at load factor " + format_value(lambda), result.statics.iterations,
                        measure);
    forces = here->contacts;
  }
  result.statics.residual = measure;
  result.contacts = std::move(forces);
  return result;
}

}  // namespace rodvv::solvers::superhelix

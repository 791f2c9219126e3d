#include "rodvv/solvers/rod3d/statics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <Eigen/SparseLU>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "hard_contact_step.hpp"

namespace rodvv::solvers::rod3d {

namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();
const std::string kMethod =
    "rod3d statics (Newton, banded LU or sparse LU with a self-contact barrier, Newton-LCP with hard self-contact, "
    "continuation)";

// Where one supported end goes during continuation: from the initial state's pose (lambda = 0) to
// the model's (lambda = 1).
struct EndPath {
  bool active = false;
  bool clamped = false;
  bool holds_angle = false;
  std::size_t vertex = 0, inner = 0, edge = 0;  // end vertex, the other vertex of the end edge, the edge
  double sign = 1.0;                            // +1: t points from inner to vertex (tip), -1 (root)
  Vec3 position_start, position_end;
  Vec3 tangent_start;
  Vec3 rotation_axis = Vec3::UnitX();
  double rotation_angle = 0.0;                  // of the end tangent, about rotation_axis
  double angle_start = 0.0, angle_end = 0.0;
  int slide_axis = -1;                          // a sliding clamp's axis (model.hpp), else -1

  Vec3 position(double lambda) const { return position_start + lambda * (position_end - position_start); }
  Vec3 tangent(double lambda) const {
    return Eigen::AngleAxisd(lambda * rotation_angle, rotation_axis) * tangent_start;
  }
  double angle(double lambda) const { return angle_start + lambda * (angle_end - angle_start); }
};

EndPath make_path(const EndCondition& end, const RodState& state, bool at_tip) {
  EndPath path;
  if (end.support == EndSupport::Free) return path;
  const std::size_t n = state.elements();
  path.active = true;
  path.clamped = end.support == EndSupport::Clamped;
  if (end.slides) path.slide_axis = sliding_axis(end);
  path.holds_angle = path.clamped || end.hold_twist;
  path.vertex = at_tip ? n : 0;
  path.inner = at_tip ? n - 1 : 1;
  path.edge = at_tip ? n - 1 : 0;
  path.sign = at_tip ? 1.0 : -1.0;
  // A clamped end is placed by its support point, the midpoint of the clamped edge (model.hpp).
  path.position_start = path.clamped ? 0.5 * (state.position[path.vertex] + state.position[path.inner])
                                     : state.position[path.vertex];
  path.position_end = end.position;
  path.tangent_start = edge_tangent(state, path.edge);
  path.angle_start = state.angle[path.edge];
  Vec3 reference_end = state.reference_director[path.edge];
  if (path.clamped) {
    const Vec3 target = end.frame.col(0);
    const Vec3 normal = path.tangent_start.cross(target);
    path.rotation_angle = std::atan2(normal.norm(), path.tangent_start.dot(target));
    if (normal.norm() > 1e-14) {
      path.rotation_axis = normal.normalized();
    } else if (path.rotation_angle > 1.0) {  // antiparallel: any axis normal to the tangent
      path.rotation_axis = state.reference_director[path.edge];
    }
    reference_end = parallel_transport(path.tangent_start, target, reference_end);
    path.angle_end = signed_angle(reference_end, end.frame.col(1), target) + end.rotation;
  } else if (end.hold_twist) {
    path.angle_end = end.rotation;
  } else {
    path.angle_end = path.angle_start;
  }
  return path;
}

// Puts the held degrees of freedom of `state` where the paths have them at lambda.
void place_ends(const RodModel& model, RodState& state, const EndPath& root, const EndPath& tip, double lambda) {
  const auto previous = edge_tangents(state);
  const double ell = rest_edge_length(model);
  for (const EndPath* path : {&root, &tip}) {
    if (!path->active) continue;
    if (path->clamped) {
      const Vec3 half_edge = 0.5 * path->sign * ell * path->tangent(lambda);
      Vec3 centre = path->position(lambda);
      if (path->slide_axis >= 0)  // along its axis a sliding clamp stays where the rod has it
        centre[path->slide_axis] = 0.5 * (state.position[path->vertex] + state.position[path->inner])[path->slide_axis];
      state.position[path->vertex] = centre + half_edge;
      state.position[path->inner] = centre - half_edge;
    } else {
      state.position[path->vertex] = path->position(lambda);
    }
  }
  transport_reference_frames(state, previous);
  for (const EndPath* path : {&root, &tip})
    if (path->active && path->holds_angle) state.angle[path->edge] = path->angle(lambda);
}

struct Scales {
  double force = 1.0, moment = 1.0, length = 1.0;
};

Scales residual_scales(const RodModel& model, const RodState& state, double load_factor) {
  Scales s;
  const double L = model.length;
  double force = model.stiffness.maxCoeff() / (L * L);
  force = std::max(force, dead_load_scale(model, load_factor));
  for (double tension : state.multiplier) force = std::max(force, std::abs(tension));
  s.force = force;
  s.moment = force * L;
  s.length = L;
  return s;
}

std::vector<char> held_mask(const RodModel& model) {
  const DofLayout layout(model);
  std::vector<char> held(layout.size(), 0);
  for (std::size_t k : held_dofs(model)) held[k] = 1;
  return held;
}

// The residual rows of the held dofs are the supports' reactions, not equations: zeroed.
void zero_held(const std::vector<char>& held, VecX& r) {
  for (std::size_t k = 0; k < held.size(); ++k)
    if (held[k]) r[Eigen::Index(k)] = 0.0;
}

enum class DofKind { Position, Angle, Multiplier };

// What degree of freedom k of the layout is (the last three are the tip vertex's coordinates).
DofKind dof_kind(const DofLayout& layout, std::size_t k) {
  const std::size_t slot = k % layout.stride();
  if (k >= layout.size() - 3 || slot < 3) return DofKind::Position;
  return slot == 3 ? DofKind::Angle : DofKind::Multiplier;
}

// Per dof: the scale of its residual row (force, moment, length) or of its unknown (length, 1, force).
VecX unit_scales(const RodModel& model, const Scales& scales, bool unknowns) {
  const DofLayout layout(model);
  VecX out(Eigen::Index(layout.size()));
  for (std::size_t k = 0; k < layout.size(); ++k) {
    switch (dof_kind(layout, k)) {
      case DofKind::Position: out[Eigen::Index(k)] = unknowns ? scales.length : scales.force; break;
      case DofKind::Angle: out[Eigen::Index(k)] = unknowns ? 1.0 : scales.moment; break;
      case DofKind::Multiplier: out[Eigen::Index(k)] = unknowns ? scales.force : scales.length; break;
    }
  }
  // Rounded to powers of two, so that scaling the system is exact in floating point.
  return out.unaryExpr([](double x) { return std::exp2(std::round(std::log2(x))); });
}

double scaled_measure(const RodModel& model, const VecX& r, const Scales& scales, const std::vector<char>& held) {
  const DofLayout layout(model);
  double worst = 0.0;
  for (std::size_t k = 0; k < layout.size(); ++k) {
    if (held[k]) continue;
    const DofKind kind = dof_kind(layout, k);
    const double scale = kind == DofKind::Position ? scales.force : kind == DofKind::Angle ? scales.moment : scales.length;
    worst = std::max(worst, std::abs(r[Eigen::Index(k)]) / scale);
  }
  return worst;
}

// The state displaced by dz and its scaled residual, or nothing if the step turns a reference twist
// by more than pi/4 (the energy's chart, discrete_energy.cpp) or pushes two segments through each
// other (self_contact.hpp): the trial of the line search and of the pseudo-transient step.
struct Trial {
  RodState state;
  double measure = 0.0;
  std::vector<ContactPair> contacts;  // hard contact: the candidates there, with the step's pair forces
  VecX residual;                      // the residual there (held rows zero)
};

bool hard_contact(const RodModel& model) { return has_self_contact(model) && is_hard(model.self_contact); }

// Whether the statics is a minimisation: every load has a potential (a dead moment on a turning edge
// has none) and the contact is the barrier's (hard contact's forces are unknowns, not an energy).
bool has_potential(const RodModel& model) {
  const auto zero = [](const Vec3& m) { return m.isZero(0.0); };
  return zero(model.end_moment) && std::all_of(model.edge_moments.begin(), model.edge_moments.end(), zero) &&
         !hard_contact(model);
}

// The l1 merit of the equality-constrained minimisation (Nocedal & Wright 2006, §15.4, eq. 15.24):
// phi = Pi + nu sum_j |c_j|, with Pi the potential energy at the load factor and c_j the
// inextensibility constraints (the multiplier rows of r). For nu > max_j |lambda_j| a minimiser of phi
// is a constrained minimiser of Pi, and the KKT step of a positive definite reduced matrix (which the
// pseudo-time mass D / tau makes it, for tau small enough) is a descent direction of phi. `noise`
// bounds the round-off of phi: N terms, each with a few ulps of the largest part.
struct Merit {
  double energy = 0.0, violation = 0.0, noise = 0.0;
  double value(double nu) const { return energy + nu * violation; }
};

// The merit's penalty weight nu = 2 max |lambda_j| (above), raised from `nu` to cover the tensions of `at`.
double penalty_weight(double nu, const RodState& at) {
  for (double tension : at.multiplier) nu = std::max(nu, 2.0 * std::abs(tension));
  return nu;
}

Merit merit(const RodModel& model, const RodState& state, double lambda, const VecX& r) {
  const EnergyParts parts = energy(model, state);
  Merit m;
  m.energy = parts.elastic() + parts.contact + lambda * (parts.gravity + parts.tip_force + parts.vertex_forces);
  const DofLayout layout(model);
  if (layout.multipliers)
    for (std::size_t j = 0; j < model.elements; ++j) m.violation += std::abs(r[Eigen::Index(layout.multiplier(j))]);
  const double size = std::abs(parts.elastic()) + std::abs(parts.contact) + std::abs(parts.gravity) +
                      std::abs(parts.tip_force) + std::abs(parts.vertex_forces);
  m.noise = 16.0 * kEps * double(model.elements) * size;
  return m;
}

// The scaled measure of the residual r (held rows zero) - with hard contact, of r less the pair forces
// `contacts` and of their complementarity with the gaps (hard_contact_step.hpp).
double equilibrium_measure(const RodModel& model, const RodState& state, double lambda, VecX r,
                           const std::vector<ContactPair>* contacts, const std::vector<char>& held) {
  const Scales scales = residual_scales(model, state, lambda);
  if (!contacts) return scaled_measure(model, r, scales, held);
  detail::subtract_contact_forces(model, *contacts, r);
  zero_held(held, r);
  return std::max(scaled_measure(model, r, scales, held),
                  detail::complementarity_measure(model, *contacts, scales.force, scales.length));
}

std::optional<Trial> try_step(const RodModel& model, const RodState& state, const VecX& dz, double lambda,
                              const std::vector<char>& held, const std::vector<ContactPair>* forces = nullptr) {
  double twist_change = 0.0;
  Trial trial{displaced(model, state, dz, &twist_change), 0.0, {}, {}};
  if (twist_change > 0.25 * std::numbers::pi) return std::nullopt;
  VecX r;
  try {
    r = static_residual(model, trial.state, lambda);
    if (forces) {
      trial.contacts = detail::candidates_with_forces(model, trial.state, *forces);
      // Hard contact holds the linearised gaps: a pair more than half the contact distance inside
      // (a segment pushed through another) is a step too long for the linearisation, not a state.
      for (const auto& pair : trial.contacts)
        if (pair.distance < model.self_contact.radius) return std::nullopt;
    }
  } catch (const SolverError&) {
    return std::nullopt;
  }
  zero_held(held, r);
  trial.measure = equilibrium_measure(model, trial.state, lambda, r, forces ? &trial.contacts : nullptr, held);
  trial.residual = std::move(r);
  if (!std::isfinite(trial.measure)) return std::nullopt;
  return trial;
}

// The round-off floor of the scaled residual. An edge vector is the difference of two positions of
// size |x|, so it carries an absolute error eps |x|, a relative error eps |x| N / L; the integrated
// curvature (a cross product of nearly parallel tangents) then has an absolute error ~ eps |x| N / L,
// and the vertex force K kappa_err / ebar^2 relative to the force scale K / L^2 grows like
// N^3 eps |x| / L. Measured on the Mattiasson cantilever: 1.1 N^3 eps at N = 128, 1.4 N^3 eps at
// N = 512; the floor is set at 8 N^3 eps max(1, |x|_max / L). An extensible rod adds the error of
// its edge tension EA (|e|/ebar - 1): EA eps |x| / ebar, relative to the force scale (measured
// 1.5e-10 on the Bathe-Bolourchi bend at N = 16, EA = 1e7, |x| = 100; this term gives 1.2e-10 there
// before the factor 8).
double round_off_floor(const RodModel& model, const RodState& state, double force_scale) {
  double extent = model.length;
  for (const Vec3& x : state.position) extent = std::max(extent, x.cwiseAbs().maxCoeff());
  const double n = double(model.elements);
  double floor = 8.0 * kEps * n * n * n * extent / model.length;
  if (!is_inextensible(model))
    floor += 8.0 * kEps * model.extensional_stiffness * extent / rest_edge_length(model) / force_scale;
  return floor;
}

// Pseudo-time bounds, in the units of add_pseudo_time: from 1e-6 (a step that fails at a pseudo-time
// step a million times shorter than the slowest elastic relaxation is a failure) to 1e6 (the
// regularisation of an exact zero mode, e.g. the turn of an isotropic rod about its tension axis,
// then stays at 1e-6 of the global stiffness, so round-off cannot drive the iterate along it, while
// the other modes converge at the rate 1e-6 times their stiffness ratio).
constexpr double kMinPseudoTime = 1e-6;
constexpr double kMaxPseudoTime = 1e6;

// The hard contacts' augmentation rho (hard_contact_step.hpp) in units of the force scale per radius h.
// Measured on the open trefoil (knot/trefoil-nodal's knot): from the tied curve with rho = 10, 425
// iterations at N = 50 and a stall at N = 100 (W indefinite whenever tau grows); with 100, 397, 411 and
// 2930 iterations at N = 50, 100, 200. Hardening the barrier's equilibrium (knot/trefoil-hard-nodal) with
// 100: 43, 16, 27 and 690 iterations at N = 50 .. 400, and a stall at looseness 0.15, N = 200; with 1000:
// 51, 15, 20, 22, and 2681 iterations (33 s) at looseness 0.15, N = 200. A barrier of stiffness k at the
// contact force F is 2 sqrt(k F) stiff: 1000 F / h is the barrier k = 2.5e5 F / h^2 (knot/trefoil-nodal
// uses 500 T / h^2).
constexpr double kContactAugmentation = 1000.0;

// Adds D / tau to the free position and angle rows of the Jacobian: the "mass" of a gradient flow
// whose unit pseudo-time relaxes a mode of the rod's global stiffness (force scale / L per unit
// displacement, force scale x L per radian) by a factor e.
void add_pseudo_time(const RodModel& model, const Scales& scales, const std::vector<char>& held, double inverse_tau,
                     Eigen::SparseMatrix<double>& jacobian) {
  const DofLayout layout(model);
  for (std::size_t k = 0; k < layout.size(); ++k) {
    const DofKind kind = dof_kind(layout, k);
    if (held[k] || kind == DofKind::Multiplier) continue;  // multiplier rows: the constraints stay exact
    const double mass = kind == DofKind::Position ? scales.force / scales.length : scales.moment;
    jacobian.coeffRef(Eigen::Index(k), Eigen::Index(k)) += mass * inverse_tau;
  }
}

// The fraction of a step that self_contact.hpp's pass_through_free_fraction allows (no two segments pass
// through each other on its straight path; a rigid motion, such as a ply turning about its axis or a
// tail sliding out of it, is not shortened), and at most kMaxVertexStep h of motion of any vertex, which
// keeps the iterate near the path of the pseudo-time flow. Measured on knot/plectoneme-nodal
// (N = 200, 400, 800) with the energy merit: 2164, 1578, 1207 iterations at 1 h; 789, 971, 637 at 2 h;
// 839, 997, 1118 at 3 h; 840, 1104, 1112 at 4 h; 915, 1087, 1266 with no bound.
constexpr double kMaxVertexStep = 2.0;

double contact_safe_fraction(const RodModel& model, const RodState& state, const VecX& dz) {
  const DofLayout layout(model);
  std::vector<Vec3> u(model.elements + 1);
  double largest = 0.0;
  for (std::size_t i = 0; i <= model.elements; ++i) {
    u[i] = dz.segment<3>(Eigen::Index(layout.vertex(i)));
    largest = std::max(largest, u[i].norm());
  }
  const double bound = kMaxVertexStep * model.self_contact.radius;
  const double alpha = largest > bound ? bound / largest : 1.0;
  return std::min(alpha, pass_through_free_fraction(model.self_contact, state.position, u, rest_edge_length(model)));
}

// The second-order correction of a step dz from `state` whose trial is `trial` (Nocedal & Wright 2006,
// §15.5-15.6): the solve, with the matrix factorised for dz, of the right-hand side whose only entries are
// the constraint violations -c(x + dz) (the multiplier rows of the trial's residual), added to dz. Nothing
// when there are no constraints, when the corrected step would move two segments through each other or
// a vertex further than the step limit allows, or when it is not a state (try_step).
template <class Solve>
std::optional<Trial> second_order_correction(const RodModel& model, const RodState& state, const VecX& dz,
                                             const Trial& trial, double lambda, const std::vector<char>& held,
                                             const DofLayout& layout, const Solve& solve_in_units) {
  if (!layout.multipliers) return std::nullopt;
  VecX violations = VecX::Zero(dz.size());
  for (std::size_t j = 0; j < model.elements; ++j) {
    const auto row = Eigen::Index(layout.multiplier(j));
    if (!held[std::size_t(row)]) violations[row] = -trial.residual[row];
  }
  const VecX corrected = dz + solve_in_units(violations);
  if (!corrected.allFinite()) return std::nullopt;
  if (has_self_contact(model) && contact_safe_fraction(model, state, corrected) < 1.0) return std::nullopt;
  return try_step(model, state, corrected, lambda, held);
}

// From which pseudo-time step (add_pseudo_time's units: 1 relaxes the rod's global stiffness by a
// factor e) a rejected step is retried with its second-order correction (newton, below).
constexpr double kCorrectionPseudoTime = 1.0;

struct NewtonOutcome {
  bool converged = false;
  std::size_t iterations = 0;
  double residual = std::numeric_limits<double>::infinity();
  std::vector<ContactPair> contacts;  // hard contact: the candidate pairs and their forces
};

// Newton at a fixed load factor with the held dofs already in place. Each iteration linearises in
// the chart of the current state (static_system) and is re-based after the step (displaced); the
// two charts differ by terms proportional to the step times the twisting moments dE/dtheta, which
// vanish at an equilibrium, so the iteration is quadratic near one. (Iterating in one fixed chart
// was tried: with a twisting moment held at a free end the equilibrium must then be re-found after
// every re-basing, which cost 20 to 200 times more iterations on the helix case.)
NewtonOutcome newton(const RodModel& model, RodState& state, double lambda, const StaticOptions& options,
                     const std::vector<char>& held, std::vector<ContactPair> contacts) {
  NewtonOutcome outcome;
  VecX r;
  Eigen::SparseMatrix<double> jacobian;
  // The banded LU (O(N)) unless self-contact (the barrier's stiffness, or the hard contacts' held forces
  // and augmentation) couples distant vertices; then a sparse LU with a fill-reducing column ordering
  // (COLAMD), still about O(N) for a few contacts.
  elastica2d::BandedLU banded;
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> sparse;
  const bool contact = has_self_contact(model);
  const bool hard = hard_contact(model);  // forces by complementarity (hard_contact_step.hpp)
  // The symbolic analysis (COLAMD ordering, elimination tree) is redone only when the sparsity
  // pattern changes - when a contact pair appears or goes - not at every iteration.
  std::vector<int> pattern_outer, pattern_inner;
  const auto factorize = [&](Eigen::SparseMatrix<double>& a) {
    if (!contact) return banded.factorize(a);
    a.makeCompressed();
    const Eigen::Index columns = a.cols(), entries = a.nonZeros();
    const bool same = std::equal(a.outerIndexPtr(), a.outerIndexPtr() + columns + 1, pattern_outer.begin(),
                                 pattern_outer.end()) &&
                      std::equal(a.innerIndexPtr(), a.innerIndexPtr() + entries, pattern_inner.begin(),
                                 pattern_inner.end());
    if (!same) {
      sparse.analyzePattern(a);
      pattern_outer.assign(a.outerIndexPtr(), a.outerIndexPtr() + columns + 1);
      pattern_inner.assign(a.innerIndexPtr(), a.innerIndexPtr() + entries);
    }
    sparse.factorize(a);
    return sparse.info() == Eigen::Success;
  };
  const auto solve = [&](const VecX& b) -> VecX { return contact ? VecX(sparse.solve(b)) : VecX(banded.solve(b)); };
  const bool pseudo_transient = options.pseudo_transient;
  const bool energy_merit = pseudo_transient && has_potential(model);
  const DofLayout layout(model);
  std::optional<Merit> here;  // the merit of the current state (energy_merit)
  double pseudo_time = options.initial_pseudo_time;
  Eigen::SparseMatrix<double> held_identity(Eigen::Index(held.size()), Eigen::Index(held.size()));
  {
    std::vector<Eigen::Triplet<double>> ones;
    for (std::size_t k = 0; k < held.size(); ++k)
      if (held[k]) ones.emplace_back(int(k), int(k), 1.0);
    held_identity.setFromTriplets(ones.begin(), ones.end());
  }
  for (std::size_t it = 0; it < options.max_iterations; ++it) {
    static_system(model, state, lambda, r, jacobian);
    zero_held(held, r);
    const Scales scales = residual_scales(model, state, lambda);
    if (hard) {
      try {
        contacts = detail::candidates_with_forces(model, state, contacts);
      } catch (const SolverError&) {  // two segments intersect
        return outcome;
      }
    }
    outcome.residual = equilibrium_measure(model, state, lambda, r, hard ? &contacts : nullptr, held);
    check_time_budget(kMethod, outcome.iterations, outcome.residual);
    if (!std::isfinite(outcome.residual)) return outcome;
    if (outcome.residual <= options.tolerance) {
      outcome.converged = true;
      outcome.contacts = std::move(contacts);
      return outcome;
    }
    // At the round-off floor the residual cannot show further progress, but the iterate may still
    // carry the error of the last step (up to floor / stiffness): one more full Newton step, taken
    // without the line search, squares that error away (kept if the residual stays at the floor).
    const bool at_floor = outcome.residual <= round_off_floor(model, state, scales.force);
    if (hard) {
      const double rho = kContactAugmentation * scales.force / model.self_contact.radius;
      detail::add_contact_stiffness(model, state, contacts, rho, jacobian);
    }
    jacobian.prune([&](Eigen::Index row, Eigen::Index, double) { return !held[std::size_t(row)]; });
    if (pseudo_transient) add_pseudo_time(model, scales, held, 1.0 / pseudo_time, jacobian);
    // Solved in the problem's own units: rows over their residual scale (forces, moments, lengths),
    // columns times their unknown's (L for positions, 1 for angles, the force scale for multipliers),
    // so that the LU's pivoting sees entries of order one at any EI and L (unscaled, EI = 1e9 or
    // L = 1e-3 failed on the Mattiasson cantilever). Scaled in place (the factors are powers of two, so
    // the order of the products does not matter). A held dof's row is then the identity, added as a
    // sparse sum: a held multiplier has no diagonal entry, and inserting one into the compressed matrix
    // moved all of it at every iteration (9 % of the plectoneme's run time).
    const VecX row_scale = unit_scales(model, scales, false), column_scale = unit_scales(model, scales, true);
    for (Eigen::Index column = 0; column < jacobian.outerSize(); ++column)
      for (Eigen::SparseMatrix<double>::InnerIterator entry(jacobian, column); entry; ++entry)
        entry.valueRef() *= column_scale[column] / row_scale[entry.row()];
    jacobian += held_identity;
    if (!factorize(jacobian)) return outcome;
    const auto solve_in_units = [&](const VecX& b) -> VecX {
      return column_scale.cwiseProduct(solve(b.cwiseQuotient(row_scale)));
    };
    VecX dz;
    std::vector<ContactPair> step_forces;  // hard contact: the pair forces this step solves for
    if (hard) {
      std::optional<detail::HardContactStep> step;
      try {
        step = detail::hard_contact_step(model, contacts, held, r, solve_in_units);
      } catch (const InputError&) {  // W refused (a negative diagonal: not positive semidefinite)
      } catch (const SolverError&) {  // no solution (an unstable linearisation)
      }
      if (step) {
        dz = std::move(step->dz);
        step_forces = std::move(step->pairs);
      } else {
        // A failed step. Under pseudo-transient continuation a shorter pseudo-time step adds mass,
        // which makes W positive definite.
        if (!pseudo_transient) return outcome;
        pseudo_time *= 0.25;
        if (pseudo_time < kMinPseudoTime) return outcome;
        ++outcome.iterations;
        continue;
      }
    } else {
      dz = solve_in_units(-r);
    }
    if (!dz.allFinite()) return outcome;
    bool capped = false;
    double cap_ratio = 1.0;  // the capped step's length over the Newton step's
    if (contact) {
      cap_ratio = contact_safe_fraction(model, state, dz);
      capped = cap_ratio < 1.0;
      if (capped) dz *= cap_ratio;
    }
    ++outcome.iterations;
    if (at_floor) {
      // Kept only if it stays at the floor: near a critical load the Jacobian is nearly singular and
      // a step on round-off noise can run along the soft mode (the lateral-torsional cantilever at
      // 0.999 P_cr: 1.2e-12 -> 1.5e-8).
      const double floor = round_off_floor(model, state, scales.force);
      if (auto trial = try_step(model, state, dz, lambda, held, hard ? &step_forces : nullptr);
          trial && trial->measure <= floor) {
        state = std::move(trial->state);
        outcome.residual = trial->measure;
        contacts = std::move(trial->contacts);
      }
      outcome.converged = true;
      outcome.contacts = std::move(contacts);
      return outcome;
    }
    // What a step is measured against: the residual here, and with hard contact also the residual here
    // under the step's own pair forces. Those forces are part of the iterate and change discontinuously
    // (a pair that a short step cannot close gets no force), so the residual under the previous forces
    // is no yardstick for a step with new ones: without this, a rejected step shortened tau, the shorter
    // step changed the forces again, and tau fell to its floor.
    const double yardstick = hard ? std::max(outcome.residual,
                                             equilibrium_measure(model, state, lambda, r, &step_forces, held))
                                  : outcome.residual;
    if (pseudo_transient) {
      // Pseudo-transient continuation (Kelley & Keyes 1998). Without a potential (hard contact, a dead
      // moment) the step is taken whole if it keeps the residual finite, within 10 x its value (far
      // from equilibrium the residual need not fall at every step), and the segments apart. After a
      // step that lowered the residual and was not shortened by contact_safe_fraction, tau grows by
      // r_old / r_new (switched evolution relaxation), clamped to [1.2, 10]: at least 1.2, so that tau
      // still grows when only a slow mode (a knot sliding along its tails) is left. A step that fails
      // is retried with a quarter of tau.
      auto trial = try_step(model, state, dz, lambda, held, hard ? &step_forces : nullptr);
      if (trial && energy_merit) {
        // A minimisation: the step is taken if it lowers the merit (or, within the merit's round-off,
        // the residual). Then tau grows by the residual's ratio clamped to [1.2, 10] as above, or stays
        // if the step was shortened by contact_safe_fraction; a step that fails is retried with a
        // quarter of tau. (Measured on knot/plectoneme-nodal at N = 200, 400, 800: 1591, 1459, 1462
        // iterations with the residual rule and an h/2 bound on each vertex's step; 2413, 2010, 1447
        // with this rule and that bound; 789, 971, 637 with this rule and contact_safe_fraction.)
        if (!here) here = merit(model, state, lambda, r);
        const Merit there = merit(model, trial->state, lambda, trial->residual);
        const double nu = penalty_weight(penalty_weight(0.0, state), trial->state);
        const double noise = std::max(here->noise, there.noise), change = there.value(nu) - here->value(nu);
        bool accept = change < -noise || (change <= noise && trial->measure < outcome.residual);
        std::optional<Merit> corrected_merit;
        if (!accept && pseudo_time >= kCorrectionPseudoTime) {
          // The Maratos effect: near a solution a good step can raise the merit through the
          // constraints' curvature alone. A second-order correction (Nocedal & Wright 2006, §15.5-15.6)
          // adds the step that, with the same factorised matrix, cancels the constraint violations
          // c(x + dz) left by the step, and the corrected point is measured instead. It only ever
          // rescues a step (a bad correction raises the merit and is refused), so it changes the path,
          // not what an equilibrium is. Tried from tau = kCorrectionPseudoTime on (the Newton-like
          // regime; a shorter tau is a step that was too long, which a shorter tau mends). Measured
          // on knot/trefoil-nodal at N = 100, 200, 400 (tying at 100, refining): 181 iterations
          // after the refinement to N = 400 without it (the residual rule: 45), 32 with it at every tau,
          // 34 from tau = 1 (bench_rod3d BM_TrefoilKnot/400: 2.7 -> 1.7 s); knot/plectoneme-nodal at N = 200, 400,
          // 800: 789, 971, 637 iterations (33.6 s CPU) without it, 700, 959, 1011 (37.4 s) at every
          // tau, 700, 900, 575 (28.9 s) from 0.1, 696, 897, 575 (25.8 s) from 1, 720, 909, 594 (24.4 s)
          // from 10, 842, 969, 588 (32.6 s; the trefoil 2.9 s) from 100; other equilibria of the same
          // N within the case's envelopes. Tried only when the step raised the constraint violation or
          // lowered the residual: slower on both (1.9 to 2.3 s; 789, 1018, 1171).
          if (auto corrected = second_order_correction(model, state, dz, *trial, lambda, held, layout,
                                                       solve_in_units)) {
            const Merit at = merit(model, corrected->state, lambda, corrected->residual);
            const double nu_c = penalty_weight(nu, corrected->state);
            const double noise_c = std::max(here->noise, at.noise), change_c = at.value(nu_c) - here->value(nu_c);
            if (change_c < -noise_c) {
              trial = std::move(corrected);
              corrected_merit = at;
              accept = true;
            }
          }
        }
        if (accept) {
          const double growth = capped ? 1.0 : std::clamp(outcome.residual / trial->measure, 1.2, 10.0);
          state = std::move(trial->state);
          here = corrected_merit ? *corrected_merit : there;
          pseudo_time = std::min(kMaxPseudoTime, pseudo_time * growth);
        } else {
          pseudo_time *= 0.25;
          if (pseudo_time < kMinPseudoTime) return outcome;
        }
        continue;
      }
      if (trial && trial->measure <= 10.0 * yardstick) {
        const bool progress = !capped && trial->measure < outcome.residual;
        // A capped step is not the pseudo-time step tau asked for but a fraction of it: tau shrinks by
        // that fraction (at most 10x per step), so that the next step is about as long as the cap allows
        // and the iterate follows the pseudo-time path instead of jumping along a soft mode (without
        // this, under the residual rule and an h/2 bound on each vertex's step, the 15-degree plectoneme
        // case ran for more than 10 minutes; with it, 30 s). The energy merit above needs neither.
        const double growth =
            progress ? std::clamp(outcome.residual / trial->measure, 1.2, 10.0) : (capped ? std::max(0.1, cap_ratio) : 1.0);
        state = std::move(trial->state);
        if (hard) contacts = std::move(step_forces);
        pseudo_time = std::min(kMaxPseudoTime, pseudo_time * growth);
      } else {
        pseudo_time *= 0.25;
        if (pseudo_time < kMinPseudoTime) return outcome;
      }
      continue;
    }
    // Backtracking on the scaled residual (Armijo 1e-4).
    double alpha = 1.0;
    bool accepted = false;
    for (int halving = 0; halving < 30; ++halving, alpha *= 0.5) {
      // nothing: a shorter step
      auto trial = try_step(model, state, alpha * dz, lambda, held, hard ? &step_forces : nullptr);
      if (trial && trial->measure <= (1.0 - 1e-4 * alpha) * yardstick) {
        state = std::move(trial->state);
        if (hard) contacts = step_forces;
        accepted = true;
        break;
      }
    }
    if (!accepted) return outcome;
  }
  return outcome;
}

void validate_options(const StaticOptions& options) {
  require_at_least("load_steps", options.load_steps, 1);
  require_at_least("max_iterations", options.max_iterations, 1);
  require_open_interval("tolerance", options.tolerance, 0.0, 1.0);
  require_closed_interval("initial_pseudo_time", options.initial_pseudo_time, kMinPseudoTime, kMaxPseudoTime);
}

}  // namespace

std::vector<std::size_t> held_dofs(const RodModel& model) {
  const DofLayout layout(model);
  std::vector<std::size_t> held;
  const auto hold_vertex = [&](std::size_t i) {
    for (std::size_t k = 0; k < 3; ++k) held.push_back(layout.vertex(i) + k);
  };
  const auto hold_end = [&](const EndCondition& end, std::size_t vertex, std::size_t inner, std::size_t edge) {
    if (end.support == EndSupport::Free) return;
    if (end.slides) {  // the transverse coordinates of the clamped edge, and its angle; its multiplier is free
      const auto axis = static_cast<std::size_t>(sliding_axis(end));
      for (std::size_t k = 0; k < 3; ++k)
        if (k != axis) held.insert(held.end(), {layout.vertex(vertex) + k, layout.vertex(inner) + k});
      held.push_back(layout.angle(edge));
      return;
    }
    hold_vertex(vertex);
    // A clamped end edge lies in the clamp: its inextensibility multiplier acts on held vertices only
    // and is part of the support's reaction, so it is held too (else the KKT matrix is singular).
    if (end.support == EndSupport::Clamped) {
      hold_vertex(inner);
      if (layout.multipliers) held.push_back(layout.multiplier(edge));
    }
    if (end.support == EndSupport::Clamped || end.hold_twist) held.push_back(layout.angle(edge));
  };
  hold_end(model.root, 0, 1, 0);
  hold_end(model.tip, model.elements, model.elements - 1, model.elements - 1);
  std::sort(held.begin(), held.end());
  held.erase(std::unique(held.begin(), held.end()), held.end());
  return held;
}

double scaled_residual(const RodModel& model, const RodState& state, double load_factor) {
  VecX r = static_residual(model, state, load_factor);
  const auto held = held_mask(model);
  return scaled_measure(model, r, residual_scales(model, state, load_factor), held);
}

StaticResult solve_static(const RodModel& model, const RodState& initial, const StaticOptions& options) {
  validate(model);
  validate_options(options);
  if (initial.elements() != model.elements)
    throw InputError("initial", "invalid parameter 'initial': the state has " + std::to_string(initial.elements()) +
                                    " elements, the model " + std::to_string(model.elements));
  const auto held = held_mask(model);
  const EndPath root = make_path(model.root, initial, false);
  const EndPath tip = make_path(model.tip, initial, true);

  StaticResult result;
  result.state = initial;
  if (is_inextensible(model) && result.state.multiplier.size() != model.elements)
    result.state.multiplier.assign(model.elements, 0.0);
  const double max_step = 1.0 / double(options.load_steps);
  double lambda = 0.0, step = max_step;
  std::size_t halvings = 0;
  double last_residual = 0.0;
  while (lambda < 1.0) {
    const double target = std::min(1.0, lambda + step);
    RodState trial = result.state;
    place_ends(model, trial, root, tip, target);
    NewtonOutcome outcome = newton(model, trial, target, options, held, result.contacts);
    result.iterations += outcome.iterations;
    last_residual = outcome.residual;
    if (outcome.converged) {
      result.state = std::move(trial);
      result.contacts = std::move(outcome.contacts);
      lambda = target;
      ++result.steps;
      halvings = 0;
      step = std::min(max_step, 1.5 * step);
      continue;
    }
    if (++halvings > options.max_halvings)
      throw SolverError(kMethod,
                        "no equilibrium found beyond load factor " + format_value(lambda) + " (step " +
                            format_value(step) + " halved " + std::to_string(options.max_halvings) + " times)",
                        result.iterations, last_residual);
    step *= 0.5;
  }
  result.residual = last_residual;
  if (has_self_contact(model)) {
    if (hard_contact(model)) {  // the pairs that carry a force
      std::erase_if(result.contacts, [](const ContactPair& pair) { return pair.force == 0.0; });
    } else {
      result.contacts = self_contacts(model.self_contact, result.state.position, rest_edge_length(model));
    }
  }
  return result;
}

}  // namespace rodvv::solvers::rod3d

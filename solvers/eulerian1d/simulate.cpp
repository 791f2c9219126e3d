#include "rodvv/solvers/eulerian1d/simulate.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/solvers/contact/velocity_qp.hpp"
#include "rodvv/solvers/eulerian1d/discretisation.hpp"

namespace rodvv::solvers::eulerian1d {

namespace {

// The cell (k, k+1) holding the solid end xi = X, chosen so that the cell contains solid
// (l_k > 0): for the left end xi_k <= 0 < xi_{k+1}, for the right end xi_k < L0 <= xi_{k+1}.
// Returns the cell and the interpolation weight a of node k+1.
struct Edge {
  Eigen::Index cell = -1;
  double weight = 0.0;
  double position = 0.0;
};
Edge solid_edge(const Grid& grid, const VecX& xi, double X, bool right_end) {
  for (Eigen::Index k = 0; k + 1 < xi.size(); ++k) {
    const bool brackets = right_end ? (xi(k) < X && X <= xi(k + 1)) : (xi(k) <= X && X < xi(k + 1));
    if (!brackets) continue;
    Edge e;
    e.cell = k;
    e.weight = (X - xi(k)) / (xi(k + 1) - xi(k));
    e.position = grid.node(static_cast<std::size_t>(k)) + e.weight * grid.dx();
    return e;
  }
  throw SolverError("eulerian1d", "the solid end xi = " + std::to_string(X) + " left the grid", 0, X);
}

struct Wall {
  Edge edge;
  double sign;   // +1: left wall (x_end + dt v_end >= wall), -1: right wall (<= wall)
  double bound;  // c of the row  sign * v_end >= sign * (wall - x_end) / dt
};

struct StepContact {
  double left_impulse = 0.0, right_impulse = 0.0;
  double violation = 0.0;
  double projection = 0.0;  // distance the edge was moved back onto a wall after advection
  bool assembled = false;
};

// Position projection after the advection (post-stabilisation, Cline & Pai, ICRA 2003). The QP
// bounds the interpolated edge velocity, x_R + dt v(x_R) <= wall, but the advected edge moves by
// dt v(x_R') at its new position x_R' and with upwind differences whose side depends on the sign
// of each nodal v, so it can cross the wall slightly (measured without projection: 2.2e-5, 6.0e-7,
// 6.0e-7 at N = 200, 400, 800 in the two-wall collision; 4.9e-7, 6.8e-7, 0 in the impact). If
// xi(wall) < L0 (right wall) the two nodes of the wall's cell are raised by L0 - xi(wall), which
// puts the edge on the wall exactly; the left wall symmetrically. Interior values of xi do not
// change the mass (the clipped lengths telescope), only the strain of the neighbouring cells, by
// the same small amount. Returns the largest distance moved (reported, so its size stays visible);
// a shift that folded xi would surface as the SolverError of cell_fields.
double project_onto_walls(const Problem& problem, VecX& xi) {
  const Grid& grid = problem.grid;
  double moved = 0.0;
  auto correct = [&](double wall, double target, bool right) {
    const double u = (wall - grid.x_min) / grid.dx();
    const auto m = std::clamp<Eigen::Index>(static_cast<Eigen::Index>(std::floor(u)), 0,
                                            static_cast<Eigen::Index>(grid.cells) - 1);
    const double b = u - static_cast<double>(m);
    const double at_wall = (1.0 - b) * xi(m) + b * xi(m + 1);
    const double delta = target - at_wall;  // > 0 needed on the right, < 0 on the left
    if (right ? !(delta > 0.0) : !(delta < 0.0)) return;
    xi(m) += delta;
    xi(m + 1) += delta;
    moved = std::max(moved, std::abs(delta) * grid.dx() / (xi(m + 1) - xi(m)));
  };
  if (problem.right_wall) correct(*problem.right_wall, problem.material.length, true);
  if (problem.left_wall) correct(*problem.left_wall, 0.0, false);
  return moved;
}

// Step 3: v = argmin 1/2 (v - v*)^T M (v - v*) s.t. the rows J v >= c of the walls. M is lumped,
// so only the (at most four) nodes in J move: the QP is solved on those nodes alone, with
// R = -M v* (seed slides 001: min 1/2 v^T M v + R^T v s.t. J v >= b).
StepContact apply_walls(const Problem& problem, const VecX& xi, const VecX& m, double dt, VecX& v) {
  std::vector<Wall> walls;
  const double L0 = problem.material.length;
  if (problem.left_wall) {
    const Edge e = solid_edge(problem.grid, xi, 0.0, false);
    walls.push_back({e, 1.0, (*problem.left_wall - e.position) / dt});
  }
  if (problem.right_wall) {
    const Edge e = solid_edge(problem.grid, xi, L0, true);
    walls.push_back({e, -1.0, -(*problem.right_wall - e.position) / dt});
  }
  StepContact result;
  if (walls.empty()) return result;
  result.assembled = true;

  std::vector<Eigen::Index> nodes;  // the distinct nodes the rows touch
  auto local = [&nodes](Eigen::Index node) {
    const auto it = std::find(nodes.begin(), nodes.end(), node);
    if (it != nodes.end()) return static_cast<Eigen::Index>(it - nodes.begin());
    nodes.push_back(node);
    return static_cast<Eigen::Index>(nodes.size() - 1);
  };
  // A node of the edge cell without (effective) mass takes the velocity of the other node in
  // step 4, so its weight in the edge velocity goes to that node.
  const auto k = static_cast<Eigen::Index>(walls.size());
  std::vector<std::array<std::pair<Eigen::Index, double>, 2>> rows;
  for (const Wall& w : walls) {
    const Eigen::Index a = w.edge.cell, b = w.edge.cell + 1;
    double wa = 1.0 - w.edge.weight, wb = w.edge.weight;
    if (m(a) == 0.0 && m(b) == 0.0)
      throw SolverError("eulerian1d", "both nodes of the solid's edge cell are massless", 0, 0.0);
    if (m(a) == 0.0) wb += std::exchange(wa, 0.0);
    if (m(b) == 0.0) wa += std::exchange(wb, 0.0);
    rows.push_back({std::pair{a, w.sign * wa}, std::pair{b, w.sign * wb}});
    if (wa != 0.0) local(a);
    if (wb != 0.0) local(b);
  }
  const auto n = static_cast<Eigen::Index>(nodes.size());
  MatX J = MatX::Zero(k, n);
  VecX c(k), m_local(n), v_star(n);
  for (Eigen::Index r = 0; r < k; ++r) {
    for (const auto& [node, weight] : rows[static_cast<std::size_t>(r)])
      if (weight != 0.0) J(r, local(node)) += weight;
    c(r) = walls[static_cast<std::size_t>(r)].bound;
  }
  for (Eigen::Index i = 0; i < n; ++i) {
    m_local(i) = m(nodes[static_cast<std::size_t>(i)]);
    v_star(i) = v(nodes[static_cast<std::size_t>(i)]);
  }
  const VecX R = -m_local.cwiseProduct(v_star);
  const auto qp = contact::solve_velocity_qp_lumped(m_local, R, J, c, contact::LcpMethod::Lemke);
  for (Eigen::Index i = 0; i < n; ++i) v(nodes[static_cast<std::size_t>(i)]) = qp.v(i);
  for (Eigen::Index r = 0; r < k; ++r) {
    (walls[static_cast<std::size_t>(r)].sign > 0 ? result.left_impulse : result.right_impulse) = qp.lambda(r);
    result.violation = std::max(result.violation, -qp.gap(r) * dt);  // as a distance
  }
  return result;
}

// Lumped masses with the nodes whose mass is at the round-off level of the total (<= 64 eps
// rho0 L0: a sliver of solid in the edge cell) set to zero. Such a node would otherwise follow
// its own acceleration -2 sigma / (rho0 dxi) while carrying a weight ~eps in the wall constraint,
// i.e. move unconstrained (measured: |v| = 0.26 on a bar held at rest by two walls whose ends sit
// on nodes); as a massless node it takes its neighbour's velocity. The recorded mass is the full sum.
VecX effective_masses(const Material& material, const CellFields& cells) {
  VecX m = lumped_masses(material, cells);
  const double floor = 64.0 * std::numeric_limits<double>::epsilon() * material.rho0 * material.length;
  for (Eigen::Index j = 0; j < m.size(); ++j)
    if (m(j) <= floor) m(j) = 0.0;
  return m;
}

struct Recorder {
  const Problem& problem;
  Result& result;

  void record(double t, const VecX& xi, const VecX& v, const CellFields& cells, const VecX& m,
              const StepContact& contact, double dt) {
    History& h = result.history;
    const double L0 = problem.material.length;
    const auto x_left = material_point_position(problem.grid, xi, 0.0);
    const auto x_right = material_point_position(problem.grid, xi, L0);
    if (!x_left || !x_right)
      throw SolverError("eulerian1d", "the solid left the grid", result.steps, t);
    h.t.push_back(t);
    h.x_left.push_back(*x_left);
    h.x_right.push_back(*x_right);
    h.mass.push_back(cells.solid_length.sum() * problem.material.rho0);
    h.momentum.push_back(m.dot(v));
    h.kinetic.push_back(0.5 * m.dot(v.cwiseProduct(v)));
    h.elastic.push_back(elastic_energy(problem.material, cells));
    h.left_wall_force.push_back(dt > 0.0 ? contact.left_impulse / dt : 0.0);
    h.right_wall_force.push_back(dt > 0.0 ? contact.right_impulse / dt : 0.0);
    double penetration = -std::numeric_limits<double>::infinity();
    if (problem.left_wall) penetration = std::max(penetration, *problem.left_wall - *x_left);
    if (problem.right_wall) penetration = std::max(penetration, *x_right - *problem.right_wall);
    h.penetration.push_back(std::isfinite(penetration) ? penetration : 0.0);
    h.constraint_violation.push_back(contact.violation);
    h.projection.push_back(contact.projection);
  }

  void snapshot(double t, const VecX& xi, const VecX& v, const CellFields& cells) {
    result.snapshots.push_back({t, xi, v, cell_density(problem.grid, problem.material, cells)});
  }
};

}  // namespace

Result simulate(const Problem& problem, const Settings& settings) {
  validate(problem, settings);
  const double least_work = least_cell_updates(problem.grid, problem.material, settings);
  if (!(least_work <= settings.max_cell_updates))
    throw SolverError("eulerian1d",
                      "work budget: reaching t_end = " + format_value(settings.t_end) + " on " +
                          std::to_string(problem.grid.cells) + " cells takes at least " + format_value(least_work) +
                          " cell updates (dt <= cfl dx / c = " +
                          format_value(settings.cfl * problem.grid.dx() / problem.material.wave_speed()) +
                          "), above the budget of " + format_value(settings.max_cell_updates) + " per run",
                      0, least_work);
  Result result;
  result.grid = problem.grid;
  Recorder recorder{problem, result};
  const Grid& grid = problem.grid;
  const double dx = grid.dx(), c = problem.material.wave_speed();

  std::vector<double> snapshot_times = settings.snapshot_times;
  std::sort(snapshot_times.begin(), snapshot_times.end());
  std::size_t next_snapshot = 0;

  VecX xi = problem.xi0, v = problem.v0;
  CellFields cells = cell_fields(grid, problem.material, xi);
  VecX m = effective_masses(problem.material, cells);
  extrapolate_velocity(m, v);
  double t = 0.0;
  recorder.record(t, xi, v, cells, m, {}, 0.0);
  while (next_snapshot < snapshot_times.size() && snapshot_times[next_snapshot] <= 0.0)
    recorder.snapshot(t, xi, v, cells), ++next_snapshot;

  while (t < settings.t_end) {
    if (result.steps >= settings.max_steps)
      throw SolverError("eulerian1d", "step limit reached before t_end", result.steps, t);
    check_time_budget("eulerian1d", result.steps, t);
    // CFL step. The characteristics move at v +- F c (Eulerian wave speed F c), but within one
    // step the velocity can jump by up to c |F - 1| (a released strain jump: the Riemann problem
    // of the bar), and the new velocity then advects xi. So the bound is
    // max|v| + c max(F + |F - 1|): with F c alone a bar released from F = 0.1 moves its end
    // 3.6 cells in the first step and xi folds (measured). F + |F - 1| is 1 for F <= 1 and
    // 2F - 1 for F > 1.
    double speed = 0.0;
    for (Eigen::Index j = 0; j < m.size(); ++j)
      if (m(j) > 0.0) speed = std::max(speed, std::abs(v(j)));
    double wave = 0.0;
    for (Eigen::Index k = 0; k < cells.solid_length.size(); ++k)
      if (cells.solid_length(k) > 0.0)
        wave = std::max(wave, (cells.stretch(k) + std::abs(cells.stretch(k) - 1.0)) * c);
    double dt = settings.cfl * dx / (speed + wave);
    double target = settings.t_end;
    if (next_snapshot < snapshot_times.size()) target = std::min(target, snapshot_times[next_snapshot]);
    const bool lands = dt >= target - t;
    if (lands) dt = target - t;

    // 1. upwind advection of v, 2. forces and gravity on nodes with mass.
    const VecX forces = nodal_forces(cells);
    VecX v_new = v - dt * upwind_transport(grid, v, v);
    for (Eigen::Index j = 0; j < m.size(); ++j)
      if (m(j) > 0.0) v_new(j) += dt * (forces(j) / m(j) + problem.gravity);
    // 3. barriers, 4. extrapolation, 5. upwind advection of xi with the new velocity.
    const StepContact contact = apply_walls(problem, xi, m, dt, v_new);
    extrapolate_velocity(m, v_new);
    v = std::move(v_new);
    xi -= dt * upwind_transport(grid, v, xi);
    if (!xi.allFinite() || !v.allFinite())
      throw SolverError("eulerian1d", "non-finite field", result.steps, t);
    StepContact step_contact = contact;
    if (settings.project_positions) step_contact.projection = project_onto_walls(problem, xi);

    t = lands ? target : t + dt;
    ++result.steps;
    if (contact.assembled) ++result.contact_solves;
    cells = cell_fields(grid, problem.material, xi);
    m = effective_masses(problem.material, cells);
    recorder.record(t, xi, v, cells, m, step_contact, dt);
    while (next_snapshot < snapshot_times.size() && snapshot_times[next_snapshot] <= t)
      recorder.snapshot(t, xi, v, cells), ++next_snapshot;
  }
  return result;
}

}  // namespace rodvv::solvers::eulerian1d

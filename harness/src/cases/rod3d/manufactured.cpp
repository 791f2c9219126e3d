// rod3d/manufactured: the method of manufactured solutions on the nodal 3-D rod (issue 13, class 2). The
// equilibrium is chosen - material strains u(s) with twist and both curvatures varying along the rod, a
// natural strain, EI1 != EI2 != GJ, an internal force n(s) varying in direction and size, a tilted clamp -
// and the distributed force f = -n' and couple c = -m' - t x n that hold it are applied through the
// rod's load interface (references/manufactured_rod.hpp; f lumped exactly per vertex cell, c per edge by
// Gauss), with n(L), m(L) at the free tip. No closed-form case has a general 3-D shape, a varying twist
// and a distributed couple: a defect anywhere in the strains, frames, stiffness indices, load lumping or
// the reported n and m moves this case off its O(h^2).
//
// Metrics: ../manufactured_metrics.hpp (positions, frames, strains, n and m against the fields).
#include <vector>

#include "../case_builder.hpp"
#include "../manufactured_metrics.hpp"
#include "rod3d_cases.hpp"
#include "rodvv/references/manufactured_rod.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

// The manufactured rod at (L, EI, amplitude): strains in units of 1/L, forces of EI/L^2, all scaled by the
// amplitude (1: the tip turns by about 2.5 rad, the twist varies by a factor 3 along the rod).
ref::ManufacturedRod manufactured_rod(const Parameters& p) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), a = parameter_value(p, "amplitude");
  const double F = EI / (L * L);
  ref::ManufacturedRod rod;
  rod.length = L;
  rod.stiffness = Vec3(0.55 * EI, EI, 1.9 * EI);  // (GJ, EI1, EI2)
  rod.natural_strain = Vec3(0.4, 0.3, -0.2) / L;
  rod.root_position = Vec3(0.3, -0.2, 0.6) * L;
  rod.root_frame = tilted_frame(0.7);
  rod.strain_mean = a * Vec3(1.2, 1.5, -0.8) / L;
  rod.strain_sine = a * Vec3(-0.6, 0.9, 1.2) / L;
  rod.strain_cosine = a * Vec3(0.3, -0.5, 0.4) / L;
  rod.force_root = a * F * Vec3(1.4, -0.7, 0.5);
  rod.force_slope = a * F * Vec3(-1.1, 0.6, 0.8);
  rod.force_sine = a * F * Vec3(0.6, 0.4, -0.9);
  return rod;
}

Solution solve(const Parameters& p, double level) {
  const ref::ManufacturedRod exact = manufactured_rod(p);
  rod::RodModel model;
  model.elements = element_count(level);
  model.length = exact.length;
  model.stiffness = exact.stiffness;
  model.natural_strain = exact.natural_strain;
  model.root.support = rod::EndSupport::Clamped;
  model.root.position = exact.root_position;
  model.root.frame = exact.root_frame;
  const std::size_t n = model.elements;
  const double ebar = rod::rest_edge_length(model), L = model.length;
  // Vertex i >= 1 sits at (i - 1/2) ebar, its cell [(i - 1) ebar, i ebar] (the tip's ends at L); the clamped
  // ghost vertex 0 takes none. Edge j spans [(j - 1/2) ebar, (j + 1/2) ebar], the clamped edge 0 from s = 0.
  std::vector<double> vertex_breaks{0.0}, edge_breaks{0.0};
  for (std::size_t i = 1; i < n; ++i) vertex_breaks.push_back(double(i) * ebar);
  vertex_breaks.push_back(L);
  for (std::size_t j = 1; j < n; ++j) edge_breaks.push_back((double(j) - 0.5) * ebar);
  edge_breaks.push_back(L);
  model.vertex_forces.assign(n + 1, Vec3::Zero());
  const auto cell_forces = ref::manufactured_cell_forces(exact, vertex_breaks);
  for (std::size_t i = 1; i <= n; ++i) model.vertex_forces[i] = cell_forces[i - 1];
  model.edge_moments = ref::manufactured_cell_couples(exact, edge_breaks);
  const auto tip = ref::manufactured_stations(exact, {L}).front();
  model.end_force = tip.force;
  model.end_moment = tip.moment;
  // From the straight rod, the dead loads ramped in eight continuation steps, as a user
  // would pose it; the proportional path passes a fold beyond the amplitude window (at 1.5 continuation stops
  // at load factor 0.93).
  rod::StaticOptions options;
  options.load_steps = 8;
  options.tolerance = 1e-12;
  const auto result = rod::solve_static(model, rod::make_straight_state(model), options);
  SpatialRodSolution solution = rod::make_solution(model, result.state);
  solution.iterations = result.iterations;
  return solution;
}

LevelOutput measure(const Parameters& p, double, const Solution& any) {
  return measure_manufactured(solution_as<SpatialRodSolution>(any, "spatial_rod"), manufactured_rod(p));
}

}  // namespace

void add_manufactured(Registry& registry) {
  // Measured at the defaults (2026-11-28) over N = 16 .. 256: every metric at order 2.00 - 2.01 (pairwise 1.996 ..
  // 2.06); at N = 128 position 9.8478e-5, frame 3.1065e-4, strain 5.7188e-4, force 5.3535e-5, moment 1.5187e-4.
  std::vector<MetricSpec> metrics = manufactured_metric_specs();
  std::vector<GateSpec> gates = manufactured_gates(
      {{"position", 9.8478e-5}, {"frame", 3.1065e-4}, {"strain", 5.7188e-4}, {"force", 5.3535e-5}, {"moment", 1.5187e-4}},
      1.0 / 128.0, "a discrete elastic rod is second order in h = L/N (the loads lumped exactly per cell, the couples by Gauss)");
  Case c = make_case(
      "rod3d",
      {"rod3d/manufactured", "Manufactured 3-D equilibrium: varying twist and curvatures, distributed force and couple",
       "Inextensible Kirchhoff rod, EI1 = EI, EI2 = 1.9 EI, GJ = 0.55 EI, natural strain u_hat, clamped in a tilted "
       "frame at s = 0; the distributed force f = -n' and couple c = -m' - t x n of a chosen equilibrium (strains "
       "u(s), internal force n(s)) and the end loads n(L), m(L).",
       "The manufactured fields (references/manufactured_rod.hpp: r, R by GSL rk8pd to 1e-14, checked against an "
       "mpmath table to 21 eps)",
       "Roache 2002 (method of manufactured solutions); Bergou et al. 2008", kMethod},
      {make_parameter("L", 1.3, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI", 0.8, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 (EI2 = 1.9 EI, GJ = 0.55 EI)"),
       // amplitude measured 2026-11-28: every gate passes from 0.02 to 1.2; at 1.3 and 1.4 the coarsest level's
       // continuation stops at a fold of the proportional load path.
       make_parameter("amplitude", 1.0, 0.0, 1.2, true, false, "",
                      "scale of the manufactured strains (units 1/L) and internal force (units EI/L^2)")},
      element_levels("number of edges", {16, 32, 64, 128}, {16, 32, 64, 128, 256}), std::move(metrics),
      std::move(gates), nullptr);
  split_level(c, solve, measure);
  c.problem_data = [](const Parameters& p, std::size_t intervals) {
    const ref::ManufacturedRod rod = manufactured_rod(p);
    return manufactured_problem_data(rod, uniform_stations(rod.length, intervals));
  };
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

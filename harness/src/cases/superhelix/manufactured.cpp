// superhelix/manufactured: the method of manufactured solutions on the Super-Helix (issue 13, class 2), the
// couple-free variant of references/manufactured_rod.hpp: the Super-Helix takes distributed forces (its dead
// point forces at the Gauss points) but no distributed couple, so the equilibrium is manufactured with c = 0 -
// both curvatures chosen along the rod, the twist from Kirchhoff's twist equation (it varies: GJ u0' =
// -(u x K (u - u_hat))_0 with EI1 != EI2 != GJ and a natural strain), the internal force n = T t + t x m' with
// a chosen tension T(s) - and held by f = -n' at the Gauss points (weights of the rod's own quadrature) with
// n(L) and the dead moment m(L) at the tip, the root clamped in a tilted frame. Piecewise-constant strains
// approximate the varying ones at second order at the element midpoints, where the solution's stations are.
// Metrics: ../manufactured_metrics.hpp.
#include <string>
#include <tuple>
#include <vector>

#include "../case_builder.hpp"
#include "../manufactured_metrics.hpp"
#include "superhelix_problems.hpp"
#include "rodvv/references/manufactured_rod.hpp"
#include "rodvv/solvers/superhelix/clothoid_kinematics.hpp"
#include "rodvv/solvers/superhelix/clothoid_solution.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace rodvv::harness::superhelix_cases {

namespace {

namespace sh = solvers::superhelix;
namespace ref = references;
using namespace cases;

// Strains in units of 1/L, tension of EI/L^2, scaled by the amplitude (1: the tip turns by about 2 rad).
ref::ManufacturedRod manufactured_rod(const Parameters& p) {
  const double L = parameter_value(p, "L"), EI = parameter_value(p, "EI"), a = parameter_value(p, "amplitude");
  const double F = EI / (L * L);
  ref::ManufacturedRod rod;
  rod.length = L;
  rod.stiffness = Vec3(0.65 * EI, EI, 1.7 * EI);  // (GJ, EI1, EI2)
  rod.natural_strain = Vec3(0.5, -0.3, 0.2) / L;
  rod.root_position = Vec3(-0.2, 0.4, 0.1) * L;
  rod.root_frame = tilted_frame(-0.9);
  rod.couple_free = true;
  rod.strain_mean = a * Vec3(0.8, 1.4, -0.9) / L;  // the twist: its root value only (couple_free)
  rod.strain_sine = a * Vec3(0.0, -0.7, 1.3) / L;
  rod.strain_cosine = a * Vec3(0.3, 0.6, -0.4) / L;
  rod.tension_root = a * 1.3 * F;
  rod.tension_slope = -a * 0.8 * F;
  rod.tension_sine = a * 0.6 * F;
  return rod;
}

// The model of either element: the rod, f = -n' at the Gauss points times their weights (mass / rho S =
// w ell / 2, the rod's own quadrature of int f ds), n(L) and the dead moment m(L) at the tip.
sh::RodModel loaded_model(const ref::ManufacturedRod& exact, std::size_t elements, bool clothoid) {
  sh::RodModel model;
  model.elements = elements;
  model.length = exact.length;
  model.stiffness = exact.stiffness;
  model.natural_strain = exact.natural_strain;
  model.root_position = exact.root_position;
  model.root_frame = exact.root_frame;
  std::vector<double> s, weights;
  const double ell = exact.length / double(elements);
  if (clothoid) {
    const sh::ClothoidKinematics at_rest(model, VecX::Zero(Eigen::Index(3 * (elements + 1))), true);
    for (const auto& point : at_rest.points())
      s.push_back(double(point.element) * ell + point.sigma), weights.push_back(point.mass / model.line_density);
  } else {
    const sh::Kinematics at_rest(model, VecX::Zero(Eigen::Index(3 * elements)));
    for (const auto& point : at_rest.points())
      s.push_back(double(point.element) * ell + point.sigma), weights.push_back(point.mass / model.line_density);
  }
  const auto fields = ref::manufactured_stations(exact, s);
  for (std::size_t g = 0; g < fields.size(); ++g) model.point_forces.push_back(fields[g].force_density * weights[g]);
  const auto tip = ref::manufactured_stations(exact, {exact.length}).front();
  model.end_force = tip.force;
  model.end_moment = tip.moment;
  return model;
}

SpatialRodSolution solve_on(const Parameters& p, double level, bool clothoid) {
  const sh::RodModel model = loaded_model(manufactured_rod(p), element_count(level), clothoid);
  sh::StaticOptions options;
  options.load_steps = 8;
  options.tolerance = 1e-12;
  const auto result = clothoid ? sh::solve_clothoid_static(model, options) : sh::solve_static(model, options);
  SpatialRodSolution solution = clothoid ? sh::make_clothoid_solution(model, result.q, sh::ClothoidStations::Midpoints)
                                         : sh::make_solution(model, result.q);
  solution.iterations = result.iterations;
  return solution;
}

Solution solve(const Parameters& p, double level) { return solve_on(p, level, false); }
Solution solve_clothoid(const Parameters& p, double level) { return solve_on(p, level, true); }

LevelOutput measure(const Parameters& p, double, const Solution& any) {
  return measure_manufactured(solution_as<SpatialRodSolution>(any, "spatial_rod"), manufactured_rod(p));
}

}  // namespace

void add_manufactured(Registry& registry) {
  // Measured at the defaults (2026-11-28) over N = 8 .. 128: orders 1.98 - 2.02 (the strain's pairwise 1.87, 1.95,
  // 1.98, 1.99: the element-midpoint stations' O(h^2) with a smaller O(h^3) beside it); at N = 64 position
  // 6.2759e-5, frame 2.5408e-4, strain 5.0585e-4, force 4.0299e-5, moment 1.5049e-4.
  std::vector<GateSpec> gates = manufactured_gates(
      {{"position", 6.2759e-5}, {"frame", 2.5408e-4}, {"strain", 5.0585e-4}, {"force", 4.0299e-5}, {"moment", 1.5049e-4}},
      1.0 / 64.0,
      "piecewise-constant strains: second order at the element midpoints (Gauss quadrature of f per element)");
  Case c = make_case(
      "superhelix",
      {"superhelix/manufactured",
       "Manufactured 3-D equilibrium without distributed couple: varying twist and curvatures, distributed force",
       "Inextensible Kirchhoff rod, EI1 = EI, EI2 = 1.7 EI, GJ = 0.65 EI, natural strain u_hat, clamped in a tilted "
       "frame at s = 0; the distributed force f = -n' of a chosen couple-free equilibrium (curvatures chosen, twist "
       "from Kirchhoff's twist equation, n = T t + t x m') at the Gauss points, n(L) and the dead moment m(L) at the "
       "tip.",
       "The manufactured fields (references/manufactured_rod.hpp, couple_free: r, R and the twist by GSL rk8pd to "
       "1e-14, checked against an mpmath table to 26 eps)",
       "Roache 2002 (method of manufactured solutions); Bertails et al. 2006", kMethod},
      {make_parameter("L", 0.9, 0.0, 1e6, true, false, "length", "rod length"),
       make_parameter("EI", 1.4, 0.0, 1e12, true, false, "force length^2", "bending stiffness EI1 (EI2 = 1.7 EI, GJ = 0.65 EI)"),
       // amplitude measured 2026-11-28: every gate passes from 0.01 to 2.4; at 2.6 Newton's line search stops at
       // load factor 0.375 on every level.
       make_parameter("amplitude", 1.0, 0.0, 2.4, true, false, "",
                      "scale of the manufactured strains (units 1/L) and tension (units EI/L^2)")},
      element_levels("number of elements", {8, 16, 32, 64}, {8, 16, 32, 64, 128}), manufactured_metric_specs(),
      std::move(gates), nullptr);
  split_level(c, solve, measure);
  c.problem_data = [](const Parameters& p, std::size_t intervals) {
    const ref::ManufacturedRod rod = manufactured_rod(p);
    return manufactured_problem_data(rod, uniform_stations(rod.length, intervals));
  };

  // The super-clothoid (strains affine per element, nodal strains) on the same problem, the same Gauss-point
  // loads of its own quadrature; stations at the element midpoints (where n(s) from the lumped point forces is
  // second order; at the Gauss stations it is first order, the forces beyond a station changing in steps).
  // Measured at the defaults (2026-11-28, on the exact-Jacobian Newton) over N = 4 .. 128: position and frame
  // at order 4 (4.51, 4.12, 4.03, 4.01, 4.00 and 4.23, 4.00, 4.01, 4.01, 4.00 pairwise), strain, force and
  // moment at 2 (the affine strain's midpoint value); at N = 64 position 3.0013e-9, frame 3.9888e-8, strain
  // 4.2620e-4, force 4.0299e-5, moment 1.6546e-4. The levels are the Super-Helix's (N = 8 .. 64: 0.19 s at
  // N = 64; on central differences N = 24 took 2.5 s and the levels stopped at 12).
  Case clothoid = c;
  clothoid.info.name = "superhelix/clothoid-manufactured";
  clothoid.info.group = "superhelix/manufactured";
  clothoid.info.title = "Manufactured 3-D equilibrium without distributed couple, super-clothoid";
  clothoid.info.method =
      "Super-clothoid (Casati & Bertails-Descoubes 2013; ALGORITHMS.md §2): nodal twist and curvatures, affine per "
      "element; frame and centreline by the adaptive power series; statics by the Super-Helix Newton on the "
      "exact Jacobian (line search, load stepping)";
  clothoid.info.resolution = element_levels("number of elements", {8, 16, 32, 64}, {8, 16, 32, 64, 128});
  clothoid.gates.clear();
  const double h = 1.0 / 64.0;
  for (const auto& [metric, order, measured] :
       {std::tuple{"position", 4.0, 3.0013e-9}, {"frame", 4.0, 3.9888e-8}, {"strain", 2.0, 4.2620e-4},
        {"force", 2.0, 4.0299e-5}, {"moment", 2.0, 1.6546e-4}}) {
    clothoid.gates.push_back(order_gate(metric, order,
                                        order == 4.0 ? "the clothoid's shape is fourth order (affine strains integrated "
                                                       "exactly per element)"
                                                     : "affine strains: second order at the element midpoints"));
    clothoid.gates.push_back(measured_bound(metric, measured, h, order));
  }
  for (auto& metric : clothoid.info.metrics)
    if (metric.name == "position" || metric.name == "frame") metric.theoretical_order = 4.0;
  split_level(clothoid, solve_clothoid, measure);
  clothoid.problem_data = c.problem_data;
  registry.add(std::move(c));
  registry.add(std::move(clothoid));
}

}  // namespace rodvv::harness::superhelix_cases

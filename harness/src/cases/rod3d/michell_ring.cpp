// rod3d/michell-ring: Michell's twisted-ring instability (Michell 1889/90; Goriely 2006, J.
// Elasticity 84:281; PHYSICS.md §7.2) on a closed discrete elastic rod (solvers/rod3d/ring.hpp): a
// circular ring of length L, isotropic bending B and twisting stiffness C, with a total twist Phi
// stored in it, is stable iff Phi < Phi_c = 2 pi sqrt(3) B/C. The case finds Phi_c as the twist at
// which the smallest eigenvalue of the constrained Hessian - the six rigid motions and the uniform
// spin of the material frames projected out exactly - crosses zero (TOMS 748), and compares it with
// references::michell_ring. B != C, non-unit L, a tilted plane off the origin. Bergou et al. (2008)
// showed this threshold on DER; here it is measured at second order in 1/N.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "../case_builder.hpp"
#include "buckling_threshold.hpp"
#include "rod3d_cases.hpp"
#include "rodvv/references/twisted_rod.hpp"
#include "rodvv/solvers/rod3d/ring.hpp"

namespace rodvv::harness::rod3d_cases {

namespace {

namespace rod = solvers::rod3d;
namespace ref = references;
using namespace cases;

rod::TwistedRing ring_of(const Parameters& p, std::size_t elements, double twist) {
  rod::TwistedRing ring;
  ring.elements = elements;
  ring.length = parameter_value(p, "L");
  const double B = parameter_value(p, "B");
  ring.stiffness = Vec3(parameter_value(p, "C"), B, B);
  ring.twist = twist;
  ring.center = Vec3(0.3, -0.2, 0.7) * ring.length;
  ring.frame = Eigen::AngleAxisd(0.9, Vec3(1, 2, -0.5).normalized()).toRotationMatrix();
  return ring;
}

LevelOutput run(const Parameters& p, double level) {
  const std::size_t n = element_count(level);
  const auto exact = ref::michell_ring({parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "L")});
  const double computed = critical_load(
      [&](double twist) { return rod::ring_stability_eigenvalue(ring_of(p, n, twist)); }, 0.7 * exact.twist_angle,
      1.3 * exact.twist_angle, "Michell critical twist");
  LevelOutput output;
  output.metrics["critical_twist"] = error_sample(computed, exact.twist_angle);
  output.metrics["critical_twist_relative"] = {computed / exact.twist_angle, 1.0,
                                               std::abs(computed / exact.twist_angle - 1.0)};
  output.metrics["critical_turns"] = diagnostic(computed / (2.0 * std::numbers::pi));
  output.metrics["equilibrium_residual"] = diagnostic(rod::linearize_ring(ring_of(p, n, computed)).residual);
  return output;
}

}  // namespace

void add_michell_ring(Registry& registry) {
  const double h = 1.0 / 96.0;
  std::vector<GateSpec> gates{order_gate("critical_twist_relative", 2.0, "vertex curvature and twist: O(h^2) (measured)"),
                              // measured 3.3383e-3 at N = 96 (pairwise orders 1.92, 1.98 over N = 24, 48, 96;
                              // 1.82 between 16 and 32, pre-asymptotic, so the levels start at 24)
                              measured_bound("critical_twist_relative", 3.3383e-3, h, 2.0)};
  std::vector<MetricSpec> metrics{
      error_metric("critical_twist", "rad", "Phi_c, the total twist at which the ring loses stability", 2.0, true),
      error_metric("critical_twist_relative", "", "|Phi_c / (2 pi sqrt(3) B/C) - 1|", 2.0),
      diagnostic_metric("critical_turns", "Phi_c / 2 pi (Michell: sqrt(3) B/C turns)"),
      diagnostic_metric("equilibrium_residual", "force imbalance of the twisted polygon / its scale (round-off)")};
  Case c = make_case(
      "rod3d",
      {"rod3d/michell-ring", "Michell's twisted ring: critical twist from the stability eigenvalue",
       "Closed inextensible ring (tilted plane), isotropic bending B, twist C, total twist Phi; Phi_c where the "
       "smallest eigenvalue of the constrained Hessian, rigid motions and the uniform spin projected out, crosses zero.",
       "Phi_c = 2 pi sqrt(3) B / C (references/twisted_rod.hpp)", "Michell 1889/90; Goriely 2006; PHYSICS.md §7.2",
       kMethod},
      {make_parameter("L", 2.7, 0.0, 1e6, true, false, "length", "ring length 2 pi R"),
       make_parameter("B", 1.3, 0.0, 1e12, true, false, "force length^2", "bending stiffness (EI1 = EI2)"),
       make_parameter("C", 0.8, 0.0, 1e12, true, false, "force length^2", "twisting stiffness GJ")},
      element_levels("number of edges", {24, 48, 96}, {24, 48, 96, 192}), std::move(metrics), std::move(gates),
      run);
  c.info.resolution.finest_honoured = double(rod::kMaxRingElements);  // the dense linearisation's limit
  // C / B in [0.6, 1e4] (measured 2026-11-26 on the default levels): at 0.54 the critical twist's order is
  // 1.89, at 0.3 and below 1.72 or no level converges (the error constant grows as the twist softens;
  // finer levels do not rescue 0.3); 1e4 passes, 7.7e11 fails.
  require(c, ratio_window("C", "B", 0.6, 1e4, "the twist-to-bending ratios the levels resolve the critical twist at"));
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::rod3d_cases

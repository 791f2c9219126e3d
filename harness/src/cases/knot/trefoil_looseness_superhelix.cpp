// knot/trefoil-looseness-superhelix: the loose-knot limit of the open trefoil (PHYSICS.md §5.1), a sweep
// over the rod's thickness instead of the mesh. The knot of knot/trefoil-superhelix (superhelix_trefoil.hpp)
// is tied at decreasing looseness eps = h sqrt(T/B); as eps -> 0 the braid shrinks to a point and the
// loop outside it tends to the tension elastica's homoclinic, whose H = T gives 1/2 B kappa_B^2 = T where
// the tangent is perpendicular to the pull (the slides' T = EI / (2 R^2), R = 1 / kappa_B). The case
// measures how fast: perpendicular_excess = 1/2 B kappa_B^2 / T - 1 (mean over the loop's two such
// points), its observed order in eps and its size, with H = T through the braid at every thickness.
//
// Why the excess is not zero at finite eps: H = T holds exactly, and at B (t perpendicular to e_x, no
// contact, no twist: the free tip carries no moment, so C Omega = 0 all along) it reads
// 1/2 B kappa_B^2 / T - 1 = -(n - T e_x).t / T: the net force the braid's contacts pass to the loop. It
// vanishes at leading order in the loose limit (PHYSICS.md §5.1); its order is measured here, not derived:
// 2.0 (below).
//
// Elements: N = max(150, 9 / eps). The rod is about 8.5 sqrt(B/T) long, so ell / h = 8.5 / (N eps): at
// most 0.94 (at fixed N it would grow as h shrinks and the braid would be resolved ever more coarsely). Measured 2026-11-27 (perpendicular_excess at N = 100, 150, 200, 400):
// eps = 0.12: 0.0463, 0.0471, 0.0481, 0.0485; eps = 0.085: 0.0240, 0.0247, 0.0246; eps = 0.06: 0.0126,
// 0.0121, 0.0125, 0.0125; eps = 0.0425: 0.0045, 0.0056, 0.0061; eps = 0.03 (N = 200): 0.0031. The mesh
// moves it by at most 4 % of itself at N = 150 where eps >= 0.06, against the factor 2 per level of the
// sweep. Pairwise orders at the defaults (eps = 0.12, 0.085, 0.06, N = 150): 1.88, 2.04; then 2.01 to
// eps = 0.0425 (N = 212). (Since the laying's Gauss-Newton is damped relative to its normal matrix,
// superhelix_on_curve.cpp, eps = 0.12 at N = 150 relaxes to a neighbouring knot: excess 0.0474, H_deviation
// 0.0126, was 0.0471 and 0.0140; the other levels moved at round-off.) The extended levels stop there: at eps = 0.03 (N = 300) the excess, 0.0034, is
// within 10 % of the mesh's own error (0.0031 at N = 200, 0.0036 at N = 150; H_deviation 0.004), and the
// last pairwise order is 1.68. 0.03 is still honoured (`--levels`): the knot holds and H = T to 0.004.
//
// Reported, not gated: the apex relation B kappa_apex^2 / (4 T) (1 for the homoclinic) is 0.16 .. 0.32
// over eps = 0.15 .. 0.03, rising with an observed order of only ~0.13; the end shortening
// (L - span) / (4 sqrt(B/T)) falls from 1.59 to 1.26, pairwise orders drifting from 0.59 to 0.43. Both
// assume the internal force in the loop to be T e_x, which it is not at these looseness (README,
// knot/trefoil-nodal: about half of T, along e_x); the perpendicular relation needs only n parallel to e_x
// and H = T, which is why it alone converges cleanly.
#include <algorithm>
#include <cmath>
#include <string>

#include "../case_builder.hpp"
#include "knot_cases.hpp"
#include "rodvv/harness/gate.hpp"
#include "superhelix_trefoil.hpp"
#include "trefoil_metrics.hpp"

namespace rodvv::harness::knot_cases {

namespace {

using namespace cases;

std::size_t elements_at(double looseness) { return std::max<std::size_t>(150, std::size_t(std::ceil(9.0 / looseness))); }

// The loose-knot relations over the looseness: the limit 1 as a line, and this level's three ratios as one
// point each, labelled "levels: ..." so that the report gathers the points of every level into the figure.
void add_relation_series(LevelOutput& output, double looseness) {
  const std::string plot = "loose-knot relations over the looseness|";
  const auto point = [&](const std::string& label, const std::string& metric) {
    output.series.push_back({plot + "levels: " + label, "looseness h sqrt(T/B)", "ratio (loose limit: 1)",
                             {looseness}, {output.metrics.at(metric).computed}});
  };
  output.series.push_back({plot + "the loose limit (tension elastica homoclinic, PHYSICS.md §5.1)",
                           "looseness h sqrt(T/B)", "ratio (loose limit: 1)", {0.0, 0.16}, {1.0, 1.0}});
  point("1/2 B kappa_B^2 / T where t is perpendicular to the pull", "perpendicular_ratio");
  point("B kappa_apex^2 / (4 T) at the apex", "apex_ratio");
  point("end shortening / (4 sqrt(B/T))", "shortening_ratio");
}

LevelOutput run(const Parameters& p, double looseness) {
  LevelOutput output = relax_superhelix_trefoil(trefoil_knot(p, looseness), elements_at(looseness));
  output.metrics["perpendicular_excess"] = value_sample(output.metrics.at("perpendicular_ratio").computed - 1.0, 1.0);
  output.metrics["elements"] = diagnostic(double(elements_at(looseness)));
  add_relation_series(output, looseness);
  return output;
}

}  // namespace

void add_trefoil_looseness_superhelix(Registry& registry) {
  std::vector<MetricSpec> metrics{invariant_metric(
      "perpendicular_excess", "1/2 B kappa_B^2 / T - 1 where t is perpendicular to the pull (loose limit: 0)", 2.0)};
  for (auto& spec : trefoil_metric_specs()) {
    if (spec.name == "H_deviation") spec.theoretical_order = std::nullopt;  // bounded in eps, not converging in it
    metrics.push_back(std::move(spec));
  }
  for (auto& spec : superhelix_trefoil_diagnostic_specs()) metrics.push_back(std::move(spec));
  metrics.push_back(diagnostic_metric("elements", "N = max(150, 9 / looseness)"));
  GateSpec H_bound = upper_bound_gate("H_deviation", 0.028, GateScope::AllLevels,
                                      "H = T through the braid at every thickness: twice the largest deviation measured "
                                      "over looseness 0.12 .. 0.0425 at N = 150 (0.0140)");
  H_bound.measured = true;
  std::vector<GateSpec> gates{
      measured_order_gate("perpendicular_excess", 2.0,
                          "measured: pairwise 1.86, 2.06 at the defaults, 1.97 over looseness 0.15 .. 0.04 at N = 200 "
                          "(PHYSICS.md §5.1 expects corrections in the looseness without deriving their order)"),
      // measured 0.0121 at looseness 0.06
      measured_bound("perpendicular_excess", 0.0121, 0.06, 2.0), H_bound};
  Case c = make_case(
      "knot",
      {"knot/trefoil-looseness-superhelix",
       "Open trefoil toward the loose limit: 1/2 B kappa_B^2 = T at the perpendicular points (Super-Helix)",
       "The open trefoil of knot/trefoil-superhelix (root clamped, tip free under the dead pull T e_x, frictionless "
       "line-contact barrier) tied at decreasing looseness h sqrt(T/B) with N = max(150, 9 / looseness) elements.",
       "loose-knot limit: the loop is the tension elastica homoclinic, H = T gives 1/2 B kappa_B^2 / T = 1 where the "
       "tangent is perpendicular to the pull (T = EI / (2 R^2)), B kappa_apex^2 / (4 T) = 1 at the apex and the end "
       "shortening 4 sqrt(B/T) (PHYSICS.md §5.1)",
       "Audoly, Clauvelin & Neukirch 2007 (PRL 99:164301); Bertails et al. 2006; PHYSICS.md §5.1",
       kSuperHelixContactMethod},
      trefoil_parameters({superhelix_barrier_parameter()}),
      Resolution{"looseness", "h sqrt(T/B), the rod's radius in knot units (N = max(150, 9 / looseness))",
                 ResolutionScale::StepSize, {0.12, 0.085, 0.06}, {0.15, 0.12, 0.085, 0.06, 0.0425}, 0.03},
      std::move(metrics), std::move(gates), run);
  require(c, ratio_window("C", "B", 0.3, 100.0, "the twist-to-bending ratios at which the trefoil was measured"));
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::knot_cases

// knot/trefoil-superhelix: the open trefoil of knot/trefoil-nodal on the Super-Helix (solvers/superhelix):
// an inextensible isotropic rod (bending B, twisting C != B) clamped at its root, free at its tip under a
// dead pull T e_x, with frictionless self-contact measured on the helical arcs (superhelix/self_contact.hpp:
// a line contact, barrier psi(d) = (k/3)(2h - d)^3 per unit length between each Gauss point and its feet
// on the other arcs). H (PHYSICS.md §1.2, §5.1) is T on the straight tails and, the contact being
// frictionless, T through the braid when the contact field V_eff = 1/2 sum psi (derived for this contact
// model in self_contact.hpp) is part of it. The case measures max_s |H(s) - T| / T over the element
// midpoints.
//
// Tying: the braid closure of trefoil_tying.hpp at the nodal case's proportions (strands 1.25 h off the
// braid axis over |x| <= 10 h, closing arcs of radius 0.6 lambda, tails 3 h apart, lambda = sqrt(B/T)),
// but with tails 2 lambda long instead of 6 lambda: a Super-Helix has equal elements, and the shorter
// rod puts them where the knot is (ell = 1.7 h at N = 50). The rod is laid on the curve element by
// element (superhelix_on_curve.hpp) and relaxed at the full load by the statics with self-contact
// (superhelix/statics.hpp: Newton on the potential, Levenberg shift, at most 1.5 h of motion per step).
// N = 25 (ell = 3.4 h) cannot hold the braid: the knot comes undone.
//
// Measured (N = 50, 100, 200; looseness 0.1, barrier 500): max |H - T|/T = 0.0696, 0.0163, 0.0086
// (least-squares order 1.51: 2.1 then 0.92), 141, 135, 134 Newton iterations, 0.2, 1.0, 6 s.
// The error mixes an O(h^2) part (midpoint stations of constant-strain elements) and an O(h) part (the
// contact forces act at Gauss points and feet, so n(s) jumps by one quadrature point's force).
#include <cmath>
#include <string>

#include "../case_builder.hpp"
#include "contact_profile.hpp"
#include "knot_cases.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/harness/gate.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
#include "rodvv/solvers/superhelix/solution.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"
#include "superhelix_on_curve.hpp"
#include "trefoil_metrics.hpp"
#include "trefoil_tying.hpp"

namespace rodvv::harness::knot_cases {

namespace {

namespace sh = solvers::superhelix;
using namespace cases;

constexpr const char* kMethod =
    "Super-Helix (Bertails et al. 2006) with a C^2 line-contact barrier (k/3)(2h - d)^3 per unit length between "
    "Gauss points and their feet on the helical arcs (chord sort-and-sweep broad phase); statics by Newton on the "
    "potential with its exact Hessian, Levenberg shift and at most 1.5 h of motion per step";

struct Knot {
  double B, C, T, looseness, barrier;
  double lambda() const { return std::sqrt(B / T); }
  double radius() const { return looseness * lambda(); }
};

Knot knot_of(const Parameters& p) {
  return {parameter_value(p, "B"), parameter_value(p, "C"), parameter_value(p, "T"), parameter_value(p, "looseness"),
          parameter_value(p, "barrier")};
}

LevelOutput run(const Parameters& p, double level) {
  const std::size_t n = element_count(level);
  const Knot k = knot_of(p);
  const double h = k.radius(), lambda = k.lambda();
  const BraidClosure braid{3, 1.25 * h, 10.0 * h, 0.6 * lambda, 3.0 * h, 2.0 * lambda};
  validate(braid);
  const LaidSuperHelix laid = superhelix_on_curve(braid_closure_curve(braid), n, Vec3::UnitZ());

  sh::RodModel model;
  model.length = laid.length;
  model.elements = n;
  model.stiffness = Vec3(k.C, k.B, k.B);
  model.root_position = laid.root_position;
  model.root_frame = laid.root_frame;
  model.end_force = Vec3(k.T, 0.0, 0.0);
  model.self_contact = {h, k.barrier * k.T / (h * h * h)};  // a line density k o^2 of T / h at o = h / sqrt(barrier)

  sh::StaticOptions options;
  options.initial_q = laid.q;
  options.max_iterations = 2000;  // measured: 134 - 141 at N = 50 .. 200
  options.tolerance = 1e-10;
  const sh::StaticResult result = sh::solve_static(model, options);

  const sh::Kinematics kinematics(model, result.q);
  const auto contacts = sh::self_contacts(kinematics, model.self_contact);
  if (contacts.empty())
    throw SolverError(kMethod, "the knot came undone: no self-contact at equilibrium", result.iterations,
                      result.residual);
  double deepest = 0.0;
  for (const auto& c : contacts) deepest = std::max(deepest, 1.0 - c.distance / (2.0 * h));

  const SpatialRodSolution solution = sh::make_solution(model, result.q);
  const double span = (kinematics.tip_position() - model.root_position).x();  // the ends' span along the pull

  LevelOutput output;
  add_trefoil_metrics(output, solution, k.B, k.T, span, {kMethod, result.iterations, result.residual});
  output.metrics["contact_points"] = diagnostic(double(contacts.size()));
  output.series.push_back(contact_force_series(kinematics.element_length(), model.self_contact, contacts));
  output.metrics["deepest_overlap"] = diagnostic(deepest);
  output.metrics["laying_miss"] = diagnostic(laid.max_miss / h);
  output.metrics["iterations"] = diagnostic(double(result.iterations));
  output.metrics["equilibrium_residual"] = diagnostic(result.residual);
  return output;
}

}  // namespace

void add_trefoil_superhelix(Registry& registry) {
  const double h = 1.0 / 200.0;
  std::vector<MetricSpec> metrics = trefoil_metric_specs();
  metrics.push_back(diagnostic_metric("contact_points", "Gauss-point contacts (a point and a foot closer than 2h)"));
  metrics.push_back(diagnostic_metric("deepest_overlap", "largest (2h - d) / 2h over the contacts"));
  metrics.push_back(diagnostic_metric("laying_miss", "largest miss of the laid rod's element ends from the curve / h"));
  metrics.push_back(diagnostic_metric("iterations", "Newton iterations on the potential"));
  metrics.push_back(diagnostic_metric("equilibrium_residual", "final residual |r|_inf"));
  std::vector<GateSpec> gates{
      order_range_gate("H_deviation", 1.0, 2.0,
                       "O(h^2) at the midpoint stations, O(h) from the contact forces at Gauss points and feet "
                       "(measured 2.1, 0.92 over N = 50 .. 200; least squares 1.51)"),
      // measured 0.0086 at N = 200
      measured_bound("H_deviation", 0.0086, h, 1.0)};
  Case c = make_case(
      "knot",
      {"knot/trefoil-superhelix", "Open trefoil knot under a dead pull: H = T through self-contact (Super-Helix)",
       "Inextensible isotropic Super-Helix (B, C), root clamped, tip free under the dead load T e_x, tied as the "
       "closure of the braid sigma_1^3 and relaxed with frictionless self-contact (line barrier on the helical "
       "arcs) of radius h = looseness sqrt(B/T).",
       "H(s) = T at every s, through the braid (Noether, frictionless contact; PHYSICS.md §1.2, §5.1)",
       "Audoly, Clauvelin & Neukirch 2007 (PRL 99:164301); Bertails et al. 2006; PHYSICS.md §5.1", kMethod},
      trefoil_parameters(
          make_parameter("looseness", 0.1, 0.08, 0.12, false, false, "", "h sqrt(T/B), the rod's radius in knot units"),
          make_parameter("barrier", 500.0, 50.0, 5000.0, false, false, "", "barrier stiffness k h^3 / T (per unit length)")),
      element_levels("number of elements", {50, 100, 200}, {50, 100, 200, 400}), std::move(metrics),
      std::move(gates), run);
  // Measured at the window's corners (default levels, 2026-11-27): looseness 0.08 and 0.12, barrier 50 and
  // 5000, C/B 0.3 and 100 all pass (orders 1.3 to 1.9); the nodal case's C/B window is kept.
  require(c, ratio_window("C", "B", 0.3, 100.0, "the twist-to-bending ratios at which the trefoil was measured"));
  registry.add(std::move(c));
}

}  // namespace rodvv::harness::knot_cases

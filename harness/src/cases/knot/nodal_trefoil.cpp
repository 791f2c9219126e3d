#include "nodal_trefoil.hpp"

#include <algorithm>
#include <cmath>

#include "../case_builder.hpp"
#include "contact_profile.hpp"
#include "knot_cases.hpp"
#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/rod3d/self_contact.hpp"
#include "rodvv/solvers/rod3d/solution.hpp"
#include "rodvv/solvers/rod3d/state.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"
#include "trefoil_tying.hpp"

namespace rodvv::harness::knot_cases {

namespace rod = solvers::rod3d;
using namespace cases;

LevelOutput relax_nodal_trefoil(const TrefoilKnot& k, std::size_t n) {
  const double h = k.radius(), lambda = k.lambda();
  const TiedRod tied = tie_braid_closure({3, 1.25 * h, 10.0 * h, 0.6 * lambda, 3.0 * h, 6.0 * lambda}, n);
  const PulledKnot pulled = pull_tied_rod(tied, k.B, k.C, k.T, {h, k.barrier * k.T / (h * h)});
  const rod::RodModel& model = pulled.model;

  rod::StaticOptions options;
  options.pseudo_transient = true;
  options.max_iterations = 200 * n;  // measured: 340 to 1200 iterations at N = 50 .. 400, barrier 125 .. 8000
  options.tolerance = 1e-9;
  const auto result = rod::solve_static(model, pulled.start, options);

  const auto solution = rod::make_solution(model, result.state);
  const auto contacts = rod::self_contacts(model.self_contact, result.state.position, rod::rest_edge_length(model));
  if (contacts.empty())
    throw SolverError(kContactStaticsMethod, "the knot came undone: no self-contact at equilibrium", result.iterations,
                      result.residual);
  double deepest = 0.0;
  for (const auto& c : contacts) deepest = std::max(deepest, 1.0 - c.distance / (2.0 * h));

  // The ends' span along the pull (root: the support point, s = 0), for the end shortening.
  const double span = (result.state.position[n] - model.root.position).x();

  LevelOutput output;
  add_trefoil_metrics(output, solution, k.B, k.T, span, {kContactStaticsMethod, result.iterations, result.residual});
  output.metrics["contact_pairs"] = diagnostic(double(contacts.size()));
  output.series.push_back(contact_force_series(model, contacts));
  output.metrics["deepest_overlap"] = diagnostic(deepest);
  output.metrics["iterations"] = diagnostic(double(result.iterations));
  output.metrics["equilibrium_residual"] = diagnostic(result.residual);
  return output;
}

std::vector<MetricSpec> nodal_trefoil_diagnostic_specs() {
  return {diagnostic_metric("contact_pairs", "segment pairs closer than 2h at equilibrium"),
          diagnostic_metric("deepest_overlap", "largest (2h - d) / 2h over the contacts"),
          diagnostic_metric("iterations", "Newton iterations of the pseudo-transient relaxation"),
          diagnostic_metric("equilibrium_residual", "final scaled residual")};
}

}  // namespace rodvv::harness::knot_cases

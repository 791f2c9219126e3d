#include "rodvv/harness/check.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/validation.hpp"
#include "rodvv/harness/sweep.hpp"

namespace rodvv::harness {

namespace {

bool has_metric(const Case& c, const std::string& metric) {
  return std::any_of(c.info.metrics.begin(), c.info.metrics.end(),
                     [&](const MetricSpec& spec) { return spec.name == metric; });
}

bool measured_anywhere(const std::vector<LevelResult>& levels, const std::string& metric) {
  return std::any_of(levels.begin(), levels.end(),
                     [&](const LevelResult& level) { return level.metrics.contains(metric); });
}

std::string solver_names(const std::vector<LevelSolution>& solutions) {
  std::vector<std::string> names;
  for (const auto& solution : solutions)
    if (!solution.solver.empty() && std::find(names.begin(), names.end(), solution.solver) == names.end())
      names.push_back(solution.solver);
  return names.empty() ? std::string("an unnamed solver") : fmt::format("{}", fmt::join(names, "; "));
}

}  // namespace

GateSpec user_bound(const Case& c, const std::string& metric, double bound) {
  if (!has_metric(c, metric)) {
    std::vector<std::string> names;
    for (const auto& spec : c.info.metrics) names.push_back(spec.name);
    throw InputError("--max-error", fmt::format("invalid --max-error '{}': case '{}' has no metric '{}'; its metrics "
                                                "are {}",
                                                metric, c.info.name, metric, fmt::join(names, ", ")));
  }
  if (!(bound >= 0.0) || !std::isfinite(bound))
    throw InputError("--max-error", fmt::format("invalid --max-error {}={}: the bound must be finite and >= 0",
                                                metric, format_value(bound)));
  return upper_bound_gate(metric, bound, GateScope::FinestLevel, "stated by the user (--max-error)");
}

SweepResult check_solutions(const Case& c, const Parameters& parameters, std::vector<LevelSolution> solutions,
                            std::span<const GateSpec> user_bounds, std::optional<double> stated_order) {
  if (stated_order && !(*stated_order > 0.0 && *stated_order <= 20.0))
    throw InputError("--order", fmt::format("invalid --order {}: must be in (0, 20]", format_value(*stated_order)));
  if (!c.checks_solutions())
    throw InputError("case", fmt::format("case '{}' does not check solution files (its level is not split into "
                                         "a solver run and measurements); `rodvv check --list` names the cases "
                                         "that do",
                                         c.info.name));
  if (solutions.empty()) throw InputError("--solution", "no solution given: `rodvv check CASE --solution FILE ...`");
  const Resolution& resolution = c.info.resolution;
  for (const auto& solution : solutions) {
    if (!(solution.level > 0.0) || !std::isfinite(solution.level) ||
        (resolution.scale == ResolutionScale::Count && solution.level != std::floor(solution.level)))
      throw InputError(resolution.name, fmt::format("{}: invalid resolution {} = {}: must be {}", solution.source,
                                                    resolution.name, format_value(solution.level),
                                                    resolution.scale == ResolutionScale::Count
                                                        ? "a whole number >= 1"
                                                        : "finite and > 0"));
  }
  // A rod at N elements has N + 1 nodes (vertices; in every snapshot of a trajectory): a file whose count
  // disagrees with its declared N would be fitted at the wrong h.
  if (resolution.scale == ResolutionScale::Count)
    for (const auto& solution : solutions) {
      std::size_t nodes = 0;
      if (const auto* planar = std::get_if<PlanarRodSolution>(&solution.solution)) nodes = planar->nodes();
      if (const auto* spatial = std::get_if<SpatialRodSolution>(&solution.solution)) nodes = spatial->vertex_s.size();
      if (const auto* trajectory = std::get_if<RodTrajectory>(&solution.solution))
        for (const auto& snapshot : trajectory->snapshots)  // the first snapshot whose count disagrees, if any
          if (double(snapshot.s.size()) != solution.level + 1.0) {
            nodes = snapshot.s.size();
            break;
          }
      if (nodes != 0 && double(nodes) != solution.level + 1.0)
        throw InputError(resolution.name, fmt::format("{}: {} = {} elements, but the rod has {} nodes (N + 1 expected)",
                                                      solution.source, resolution.name, format_value(solution.level),
                                                      nodes));
    }
  // Coarse to fine, whatever order the files came in; two files at one level are ambiguous.
  std::stable_sort(solutions.begin(), solutions.end(), [&](const LevelSolution& a, const LevelSolution& b) {
    return resolution.h(a.level) > resolution.h(b.level);
  });
  for (std::size_t i = 1; i < solutions.size(); ++i)
    if (resolution.h(solutions[i].level) == resolution.h(solutions[i - 1].level))
      throw InputError("--solution", fmt::format("{} and {} are both at {} = {}: one solution per level",
                                                 solutions[i - 1].source, solutions[i].source, resolution.name,
                                                 format_value(solutions[i].level)));
  if (c.check_parameters) c.check_parameters(parameters);

  SweepResult result;
  result.info = c.info;
  result.info.parameters = parameters;
  result.info.method = "solution files written by " + solver_names(solutions) + " (rodvv check)";
  for (const auto& solution : solutions) {
    LevelResult level;
    level.level = solution.level;
    level.h = resolution.h(solution.level);
    level.cpu_seconds = solution.cpu_seconds;  // the solver's own cost, not the check's
    level.wall_seconds = solution.wall_seconds;
    try {
      LevelOutput output = c.measure(parameters, solution.level, solution.solution);
      level.metrics = std::move(output.metrics);
      level.series = std::move(output.series);
    } catch (const InputError& error) {
      throw InputError(error.parameter(), fmt::format("{}: {}", solution.source, error.what()));
    } catch (const SolverError& error) {
      level.failure = fmt::format("{}: {}", solution.source, error.what());
    }
    result.levels.push_back(std::move(level));
  }
  result.analyses = analyse_levels(c, result.levels);

  for (const GateSpec& gate : c.gates) {
    if (gate.kind != GateKind::Order && !gate.relative) {
      result.skipped_gates.push_back(gate.name + ": a bound on rodvv's own solver, not a property of the problem");
    } else if (gate.measured) {
      result.skipped_gates.push_back(gate.name + ": an order measured on rodvv's own solver at the case's defaults "
                                                 "(not derived), not a property of the problem");
    } else if (!measured_anywhere(result.levels, gate.metric)) {
      result.skipped_gates.push_back(gate.name + ": the solutions lack the fields this metric needs");
    } else if (solutions.size() < c.fit_levels) {
      result.skipped_gates.push_back(
          fmt::format("{}: an order needs solutions at {} levels or more, got {}", gate.name, c.fit_levels,
                      solutions.size()));
    } else if (gate.relative) {
      // The order's magnitude beside it (a property of any solver's solutions, not a bound on rodvv's).
      result.gates.push_back(evaluate_gate(gate, result));
    } else if (stated_order) {
      result.gates.push_back(evaluate_gate(
          order_gate(gate.metric, *stated_order, fmt::format("the order stated for the solver (--order {:g})",
                                                             *stated_order)),
          result));
    } else {
      result.gates.push_back(evaluate_gate(gate, result));
    }
  }
  for (const GateSpec& gate : user_bounds) result.gates.push_back(evaluate_gate(gate, result));
  return result;
}

}  // namespace rodvv::harness

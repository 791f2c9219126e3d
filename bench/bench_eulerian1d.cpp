// Google Benchmark for the 1-D reference-map solid (solvers/eulerian1d).
//  - BM_StepCost: ~64 time steps (65-67: dt shrinks with max F) of the free-free standing wave (A = 0.02) against the number of
//    cells N = 128 .. 8192; items = cell-steps, so items/s is flat and the complexity fit reports
//    ~N when a step costs O(N) (every operator is a sweep over the nodes).
//  - BM_ImpactToSolution: the whole impact case (bar at v0 = 0.1 c hitting a wall, t_end = 4 L0/c)
//    at N = 200 .. 3200, the default and extended levels of eulerian1d/impact: steps grow ~N, so
//    the time to solution grows ~N^2; each step with a wall solves a 1-row LCP (Lemke).
// Set-up (initial reference map) is outside the timed loop.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "rodvv/solvers/eulerian1d/simulate.hpp"

namespace {

namespace eu = rodvv::solvers::eulerian1d;

// Initial map of the standing wave x = X + A cos(pi X) (L0 = 1) by Newton, continued linearly.
eu::Problem standing_wave(std::size_t cells) {
  eu::Problem p;
  p.grid = {-0.5, 1.5, cells};
  const auto n = static_cast<Eigen::Index>(p.grid.nodes());
  p.xi0.resize(n);
  p.v0 = rodvv::VecX::Zero(n);
  const double A = 0.02;
  for (Eigen::Index j = 0; j < n; ++j) {
    const double x = p.grid.node(static_cast<std::size_t>(j));
    if (x <= A) { p.xi0(j) = x - A; continue; }
    if (x >= 1.0 - A) { p.xi0(j) = 1.0 + x - (1.0 - A); continue; }
    double X = x;
    for (int k = 0; k < 50; ++k)
      X -= (X + A * std::cos(std::numbers::pi * X) - x) / (1.0 - A * std::numbers::pi * std::sin(std::numbers::pi * X));
    p.xi0(j) = X;
  }
  return p;
}

void BM_StepCost(benchmark::State& state) {
  const auto cells = static_cast<std::size_t>(state.range(0));
  const eu::Problem problem = standing_wave(cells);
  eu::Settings settings;
  // ~64 steps: dt = cfl dx / c at the start (v = 0, F ~ 1).
  settings.t_end = 64 * settings.cfl * problem.grid.dx() * (1.0 - 1e-9);
  std::size_t steps = 0;
  for (auto _ : state) {
    const auto result = eu::simulate(problem, settings);
    benchmark::DoNotOptimize(result.history.x_right.data());
    steps = result.steps;
  }
  state.SetComplexityN(state.range(0));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps) * state.range(0));
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_StepCost)->RangeMultiplier(4)->Range(128, 8192)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();

void BM_ImpactToSolution(benchmark::State& state) {
  const auto cells = static_cast<std::size_t>(state.range(0));
  eu::Problem p;
  p.grid = {-0.25, 1.35, cells};  // the impact case's domain at its default parameters
  p.xi0 = eu::linear_reference_map(p.grid, 0.0, 1.0);
  p.v0 = rodvv::VecX::Constant(static_cast<Eigen::Index>(p.grid.nodes()), 0.1);
  p.right_wall = 1.1;
  eu::Settings settings;
  settings.t_end = 4.0;
  std::size_t steps = 0;
  for (auto _ : state) {
    const auto result = eu::simulate(p, settings);
    benchmark::DoNotOptimize(result.history.momentum.data());
    steps = result.steps;
  }
  state.SetComplexityN(state.range(0));
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_ImpactToSolution)->Arg(200)->Arg(400)->Arg(800)->Arg(1600)->Arg(3200)->ArgName("N")
    ->Unit(benchmark::kMillisecond)->Complexity(benchmark::oNSquared);

}  // namespace

BENCHMARK_MAIN();

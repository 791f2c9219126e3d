// Google Benchmark for the planar discrete-rod solvers (elastica2d): one Newton solve (KKT assembly,
// sparse LU, line search, solution output) of the pinned-pinned column at P L^2 / EI = 13.75
// (theta0 = 90 deg, PHYSICS.md §3.3) from the first-mode guess theta = cos(pi s / L), against the
// element count N = 16 .. 1024. Set-up is outside the timed loop; items = elements, and the
// complexity fit reports the growth in N (expected ~linear: the KKT matrix is banded).
// Also the shooting solver on the Mattiasson cantilever (BM_ShootingMattiasson, below).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "rodvv/solvers/elastica2d/shooting.hpp"
#include "rodvv/solvers/elastica2d/solve_static.hpp"

namespace {

namespace e2 = rodvv::solvers::elastica2d;

void BM_PinnedColumn(benchmark::State& state, e2::Scheme scheme) {
  const auto n = static_cast<std::size_t>(state.range(0));
  e2::Problem problem;
  problem.start.support = e2::Support::Pinned;
  problem.end.support = e2::Support::Sliding;
  problem.end.load.force_x = -13.750371636041;
  e2::InitialGuess guess;
  guess.theta = [](double s) { return std::cos(std::numbers::pi * s); };
  const e2::Discretisation discretisation{scheme, n};
  const e2::SolverOptions options{};
  std::size_t iterations = 0;
  for (auto _ : state) {
    const rodvv::PlanarRodSolution sol = e2::solve_static(problem, discretisation, options, guess);
    benchmark::DoNotOptimize(sol.y.data());
    iterations = sol.iterations;
  }
  state.SetComplexityN(state.range(0));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
  state.counters["newton_iterations"] = static_cast<double>(iterations);
}

BENCHMARK_CAPTURE(BM_PinnedColumn, polygon, e2::Scheme::Polygon)
    ->RangeMultiplier(2)
    ->Range(16, 1024)
    ->ArgName("N")
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();
BENCHMARK_CAPTURE(BM_PinnedColumn, arcs, e2::Scheme::Arcs)
    ->RangeMultiplier(2)
    ->Range(16, 1024)
    ->ArgName("N")
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();

// The shooting solver (shooting.hpp) on the Mattiasson cantilever, alpha = P L^2/EI = 1, 2, 5, 10
// (PHYSICS.md §3.5): damped Newton with the variational equations, RKF78 at 1e-13, sampled at 64
// nodes, from the guess the harness uses (the discrete arcs solution at N = 64; from the straight
// rod Newton stalls at alpha = 10), built outside the timed loop.
void BM_ShootingMattiasson(benchmark::State& state) {
  const double alpha = static_cast<double>(state.range(0));
  e2::Problem problem;
  problem.start.support = e2::Support::Clamped;
  problem.end.load.force_y = -alpha;
  e2::ShootingOptions options;
  options.sample_points = 64;
  e2::SolverOptions discrete;
  discrete.load_steps = 6;
  const e2::ShootingGuess guess =
      e2::shooting_guess_from(e2::solve_static(problem, {e2::Scheme::Arcs, 64}, discrete), problem);
  std::size_t iterations = 0;
  for (auto _ : state) {
    const rodvv::PlanarRodSolution sol = e2::solve_shooting(problem, options, guess);
    benchmark::DoNotOptimize(sol.y.data());
    iterations = sol.iterations;
  }
  state.counters["newton_iterations"] = static_cast<double>(iterations);
}

BENCHMARK(BM_ShootingMattiasson)->Arg(1)->Arg(2)->Arg(5)->Arg(10)->ArgName("alpha")->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();

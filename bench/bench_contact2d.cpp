// Google Benchmark for hard frictionless contact of the planar elastica (elastica2d/contact.hpp):
// the pinned-pinned column between walls y = +/- 0.1 (PHYSICS.md §4.1) at end-shortening 0.026
// (one point contact) and 0.0345 (line contact: the number of active nodes grows with N), 8
// displacement steps from the first-mode guess, against N = 32 .. 1024. Counters: active contacts,
// active-set updates and Newton iterations (all load steps). Expected growth ~N x (updates): each
// Newton step is O(N) (banded KKT with the contact rows next to their nodes).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "rodvv/solvers/elastica2d/contact.hpp"

namespace {

namespace e2 = rodvv::solvers::elastica2d;

void BM_Cavity(benchmark::State& state, e2::Scheme scheme, double shortening) {
  const auto n = static_cast<std::size_t>(state.range(0));
  e2::Problem problem;
  problem.start.support = e2::Support::Pinned;
  problem.end.support = e2::Support::Pinned;
  problem.end.x = 1.0 - shortening;
  e2::InitialGuess guess;
  guess.theta = [](double s) { return 0.25 * std::cos(std::numbers::pi * s); };
  e2::SolverOptions options;
  options.load_steps = 8;
  const auto walls = e2::cavity_walls(0.1);
  e2::ContactSolution last;
  for (auto _ : state) {
    last = e2::solve_static_contact(problem, {scheme, n}, walls, options, guess);
    benchmark::DoNotOptimize(last.rod.y.data());
  }
  state.SetComplexityN(state.range(0));
  state.counters["contacts"] = static_cast<double>(last.contacts.size());
  state.counters["active_set_updates"] = static_cast<double>(last.active_set_iterations);
  state.counters["newton_iterations"] = static_cast<double>(last.rod.iterations);
}

BENCHMARK_CAPTURE(BM_Cavity, point_polygon, e2::Scheme::Polygon, 0.026)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, point_arcs, e2::Scheme::Arcs, 0.026)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, line_polygon, e2::Scheme::Polygon, 0.0345)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, line_arcs, e2::Scheme::Arcs, 0.0345)->RangeMultiplier(2)->Range(32, 1024)->Complexity();

}  // namespace

BENCHMARK_MAIN();

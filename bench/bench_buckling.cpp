// Google Benchmark for the Euler critical loads of the discrete elastica (elastica2d/buckling.hpp):
// Hessian assembly at the straight state, null-space reduction and the dense symmetric-definite eigen
// solve, for the clamped-pinned column, the two lowest modes, against N = 16 .. 512. Items =
// elements; the complexity fit is expected ~N^3 (the reduced pencil is dense).
#include <benchmark/benchmark.h>

#include <cstdint>

#include "rodvv/solvers/elastica2d/buckling.hpp"

namespace {

namespace e2 = rodvv::solvers::elastica2d;

void BM_CriticalLoads(benchmark::State& state, e2::Scheme scheme) {
  const auto n = static_cast<std::size_t>(state.range(0));
  const e2::BucklingProblem column{e2::EndSupports::ClampedPinned, 1.0, 1.0};
  const e2::Discretisation discretisation{scheme, n};
  for (auto _ : state) {
    const e2::BucklingResult result = e2::critical_loads(column, discretisation, 2);
    benchmark::DoNotOptimize(result.modes.data());
  }
  state.SetComplexityN(state.range(0));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * state.range(0));
}

BENCHMARK_CAPTURE(BM_CriticalLoads, polygon, e2::Scheme::Polygon)
    ->RangeMultiplier(2)
    ->Range(16, 512)
    ->ArgName("N")
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNCubed);
BENCHMARK_CAPTURE(BM_CriticalLoads, arcs, e2::Scheme::Arcs)
    ->RangeMultiplier(2)
    ->Range(16, 512)
    ->ArgName("N")
    ->Unit(benchmark::kMillisecond)
    ->Complexity(benchmark::oNCubed);

}  // namespace

BENCHMARK_MAIN();

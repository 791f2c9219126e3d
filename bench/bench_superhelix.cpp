// Google Benchmark for the Super-Helix (solvers/superhelix, ALGORITHMS.md §1.5-1.6).
//  - BM_StepRecursive: one semi-implicit Euler step (kinematics, velocity terms, O(N) articulated-body
//    solve) vs N = 16 .. 1024, with Google Benchmark's complexity fit (target: linear, < 1 ms at
//    N = 1024).
//  - BM_StepDense: the same step by dense assembly (O(N^3)) and LDL^T, N = 16 .. 256 (target: the
//    recursive step at least 20x faster at N = 256).
//  - BM_Statics: the heavy-cantilever static solve (Newton with a finite-difference Jacobian), N = 8 .. 64.
// The state is a curved, moving rod under gravity (set up outside the timed loop).
#include <benchmark/benchmark.h>

#include <cstdint>

#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/statics.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Vec3;
using rodvv::VecX;

sh::RodModel model_of(std::size_t n) {
  sh::RodModel model;
  model.elements = n;
  model.stiffness = Vec3(0.7, 1.0, 1.3);
  model.natural_strain = Vec3(0.3, 2.0, 0.8);
  model.gravity = Vec3(0.0, 0.0, -9.81);
  model.rayleigh_stiffness = 1e-3;
  return model;
}

sh::DynamicState state_of(std::size_t n) {
  sh::DynamicState state;
  state.q = VecX::Constant(static_cast<Eigen::Index>(3 * n), 0.5);
  state.qdot = VecX::LinSpaced(static_cast<Eigen::Index>(3 * n), -0.2, 0.3);
  return state;
}

void step_benchmark(benchmark::State& bench, sh::DynamicsPath path) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  const sh::RodModel model = model_of(n);
  const sh::DynamicState state = state_of(n);
  for (auto _ : bench) {
    const VecX dv = sh::velocity_change(model, state, 1e-3, path);
    benchmark::DoNotOptimize(dv.data());
  }
  bench.SetComplexityN(bench.range(0));
  bench.SetItemsProcessed(static_cast<std::int64_t>(bench.iterations()) * bench.range(0));
}

void BM_StepRecursive(benchmark::State& bench) { step_benchmark(bench, sh::DynamicsPath::Recursive); }
void BM_StepDense(benchmark::State& bench) { step_benchmark(bench, sh::DynamicsPath::Dense); }

void BM_Statics(benchmark::State& bench) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  sh::RodModel model = model_of(n);
  model.gravity = Vec3(0.0, 0.0, -3.0);
  sh::StaticOptions options;
  options.load_steps = 2;
  std::size_t iterations = 0;
  for (auto _ : bench) {
    const auto result = sh::solve_static(model, options);
    benchmark::DoNotOptimize(result.q.data());
    iterations = result.iterations;
  }
  bench.SetComplexityN(bench.range(0));
  bench.counters["newton_iterations"] = static_cast<double>(iterations);
}

BENCHMARK(BM_StepRecursive)->RangeMultiplier(2)->Range(16, 1024)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_StepDense)->RangeMultiplier(2)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_Statics)->RangeMultiplier(2)->Range(8, 64)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();

}  // namespace

BENCHMARK_MAIN();

// Google Benchmark for the pendulum family: closed-form reference evaluations (items = evaluations)
// and the six integrators (items = steps, so items/s is steps per second and 1/rate is ns per
// step). Set-up is outside the timed loop; results are kept alive with DoNotOptimize.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <numbers>

#include "rodvv/references/pendulum.hpp"
#include "rodvv/solvers/pendulum/integrators.hpp"

namespace {

namespace ref = rodvv::references;
namespace pendulum = rodvv::solvers::pendulum;

constexpr double kDegree = std::numbers::pi / 180.0;

// Evaluate at times spread over a few periods, so neither the compiler nor the elliptic routines see
// one repeated argument.
template <class Evaluate>
void run_reference(benchmark::State& state, Evaluate&& evaluate) {
  double t = 0.0;
  for (auto _ : state) {
    const ref::PendulumState s = evaluate(t);
    benchmark::DoNotOptimize(s);
    t += 0.0137;
    if (t > 50.0) t = 0.0;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()));
}

void BM_ReferenceLibration(benchmark::State& state) {
  const ref::Libration motion{1.0, static_cast<double>(state.range(0)) * kDegree};
  run_reference(state, [&](double t) { return ref::libration_state(motion, t); });
}
BENCHMARK(BM_ReferenceLibration)->Arg(30)->Arg(179)->ArgName("theta0_deg");

void BM_ReferenceRotation(benchmark::State& state) {
  const ref::Rotation motion{1.0, 3.0};
  run_reference(state, [&](double t) { return ref::rotation_state(motion, t); });
}
BENCHMARK(BM_ReferenceRotation);

void BM_ReferenceSeparatrix(benchmark::State& state) {
  const ref::Separatrix motion{1.0};
  run_reference(state, [&](double t) { return ref::separatrix_state(motion, t); });
}
BENCHMARK(BM_ReferenceSeparatrix);

// integrate() over range(0) steps of dt = 0.01 (libration from rest at 90 deg), recording every
// range(1)-th point: 1 = full trajectory as the harness uses it, = steps for the stepping cost alone.
// dopri5 (tol 1e-8) takes its own steps: items are then output intervals and the accepted steps are
// reported as a counter.
void BM_Integrate(benchmark::State& state, pendulum::Method method) {
  const auto steps = static_cast<std::size_t>(state.range(0));
  const double dt = 0.01;
  const pendulum::Problem problem{1.0, 90.0 * kDegree, 0.0, static_cast<double>(steps) * dt};
  pendulum::Settings settings;
  settings.method = method;
  settings.dt = dt;
  settings.tolerance = 1e-8;
  settings.record_every = static_cast<std::size_t>(state.range(1));
  std::size_t accepted = 0;
  for (auto _ : state) {
    const rodvv::Trajectory tr = pendulum::integrate(problem, settings);
    benchmark::DoNotOptimize(tr.theta.data());
    accepted = tr.steps;
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * steps));
  state.counters["accepted_steps"] = static_cast<double>(accepted);
}

#define RODVV_BENCH_METHOD(name, method)                                        \
  BENCHMARK_CAPTURE(BM_Integrate, name, method)                                 \
      ->Args({10000, 1})                                                        \
      ->Args({100000, 1})                                                       \
      ->Args({100000, 100000})                                                  \
      ->ArgNames({"steps", "record_every"})                                     \
      ->Unit(benchmark::kMicrosecond)

RODVV_BENCH_METHOD(explicit_euler, pendulum::Method::ExplicitEuler);
RODVV_BENCH_METHOD(symplectic_euler, pendulum::Method::SymplecticEuler);
RODVV_BENCH_METHOD(stormer_verlet, pendulum::Method::StormerVerlet);
RODVV_BENCH_METHOD(rk4, pendulum::Method::RungeKutta4);
RODVV_BENCH_METHOD(dopri5, pendulum::Method::DormandPrince5);
RODVV_BENCH_METHOD(rkn4_mclachlan, pendulum::Method::McLachlanRkn4);

}  // namespace

BENCHMARK_MAIN();

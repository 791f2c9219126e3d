// Google Benchmark for the nodal 3-D rod (solvers/rod3d, a discrete elastic rod).
//  - BM_NewtonIteration: one Newton iteration's work at a bent, twisted state - the banded
//    residual and Jacobian (second-order jets of the stencils), the banded LU and the solve - vs N = 32 .. 4096,
//    with Google Benchmark's complexity fit (issue 11 target: fit exponent <= 1.1, i.e. O(N)).
//  - BM_Residual: the residual alone (each line-search trial evaluates one), same N.
//  - BM_HelicalBuckling: the whole rod3d/helical-buckling level as `rodvv sweep` runs it (PyElastica's
//    localized helical buckling: Newton from the infinite-rod guess, then the metrics) at N = 100
//    (envelope error 0.79, PyElastica reaches 0.72 at 100 elements in about 8 minutes of explicit
//    stepping), 400 (0.092) and 1600 (0.0054).
//  - BM_TrefoilKnot: the whole knot/trefoil-nodal level (tying, pseudo-transient relaxation with
//    self-contact, metrics) at N = 100, 200, 400 (issue 12 target at N = 400: under 2 s).
//  - BM_TrefoilKnotHard: the whole knot/trefoil-hard-nodal level (the same tying and barrier relaxation,
//    then the hard-contact Newton-LCP from the barrier's equilibrium) at N = 100, 200, 400.
//  - BM_TrefoilKnotSuperHelix: the whole knot/trefoil-superhelix level (laying the Super-Helix on the
//    braid closure, the potential Newton with line self-contact, metrics) at N = 50, 100, 200, 400.
//  - BM_TrefoilKnotHardSuperHelix: the whole knot/trefoil-hard-superhelix level (the barrier knot above, then
//    the Newton-LCP on the closest points of its arcs from that equilibrium) at N = 50, 100, 200, 400.
//  - BM_Plectoneme: the whole knot/plectoneme-nodal level (laying the 15-degree ply, its relaxation under
//    the dead pull with self-contact, metrics) at N = 200, 400, 800.
//  - BM_PlectonemeSuperHelix: the whole knot/plectoneme-superhelix level (laying the twisted Super-Helix on the
//    ply, its relaxation in the sliding clamp with line self-contact, metrics) at N = 70, 100, 200.
//  - BM_PlectonemeTwisting: the whole plectoneme continuation, knot/plectoneme-twisted-nodal's level N = 200
//    (a straight rod twisted past its buckling in 8 steps per turn until the ply forms, relaxed, metrics),
//    then its level N = 400, which refines the formed ply the case keeps (the refinement and its relaxation).
// The exponent is the least-squares slope of log(cpu time) against log N of the BM_NewtonIteration rows.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "rodvv/harness/registry.hpp"
#include "rodvv/solvers/elastica2d/banded_lu.hpp"
#include "rodvv/solvers/rod3d/discrete_energy.hpp"
#include "rodvv/solvers/rod3d/statics.hpp"

namespace {

namespace rod = rodvv::solvers::rod3d;
using rodvv::Vec3;

struct Fixture {
  rod::RodModel model;
  rod::RodState state;
};

// A clamped rod bent into a helix-like curve with twist: every stencil term is non-trivial.
Fixture fixture_of(std::size_t n) {
  Fixture f;
  f.model.elements = n;
  f.model.length = 2.0;
  f.model.stiffness = Vec3(0.7, 1.0, 1.3);
  f.model.natural_strain = Vec3(0.3, 0.5, -0.2);
  f.model.root.support = rod::EndSupport::Clamped;
  f.model.gravity = Vec3(0.0, 0.0, -9.81);
  std::vector<Vec3> x(n + 1);
  for (std::size_t i = 0; i <= n; ++i) {
    const double s = rod::vertex_arclength(f.model, i);
    x[i] = Vec3(0.5 * std::cos(s), 0.5 * std::sin(s), 0.8 * s);
  }
  const Vec3 t0 = (x[1] - x[0]).normalized();
  std::vector<double> angles(n);
  for (std::size_t j = 0; j < n; ++j) angles[j] = 0.4 * double(j) / double(n);
  f.state = rod::make_state(x, t0.cross(Vec3::UnitZ()).normalized(), angles);
  f.state.multiplier.assign(n, 0.3);
  return f;
}

void BM_NewtonIteration(benchmark::State& bench) {
  const auto f = fixture_of(static_cast<std::size_t>(bench.range(0)));
  rodvv::VecX r;
  Eigen::SparseMatrix<double> jacobian;
  rodvv::solvers::elastica2d::BandedLU lu;
  const auto held = rod::held_dofs(f.model);
  std::vector<char> is_held(rod::DofLayout(f.model).size(), 0);
  for (const std::size_t k : held) is_held[k] = 1;
  for (auto _ : bench) {
    rod::static_system(f.model, f.state, 1.0, r, jacobian);
    jacobian.prune([&](Eigen::Index row, Eigen::Index, double) { return !is_held[std::size_t(row)]; });
    for (const std::size_t k : held) {
      jacobian.coeffRef(Eigen::Index(k), Eigen::Index(k)) = 1.0;
      r[Eigen::Index(k)] = 0.0;
    }
    lu.factorize(jacobian);
    benchmark::DoNotOptimize(lu.solve(r));
  }
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_NewtonIteration)->RangeMultiplier(2)->Range(32, 4096)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);

void BM_Residual(benchmark::State& bench) {
  const auto f = fixture_of(static_cast<std::size_t>(bench.range(0)));
  for (auto _ : bench) benchmark::DoNotOptimize(rod::static_residual(f.model, f.state, 1.0));
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_Residual)->RangeMultiplier(2)->Range(32, 4096)->Complexity(benchmark::oN)->Unit(benchmark::kMillisecond);

void BM_HelicalBuckling(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("rod3d/helical-buckling");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_HelicalBuckling)->Arg(100)->Arg(400)->Arg(1600)->Unit(benchmark::kMillisecond);

void BM_TrefoilKnot(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/trefoil-nodal");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_TrefoilKnot)->Arg(100)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond);

void BM_TrefoilKnotHard(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/trefoil-hard-nodal");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_TrefoilKnotHard)->Arg(100)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_TrefoilKnotSuperHelix(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/trefoil-superhelix");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_TrefoilKnotSuperHelix)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_TrefoilKnotHardSuperHelix(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/trefoil-hard-superhelix");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_TrefoilKnotHardSuperHelix)->Arg(50)->Arg(100)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_Plectoneme(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/plectoneme-nodal");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_Plectoneme)->Arg(200)->Arg(400)->Arg(800)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_PlectonemeSuperHelix(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/plectoneme-superhelix");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_PlectonemeSuperHelix)->Arg(70)->Arg(100)->Arg(200)->Unit(benchmark::kMillisecond)->Iterations(1);

void BM_PlectonemeTwisting(benchmark::State& bench) {
  const auto* c = rodvv::harness::default_registry().find("knot/plectoneme-twisted-nodal");
  for (auto _ : bench) benchmark::DoNotOptimize(c->run_level(c->info.parameters, double(bench.range(0))));
}
BENCHMARK(BM_PlectonemeTwisting)->Arg(200)->Arg(400)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();

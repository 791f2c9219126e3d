// Google Benchmark for the frictionless contact solvers (solvers/contact): Lemke and projected
// Gauss-Seidel on random positive definite LCPs W = A A^T + 0.1 I (b uniform in [-1, 1], so about
// half the constraints are active) against the number of contacts n = 2 .. 64, and the lumped
// velocity QP with 2 rows (the two walls of the Eulerian solid) against the number of nodes; and the
// self-contact broad phase (segment_proximity: sort and sweep) against all pairs on a two-strand ply
// of N segments, the geometry of a plectoneme (every segment has neighbours within the cutoff).
// Problem set-up is outside the timed loop.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>

#include <cmath>
#include <vector>

#include "rodvv/solvers/contact/lcp.hpp"
#include "rodvv/solvers/contact/segment_proximity.hpp"
#include "rodvv/solvers/contact/velocity_qp.hpp"

namespace {

namespace contact = rodvv::solvers::contact;
using rodvv::MatX;
using rodvv::VecX;

struct Lcp {
  MatX W;
  VecX b;
};
Lcp random_lcp(Eigen::Index n) {
  std::mt19937 rng(1234);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatX A(n, n);
  for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = u(rng);
  Lcp p{A * A.transpose() + 0.1 * MatX::Identity(n, n), VecX(n)};
  for (Eigen::Index i = 0; i < n; ++i) p.b(i) = u(rng);
  return p;
}

void BM_Lcp(benchmark::State& state, contact::LcpMethod method) {
  const auto p = random_lcp(state.range(0));
  contact::LcpSettings settings;
  settings.tolerance = 1e-10;
  std::size_t iterations = 0;
  for (auto _ : state) {
    const auto s = contact::solve_lcp(p.W, p.b, method, settings);
    benchmark::DoNotOptimize(s.lambda.data());
    iterations = s.iterations;
  }
  state.SetComplexityN(state.range(0));
  state.counters["iterations"] = static_cast<double>(iterations);
}
BENCHMARK_CAPTURE(BM_Lcp, lemke, contact::LcpMethod::Lemke)
    ->RangeMultiplier(2)->Range(2, 64)->ArgName("n")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK_CAPTURE(BM_Lcp, pgs, contact::LcpMethod::ProjectedGaussSeidel)
    ->RangeMultiplier(2)->Range(2, 64)->ArgName("n")->Unit(benchmark::kMicrosecond)->Complexity();

void BM_LumpedQpTwoWalls(benchmark::State& state) {
  const Eigen::Index n = state.range(0);
  const VecX m = VecX::Constant(n, 1.0 / static_cast<double>(n));
  const VecX R = -m.cwiseProduct(VecX::LinSpaced(n, -1.0, 1.0));  // v* from -1 to 1: both walls hit
  MatX J = MatX::Zero(2, n);
  J(0, 0) = 1.0;        // left edge: v_0 >= 0
  J(1, n - 1) = -1.0;   // right edge: v_last <= 0
  const VecX c = VecX::Zero(2);
  for (auto _ : state) {
    const auto s = contact::solve_velocity_qp_lumped(m, R, J, c);
    benchmark::DoNotOptimize(s.v.data());
  }
  state.SetComplexityN(state.range(0));
}
BENCHMARK(BM_LumpedQpTwoWalls)->RangeMultiplier(4)->Range(16, 4096)->ArgName("nodes")
    ->Unit(benchmark::kMicrosecond)->Complexity();

}  // namespace

// Down one strand of a ply (radius 0.05, helix angle ~30 deg), round a loop and back up the other:
// N segments of length ~0.01, cutoff 0.11 (two rod radii and a little): each segment sees ~20 others.
std::vector<rodvv::Vec3> ply_polyline(std::size_t segments) {
  std::vector<rodvv::Vec3> x;
  const std::size_t half = segments / 2;
  for (std::size_t i = 0; i <= half; ++i) {
    const double a = 0.1 * double(i);
    x.emplace_back(0.05 * std::cos(a), 0.05 * std::sin(a), 0.0087 * double(i));
  }
  for (std::size_t i = half; i-- > 0;) {
    const double a = 0.1 * double(i);
    x.emplace_back(-0.05 * std::cos(a), -0.05 * std::sin(a), 0.0087 * double(i) + 1e-3);
  }
  return x;
}

void BM_BroadPhase(benchmark::State& bench) {
  const auto x = ply_polyline(std::size_t(bench.range(0)));
  std::size_t pairs = 0;
  for (auto _ : bench) {
    const auto found = bench.range(1) ? contact::segments_within(x, 0.11, 3) : contact::segments_within_all_pairs(x, 0.11, 3);
    pairs = found.size();
    benchmark::DoNotOptimize(pairs);
  }
  bench.counters["pairs"] = double(pairs);
  bench.SetComplexityN(bench.range(0));
}
BENCHMARK(BM_BroadPhase)->ArgNames({"segments", "sweep"})->ArgsProduct({{100, 400, 1600, 6400}, {0, 1}})
    ->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();

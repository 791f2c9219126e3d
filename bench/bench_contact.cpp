// Google Benchmark for the frictionless contact solvers (solvers/contact): Lemke and projected
// Gauss-Seidel on random positive definite LCPs W = A A^T + 0.1 I (b uniform in [-1, 1], so about
// half the constraints are active) against the number of contacts n = 2 .. 64, and the lumped
// velocity QP with 2 rows (the two walls of the Eulerian solid) against the number of nodes.
// Problem set-up is outside the timed loop.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>

#include "rodvv/solvers/contact/lcp.hpp"
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

BENCHMARK_MAIN();

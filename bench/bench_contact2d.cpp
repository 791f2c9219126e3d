// Google Benchmark for hard frictionless contact of the planar elastica (elastica2d/contact.hpp):
// the pinned-pinned column between walls y = +/- 0.1 (PHYSICS.md §4.1) at end-shortening 0.026
// (one point contact) and 0.0345 (line contact: the number of active nodes grows with N), 8
// displacement steps from the first-mode guess, against N = 32 .. 1024. Counters: active contacts,
// active-set updates and Newton iterations (all load steps). Expected growth ~N x (updates): each
// Newton step is O(N) (banded KKT with the contact rows next to their nodes).
//
// BM_CavityLcp: the same problems by ContactMethod::NewtonLcp (Josephy-Newton, one LCP per
// iterate through solvers/contact: Lemke or PGS). Forming the Delassus matrix costs one banded
// solve per candidate pair, O(N m) per iterate (m = 2(N + 1) with every pair, m ~ N/3 with the
// candidates within a/2 of a wall), so the expected growth is ~N^2; Lemke adds O(m^2) per pivot,
// PGS O(m^2) per sweep, and PGS needs ~(flat run / h)^4 sweeps on the line contact, so its line
// runs stop at N = 64. The line contact stops at N = 128: from N = 256 an iterate of the 8-step
// path is unstable even with its loaded pairs held and NewtonLcp ends in SolverError
// (contact_lcp.hpp). Counters: LCP pivots / sweeps (all iterates), pairs in the last LCP.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <limits>
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

void BM_CavityLcp(benchmark::State& state, e2::Scheme scheme, double shortening,
                  rodvv::solvers::contact::LcpMethod lcp, double candidate_distance) {
  const auto n = static_cast<std::size_t>(state.range(0));
  e2::Problem problem;
  problem.start.support = e2::Support::Pinned;
  problem.end.support = e2::Support::Pinned;
  problem.end.x = 1.0 - shortening;
  e2::InitialGuess guess;
  guess.theta = [](double s) { return 0.25 * std::cos(std::numbers::pi * s); };
  e2::SolverOptions options;
  options.load_steps = 8;
  e2::ContactOptions contact;
  contact.method = e2::ContactMethod::NewtonLcp;
  contact.lcp = lcp;
  contact.candidate_distance = candidate_distance;
  const auto walls = e2::cavity_walls(0.1);
  e2::ContactSolution last;
  for (auto _ : state) {
    last = e2::solve_static_contact(problem, {scheme, n}, walls, options, guess, contact);
    benchmark::DoNotOptimize(last.rod.y.data());
  }
  state.SetComplexityN(state.range(0));
  state.counters["contacts"] = static_cast<double>(last.contacts.size());
  state.counters["newton_iterations"] = static_cast<double>(last.rod.iterations);
  state.counters["lcp_iterations"] = static_cast<double>(last.lcp_iterations);
  state.counters["lcp_size"] = static_cast<double>(last.lcp_candidates);
}

constexpr double kAll = std::numeric_limits<double>::infinity();
constexpr auto kLemke = rodvv::solvers::contact::LcpMethod::Lemke;
constexpr auto kPgs = rodvv::solvers::contact::LcpMethod::ProjectedGaussSeidel;

BENCHMARK_CAPTURE(BM_Cavity, point_polygon, e2::Scheme::Polygon, 0.026)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, point_arcs, e2::Scheme::Arcs, 0.026)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, line_polygon, e2::Scheme::Polygon, 0.0345)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_Cavity, line_arcs, e2::Scheme::Arcs, 0.0345)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, point_polygon_lemke, e2::Scheme::Polygon, 0.026, kLemke, kAll)->RangeMultiplier(2)->Range(32, 256)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, point_polygon_lemke_near, e2::Scheme::Polygon, 0.026, kLemke, 0.05)->RangeMultiplier(2)->Range(32, 1024)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, point_polygon_pgs, e2::Scheme::Polygon, 0.026, kPgs, kAll)->RangeMultiplier(2)->Range(32, 256)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, line_polygon_lemke, e2::Scheme::Polygon, 0.0345, kLemke, kAll)->RangeMultiplier(2)->Range(32, 128)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, line_polygon_lemke_near, e2::Scheme::Polygon, 0.0345, kLemke, 0.05)->RangeMultiplier(2)->Range(32, 128)->Complexity();
BENCHMARK_CAPTURE(BM_CavityLcp, line_polygon_pgs, e2::Scheme::Polygon, 0.0345, kPgs, kAll)->RangeMultiplier(2)->Range(32, 64)->Complexity();

}  // namespace

BENCHMARK_MAIN();

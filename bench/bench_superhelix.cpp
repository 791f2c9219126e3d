// Google Benchmark for the Super-Helix (solvers/superhelix, ALGORITHMS.md §1.5-1.6).
//  - BM_StepRecursive: one semi-implicit Euler step (kinematics, velocity terms, O(N) articulated-body
//    solve) vs N = 16 .. 1024, with Google Benchmark's complexity fit (target: linear, < 1 ms at
//    N = 1024).
//  - BM_StepDense: the same step by dense assembly (O(N^3)) and LDL^T, N = 16 .. 256 (target: the
//    recursive step at least 20x faster at N = 256).
//  - BM_StepRecursiveTranslationalOnly: BM_StepRecursive without the cross-sections' rotational
//    inertia (rotational_inertia = 0, the pre-issue-11 model): the cost of the rotational terms
//    (measured: +32 % CPU time, 0.51 -> 0.68 ms at N = 1024, linear; machine shared with a build).
//  - BM_StepRecursiveMovingRoot: the recursive step with a translating, spinning-up root (root_motion.hpp).
//  - BM_ClothoidStepRecursive / BM_ClothoidStepDense: the super-clothoid step by the O(N) nodal-strain
//    recursion (N = 16 .. 1024) and by dense assembly + LDL^T (N = 16 .. 256).
//  - BM_Statics: the heavy-cantilever static solve (Newton with the exact Jacobian), N = 8 .. 256
//    (issue 17's target: under 50 ms at N = 256).
//  - BM_JacobianExact / BM_JacobianCentralDifference: the static Jacobian of the same state, exact
//    (load_stiffness.hpp, O(N^2)) and by central differences of the residual (6N residuals of O(N):
//    what Newton used before).
//  - BM_ClothoidStatics: the same static solve for the super-clothoid (Newton with its exact Jacobian,
//    clothoid_load_stiffness.hpp), N = 8 .. 256 (issue 17's target: under 200 ms at N = 256).
//  - BM_ClothoidJacobianExact / BM_ClothoidJacobianCentralDifference: the super-clothoid's static
//    Jacobian, exact (O(N) element second-derivative series, O(N^2) block products) and by central
//    differences (what its Newton used before, 2 x 3(N+1) residuals of O(N)).
//  - BM_InverseStatics: q0, load stiffness and the generalised eigenvalue (dense, O(N^3)).
//  - BM_InverseHairOnSphere: the inverse statics with frictional contact of S strands (10 elements,
//    one contact each, mu = 0.6) lying on a sphere along great circles, strand by strand (no
//    strand-strand contact: each SOCQP is its own), S = 10 .. 1000 (10 000 contacts at S = 1000; the
//    issue's target: under 5 s).
//  - BM_InverseBundle: the inverse statics of a bundle with strand-strand contacts (inverse_bundle.hpp,
//    one SOCQP over all strands on the factored Delassus operator): P pairs of strands (8 elements,
//    radius 5e-5 L) along meridians of a head, each outer strand lying on its inner one, every Gauss point
//    in contact (16 P contacts: 624, 2 496, 10 000 at P = 39, 156, 625), at gamma = 1e-3 (the cases'
//    default) and 1e-2 (the target: 10 000 contacts under 5 s; met at both).
//  - BM_FrictionalDrawOnSlope: the forward frictional statics (frictional_statics.hpp) of a heavy rod lying
//    on a plane tilted 20 degrees, one contact per element (mu = 0.35), drawn up the slope by one increment
//    from its frictionless rest (the rest solved outside the timed loop), N = 8 .. 256: Newton on (q, r),
//    each iteration an O(N^3) dense LU of the tangent stiffness and the contact problem on N contacts.
//  - BM_SelfContacts / BM_SelfContactsAllPairs: the self-contacts of a coil spring whose turns touch
//    (20 turns, every Gauss point in contact with the next and the previous turn) by the chord sort-and-sweep broad phase and by testing every element pair,
//    N = 64 .. 1024 (issue 12: the broad phase vs N).
// The fit exponent over N = 16 .. 1024 (issue: <= 1.1) is the least-squares slope of log(cpu time)
// against log N of the BM_StepRecursive rows (e.g. from --benchmark_format=json).
// The state is a curved, moving rod under gravity (set up outside the timed loop), with the model's
// default rotational inertia (model.hpp) unless stated.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "rodvv/solvers/superhelix/clothoid_dynamics.hpp"
#include "rodvv/solvers/superhelix/clothoid_statics.hpp"
#include "rodvv/solvers/superhelix/contact_dynamics.hpp"
#include "rodvv/solvers/superhelix/dynamics.hpp"
#include "rodvv/solvers/superhelix/frictional_statics.hpp"
#include "rodvv/solvers/superhelix/inverse_bundle.hpp"
#include "rodvv/solvers/superhelix/inverse_contact.hpp"
#include "rodvv/solvers/superhelix/inverse_statics.hpp"
#include "rodvv/solvers/superhelix/kinematics.hpp"
#include "rodvv/solvers/superhelix/root_motion.hpp"
#include "rodvv/solvers/superhelix/self_contact.hpp"
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

void step_benchmark(benchmark::State& bench, sh::DynamicsPath path, bool rotational_inertia = true) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  sh::RodModel model = model_of(n);
  if (!rotational_inertia) model.rotational_inertia.setZero();
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
void BM_StepRecursiveTranslationalOnly(benchmark::State& bench) {
  step_benchmark(bench, sh::DynamicsPath::Recursive, false);
}

void BM_StepRecursiveMovingRoot(benchmark::State& bench) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  const sh::RodModel model = model_of(n);
  const sh::RootMotion root =
      sh::uniformly_accelerated_root(model, Vec3(0.3, 0.0, 0.1), Vec3(1.0, 2.0, -0.5), Vec3(0.0, 0.6, 0.8), 2.0, -3.0);
  sh::DynamicState state = state_of(n);
  state.time = 0.25;
  for (auto _ : bench) {
    const VecX dv = sh::velocity_change(model, state, 1e-3, sh::DynamicsPath::Recursive, root);
    benchmark::DoNotOptimize(dv.data());
  }
  bench.SetComplexityN(bench.range(0));
}

void clothoid_benchmark(benchmark::State& bench, sh::DynamicsPath path) {
  const auto n = static_cast<std::size_t>(bench.range(0));
  const sh::RodModel model = model_of(n);
  sh::DynamicState state;
  state.q = VecX::Constant(static_cast<Eigen::Index>(sh::clothoid_dof_count(model)), 0.5);
  state.qdot = VecX::LinSpaced(state.q.size(), -0.2, 0.3);
  for (auto _ : bench) {
    const VecX dv = sh::clothoid_velocity_change(model, state, 1e-3, path);
    benchmark::DoNotOptimize(dv.data());
  }
  bench.SetComplexityN(bench.range(0));
}
void BM_ClothoidStepRecursive(benchmark::State& bench) { clothoid_benchmark(bench, sh::DynamicsPath::Recursive); }
void BM_ClothoidStepDense(benchmark::State& bench) { clothoid_benchmark(bench, sh::DynamicsPath::Dense); }

// A heavy cantilever's statics (2 load steps) by `solve` at N = bench.range(0).
template <class Solve>
void statics_benchmark(benchmark::State& bench, Solve solve) {
  sh::RodModel model = model_of(static_cast<std::size_t>(bench.range(0)));
  model.gravity = Vec3(0.0, 0.0, -3.0);
  sh::StaticOptions options;
  options.load_steps = 2;
  std::size_t iterations = 0;
  for (auto _ : bench) {
    const auto result = solve(model, options);
    benchmark::DoNotOptimize(result.q.data());
    iterations = result.iterations;
  }
  bench.SetComplexityN(bench.range(0));
  bench.counters["newton_iterations"] = static_cast<double>(iterations);
}

void BM_Statics(benchmark::State& bench) {
  statics_benchmark(bench, [](const sh::RodModel& m, const sh::StaticOptions& o) { return sh::solve_static(m, o); });
}

// The super-clothoid's statics on the same heavy rod, on its exact Jacobian (clothoid_load_stiffness.hpp;
// issue 17's target: under 200 ms at N = 256; on central differences it took 2.4 s at N = 32, 8.3 s at 64).
void BM_ClothoidStatics(benchmark::State& bench) {
  statics_benchmark(bench, [](const sh::RodModel& m, const sh::StaticOptions& o) {
    return sh::solve_clothoid_static(m, o);
  });
}

// The heavy cantilever's equilibrium at N (shared by the Jacobian and inverse benchmarks).
rodvv::VecX heavy_equilibrium(const sh::RodModel& model) {
  sh::StaticOptions options;
  options.load_steps = 2;
  return sh::solve_static(model, options).q;
}

sh::RodModel heavy_model(std::size_t n) {
  sh::RodModel model = model_of(n);
  model.gravity = Vec3(0.0, 0.0, -3.0);
  return model;
}

void BM_JacobianExact(benchmark::State& bench) {
  const sh::RodModel model = heavy_model(static_cast<std::size_t>(bench.range(0)));
  const rodvv::VecX q = heavy_equilibrium(model);
  for (auto _ : bench) benchmark::DoNotOptimize(sh::static_jacobian(model, q).data());
  bench.SetComplexityN(bench.range(0));
}

void BM_JacobianCentralDifference(benchmark::State& bench) {
  const sh::RodModel model = heavy_model(static_cast<std::size_t>(bench.range(0)));
  const rodvv::VecX q = heavy_equilibrium(model);
  const sh::StaticResidual residual = [&model](const rodvv::VecX& x, double lambda) {
    return sh::static_residual(model, x, lambda);
  };
  for (auto _ : bench) benchmark::DoNotOptimize(sh::central_difference_jacobian(residual, q, 1.0, model.length).data());
  bench.SetComplexityN(bench.range(0));
}

// The super-clothoid's exact static Jacobian (forward-mode element second derivatives, O(N) of them, and
// O(N^2) 6 x 6 block products) against central differences of its residual (2 n residuals of O(N)).
rodvv::VecX clothoid_heavy_equilibrium(const sh::RodModel& model) {
  sh::StaticOptions options;
  options.load_steps = 2;
  return sh::solve_clothoid_static(model, options).q;
}

void BM_ClothoidJacobianExact(benchmark::State& bench) {
  const sh::RodModel model = heavy_model(static_cast<std::size_t>(bench.range(0)));
  const rodvv::VecX q = clothoid_heavy_equilibrium(model);
  for (auto _ : bench) benchmark::DoNotOptimize(sh::clothoid_static_jacobian(model, q).data());
  bench.SetComplexityN(bench.range(0));
}

void BM_ClothoidJacobianCentralDifference(benchmark::State& bench) {
  const sh::RodModel model = heavy_model(static_cast<std::size_t>(bench.range(0)));
  const rodvv::VecX q = clothoid_heavy_equilibrium(model);
  const sh::StaticResidual residual = [&model](const rodvv::VecX& x, double lambda) {
    return sh::clothoid_static_residual(model, x, lambda);
  };
  for (auto _ : bench) benchmark::DoNotOptimize(sh::central_difference_jacobian(residual, q, 1.0, model.length).data());
  bench.SetComplexityN(bench.range(0));
}

// A spring of 20 turns of pitch 0.05 on L = 6 (|q| L = 40 pi), contact radius 0.03 (2h > the turn distance).
sh::Kinematics spring(std::size_t n) {
  sh::RodModel model;
  model.length = 6.0;
  model.elements = n;
  const double omega = 40.0 * 3.141592653589793 / model.length, b = 0.05 / (2.0 * 3.141592653589793);
  const double tau = b * omega * omega;
  model.natural_strain = Vec3(tau, std::sqrt(omega * omega - tau * tau), 0.0);
  rodvv::VecX q(3 * static_cast<Eigen::Index>(n));
  for (std::size_t e = 0; e < n; ++e) q.segment<3>(3 * static_cast<Eigen::Index>(e)) = model.natural_strain;
  return sh::Kinematics(model, q);
}

void BM_SelfContacts(benchmark::State& bench) {
  const sh::Kinematics kinematics = spring(static_cast<std::size_t>(bench.range(0)));
  for (auto _ : bench) benchmark::DoNotOptimize(sh::self_contacts(kinematics, {0.03, 1.0}).size());
  bench.SetComplexityN(bench.range(0));
}

void BM_SelfContactsAllPairs(benchmark::State& bench) {
  const sh::Kinematics kinematics = spring(static_cast<std::size_t>(bench.range(0)));
  for (auto _ : bench) benchmark::DoNotOptimize(sh::self_contacts_all_pairs(kinematics, {0.03, 1.0}).size());
  bench.SetComplexityN(bench.range(0));
}

void BM_InverseStatics(benchmark::State& bench) {
  const sh::RodModel model = heavy_model(static_cast<std::size_t>(bench.range(0)));
  const rodvv::VecX q = heavy_equilibrium(model);
  for (auto _ : bench) benchmark::DoNotOptimize(sh::inverse_statics(model, q).critical_stiffness_factor);
  bench.SetComplexityN(bench.range(0));
}

// One strand of the bundle: a great-circle arc of the sphere (radius rho, centre 0) in the plane
// through the vertical turned by `azimuth`, from 10 degrees before the top, 10 elements.
struct Strand {
  sh::RodModel model;
  rodvv::VecX q;
  std::vector<sh::RodContact> contacts;
};

Strand strand_on_sphere(double azimuth) {
  const double rho = 0.2025, L = 0.25, start = -0.1745;
  const Vec3 a(std::cos(azimuth), std::sin(azimuth), 0.0), up(0.0, 0.0, 1.0);
  Strand s;
  s.model.elements = 10;
  s.model.length = L;
  s.model.gauss_points = 1;
  s.model.stiffness = Vec3(0.6e-3, 1.4e-3, 1e-3);
  s.model.line_density = 0.05;
  s.model.gravity = Vec3(0.0, 0.0, -9.81);
  const Vec3 outward = std::sin(start) * a + std::cos(start) * up;
  const Vec3 tangent = std::cos(start) * a - std::sin(start) * up;
  s.model.root_position = rho * outward;
  s.model.root_frame << tangent, -outward, tangent.cross(-outward);
  s.q = rodvv::VecX::Zero(30);
  for (int e = 0; e < 10; ++e) s.q[3 * e + 2] = 1.0 / rho;
  const sh::Kinematics kinematics(s.model, s.q);
  for (std::size_t g = 0; g < kinematics.points().size(); ++g)
    s.contacts.push_back({g, kinematics.points()[g].position.normalized(), 0.6});
  return s;
}

void BM_InverseHairOnSphere(benchmark::State& bench) {
  const auto strands = static_cast<std::size_t>(bench.range(0));
  std::vector<Strand> bundle;
  for (std::size_t i = 0; i < strands; ++i) bundle.push_back(strand_on_sphere(6.283185307179586 * double(i) / double(strands)));
  sh::InverseContactOptions options;
  options.solver.tolerance = 1e-8;
  std::size_t sweeps = 0;
  for (auto _ : bench) {
    sweeps = 0;
    for (const Strand& s : bundle) {
      const auto result = sh::inverse_statics_with_contacts(s.model, s.q, s.contacts, options);
      benchmark::DoNotOptimize(result.natural_strain.data());
      sweeps += result.sweeps;
    }
  }
  bench.SetComplexityN(bench.range(0));
  bench.counters["contacts"] = static_cast<double>(10 * strands);
  bench.counters["mean_sweeps"] = static_cast<double>(sweeps) / static_cast<double>(strands);
}

// Pairs of strands along meridians of a head (inverse/bundle's layout): the inner strand on the head,
// the outer one on the inner, 8 elements each, one contact per element and per layer.
struct StrandBundle {
  std::vector<sh::RodModel> strands;
  std::vector<rodvv::VecX> q;
  std::vector<sh::BundleContact> contacts;
};

StrandBundle strand_bundle(std::size_t pairs) {
  const double R = 0.2, a = 1.25e-5, L = 0.25, pi = 3.141592653589793;
  StrandBundle b;
  for (std::size_t p = 0; p < pairs; ++p) {
    const double azimuth = 2.0 * pi * (double(p) + 0.3) / double(pairs);
    const double theta = pi / 12.0 + (pi / 12.0) * double((7 * p) % pairs) / double(pairs);
    const Vec3 across(std::cos(azimuth), std::sin(azimuth), 0.0);
    const Vec3 outward = std::sin(theta) * across + std::cos(theta) * Vec3::UnitZ();
    const Vec3 tangent = std::cos(theta) * across - std::sin(theta) * Vec3::UnitZ();
    const std::size_t first = b.strands.size();
    for (const double rho : {R + a, R + 3.0 * a}) {
      sh::RodModel m;
      m.length = L * rho / (R + a);
      m.elements = 8;
      m.gauss_points = 1;
      m.stiffness = Vec3(0.6e-3, 1.4e-3, 1e-3);
      m.line_density = 0.05;
      m.gravity = Vec3(0.0, 0.0, -9.81);
      m.root_position = rho * outward;
      m.root_frame << tangent, -outward, tangent.cross(-outward);
      rodvv::VecX q = rodvv::VecX::Zero(24);
      for (int e = 0; e < 8; ++e) q[3 * e + 2] = 1.0 / rho;
      b.strands.push_back(m);
      b.q.push_back(q);
    }
    const sh::Kinematics on_head(b.strands[first], b.q[first]);
    for (std::size_t g = 0; g < 8; ++g) {
      const Vec3 normal = on_head.points()[g].position.normalized();
      b.contacts.push_back({first, g, sh::kObstacle, 0, normal, 0.6});
      b.contacts.push_back({first + 1, g, first, g, normal, 0.6});
    }
  }
  return b;
}

void BM_InverseBundle(benchmark::State& bench) {
  const StrandBundle b = strand_bundle(static_cast<std::size_t>(bench.range(0)));
  sh::InverseBundleOptions options;
  options.gamma = std::pow(10.0, -double(bench.range(1)));
  options.solver.tolerance = 1e-8;
  std::size_t sweeps = 0;
  for (auto _ : bench) {
    const auto result = sh::inverse_statics_of_bundle(b.strands, b.q, b.contacts, options);
    benchmark::DoNotOptimize(result.local_forces.data());
    sweeps = result.sweeps;
  }
  bench.counters["contacts"] = static_cast<double>(b.contacts.size());
  bench.counters["sweeps"] = static_cast<double>(sweeps);
}

// A heavy rod (N elements) lying down the fall line of a plane tilted by 20 degrees, clamped at its upper end,
// and its frictionless rest there.
struct RodOnSlope {
  sh::RodModel model;
  sh::RigidObstacle slope;
  rodvv::Vec3 down;
  sh::FrictionalStaticResult rest;
};

RodOnSlope rod_on_slope(std::size_t elements, std::size_t gauss_points) {
  const double alpha = 20.0 * 3.141592653589793 / 180.0;
  const rodvv::Vec3 normal(std::sin(alpha), 0.0, std::cos(alpha)), down(std::cos(alpha), 0.0, -std::sin(alpha));
  RodOnSlope r;
  r.model.length = 1.3;
  r.model.elements = elements;
  r.model.gauss_points = gauss_points;
  r.model.stiffness = rodvv::Vec3(0.9, 2.1, 1.4);
  r.model.line_density = 0.7;
  r.model.gravity = rodvv::Vec3(0.0, 0.0, -7.3);
  r.model.root_frame << down, normal.cross(down), normal;
  r.slope = {sh::RigidObstacle::Shape::Plane, rodvv::Vec3::Zero(), normal, 0.0, 0.0};
  r.down = down;
  const rodvv::VecX straight = rodvv::VecX::Zero(3 * static_cast<Eigen::Index>(elements));
  r.rest = sh::solve_frictional_increment(r.model, {r.slope}, sh::frictional_start(r.model, straight));
  return r;
}

void BM_FrictionalDrawOnSlope(benchmark::State& bench) {
  const RodOnSlope on_slope = rod_on_slope(static_cast<std::size_t>(bench.range(0)), 1);
  sh::RodModel model = on_slope.model;
  const rodvv::Vec3 down = on_slope.down;
  const auto& rest = on_slope.rest;
  sh::RigidObstacle rough = on_slope.slope;
  rough.mu = 0.35;
  model.root_position -= 0.01 * down;
  std::size_t iterations = 0;
  for (auto _ : bench) {
    const auto drawn = sh::solve_frictional_increment(model, {rough}, rest);
    benchmark::DoNotOptimize(drawn.q.data());
    iterations = drawn.iterations;
  }
  bench.SetComplexityN(bench.range(0));
  bench.counters["iterations"] = static_cast<double>(iterations);
}

// One dynamics step of a rod lying on a plane (every Gauss point a contact, the frictionless rest of the
// slope above), by the dense step's QP (contact_dynamics.hpp): assembly O(N^3), the Delassus matrix of m
// contacts O(N^2 m), Lemke on it; with four Gauss points per element the compliance makes the redundant
// contacts solvable. Compare with BM_StepDense at the same N.
void BM_StepOnPlane(benchmark::State& bench) {
  const RodOnSlope on_slope =
      rod_on_slope(static_cast<std::size_t>(bench.range(0)), static_cast<std::size_t>(bench.range(1)));
  sh::RodModel model = on_slope.model;
  model.rayleigh_stiffness = 0.05;
  const sh::RigidObstacle& plane = on_slope.slope;
  const sh::DynamicState state{on_slope.rest.q, rodvv::VecX::Zero(on_slope.rest.q.size()), 0.0};
  std::size_t contacts = 0, pivots = 0;
  for (auto _ : bench) {
    const auto next = sh::step_with_obstacles(model, state, 1e-2, {plane});
    benchmark::DoNotOptimize(next.state.q.data());
    contacts = next.contacts.size();
    pivots = next.lcp_iterations;
  }
  bench.SetComplexityN(bench.range(0));
  bench.counters["contacts"] = static_cast<double>(contacts);
  bench.counters["pivots"] = static_cast<double>(pivots);
}

BENCHMARK(BM_StepRecursive)->RangeMultiplier(2)->Range(16, 1024)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_StepDense)->RangeMultiplier(2)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_StepRecursiveTranslationalOnly)->RangeMultiplier(4)->Range(16, 1024)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_StepRecursiveMovingRoot)->RangeMultiplier(4)->Range(16, 1024)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity(benchmark::oN);
BENCHMARK(BM_ClothoidStepRecursive)->RangeMultiplier(2)->Range(16, 1024)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_ClothoidStepDense)->RangeMultiplier(2)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMicrosecond)->Complexity();
BENCHMARK(BM_Statics)->RangeMultiplier(2)->Range(8, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_ClothoidStatics)->RangeMultiplier(2)->Range(8, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_ClothoidJacobianExact)->RangeMultiplier(2)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_ClothoidJacobianCentralDifference)->RangeMultiplier(2)->Range(16, 64)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_JacobianExact)->RangeMultiplier(4)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_JacobianCentralDifference)->RangeMultiplier(4)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_SelfContacts)->RangeMultiplier(2)->Range(64, 1024)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_SelfContactsAllPairs)->RangeMultiplier(2)->Range(64, 1024)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_InverseStatics)->RangeMultiplier(4)->Range(16, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_StepOnPlane)->ArgsProduct({{8, 16, 32, 64}, {1, 4}})->ArgNames({"N", "gauss"})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrictionalDrawOnSlope)->RangeMultiplier(2)->Range(8, 256)->ArgName("N")->Unit(benchmark::kMillisecond)->Complexity();
BENCHMARK(BM_InverseBundle)->ArgsProduct({{39, 156, 625}, {3, 2}})->ArgNames({"P", "gamma_exp"})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_InverseHairOnSphere)->RangeMultiplier(10)->Range(10, 1000)->ArgName("strands")->Unit(benchmark::kMillisecond)->Complexity(benchmark::oN);

}  // namespace

BENCHMARK_MAIN();

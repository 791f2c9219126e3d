// run_sweeps (parallel_sweeps.hpp): the results of N workers are those of one, level by level and
// bit for bit, with level failures in place; cases are reported in order; bad input and an
// InputError naming a case's parameter stop the run as in a serial sweep.
#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/parallel_sweeps.hpp"
#include "rodvv/harness/registry.hpp"
#include "synthetic_case.hpp"

namespace {

using namespace rodvv::harness;
using rodvv::testing::synthetic_case;

// Synthetic cases whose levels take unequal times (so that levels finish out of order on several
// workers), one with a failing level.
std::vector<Case> uneven_cases() {
  std::vector<Case> cases;
  for (int k = 0; k < 5; ++k) {
    Case c = synthetic_case(1.0 + 0.5 * k, 0.3 + k);
    c.info.name = "synthetic/case-" + std::to_string(k);
    const LevelRunner original = c.run_level;
    c.run_level = [original, k](const Parameters& p, double level) {
      std::this_thread::sleep_for(std::chrono::milliseconds((7 * k + int(level * 100)) % 9));
      if (k == 3 && level == 0.05) throw rodvv::SolverError("synthetic Newton", "no convergence", 12, 3e-4);
      return original(p, level);
    };
    cases.push_back(std::move(c));
  }
  return cases;
}

std::vector<SweepJob> jobs_of(const std::vector<const Case*>& cases) {
  std::vector<SweepJob> jobs;
  for (const Case* c : cases) {
    const auto levels = sweep_levels(*c, false);
    jobs.push_back({c, c->info.parameters, {levels.begin(), levels.end()}});
  }
  return jobs;
}

void expect_same_results(const std::vector<SweepResult>& a, const std::vector<SweepResult>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].info.name, b[i].info.name);
    ASSERT_EQ(a[i].levels.size(), b[i].levels.size()) << a[i].info.name;
    for (std::size_t l = 0; l < a[i].levels.size(); ++l) {
      const auto &x = a[i].levels[l], &y = b[i].levels[l];
      EXPECT_EQ(x.level, y.level);
      EXPECT_EQ(x.failure, y.failure) << a[i].info.name;
      ASSERT_EQ(x.metrics.size(), y.metrics.size()) << a[i].info.name;
      for (const auto& [name, sample] : x.metrics) {
        const auto& other = y.metrics.at(name);
        EXPECT_EQ(sample.computed, other.computed) << a[i].info.name << " " << name;  // bit for bit
        EXPECT_EQ(sample.error, other.error) << a[i].info.name << " " << name;
      }
    }
    ASSERT_EQ(a[i].gates.size(), b[i].gates.size());
    for (std::size_t g = 0; g < a[i].gates.size(); ++g) {
      EXPECT_EQ(a[i].gates[g].passed, b[i].gates[g].passed);
      EXPECT_EQ(a[i].gates[g].measured, b[i].gates[g].measured);
    }
  }
}

TEST(ParallelSweeps, SeveralWorkersGiveTheResultsOfOneInCaseOrder) {
  const auto cases = uneven_cases();
  std::vector<const Case*> pointers;
  for (const auto& c : cases) pointers.push_back(&c);
  const auto jobs = jobs_of(pointers);
  std::vector<std::string> reported;
  std::size_t levels_seen = 0;
  const auto serial = run_sweeps(jobs, 1);
  const auto parallel = run_sweeps(
      jobs, 4, kDefaultLevelBudgetSeconds, [&](const SweepProgress&) { ++levels_seen; },
      [&](const SweepResult& r) { reported.push_back(r.info.name); });
  expect_same_results(serial, parallel);
  EXPECT_EQ(levels_seen, 5u * 4u);
  EXPECT_EQ(reported, (std::vector<std::string>{"synthetic/case-0", "synthetic/case-1", "synthetic/case-2",
                                                "synthetic/case-3", "synthetic/case-4"}));
  // The failing level stays a level failure of its own case.
  ASSERT_TRUE(parallel[3].levels[1].failure);
  EXPECT_NE(parallel[3].levels[1].failure->find("synthetic Newton"), std::string::npos);
  EXPECT_FALSE(parallel[3].passed());
  // And the same as run_sweep.
  expect_same_results({run_sweep(cases[3], cases[3].info.parameters, cases[3].info.resolution.default_levels)},
                      {parallel[3]});
}

TEST(ParallelSweeps, RealCasesAreBitIdenticalOnTwoWorkers) {
  // Solvers of three families (explicit and adaptive time steppers, Newton on the elastica).
  const std::vector<std::string> patterns{"pendulum/libration-90", "elastica/pinned-pinned-10", "sleeve"};
  const auto cases = default_registry().select(patterns);
  ASSERT_GE(cases.size(), 8u);
  const auto jobs = jobs_of(cases);
  expect_same_results(run_sweeps(jobs, 1), run_sweeps(jobs, 2));
}

TEST(ParallelSweeps, BadInputStopsTheRunBeforeAndDuringIt) {
  auto cases = uneven_cases();
  std::vector<const Case*> pointers;
  for (const auto& c : cases) pointers.push_back(&c);
  auto jobs = jobs_of(pointers);
  EXPECT_THROW(run_sweeps(jobs, 0), rodvv::InputError);
  // Levels that do not refine: refused before anything runs.
  auto bad_levels = jobs;
  bad_levels[2].levels = {0.05, 0.1, 0.025};
  try {
    run_sweeps(bad_levels, 2);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "levels");
  }
  // An InputError naming the case's parameter, thrown inside a level: rethrown (exit 2 in the CLI).
  cases[1].run_level = [](const Parameters&, double) -> LevelOutput { throw rodvv::InputError("c", "c is wrong"); };
  try {
    run_sweeps(jobs, 3);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), "c");
  }
}

}  // namespace

// The per-thread wall-clock budget the solvers' loops check (common/time_budget.hpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <thread>

#include "rodvv/common/errors.hpp"
#include "rodvv/common/time_budget.hpp"

namespace {

using rodvv::check_time_budget;
using rodvv::TimeBudget;

std::string failure_of(const std::string& method) {
  try {
    check_time_budget(method, 7, 0.5);
  } catch (const rodvv::SolverError& error) {
    return error.what();
  }
  return {};
}

TEST(TimeBudget, FreeWithoutABudgetAndWithinOne) {
  EXPECT_EQ(failure_of("loop"), "");
  const TimeBudget budget(60.0);
  EXPECT_EQ(failure_of("loop"), "");
}

TEST(TimeBudget, PastTheDeadlineTheLoopFailsNamingMethodBudgetAndIterations) {
  const TimeBudget budget(1e-6);
  std::this_thread::sleep_for(std::chrono::milliseconds(2));
  const std::string message = failure_of("some Newton");
  EXPECT_NE(message.find("some Newton"), std::string::npos) << message;
  EXPECT_NE(message.find("exceeded its time budget of 1e-06 s per level"), std::string::npos) << message;
  EXPECT_NE(message.find("after 7 iterations"), std::string::npos) << message;
}

TEST(TimeBudget, NestedBudgetsKeepTheEarlierDeadlineAndRestoreOnExit) {
  {
    const TimeBudget outer(1e-6);
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
    {
      const TimeBudget inner(60.0);  // later than the outer deadline: the outer one still holds
      EXPECT_NE(failure_of("inner"), "");
    }
    EXPECT_NE(failure_of("outer"), "");
  }
  EXPECT_EQ(failure_of("after"), "");  // no budget left on this thread
  {
    const TimeBudget outer(60.0);
    {
      const TimeBudget inner(1e-6);  // earlier: it applies inside ...
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      EXPECT_NE(failure_of("inner"), "");
    }
    EXPECT_EQ(failure_of("outer"), "");  // ... and the outer 60 s return after it
  }
}

TEST(TimeBudget, ANonPositiveBudgetIsBadInput) {
  EXPECT_THROW(TimeBudget(0.0), rodvv::InputError);
  EXPECT_THROW(TimeBudget(-1.0), rodvv::InputError);
  EXPECT_THROW(TimeBudget(std::nan("")), rodvv::InputError);
  const TimeBudget huge(1e300);  // clamped, no clock overflow
  EXPECT_EQ(failure_of("loop"), "");
}

}  // namespace

#include <gtest/gtest.h>

#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/harness/richardson.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::harness::richardson_gci;
using rodvv::harness::RichardsonInput;
using rodvv::testing::is_close;

// f(h) = f_exact + C h^p exactly: Richardson recovers f_exact and p, and the asymptotic ratio is 1.
RichardsonInput synthetic(double f_exact, double c, double p, double h1, double r21, double r32) {
  const double h2 = h1 * r21, h3 = h2 * r32;
  return {h1, h2, h3, f_exact + c * std::pow(h1, p), f_exact + c * std::pow(h2, p),
          f_exact + c * std::pow(h3, p)};
}

TEST(Richardson, ConstantRatioRecoversExactValueAndOrder) {
  std::string why;
  const auto result = richardson_gci(synthetic(7.5, 0.3, 2.0, 0.01, 2.0, 2.0), &why);
  ASSERT_TRUE(result.has_value()) << why;
  // Exact arithmetic would give these exactly; the differences f2 - f1 ~ 1e-5 lose ~1e-11 relative.
  EXPECT_TRUE(is_close(result->observed_order, 2.0, 1e-9, 1e-9));
  EXPECT_TRUE(is_close(result->extrapolated, 7.5, 1e-13, 0.0));
  EXPECT_DOUBLE_EQ(result->refinement_ratio, 2.0);
  // GCI_fine = 1.25 |f2 - f1| / |f1| / (r^p - 1) by definition (Roache 1994); with e32 = r^p e21
  // exactly, the asymptotic ratio GCI_coarse / (r^p GCI_fine) is |f1 / f2| (the relative
  // normalisations differ), i.e. 1 up to the size of the discretisation error.
  const double f1 = 7.5 + 0.3e-4, f2 = 7.5 + 0.3 * 4e-4;
  EXPECT_TRUE(is_close(result->asymptotic_ratio, f1 / f2, 1e-9, 0.0));
  EXPECT_TRUE(is_close(result->gci_fine, 1.25 * std::abs(f2 - f1) / f1 / 3.0, 1e-9, 0.0));
}

TEST(Richardson, NonConstantRatioConvergesToTheTrueOrder) {
  std::string why;
  const auto result = richardson_gci(synthetic(-1.0, 2.0, 3.0, 0.01, 1.5, 2.5), &why);
  ASSERT_TRUE(result.has_value()) << why;
  EXPECT_TRUE(is_close(result->observed_order, 3.0, 1e-8, 1e-8));
  EXPECT_TRUE(is_close(result->extrapolated, -1.0, 1e-12, 0.0));
}

TEST(Richardson, DeclinesOscillatoryOrConvergedData) {
  std::string why;
  EXPECT_FALSE(richardson_gci({0.01, 0.02, 0.04, 1.0, 1.1, 0.9}, &why).has_value());
  EXPECT_NE(why.find("oscillatory"), std::string::npos);
  EXPECT_FALSE(richardson_gci({0.01, 0.02, 0.04, 1.0, 1.0, 1.0}, &why).has_value());
  EXPECT_NE(why.find("vanish"), std::string::npos);
  EXPECT_FALSE(richardson_gci({0.01, 0.02, 0.04, 1.0, std::nan(""), 1.0}, &why).has_value());
}

TEST(Richardson, RejectsMeshSizesOutOfOrder) {
  EXPECT_THROW(richardson_gci({0.02, 0.01, 0.04, 1, 2, 3}, nullptr), rodvv::InputError);
  EXPECT_THROW(richardson_gci({0.0, 0.01, 0.04, 1, 2, 3}, nullptr), rodvv::InputError);
}

}  // namespace

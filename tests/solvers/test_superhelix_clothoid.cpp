// Super-clothoid element (ALGORITHMS.md §2): the power series reduces to the Super-Helix closed form
// for constant strains, matches an independent fine RK4 integration for affine strains (the
// example of §2: |a| ~ 4, |b| ~ 10, ell = 0.8), keeps the frame orthonormal, and rejects bad input.
#include <gtest/gtest.h>

#include <cmath>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/superhelix/clothoid_element.hpp"
#include "rodvv/solvers/superhelix/element.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace sh = rodvv::solvers::superhelix;
using rodvv::Mat3;
using rodvv::Vec3;
using rodvv::testing::kEpsilon;

// Classical RK4 on (R, r)' = (R [a + s b]x, R e0), n steps: an independent integrator.
void rk4(const Vec3& a, const Vec3& b, double ell, int n, Mat3& R, Vec3& r) {
  R = Mat3::Identity();
  r = Vec3::Zero();
  const double h = ell / n;
  auto f = [&](double s, const Mat3& Rs) { return Mat3(Rs * sh::skew(a + s * b)); };
  for (int i = 0; i < n; ++i) {
    const double s = i * h;
    const Mat3 k1 = f(s, R), k2 = f(s + h / 2, R + h / 2 * k1), k3 = f(s + h / 2, R + h / 2 * k2),
               k4 = f(s + h, R + h * k3);
    const Vec3 v1 = R.col(0), v2 = (R + h / 2 * k1).col(0), v3 = (R + h / 2 * k2).col(0), v4 = (R + h * k3).col(0);
    r += h / 6 * (v1 + 2 * v2 + 2 * v3 + v4);
    R += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
}

TEST(SuperClothoidElement, ConstantStrainEqualsSuperHelixClosedForm) {
  // b = 0: the series sums exp(ell [a]x) and its integral; 20-40 terms of size <= 1, so 64 eps.
  for (double scale : {0.0, 0.3, 2.0, 7.0}) {
    const Vec3 a = scale * Vec3(0.4, -0.7, 0.59);
    const auto pose = sh::clothoid_element(a, Vec3::Zero(), 0.9);
    const auto maps = sh::element_maps(a, 0.9);
    EXPECT_LE((pose.R - maps.E).cwiseAbs().maxCoeff(), 64 * kEpsilon * double(pose.pieces)) << scale;
    EXPECT_LE((pose.r - maps.G * Vec3::UnitX()).norm(), 64 * kEpsilon * double(pose.pieces)) << scale;
  }
}

TEST(SuperClothoidElement, AffineStrainMatchesFineRk4) {
  // ALGORITHMS.md §2 example scale. RK4 with 20000 steps: error ~ (4e-5)^4 x |kappa|^5 ~ 1e-13;
  // tolerance 1e-11 (the series itself is at ~1e-15, see the next test).
  const Vec3 a(3.0, -2.0, 1.5), b(-6.0, 7.0, 4.0);
  const double ell = 0.8;
  const auto pose = sh::clothoid_element(a, b, ell);
  Mat3 R;
  Vec3 r;
  rk4(a, b, ell, 20000, R, r);
  EXPECT_LE((pose.R - R).cwiseAbs().maxCoeff(), 1e-11);
  EXPECT_LE((pose.r - r).norm(), 1e-11);
  EXPECT_LE((pose.R.transpose() * pose.R - Mat3::Identity()).norm(), 256 * kEpsilon);
  EXPECT_GT(pose.pieces, 1u);  // (|a| + |b| ell) ell = 6.4 > 2: subdivided
  EXPECT_LE(pose.max_terms, 60u);
  // Teeth: the same rod with b dropped is far away.
  EXPECT_GT((sh::clothoid_element(a, Vec3::Zero(), ell).r - r).norm(), 1e-2);
}

TEST(SuperClothoidElement, SubdivisionIsConsistent) {
  // Two halves composed equal the whole (the second half starts with strain a + (ell/2) b).
  const Vec3 a(1.0, 2.0, -0.5), b(3.0, -1.0, 2.0);
  const double ell = 1.2;
  const auto whole = sh::clothoid_element(a, b, ell);
  const auto first = sh::clothoid_element(a, b, ell / 2), second = sh::clothoid_element(a + ell / 2 * b, b, ell / 2);
  EXPECT_LE((whole.R - first.R * second.R).cwiseAbs().maxCoeff(), 256 * kEpsilon);
  EXPECT_LE((whole.r - (first.r + first.R * second.r)).norm(), 256 * kEpsilon);
}

TEST(SuperClothoidElement, BadInputNamesTheParameter) {
  auto expect_parameter = [](auto&& call, const std::string& name) {
    try {
      call();
      ADD_FAILURE() << "no InputError for " << name;
    } catch (const rodvv::InputError& e) {
      EXPECT_EQ(e.parameter(), name);
    }
  };
  expect_parameter([] { sh::clothoid_element(Vec3::Zero(), Vec3::Zero(), 0.0); }, "ell");
  expect_parameter([] { sh::clothoid_element(Vec3(std::nan(""), 0, 0), Vec3::Zero(), 1.0); }, "a");
  expect_parameter([] { sh::clothoid_element(Vec3::Zero(), Vec3::Zero(), 1.0, 0.1); }, "tolerance");
}

}  // namespace

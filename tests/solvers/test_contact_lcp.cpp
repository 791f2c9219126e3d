// solvers/contact: the frictionless LCP (projected Gauss-Seidel and Lemke) and the velocity-level QP
// solved through its dual LCP. Known solutions, random positive (semi)definite problems on which the
// two methods must agree, degenerate and infeasible problems, and bad input.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/contact/lcp.hpp"
#include "rodvv/solvers/contact/velocity_qp.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

using rodvv::MatX;
using rodvv::VecX;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
namespace contact = rodvv::solvers::contact;
using contact::LcpMethod;

// Random W = A A^T + shift I (A with entries in [-1, 1], n x rank), b in [-1, 1]^n.
struct RandomLcp {
  MatX W;
  VecX b;
};
RandomLcp random_lcp(std::mt19937& rng, Eigen::Index n, Eigen::Index rank, double shift) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  MatX A(n, rank);
  for (Eigen::Index i = 0; i < A.size(); ++i) A.data()[i] = u(rng);
  RandomLcp p{A * A.transpose() + shift * MatX::Identity(n, n), VecX(n)};
  for (Eigen::Index i = 0; i < n; ++i) p.b(i) = u(rng);
  return p;
}

// Complementarity conditions of a computed solution to within `tol`.
void expect_complementary(const contact::LcpSolution& s, double tol) {
  EXPECT_GE(s.lambda.minCoeff(), 0.0);
  EXPECT_GE(s.w.minCoeff(), -tol) << "w = " << s.w.transpose();
  EXPECT_LE(s.residual, tol);
  // |phi_FB| <= (2 + sqrt 2) |min(a, c)| (Tseng 1996, Lemma 3.1 of the FB/natural-map equivalence).
  EXPECT_LE(s.fischer_burmeister, (2.0 + std::sqrt(2.0)) * tol);
}

TEST(Lcp, TwoByTwoKnownSolutionBothMethods) {
  // ALGORITHMS.md §4.4: M = [[2,1],[1,2]], q = (-5,-6) -> z = (4/3, 7/3) (both constraints active).
  MatX W(2, 2);
  W << 2, 1, 1, 2;
  const VecX b = (VecX(2) << -5, -6).finished();
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_lcp(W, b, method);
    // Lemke: two pivots on O(1) numbers, a few eps. PGS: stopped at tolerance 1e-13 max|b| on the
    // residual; lambda errors are residual / smallest eigenvalue (1) -> 6e-13, allow 1e-12.
    const double tol = method == LcpMethod::Lemke ? 16 * kEpsilon : 1e-12;
    EXPECT_TRUE(is_close(s.lambda(0), 4.0 / 3.0, 0.0, tol));
    EXPECT_TRUE(is_close(s.lambda(1), 7.0 / 3.0, 0.0, tol));
    EXPECT_GT(s.iterations, 0u);
  }
}

TEST(Lcp, NonNegativeBGivesZeroImpulse) {
  const MatX W = MatX::Identity(3, 3);
  const VecX b = (VecX(3) << 0.5, 0.0, 2.0).finished();
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_lcp(W, b, method);
    EXPECT_EQ(s.lambda.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_EQ(s.iterations, 0u);
  }
}

TEST(Lcp, RandomPositiveDefiniteProblemsMethodsAgree) {
  std::mt19937 rng(20261121);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Index n = 1 + trial % 8;
    const auto p = random_lcp(rng, n, n, 0.1);  // smallest eigenvalue >= 0.1
    const auto lemke = contact::solve_lcp_lemke(p.W, p.b);
    const auto pgs = contact::solve_lcp_pgs(p.W, p.b);
    // Complementarity to round-off: w = W lambda + b is formed with n terms of size
    // <= max|W| max|lambda| + max|b|; Lemke's tableau adds cond(W_AA) <= (n + 0.1 n... )/0.1 ~ 100
    // more. 1e4 eps times that scale covers both; PGS stops at 1e-13 max|b| by construction.
    const double scale = p.W.cwiseAbs().maxCoeff() * lemke.lambda.cwiseAbs().maxCoeff() +
                         p.b.cwiseAbs().maxCoeff();
    expect_complementary(lemke, 1e4 * kEpsilon * scale);
    expect_complementary(pgs, 1e-13 * p.b.cwiseAbs().maxCoeff() * (1 + 1e-9));
    // A PD LCP has a unique solution; the difference is bounded by residual / lambda_min(W) with
    // lambda_min >= 0.1 and the PGS residual <= 1e-13 max|b| (<= 1e-13): 1e-11 absolute allows
    // for the diagonal scaling of the residual (W_ii <= n + 0.1).
    for (Eigen::Index i = 0; i < n; ++i)
      EXPECT_TRUE(is_close(pgs.lambda(i), lemke.lambda(i), 0.0, 1e-11, i)) << "trial " << trial;
  }
}

TEST(Lcp, RandomSemidefiniteProblemsLemkeIsComplementaryAndPgsAgreesOnWLambda) {
  // Rank-deficient W: lambda is not unique, but for a convex QP W lambda (hence w) is.
  std::mt19937 rng(7);
  int solved = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Index n = 2 + trial % 6;
    const auto p = random_lcp(rng, n, n - 1, 0.0);
    // Make it feasible by construction: b = w* - W lambda* with lambda*, w* >= 0 complementary.
    VecX lambda_star = VecX::Zero(n), w_star = VecX::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) (i % 2 ? lambda_star(i) : w_star(i)) = 0.5 + 0.1 * double(i);
    const VecX b = w_star - p.W * lambda_star;
    const auto lemke = contact::solve_lcp_lemke(p.W, b);
    const double scale = p.W.cwiseAbs().maxCoeff() * lemke.lambda.cwiseAbs().maxCoeff() +
                         b.cwiseAbs().maxCoeff();
    expect_complementary(lemke, 1e5 * kEpsilon * scale);  // singular W: cond(W_AA) up to ~1e3
    contact::LcpSettings settings;
    settings.tolerance = 1e-10;  // PGS converges linearly and slowly on singular W
    const auto pgs = contact::solve_lcp_pgs(p.W, b, settings);
    const VecX wl_lemke = p.W * lemke.lambda, wl_pgs = p.W * pgs.lambda;
    // Both agree with the unique W lambda* up to their residuals times the conditioning of the
    // nonzero spectrum; 1e-6 is a loose, measured-safe bound (PGS stops at 1e-10 max|b|).
    for (Eigen::Index i = 0; i < n; ++i) EXPECT_TRUE(is_close(wl_pgs(i), wl_lemke(i), 0.0, 1e-6, i));
    ++solved;
  }
  EXPECT_EQ(solved, 200);
}

// Lemke's tableau tolerances are absolute, so the same problem in other units (W in 1e-12, the Delassus
// matrix of a massive rod) can end on a wrong "solution"; solve_lcp_verified catches that by its residual and
// solves the Jacobi-scaled problem: W lambda matches the unit-scale problem's to 1e-12 relative at W units
// 1e-12 and 1e12 and b units 1e-6 and 1e6. Plain Lemke fails at least one of them (the verification has work
// to do), and an accuracy out of (0, 1) is refused by name.
TEST(Lcp, VerifiedSolveIsIndependentOfTheUnitsOfWAndB) {
  std::mt19937 rng(11);
  int plain_failures = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::Index n = 2 + trial % 6;
    const auto p = random_lcp(rng, n, n, 0.1);
    VecX lambda_star = VecX::Zero(n), w_star = VecX::Zero(n);
    for (Eigen::Index i = 0; i < n; ++i) (i % 2 ? lambda_star(i) : w_star(i)) = 0.5 + 0.1 * double(i);
    const VecX b = w_star - p.W * lambda_star;
    const auto unit = contact::solve_lcp_verified(p.W, b, LcpMethod::Lemke, {}, 1e-6);
    for (const auto& [w_unit, b_unit] : {std::pair{1e-12, 1e-6}, std::pair{1e12, 1e6}, std::pair{1e-12, 1e6}}) {
      std::size_t rescaled = 0;
      const auto scaled =
          contact::solve_lcp_verified(w_unit * p.W, b_unit * b, LcpMethod::Lemke, {}, 1e-6, &rescaled);
      const VecX wl = p.W * (scaled.lambda * (w_unit / b_unit)), wl_unit = p.W * unit.lambda;
      for (Eigen::Index i = 0; i < n; ++i)
        EXPECT_TRUE(is_close(wl(i), wl_unit(i), 0.0, 1e-12 * (1.0 + wl_unit.cwiseAbs().maxCoeff()), i))
            << "trial " << trial << " W unit " << w_unit << " b unit " << b_unit;
      try {
        const auto plain = contact::solve_lcp_lemke(w_unit * p.W, b_unit * b);
        const VecX wp = p.W * (plain.lambda * (w_unit / b_unit));
        if ((wp - wl_unit).cwiseAbs().maxCoeff() > 1e-6 * (1.0 + wl_unit.cwiseAbs().maxCoeff())) ++plain_failures;
      } catch (const rodvv::SolverError&) {
        ++plain_failures;
      }
    }
  }
  EXPECT_GT(plain_failures, 0);
  try {
    contact::solve_lcp_verified(MatX::Identity(1, 1), -VecX::Ones(1), LcpMethod::Lemke, {}, 0.0);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "accuracy"); }
}

TEST(Lcp, DegenerateProblems) {
  // Non-unique lambda: W = [[1,1],[1,1]], b = (-1,-1): any lambda >= 0 with lambda_0 + lambda_1 = 1.
  MatX W(2, 2);
  W << 1, 1, 1, 1;
  const VecX b = (VecX(2) << -1, -1).finished();
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_lcp(W, b, method);
    EXPECT_TRUE(is_close(s.lambda.sum(), 1.0, 0.0, 1e-12));
    expect_complementary(s, 1e-12);
  }
  // Weakly complementary: W = I, b = (0, -1): lambda = (0, 1), w = (0, 0) (both zero in row 0,
  // a tie in Lemke's ratio test).
  const MatX I = MatX::Identity(2, 2);
  const VecX b2 = (VecX(2) << 0.0, -1.0).finished();
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_lcp(I, b2, method);
    EXPECT_EQ(s.lambda(0), 0.0);
    EXPECT_TRUE(is_close(s.lambda(1), 1.0, 0.0, 4 * kEpsilon));
  }
  // Repeated constraint rows (the same contact twice): W = 2 x 2 of ones times 3, equal b.
  MatX W3 = 3.0 * MatX::Ones(3, 3);
  const VecX b3 = VecX::Constant(3, -0.3);
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_lcp(W3, b3, method);
    EXPECT_TRUE(is_close(s.lambda.sum(), 0.1, 0.0, 1e-14));
  }
}

TEST(Lcp, InfeasibleProblemThrowsSolverError) {
  // W = [[1,-1],[-1,1]], b = (-1,-1): w_0 + w_1 = -2 for every lambda, so w >= 0 is impossible.
  MatX W(2, 2);
  W << 1, -1, -1, 1;
  const VecX b = (VecX(2) << -1, -1).finished();
  EXPECT_THROW(contact::solve_lcp_lemke(W, b), rodvv::SolverError);
  contact::LcpSettings settings;
  settings.max_iterations = 2000;
  EXPECT_THROW(contact::solve_lcp_pgs(W, b, settings), rodvv::SolverError);
  // A zero row with b_i < 0.
  const MatX Z = MatX::Zero(1, 1);
  const VecX bz = VecX::Constant(1, -1.0);
  EXPECT_THROW(contact::solve_lcp_pgs(Z, bz), rodvv::SolverError);
  EXPECT_THROW(contact::solve_lcp_lemke(Z, bz), rodvv::SolverError);
}

TEST(Lcp, ResidualDetectsAPerturbedSolution) {
  // The residuals are what the other tests trust: a solution moved off by 1e-6 must show it.
  MatX W(2, 2);
  W << 2, 1, 1, 2;
  const VecX b = (VecX(2) << -5, -6).finished();
  const auto s = contact::solve_lcp_lemke(W, b);
  VecX lambda = s.lambda;
  lambda(0) += 1e-6;
  const VecX w = W * lambda + b;
  EXPECT_GT(contact::natural_map_residual(W, lambda, w), 1e-6);
  EXPECT_GT(contact::fischer_burmeister_residual(W, lambda, w), 1e-6);
  // And a wrong active set (lambda = 0 where w < 0).
  const VecX zero = VecX::Zero(2);
  EXPECT_GT(contact::natural_map_residual(W, zero, b), 4.0);
}

TEST(Lcp, BadInputNamesTheArgument) {
  auto expect_input_error = [](const MatX& W, const VecX& b, const std::string& name) {
    for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
      try {
        contact::solve_lcp(W, b, method);
        ADD_FAILURE() << "no InputError for " << name;
      } catch (const rodvv::InputError& e) {
        EXPECT_EQ(e.parameter(), name) << e.what();
      }
    }
  };
  expect_input_error(MatX::Identity(2, 3), VecX::Zero(2), "W");
  expect_input_error(MatX::Identity(2, 2), VecX::Zero(3), "b");
  MatX nonsym(2, 2);
  nonsym << 1, 0.5, 0, 1;
  expect_input_error(nonsym, VecX::Constant(2, -1.0), "W");
  MatX negative = -MatX::Identity(2, 2);
  expect_input_error(negative, VecX::Constant(2, -1.0), "W");
  MatX nan = MatX::Identity(2, 2);
  nan(0, 0) = std::numeric_limits<double>::quiet_NaN();
  expect_input_error(nan, VecX::Constant(2, -1.0), "W");
  expect_input_error(MatX::Identity(2, 2), VecX::Constant(2, std::numeric_limits<double>::infinity()), "b");
}

// --- the velocity-level QP ---

TEST(VelocityQp, ProjectionOntoAHalfPlane) {
  // min 1/2 |v|^2 - (1,1).v  s.t.  -(v_0 + v_1) >= -1: the free optimum (1,1) projected onto
  // v_0 + v_1 <= 1 is (1/2, 1/2) with impulse 1/2.
  const MatX M = MatX::Identity(2, 2);
  const VecX R = (VecX(2) << -1, -1).finished();
  const MatX J = (MatX(1, 2) << -1, -1).finished();
  const VecX c = VecX::Constant(1, -1.0);
  for (LcpMethod method : {LcpMethod::Lemke, LcpMethod::ProjectedGaussSeidel}) {
    const auto s = contact::solve_velocity_qp(M, R, J, c, method);
    EXPECT_TRUE(is_close(s.v(0), 0.5, 0.0, 1e-13));
    EXPECT_TRUE(is_close(s.v(1), 0.5, 0.0, 1e-13));
    EXPECT_TRUE(is_close(s.lambda(0), 0.5, 0.0, 1e-13));
    EXPECT_TRUE(is_close(s.gap(0), 0.0, 0.0, 1e-13));
  }
}

TEST(VelocityQp, RandomProblemsSatisfyKktAndDenseMatchesLumped) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> u(-1.0, 1.0), pos(0.5, 2.0);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::Index n = 3 + trial % 5, k = 1 + trial % 3;
    VecX m(n), R(n), c(k);
    MatX J(k, n);
    for (Eigen::Index i = 0; i < n; ++i) { m(i) = pos(rng); R(i) = u(rng); }
    for (Eigen::Index i = 0; i < J.size(); ++i) J.data()[i] = u(rng);
    for (Eigen::Index i = 0; i < k; ++i) c(i) = u(rng);
    const auto lumped = contact::solve_velocity_qp_lumped(m, R, J, c);
    const auto dense = contact::solve_velocity_qp(MatX(m.asDiagonal()), R, J, c);
    // KKT: stationarity M v + R = J^T lambda, primal gap >= 0, lambda >= 0, lambda . gap = 0.
    // Entries of M, R, J, c are O(1), k <= 3, n <= 7; round-off in J^T lambda and in the LCP's
    // W lambda scales with |lambda| (large when random rows of J are nearly parallel), so the
    // bound is 1e3 eps x max(1, max|lambda|) (cond(W) of these Delassus matrices measured < 1e2).
    const double scale = std::max(1.0, lumped.lambda.cwiseAbs().maxCoeff());
    const double tol = 1e3 * kEpsilon * scale;
    const VecX stationarity = m.asDiagonal() * lumped.v + R - J.transpose() * lumped.lambda;
    EXPECT_LE(stationarity.cwiseAbs().maxCoeff(), tol);
    EXPECT_GE(lumped.gap.minCoeff(), -tol);
    EXPECT_GE(lumped.lambda.minCoeff(), 0.0);
    EXPECT_LE(std::abs(lumped.lambda.dot(lumped.gap)), tol * scale);
    for (Eigen::Index i = 0; i < n; ++i)
      EXPECT_TRUE(is_close(dense.v(i), lumped.v(i), 0.0, tol, i));
  }
}

// A compliance eps (relative to max W_ii) softens each constraint to J v - c + eps max(W_ii) lambda >= 0,
// complementary to lambda: on the half-plane problem above (W = 2) the impulse is 1 / (2 (1 + eps)) in closed
// form and the gap -eps max(W_ii) lambda; two identical rows (a redundant contact, W singular) share the
// impulse equally, the projection unchanged to O(eps).
TEST(VelocityQp, ComplianceSoftensTheConstraintAsDocumented) {
  const MatX M = MatX::Identity(2, 2);
  const VecX R = (VecX(2) << -1, -1).finished();
  const MatX J = (MatX(1, 2) << -1, -1).finished();
  const VecX c = VecX::Constant(1, -1.0);
  const double eps = 1e-3;
  const auto s = contact::solve_velocity_qp(M, R, J, c, LcpMethod::Lemke, {}, eps);
  EXPECT_TRUE(is_close(s.lambda(0), 0.5 / (1.0 + eps), 0.0, 1e-15));
  EXPECT_TRUE(is_close(s.gap(0), -eps * 2.0 * s.lambda(0), 0.0, 1e-15));
  const MatX twice = (MatX(2, 2) << -1, -1, -1, -1).finished();
  const VecX c2 = VecX::Constant(2, -1.0);
  const auto redundant = contact::solve_velocity_qp(M, R, twice, c2, LcpMethod::Lemke, {}, 1e-9);
  EXPECT_TRUE(is_close(redundant.lambda(0), redundant.lambda(1), 0.0, 1e-12));
  EXPECT_TRUE(is_close(redundant.v(0), 0.5, 0.0, 1e-8));
  try {
    contact::solve_velocity_qp(M, R, J, c, LcpMethod::Lemke, {}, -1e-9);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "compliance"); }
}

TEST(VelocityQp, InfeasibleConstraintsThrowSolverError) {
  // v >= 1 and -v >= 0 cannot both hold.
  const MatX M = MatX::Identity(1, 1);
  const VecX R = VecX::Zero(1);
  const MatX J = (MatX(2, 1) << 1, -1).finished();
  const VecX c = (VecX(2) << 1, 0).finished();
  EXPECT_THROW(contact::solve_velocity_qp(M, R, J, c), rodvv::SolverError);
}

TEST(VelocityQp, BadInputNamesTheArgument) {
  const MatX J = MatX::Ones(1, 2);
  const VecX R = VecX::Zero(2), c = VecX::Zero(1);
  MatX indefinite(2, 2);
  indefinite << 1, 2, 2, 1;
  try {
    contact::solve_velocity_qp(indefinite, R, J, c);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "M"); }
  try {
    contact::solve_velocity_qp_lumped((VecX(2) << 1.0, 0.0).finished(), R, J, c);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "m"); }
  try {
    contact::solve_velocity_qp_lumped(VecX::Ones(2), R, MatX::Ones(1, 3), c);
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "J"); }
  try {
    contact::solve_velocity_qp_lumped(VecX::Ones(2), R, J, VecX::Zero(2));
    ADD_FAILURE();
  } catch (const rodvv::InputError& e) { EXPECT_EQ(e.parameter(), "c"); }
}

}  // namespace

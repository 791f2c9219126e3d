// Cone complementarity (solvers/contact/cone_complementarity.hpp): the local exact solver and the
// block Gauss-Seidel, for the Coulomb law and the plain SOC law, checked by the laws' own conditions
// (take-off / stick / slide, r in K, u in K*, r.u = 0: no solver code), by Siconos' hand-checked
// single contact (ALGORITHMS.md §4.4), and for the SOC law against an independent minimisation of
// 1/2 r^T W r + b^T r over the cones (accelerated projected gradient: another algorithm).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/LU>
#include <string>

#include "rodvv/common/errors.hpp"
#include "rodvv/solvers/contact/cone_complementarity.hpp"
#include "rodvv/solvers/contact/factored_delassus.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace contact = rodvv::solvers::contact;
using contact::ConeLaw;
using rodvv::Mat3;
using rodvv::MatX;
using rodvv::Vec3;
using rodvv::VecX;
using rodvv::testing::kEpsilon;

double tangential(const Vec3& x) { return std::hypot(x[1], x[2]); }

// The law's conditions at one contact, as the largest violation relative to `scale` (|r| |W| + |b|).
double law_violation(const Vec3& r, const Vec3& u, double mu, ConeLaw law, double scale) {
  double v = std::max(0.0, tangential(r) - mu * r[0]);  // r in K_mu
  v = std::max(v, -r[0]);
  if (law == ConeLaw::SecondOrderCone) {
    v = std::max(v, mu * tangential(u) - u[0]);  // u in K_mu*
    v = std::max(v, std::abs(r.dot(u)) / scale);  // orthogonal (r.u has units r u)
    return v / scale;
  }
  v = std::max(v, -u[0]);                                  // u_N >= 0
  v = std::max(v, std::abs(r[0] * u[0]) / scale);          // r_N u_N = 0
  if (tangential(u) > 1e3 * kEpsilon * scale) {            // sliding: r_T = -mu r_N u_T / |u_T|
    const Vec3 expected(r[0], -mu * r[0] * u[1] / tangential(u), -mu * r[0] * u[2] / tangential(u));
    v = std::max(v, (r - expected).norm());
  }
  return v / scale;
}

Mat3 random_spd(std::mt19937& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  Mat3 a;
  for (int i = 0; i < 9; ++i) a(i / 3, i % 3) = entry(rng);
  return a * a.transpose() + 0.2 * Mat3::Identity();
}

TEST(ConeComplementarity, SiconosHandCheckedSlidingContact) {
  // W = diag(2, 1, 1), b = (-1, 0.3, 0), mu = 0.5: sliding, r = (0.5, -0.25, 0), u = (0, 0.05, 0).
  const Mat3 W = Vec3(2.0, 1.0, 1.0).asDiagonal();
  const Vec3 r = contact::solve_local_cone_problem(W, Vec3(-1.0, 0.3, 0.0), 0.5, ConeLaw::Coulomb);
  EXPECT_LE((r - Vec3(0.5, -0.25, 0.0)).norm(), 8 * kEpsilon);
}

TEST(ConeComplementarity, LocalSolutionsSatisfyTheirLaws) {
  std::mt19937 rng(20261126);
  std::uniform_real_distribution<double> entry(-1.0, 1.0), friction(0.05, 1.5);
  int slides[2] = {0, 0};
  for (int trial = 0; trial < 400; ++trial) {
    const Mat3 W = random_spd(rng);
    const Vec3 b(entry(rng), entry(rng), entry(rng));
    const double mu = friction(rng);
    for (ConeLaw law : {ConeLaw::Coulomb, ConeLaw::SecondOrderCone}) {
      const Vec3 r = contact::solve_local_cone_problem(W, b, mu, law);
      const Vec3 u = W * r + b;
      const double scale = r.norm() * W.norm() + b.norm();
      // exact up to the rounding of a root in phi and a few products: 1e3 eps
      EXPECT_LE(law_violation(r, u, mu, law, scale), 1e3 * kEpsilon) << "trial " << trial;
      slides[law == ConeLaw::Coulomb] += r[0] > 0.0 && std::abs(tangential(r) - mu * r[0]) < 1e-12 * r[0];
      // The warm start (Newton on the sliding angle from a guess 0.03 rad off): a solution of the law to
      // the same round-off; for the SOC law the same, unique, solution (W's inverse given, as the
      // Gauss-Seidel calls it).
      const Vec3 guess(r[0], std::cos(0.03) * r[1] - std::sin(0.03) * r[2], std::sin(0.03) * r[1] + std::cos(0.03) * r[2]);
      const Vec3 warm = contact::solve_local_cone_problem(W, W.inverse(), b, mu, law, &guess);
      EXPECT_LE(law_violation(warm, W * warm + b, mu, law, scale), 1e3 * kEpsilon) << "trial " << trial;
      if (law == ConeLaw::SecondOrderCone) {
        EXPECT_LE((warm - r).norm(), 1e-12 * (1.0 + r.norm()));
      }
    }
  }
  // The draws exercise the sliding branch of both laws.
  EXPECT_GT(slides[0], 40);
  EXPECT_GT(slides[1], 40);
}

// min 1/2 r^T W r + b^T r over the product of cones, by FISTA with the cone projection (Beck &
// Teboulle 2009): an independent path to the SOC law's solution.
VecX minimise_over_cones(const MatX& W, const VecX& b, const VecX& mu) {
  const double step = 1.0 / W.operatorNorm();
  VecX r = VecX::Zero(b.size()), y = r;
  double t = 1.0;
  for (int iteration = 0; iteration < 200000; ++iteration) {
    VecX next = y - step * (W * y + b);
    for (Eigen::Index k = 0; k < mu.size(); ++k)
      next.segment<3>(3 * k) = contact::project_onto_friction_cone(next.segment<3>(3 * k), mu[k]);
    const double t_next = 0.5 * (1.0 + std::sqrt(1.0 + 4.0 * t * t));
    y = next + ((t - 1.0) / t_next) * (next - r);
    if ((next - r).norm() < 1e-15 * (1.0 + next.norm())) return next;
    r = next;
    t = t_next;
  }
  return r;
}

MatX random_delassus(std::mt19937& rng, int contacts) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0);
  MatX H(3 * contacts, 3 * contacts + 4);
  for (Eigen::Index i = 0; i < H.size(); ++i) H(i % H.rows(), i / H.rows()) = entry(rng);
  return H * H.transpose() + 0.05 * MatX::Identity(3 * contacts, 3 * contacts);
}

TEST(ConeComplementarity, BlockGaussSeidelSolvesBothLaws) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> entry(-1.0, 1.0), friction(0.1, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    const int n = 5;
    const MatX W = random_delassus(rng, n);
    VecX b(3 * n), mu(n);
    for (int i = 0; i < 3 * n; ++i) b[i] = entry(rng);
    for (int k = 0; k < n; ++k) mu[k] = friction(rng);
    for (ConeLaw law : {ConeLaw::Coulomb, ConeLaw::SecondOrderCone}) {
      contact::ConeSolution solution;
      try {
        solution = contact::solve_cone_complementarity(W, b, mu, law);
      } catch (const rodvv::SolverError& e) {
        // Gauss-Seidel on the Coulomb law is not guaranteed to converge (the problem is not a
        // convex program); the SOC law's is (block coordinate descent on a convex QP).
        EXPECT_EQ(law, ConeLaw::Coulomb) << e.what();
        continue;
      }
      EXPECT_LE(solution.residual, 1e-12);
      EXPECT_LE(solution.cone_violation, 1e-12);
      const double scale = solution.r.norm() * W.norm() + b.norm();
      for (int k = 0; k < n; ++k)
        EXPECT_LE(law_violation(solution.r.segment<3>(3 * k), solution.u.segment<3>(3 * k), mu[k], law, scale), 1e-10)
            << "trial " << trial << " contact " << k;
      if (law == ConeLaw::SecondOrderCone) {
        // The unique minimiser (W positive definite): both methods to their tolerances.
        EXPECT_LE((solution.r - minimise_over_cones(W, b, mu)).norm(), 1e-8 * (1.0 + solution.r.norm())) << trial;
      }
    }
  }
}

TEST(ConeComplementarity, AWrongConeLawIsSeenByTheResidual) {
  // A sliding contact: the Coulomb solution is not the SOC law's, and each law's residual says so.
  const Mat3 W = Vec3(2.0, 1.0, 1.0).asDiagonal();
  const Vec3 b(-1.0, 0.3, 0.0);
  const VecX mu = VecX::Constant(1, 0.5);
  const VecX coulomb = contact::solve_local_cone_problem(W, b, 0.5, ConeLaw::Coulomb);
  const VecX soc = contact::solve_local_cone_problem(W, b, 0.5, ConeLaw::SecondOrderCone);
  EXPECT_GT((coulomb - soc).norm(), 1e-3);
  EXPECT_LE(contact::cone_residual(W, b, mu, coulomb, ConeLaw::Coulomb), 1e-15);
  EXPECT_LE(contact::cone_residual(W, b, mu, soc, ConeLaw::SecondOrderCone), 1e-15);
  EXPECT_GT(contact::cone_residual(W, b, mu, coulomb, ConeLaw::SecondOrderCone), 1e-3);
  EXPECT_GT(contact::cone_residual(W, b, mu, soc, ConeLaw::Coulomb), 1e-3);
}

// The classic forward check: a rigid body resting on an incline of angle alpha on three contacts (an
// equilateral triangle in the plane through its centre of mass, so that the sliding body does not
// turn), one implicit step h from rest: W = H M^-1 H^T (9 x 9, rank 6: redundant contacts), b the
// free contact velocities h H M^-1 (m g, 0). It sticks iff tan alpha <= mu; when it slides, every
// contact moves downhill at h g (sin alpha - mu cos alpha) (Coulomb's sliding block) with u_N = 0.
TEST(ConeComplementarity, ABodyOnAnInclineSticksIffTanAlphaIsAtMostMu) {
  const double alpha = 0.47, g = 9.81, m = 2.3, h = 1e-2;
  const Mat3 plane = Eigen::AngleAxisd(alpha, Vec3::UnitX()).toRotationMatrix();  // columns: x, downhill-ish, normal
  const Vec3 normal = plane.col(2), across = plane.col(0), uphill = plane.col(1);
  const Mat3 inertia = Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix() *
                       Vec3(0.3, 0.5, 0.7).asDiagonal() *
                       Eigen::AngleAxisd(0.4, Vec3(1, 2, 3).normalized()).toRotationMatrix().transpose();
  MatX M = MatX::Zero(6, 6);
  M.topLeftCorner(3, 3) = m * Mat3::Identity();
  M.bottomRightCorner(3, 3) = inertia;
  MatX H(9, 6);
  for (int k = 0; k < 3; ++k) {
    const double phi = 2.0 * 3.141592653589793 * k / 3.0 + 0.3;
    const Vec3 d = 0.4 * (std::cos(phi) * across + std::sin(phi) * uphill);
    Mat3 frame;
    frame << normal, across, uphill;  // (n, t1, t2)
    Mat3 skew;
    skew << 0, -d.z(), d.y(), d.z(), 0, -d.x(), -d.y(), d.x(), 0;
    H.block(3 * k, 0, 3, 3) = frame.transpose();
    H.block(3 * k, 3, 3, 3) = -frame.transpose() * skew;  // v + omega x d = v - [d]x omega
  }
  const MatX Minv = M.inverse();
  MatX W = H * Minv * H.transpose();
  W = 0.5 * (W + W.transpose());
  VecX force = VecX::Zero(6);
  force.head(3) = m * g * Vec3(0.0, 0.0, -1.0);
  const VecX b = h * H * Minv * force;
  for (double factor : {1.001, 0.999}) {
    const double mu = factor * std::tan(alpha);
    const auto solution = contact::solve_cone_complementarity(W, b, VecX::Constant(3, mu), ConeLaw::Coulomb);
    const double slide = h * g * (std::sin(alpha) - mu * std::cos(alpha));  // downhill, when > 0
    for (int k = 0; k < 3; ++k) {
      const Vec3 u = solution.u.segment<3>(3 * k);
      if (factor > 1.0) {
        EXPECT_LE(u.norm(), 1e-10 * h * g) << "sticks, contact " << k;
      } else {
        // downhill is -uphill: u_T2 = -slide; u_N = 0 and no sideways motion
        EXPECT_NEAR(u[2], -slide, 1e-9 * std::abs(slide)) << "slides, contact " << k;
        EXPECT_LE(std::abs(u[0]) + std::abs(u[1]), 1e-10 * h * g) << k;
      }
    }
    EXPECT_LE(solution.residual, 1e-12);
  }
}

// A planar contact (b_T2 = 4e-14, W's T2 row decoupled: a block of inverse/bundle's meridian strands)
// slides exactly along t1: the sliding angle's equation is odd about phi = 0 and its root lies within
// 1e-16 of it. The phi scan once evaluated its last end at 2 pi, where sin(2 pi) = -2.4e-16, so neither
// end interval saw the sign change ("no sliding solution"). r_N from mpmath (40 digits) at phi = 0,
// r = r_N (1, mu, 0): the minimiser of 1/2 r^T W r + b^T r on that ray.
TEST(ConeComplementarity, APlanarSlidingRootNextToPhiZeroIsFound) {
  Mat3 W;
  W << 145749.79464043232, 56973.325078089139, -2.1143929131807251e-12,  //
      56973.325078089139, 24890.05331230268, 3.4735736008646333e-12,     //
      -2.1143929131807251e-12, 3.4735736008646333e-12, 141867.3525641512;
  const double mu = 0.6, r_N = 0.002911436319381132068;
  for (const double b_T2 : {4.0043144055931211e-14, 0.0, -4.0043144055931211e-14}) {
    const Vec3 b(-522.85853816888221, -211.03241134206544, b_T2);
    const Vec3 r = contact::solve_local_cone_problem(W, b, mu, ConeLaw::SecondOrderCone);
    // the stick solution's rounding, through W's condition number 74 (eigenvalues 2.3e3 .. 1.7e5)
    EXPECT_LE((r - Vec3(r_N, mu * r_N, 0.0)).norm(), 1e3 * kEpsilon * r_N) << "b_T2 = " << b_T2;
    const double scale = r.norm() * W.norm() + b.norm();
    EXPECT_LE(law_violation(r, W * r + b, mu, ConeLaw::SecondOrderCone, scale), 1e3 * kEpsilon) << b_T2;
  }
}

// W = sum_b H_b M_b H_b^T + C assembled densely here from random factors: three bodies, contacts on one
// body or two.
struct Factored {
  contact::FactoredDelassus factors;
  MatX dense;
};

Factored random_factored(std::mt19937& rng) {
  std::uniform_real_distribution<double> entry(-1.0, 1.0), weight(0.2, 2.0);
  const std::vector<int> sizes{5, 7, 4};
  const std::vector<std::vector<std::size_t>> touching{{0}, {0, 1}, {2, 1}, {1}, {2, 0}, {2}};
  Factored f;
  std::vector<Eigen::Index> offset{0};
  for (const int n : sizes) {
    VecX m(n);
    for (int i = 0; i < n; ++i) m[i] = weight(rng);
    f.factors.body_weights.push_back(m);
    offset.push_back(offset.back() + n);
  }
  MatX H = MatX::Zero(3 * Eigen::Index(touching.size()), offset.back());
  VecX M(offset.back());
  for (std::size_t b = 0; b < sizes.size(); ++b) M.segment(offset[b], sizes[b]) = f.factors.body_weights[b];
  for (std::size_t k = 0; k < touching.size(); ++k) {
    std::vector<contact::ContactSide> sides;
    for (const std::size_t body : touching[k]) {
      // the leading columns only on some sides (the rest of the block is zero)
      Eigen::Matrix<double, 3, Eigen::Dynamic> rows(3, sizes[body] - int(k % 3));
      for (Eigen::Index i = 0; i < rows.size(); ++i) rows(i % 3, i / 3) = entry(rng);
      H.block(3 * Eigen::Index(k), offset[body], 3, rows.cols()) = rows;
      sides.push_back({body, rows});
    }
    f.factors.sides.push_back(sides);
  }
  f.factors.compliance = VecX::Constant(Eigen::Index(touching.size()), 0.05);
  f.dense = H * M.asDiagonal() * H.transpose();
  f.dense.diagonal().array() += 0.05;
  return f;
}

TEST(ConeComplementarity, TheFactoredOperatorIsTheDenseOne) {
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> entry(-1.0, 1.0), friction(0.1, 1.0);
  for (int trial = 0; trial < 8; ++trial) {
    const Factored f = random_factored(rng);
    const Eigen::Index n = f.dense.rows() / 3;
    VecX b(3 * n), mu(n), r(3 * n);
    for (Eigen::Index i = 0; i < 3 * n; ++i) b[i] = entry(rng), r[i] = entry(rng);
    for (Eigen::Index k = 0; k < n; ++k) mu[k] = friction(rng);
    const double size = f.dense.norm();
    EXPECT_LE((contact::apply(f.factors, r) - f.dense * r).norm(), 64 * kEpsilon * size * r.norm());
    for (Eigen::Index k = 0; k < n; ++k)
      EXPECT_LE((contact::diagonal_block(f.factors, std::size_t(k)) - f.dense.block<3, 3>(3 * k, 3 * k)).norm(),
                64 * kEpsilon * size);
    const MatX W = 0.5 * (f.dense + f.dense.transpose());
    for (ConeLaw law : {ConeLaw::Coulomb, ConeLaw::SecondOrderCone}) {
      contact::ConeSolution dense, factored;
      try {
        dense = contact::solve_cone_complementarity(W, b, mu, law);
      } catch (const rodvv::SolverError&) {
        EXPECT_EQ(law, ConeLaw::Coulomb);  // not a convex program: Gauss-Seidel may not converge
        continue;
      }
      factored = contact::solve_cone_complementarity(f.factors, b, mu, law);
      EXPECT_LE(factored.residual, 1e-12);
      // the same sweeps on the same operator, up to the rounding of its products
      EXPECT_LE((factored.r - dense.r).norm(), 1e-9 * (1.0 + dense.r.norm())) << "trial " << trial;
      EXPECT_LE((factored.u - (W * factored.r + b)).norm(), 1e-12 * (size * factored.r.norm() + b.norm()));
      if (law == ConeLaw::SecondOrderCone) {
        EXPECT_LE((factored.r - minimise_over_cones(W, b, mu)).norm(), 1e-8 * (1.0 + factored.r.norm())) << trial;
      }
    }
  }
}

TEST(ConeComplementarity, TheFactoredOperatorRefusesMalformedFactors) {
  std::mt19937 rng(3);
  const Factored f = random_factored(rng);
  const Eigen::Index n = f.dense.rows() / 3;
  const VecX b = VecX::Constant(3 * n, -1.0), mu = VecX::Constant(n, 0.3);
  const auto with = [&](auto change) {
    contact::FactoredDelassus W = f.factors;
    VecX bb = b, m = mu;
    change(W, bb, m);
    try {
      contact::solve_cone_complementarity(W, bb, m, ConeLaw::SecondOrderCone);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  using F = contact::FactoredDelassus;
  EXPECT_EQ(with([](F&, VecX&, VecX&) {}), "none");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.body_weights[1][2] = 0.0; }), "body_weights");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[3].clear(); }), "sides");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[1][1].body = 0; }), "sides");          // two sides, one body
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[0][0].body = 3; }), "sides");          // no such body
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[0][0].rows.setOnes(3, 6); }), "sides");  // body 0 has 5 dofs
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[0][0].rows.resize(3, 0); }), "sides");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.sides[2][0].rows(1, 1) = std::nan(""); }), "sides");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.compliance[4] = -1e-3; }), "compliance");
  EXPECT_EQ(with([](F& W, VecX&, VecX&) { W.compliance = VecX::Zero(2); }), "compliance");
  EXPECT_EQ(with([](F&, VecX& bb, VecX&) { bb = VecX::Zero(5); }), "b");
  EXPECT_EQ(with([](F&, VecX&, VecX& m) { m[0] = -0.2; }), "mu");
  // A contact whose rows are zero and no compliance: a singular diagonal block.
  EXPECT_EQ(with([](F& W, VecX&, VecX&) {
              W.sides[0][0].rows.setZero();
              W.compliance.resize(0);
            }),
            "W");
  EXPECT_THROW(contact::apply(f.factors, VecX::Zero(4)), rodvv::InputError);
  EXPECT_THROW(contact::diagonal_block(f.factors, 6), rodvv::InputError);  // six contacts
  contact::FactoredDelassus broken = f.factors;
  broken.sides[2][0].body = 7;
  EXPECT_THROW(contact::apply(broken, VecX::Zero(3 * n)), rodvv::InputError);
  EXPECT_THROW(contact::diagonal_block(broken, 2), rodvv::InputError);
}

TEST(ConeComplementarity, RefusesMalformedProblems) {
  const MatX W = MatX::Identity(6, 6);
  const VecX b = VecX::Constant(6, -1.0), mu = VecX::Constant(2, 0.3);
  const auto parameter_of = [](const MatX& w, const VecX& bb, const VecX& m) {
    try {
      contact::solve_cone_complementarity(w, bb, m, ConeLaw::Coulomb);
    } catch (const rodvv::InputError& e) {
      return e.parameter();
    }
    return std::string("none");
  };
  EXPECT_EQ(parameter_of(W, b, mu), "none");
  EXPECT_EQ(parameter_of(MatX::Identity(5, 5), VecX::Zero(5), mu), "W");
  EXPECT_EQ(parameter_of(W, VecX::Zero(3), mu), "b");
  EXPECT_EQ(parameter_of(W, b, VecX::Constant(3, 0.3)), "mu");
  EXPECT_EQ(parameter_of(W, b, VecX::Constant(2, -0.1)), "mu");
  MatX unsymmetric = W;
  unsymmetric(0, 4) = 0.5;
  EXPECT_EQ(parameter_of(unsymmetric, b, mu), "W");
  MatX singular = W;
  singular(4, 4) = 0.0;
  EXPECT_EQ(parameter_of(singular, b, mu), "W");
  VecX nan = b;
  nan[2] = std::nan("");
  EXPECT_EQ(parameter_of(W, nan, mu), "b");
}

}  // namespace

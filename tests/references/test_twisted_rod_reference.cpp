// Tests of the twisted-rod references (references/src/twisted_rod.cpp; PHYSICS.md §7.2, §7.3,
// PRIOR_ART.md §4.5, §4.6).
//
// Oracle: tests/data/twisted_rod_reference.csv from tests/data/make_twisted_rod_table.py (mpmath,
// 40 digits, at the exact double inputs; independent methods: mpmath.diff of the helical curve and
// quad for the end shortening, 2-D findroot on the finite-rod equations in (m, t), complex shooting
// for Greenhill (second- and third-order: axial and semi-tangential end torques, clamped ends), besselj zero + odefun shooting for gamma). Error unit: eps relative to
// max(|expected|, 1) (in_epsilons). Tolerances:
//  - helical curve: a sqrt, sin, cos, cosh, tanh and products, each correctly rounded to ~1 ulp; the
//    argument omega s carries ~|omega s| eps and 4BT - M^2 amplifies by 4BT/(4BT - M^2) (<= 11 in
//    the table, where it enters through a square root, ~5) -> 16 eps;
//  - finite rod: the angle theta to a 4 eps bracket (TOMS 748), conditioned by Phi/(theta f'(theta))
//    (<= ~3 in the table), then m, t, alpha from sin/cos of theta -> 16 eps;
//  - Greenhill, Michell, gamma sqrt(EI GJ)/L^2: a handful of roundings -> 8 eps; the semi-tangential
//    moment is a root to a 4 eps bracket of a determinant whose value is well conditioned -> 8 eps;
//  - gamma: root of the Frobenius series to a 4 eps bracket, series error ~4 eps / |g'| -> 8 eps.
// Measured (x86-64 Release, GCC 12): helical 2.9, finite 1.8, Greenhill 1.7, Michell 0.7, gamma and
// P_cr 1.0 eps (the "[ summary  ]" line).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>
#include <string>
#include <vector>

#include "rodvv/common/errors.hpp"
#include "rodvv/references/twisted_rod.hpp"
#include "rodvv/testing/reference_table.hpp"
#include "rodvv/testing/tolerance.hpp"

namespace {

namespace ref = rodvv::references;
using rodvv::Vec3;
using rodvv::testing::in_epsilons;
using rodvv::testing::is_close;
using rodvv::testing::kEpsilon;
using rodvv::testing::parse_table_number;

constexpr const char* kHeader = "quantity,index,B,C,T,M,L,Phi,D,P,s,value";
enum Column { kQuantity, kIndex, kB, kC, kT, kM, kL, kPhi, kD, kP, kS, kValue };

enum Family { kHelical, kFinite, kGreenhill, kMichell, kLtb, kFamilies };
constexpr const char* kFamilyName[kFamilies] = {"helical", "finite", "greenhill", "michell", "ltb"};
constexpr double kTolerance[kFamilies] = {16.0, 16.0, 8.0, 8.0, 8.0};  // eps, see the file comment

bool starts_with(const std::string& text, const char* prefix) { return text.rfind(prefix, 0) == 0; }

// The C++ value of a table row and its family; the bending stiffness (B column) is scaled by
// (1 + b_perturbation) before the call (0 for the real test).
double evaluate(const std::vector<std::string>& row, double b_perturbation, Family& family) {
  auto number = [&](Column c) { return parse_table_number(row[c]); };
  const std::string& name = row[kQuantity];
  const double B = number(kB) * (1.0 + b_perturbation);
  if (starts_with(name, "helical_")) {
    family = kHelical;
    const ref::LocalizedHelicalBuckling rod{B, number(kT), number(kM)};
    const auto sol = ref::localized_helical_buckling(rod);
    if (name == "helical_alpha") return sol.alpha;
    if (name == "helical_amplitude") return sol.amplitude;
    if (name == "helical_cos_phi_max") return sol.cos_phi_max;
    if (name == "helical_end_shortening") return sol.end_shortening;
    const auto point = ref::localized_helical_buckling_point(rod, number(kS));
    if (name == "helical_position") return point.position[std::stoi(row[kIndex])];
    if (name == "helical_tangent") return point.tangent[std::stoi(row[kIndex])];
    if (name == "helical_cos_phi") return point.cos_phi;
    if (name == "helical_envelope") return point.envelope;
  } else if (starts_with(name, "finite_")) {
    family = kFinite;
    const auto sol = ref::finite_helical_buckling({B, number(kC), number(kL), number(kPhi), number(kD)});
    if (name == "finite_m") return sol.m;
    if (name == "finite_t") return sol.t;
    if (name == "finite_M") return sol.M;
    if (name == "finite_T") return sol.T;
    if (name == "finite_alpha") return sol.alpha;
    if (name == "finite_cos_phi_max") return sol.cos_phi_max;
  } else if (name == "greenhill_moment") {
    family = kGreenhill;
    return ref::greenhill_critical_moment({B, number(kL), number(kP)});
  } else if (name == "greenhill_semitangential_moment") {
    family = kGreenhill;
    return ref::greenhill_semitangential_critical_moment({B, number(kL), number(kP)});
  } else if (name == "clamped_column_moment") {
    family = kGreenhill;
    return ref::clamped_twisted_column_critical_moment({B, number(kL), number(kP)});
  } else if (starts_with(name, "michell_")) {
    family = kMichell;
    const auto sol = ref::michell_ring({B, number(kC), number(kL)});
    if (name == "michell_twist_angle") return sol.twist_angle;
    if (name == "michell_twisting_moment") return sol.twisting_moment;
  } else if (name == "ltb_gamma") {
    family = kLtb;
    return ref::prandtl_cantilever_gamma();
  } else if (name == "ltb_critical_load") {
    family = kLtb;
    return ref::lateral_torsional_cantilever_critical_load({B, number(kC), number(kL)});
  }
  ADD_FAILURE() << "unknown quantity " << name;
  return 0.0;
}

struct TableCheck {
  double worst[kFamilies] = {};
  int failures[kFamilies] = {};
  int rows[kFamilies] = {};
};

TableCheck check_table(double b_perturbation) {
  TableCheck check;
  for (const auto& row : rodvv::testing::read_reference_table("twisted_rod_reference.csv", kHeader)) {
    Family family = kFamilies;
    const double actual = evaluate(row, b_perturbation, family);
    if (family == kFamilies) continue;
    const double expected = parse_table_number(row[kValue]);
    const double error = in_epsilons(actual - expected, expected);
    check.worst[family] = std::max(check.worst[family], error);
    check.failures[family] += !(error <= kTolerance[family]);
    ++check.rows[family];
  }
  return check;
}

TEST(TwistedRodReference, MatchesMpmathTable) {
  const TableCheck check = check_table(0.0);
  const int expected_rows[kFamilies] = {136, 30, 14, 6, 3};
  std::cout << "[ summary  ] max error (eps):";
  for (int f = 0; f < kFamilies; ++f) {
    EXPECT_EQ(check.rows[f], expected_rows[f]) << kFamilyName[f];
    EXPECT_EQ(check.failures[f], 0) << kFamilyName[f] << ": worst " << check.worst[f] << " eps";
    std::cout << " " << kFamilyName[f] << " " << check.worst[f];
  }
  std::cout << "\n";
}

TEST(TwistedRodReference, PerturbedInputTurnsTableRed) {
  // B (1 + 1e-9) moves every B-dependent value by ~1e-9 relative, >= 4.5e6 eps: far above all
  // tolerances. Each family must fail (rows that cannot move stay green: gamma has no input, x(0) = 0,
  // the tails where t.e_z = 1 - 1e-21 and the planar loop's zeros).
  const TableCheck check = check_table(1e-9);
  std::cout << "[ summary  ] rows red with B (1 + 1e-9):";
  for (int f = 0; f < kFamilies; ++f) {
    EXPECT_GT(check.failures[f], 0) << kFamilyName[f];
    std::cout << " " << kFamilyName[f] << " " << check.failures[f] << "/" << check.rows[f];
  }
  std::cout << "\n";
}

TEST(TwistedRodReference, PhysicsExamples) {
  // PHYSICS.md §7.3, printed to 15 significant digits: 1e-15 relative covers the rounding.
  const auto sol = ref::localized_helical_buckling({1.345, 2.0, 1.9});
  EXPECT_TRUE(is_close(sol.alpha, 0.994032859265497, 1e-15, 0.0));
  EXPECT_TRUE(is_close(sol.cos_phi_max, -0.328996282527881, 1e-15, 0.0));
  EXPECT_TRUE(is_close(sol.end_shortening, 2.67394839142419, 2e-15, 0.0));
  // PyElastica's case (PHYSICS.md §7.3): m, t to 18 digits (16 eps), alpha L, cos phi_max to 15 (1e-15)
  const ref::FiniteHelicalBuckling rod{1.345, 0.789, 1.0, 27 * 2 * std::numbers::pi, 0.03};
  const auto fin = ref::finite_helical_buckling(rod);
  EXPECT_TRUE(is_close(fin.m, 98.5414961711907418, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(fin.t, 2900.99320579213075, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(fin.alpha * rod.L, 21.7574490434410, 1e-15, 0.0));
  EXPECT_TRUE(is_close(fin.cos_phi_max, 0.673638264348385, 1e-15, 0.0));
  // Michell (PHYSICS.md §7.2): A = C gives 2 pi sqrt(3) = 10.883 rad, 1.7320508 turns; A = 1, C = 0.5: twice
  EXPECT_NEAR(ref::michell_ring({1.0, 1.0, 1.0}).twist_angle, 10.883, 5e-4);
  EXPECT_NEAR(ref::michell_ring({1.0, 1.0, 1.0}).twist_turns, 1.7320508, 1e-7);
  // (PHYSICS.md's 1.73205087 and 3.46410174 come from a discretised Hessian: 6e-8 and 1.2e-7 above
  // sqrt(3) B/C; only the 8 digits 3.4641017 are checked)
  EXPECT_NEAR(ref::michell_ring({1.0, 0.5, 1.0}).twist_turns, 3.4641017, 1e-7);
  // PRIOR_ART.md §4.5 gamma = 4.012599 (7 digits), §4.6 Greenhill M_cr = 2 pi B/L at P = 0
  EXPECT_NEAR(ref::prandtl_cantilever_gamma(), 4.012599, 5e-7);
  EXPECT_TRUE(is_close(ref::greenhill_critical_moment({1.3, 0.7, 0.0}), 2 * std::numbers::pi * 1.3 / 0.7, 4 * kEpsilon, 0.0));
}

TEST(TwistedRodReference, FiniteRodScalesWithLengthAndMatchesTheInfiniteRod) {
  const ref::FiniteHelicalBuckling unit{1.345, 0.789, 1.0, 27 * 2 * std::numbers::pi, 0.03};
  ref::FiniteHelicalBuckling scaled = unit;
  scaled.L = 100.0;
  scaled.D = 3.0;
  const auto a = ref::finite_helical_buckling(unit), b = ref::finite_helical_buckling(scaled);
  // m, t are dimensionless: equal up to the root tolerance (D/L differs by <= 1 ulp) -> 16 eps
  EXPECT_TRUE(is_close(b.m, a.m, 16 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(b.t, a.t, 16 * kEpsilon, 0.0));
  // M = m B/L, T = t B/L^2, alpha = alpha L / L: one or two roundings -> 4 eps
  EXPECT_TRUE(is_close(b.M, b.m * scaled.B / scaled.L, 4 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(b.T, b.t * scaled.B / (scaled.L * scaled.L), 4 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(b.alpha * scaled.L, a.alpha * unit.L, 16 * kEpsilon, 0.0));
  // The (M, T) found is the infinite rod whose end shortening is D, cos phi_max and alpha equal,
  // and the rotation relation holds: a few roundings on O(100) quantities -> 64 eps.
  const auto inf = ref::localized_helical_buckling({scaled.B, b.T, b.M});
  EXPECT_TRUE(is_close(inf.end_shortening, scaled.D, 64 * kEpsilon, 0.0));
  EXPECT_TRUE(is_close(inf.alpha, b.alpha, 64 * kEpsilon, 0.0));
  EXPECT_NEAR(inf.cos_phi_max, b.cos_phi_max, 64 * kEpsilon);
  const double phi = b.m * scaled.B / scaled.C + 4 * std::acos(b.m / (2 * std::sqrt(b.t)));
  EXPECT_TRUE(is_close(phi, scaled.Phi, 64 * kEpsilon, 0.0));
}

TEST(TwistedRodReference, FiniteRodBranchEnd) {
  // C D/(2 B L) = 0.3 < 1: the branch ends at theta_end = arccos(-0.3)/2 with Phi_end = f(theta_end);
  // Phi = Phi_end is accepted (root at the bracket end), just above is rejected.
  ref::FiniteHelicalBuckling rod{1.0, 2.0, 1.0, 1.0, 0.3};
  const double d = rod.D / rod.L, theta_end = 0.5 * std::acos(-rod.C * d / (2 * rod.B));
  rod.Phi = 4 * rod.B / (rod.C * d) * std::sin(2 * theta_end) + 4 * theta_end;
  const auto sol = ref::finite_helical_buckling(rod);
  EXPECT_NEAR(sol.cos_phi_max, std::cos(2 * theta_end), 4 * kEpsilon);
  rod.Phi *= 1 + 1e-12;
  EXPECT_THROW(ref::finite_helical_buckling(rod), rodvv::InputError);
}

TEST(TwistedRodReference, HelicalCurveIsUnitSpeedAndLocalized) {
  const ref::LocalizedHelicalBuckling rod{0.7, 3.2, -2.5};
  const auto sol = ref::localized_helical_buckling(rod);
  const double h = 1e-5;  // central differences: truncation ~h^2 |r'''| ~ 1e-10, round-off ~eps/h ~ 1e-11
  for (double s : {-4.0, -0.6, 0.0, 0.35, 2.0, 800.0}) {
    const auto p = ref::localized_helical_buckling_point(rod, s);
    EXPECT_NEAR(p.tangent.norm(), 1.0, 8 * kEpsilon) << s;  // |r'| = 1: a few roundings
    const Vec3 dr = (ref::localized_helical_buckling_point(rod, s + h).position -
                     ref::localized_helical_buckling_point(rod, s - h).position) / (2 * h);
    EXPECT_LE((dr - p.tangent).norm(), 1e-9 * (1 + std::abs(s))) << s;
    EXPECT_NEAR((p.cos_phi - sol.cos_phi_max) / (1 - sol.cos_phi_max), p.envelope, 16 * kEpsilon) << s;
  }
  // the straight tails: z(s) - s -> -/+ A, so the two tails are Delta = 2A apart (cosh overflows:
  // sech = 0 exactly at s = 800)
  const auto far = ref::localized_helical_buckling_point(rod, 800.0), near = ref::localized_helical_buckling_point(rod, -800.0);
  EXPECT_NEAR((1600.0 - (far.position.z() - near.position.z())), sol.end_shortening, 1600 * 4 * kEpsilon);
  EXPECT_EQ(far.position.x(), 0.0);
  EXPECT_EQ(far.tangent.z(), 1.0);
}

TEST(TwistedRodReference, GreenhillMomentAndLoadAreInverse) {
  // (M/2B)^2 + P/B = (pi/L)^2 both ways (Euler load 2.96): a few roundings on (pi/L)^2 B ~ 3 -> 16 eps
  // absolute in P
  for (double P : {-3.0, 0.0, 1.5, 2.9}) {
    const ref::GreenhillColumn column{1.2, 2.0, P};
    const double M = ref::greenhill_critical_moment(column);
    EXPECT_NEAR(ref::greenhill_critical_load(column, M), P, 16 * kEpsilon * (1 + std::abs(P))) << P;
  }
}

TEST(TwistedRodReference, GreenhillSemiTangentialScalesAndIsContinuousAtZeroLoad) {
  // M_cr L/B = 4.911287725758880608 (mpmath; x/2 + arctan(x/6) = pi at P = 0) for any B, L: 8 eps
  const double x = 4.911287725758880608;
  EXPECT_TRUE(is_close(ref::greenhill_semitangential_critical_moment({1.3, 0.7, 0.0}) * 0.7 / 1.3, x, 8 * kEpsilon, 0.0));
  EXPECT_NEAR(x / 2 + std::atan(x / 6), std::numbers::pi, 4 * kEpsilon);
  // P -> 0 from either side: the basis function (e^{i k2 s} - 1 - i k2 s)/(i k2)^2 -> s^2/2 has no
  // cancellation, so M_cr(P) is smooth through 0: dM/dP ~ -0.4 L/... here, so |P| = 1e-9 moves it by
  // < 1e-9; a basis that degenerated (1, s, e^{i k1 s}, e^{i k2 s}) would lose ~eps/|k2 L| instead.
  const double m0 = ref::greenhill_semitangential_critical_moment({1.0, 1.0, 0.0});
  for (double P : {-1e-9, 1e-9}) EXPECT_NEAR(ref::greenhill_semitangential_critical_moment({1.0, 1.0, P}), m0, 1e-9) << P;
  // below the axial (Greenhill) moment at every load, and equal to neither
  for (double P : {-4.0, 0.0, 5.0}) {
    const ref::GreenhillColumn column{1.0, 1.0, P};
    EXPECT_LT(ref::greenhill_semitangential_critical_moment(column), 0.85 * ref::greenhill_critical_moment(column)) << P;
  }
  EXPECT_THROW(ref::greenhill_semitangential_critical_moment({1.0, 1.0, 10.0}), rodvv::InputError);  // > Euler 9.87
}

TEST(TwistedRodReference, ClampedTwistedColumn) {
  // P = 0: M_cr L/B = 2 y, tan y = y (y = 4.4934094579090641753): 8 eps
  const double x = 8.98681891581812835;
  EXPECT_TRUE(is_close(ref::clamped_twisted_column_critical_moment({0.7, 2.3, 0.0}) * 2.3 / 0.7, x, 8 * kEpsilon, 0.0));
  EXPECT_NEAR(std::tan(x / 2) - x / 2, 0.0, 64 * kEpsilon * x);  // tan is ill-conditioned near its pole: 64 eps
  // the moment falls to 0 at the clamped Euler load 4 pi^2 B/L^2 (39.48 here) and rises under tension
  const double m_near_euler = ref::clamped_twisted_column_critical_moment({1.0, 1.0, 39.0});
  EXPECT_LT(m_near_euler, 0.25 * x);
  EXPECT_GT(ref::clamped_twisted_column_critical_moment({1.0, 1.0, -5.0}), x);
  EXPECT_THROW(ref::clamped_twisted_column_critical_moment({1.0, 1.0, 40.0}), rodvv::InputError);
  EXPECT_THROW(ref::clamped_twisted_column_critical_moment({-1.0, 1.0, 0.0}), rodvv::InputError);
}

TEST(TwistedRodReference, MichellAndCantileverFormulas) {
  const auto ring = ref::michell_ring({1.3, 0.9, 3.7});
  EXPECT_TRUE(is_close(ring.twisting_moment, 0.9 * ring.twist_angle / 3.7, 4 * kEpsilon, 0.0));  // M = C Phi / L
  EXPECT_TRUE(is_close(ring.twist_angle, 2 * std::numbers::pi * ring.twist_turns, 2 * kEpsilon, 0.0));
  const double gamma = ref::prandtl_cantilever_gamma();
  EXPECT_TRUE(is_close(ref::lateral_torsional_cantilever_critical_load({2.0, 0.5, 2.0}), gamma * 1.0 / 4.0, 2 * kEpsilon, 0.0));
}

template <class F>
void expect_parameter(F&& call, const std::string& name) {
  try {
    call();
    ADD_FAILURE() << "no InputError for " << name;
  } catch (const rodvv::InputError& e) {
    EXPECT_EQ(e.parameter(), name);
  }
}

TEST(TwistedRodReference, BadInputNamesTheParameter) {
  const double nan = std::nan("");
  expect_parameter([] { ref::localized_helical_buckling({0.0, 1.0, 0.0}); }, "B");
  expect_parameter([] { ref::localized_helical_buckling({1.0, -1.0, 0.0}); }, "T");
  expect_parameter([] { ref::localized_helical_buckling({1.0, 1.0, 2.0}); }, "M");  // M^2 = 4BT
  expect_parameter([&] { ref::localized_helical_buckling({1.0, 1.0, nan}); }, "M");
  expect_parameter([&] { ref::localized_helical_buckling_point({1.0, 1.0, 0.5}, nan); }, "s");
  const ref::FiniteHelicalBuckling good;
  EXPECT_NO_THROW(ref::finite_helical_buckling(good));
  auto bad = good;
  bad.B = -1.0;
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "B");
  bad = good;
  bad.C = 0.0;
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "C");
  bad = good;
  bad.L = nan;
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "L");
  bad = good;
  bad.D = bad.L;  // the rod cannot shorten by its length
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "D");
  bad = good;
  bad.Phi = 0.0;
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "Phi");
  bad = good;
  bad.Phi = 300.0;  // beyond the branch end Phi_end ~ 230.4
  expect_parameter([&] { ref::finite_helical_buckling(bad); }, "Phi");
  expect_parameter([] { ref::greenhill_critical_moment({0.0, 1.0, 0.0}); }, "B");
  expect_parameter([] { ref::greenhill_critical_moment({1.0, 0.0, 0.0}); }, "L");
  expect_parameter([] { ref::greenhill_critical_moment({1.0, 1.0, 10.0}); }, "P");  // above pi^2 B/L^2
  expect_parameter([&] { ref::greenhill_critical_load({1.0, 1.0, 0.0}, nan); }, "M");
  expect_parameter([] { ref::michell_ring({0.0, 1.0, 1.0}); }, "B");
  expect_parameter([] { ref::michell_ring({1.0, -1.0, 1.0}); }, "C");
  expect_parameter([] { ref::michell_ring({1.0, 1.0, 0.0}); }, "L");
  expect_parameter([] { ref::lateral_torsional_cantilever_critical_load({0.0, 1.0, 1.0}); }, "EI_weak");
  expect_parameter([] { ref::lateral_torsional_cantilever_critical_load({1.0, 0.0, 1.0}); }, "GJ");
  expect_parameter([&] { ref::lateral_torsional_cantilever_critical_load({1.0, 1.0, nan}); }, "L");
}

}  // namespace
